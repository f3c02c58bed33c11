/// @file real_breath_test.cpp
/// @brief The follower held against real recordings no one here wrote: the ExtMarker data set's 15 chest and
///        abdomen markers of supine volunteers (tests/data/breath/, CC BY 4.0, Krilavicius et al.), read as
///        published, followed every 10 ms as `lungar-breathe --breath FILE --dt 0.01` does, and judged as
///        `../shared/tools/breath-check` judges them (breath_judge.h): |corr| >= 0.9 with the marker's breathing
///        axis, a median swing of V_T +- 15 %, dV within [-V_T/2, 3 V_T]; a file whose main motion is slower than
///        5 cycles a minute on its bounds only.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "sim/breathing/breath_follower.h"
#include "sim/breathing/breath_trace.h"
#include "tests/sim/breathing/breath_judge.h"

namespace lungar::sim {
namespace {

const std::string kData = std::string(LUNGAR_SOURCE_DIR) + "/tests/data/breath/extmarker/";

struct Followed {
  std::vector<double> t, dv;
  long bounded = 0;
  int irregular = 0;
};

Followed follow(const BreathTrace& trace, double seconds, FollowerParams p = {}) {
  BreathFollower f(p);
  Followed out;
  std::size_t next = 0;
  for (long k = 0; k * 0.01 <= seconds + 1e-9; ++k) {
    const double t = static_cast<double>(k) * 0.01;
    for (; next < trace.samples.size() && trace.samples[next].t_s <= t; ++next)
      f.add(trace.samples[next].t_s, trace.samples[next].value);
    out.t.push_back(t);
    out.dv.push_back(f.at(t, 0.0).dv_ml);
  }
  out.bounded = f.bounded_samples();
  out.irregular = f.irregular_breaths();
  return out;
}

std::vector<std::string> recordings() {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(kData))
    if (e.path().extension() == ".csv") names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(RealBreath, EveryExtMarkerRecordingMeetsTheFiguresOfBreathCheck) {
  const std::vector<std::string> names = recordings();
  ASSERT_EQ(names.size(), 15u) << "the data set's 15 files, in " << kData;
  int met = 0;
  for (const std::string& name : names) {
    SCOPED_TRACE(name);
    auto trace = read_breath_trace(kData + name);
    ASSERT_TRUE(trace) << trace.error();
    EXPECT_EQ(trace->format, "extmarker");
    const testing::MarkerRecording m = testing::read_marker_recording(kData + name);
    const Followed run = follow(*trace, std::floor(m.t_s.back() - m.t_s.front()) - 1.0);
    const testing::BreathFigures f = testing::judge(m, run.t, run.dv);
    const bool bounded = f.lo_ml >= -250.0 && f.hi_ml <= 1500.0;
    EXPECT_TRUE(bounded) << "dV " << f.lo_ml << ".." << f.hi_ml << " mL";
    if (f.period_s > 12.0) {  // slower than 5 a minute: not breathing, judged on its bounds
      met += bounded ? 1 : 0;
      continue;
    }
    EXPECT_GE(f.corr, 0.9);
    EXPECT_GE(f.median_swing_ml, 425.0);
    EXPECT_LE(f.median_swing_ml, 575.0);
    met += bounded && f.corr >= 0.9 && f.median_swing_ml >= 425.0 && f.median_swing_ml <= 575.0 ? 1 : 0;
  }
  EXPECT_EQ(met, 15);
}

TEST(RealBreath, TalkingIsFollowedAndFlaggedWithoutRescalingTheBreath) {
  // The `T` session: the volunteer talks through much of it. The chest's small fast turns are flagged
  // irregular, and the breath stays its size.
  const std::string name = "201205101519-UCC-1-T-222-6.csv";
  auto trace = read_breath_trace(kData + name);
  ASSERT_TRUE(trace) << trace.error();
  const testing::MarkerRecording m = testing::read_marker_recording(kData + name);
  const Followed run = follow(*trace, std::floor(m.t_s.back() - m.t_s.front()) - 1.0);
  EXPECT_GE(run.irregular, 10) << "talking flagged";
  const testing::BreathFigures f = testing::judge(m, run.t, run.dv);
  EXPECT_NEAR(f.median_swing_ml, 500.0, 75.0);
}

TEST(RealBreath, TheBoundsActAndAreCountedWhereTheChestMovesBeyondABreath) {
  // The `LT` upper-chest marker moves six breaths' depth at once: the bound holds dV and counts it.
  auto trace = read_breath_trace(kData + "201205101536-UCC-1-LT-142-6.csv");
  ASSERT_TRUE(trace) << trace.error();
  EXPECT_EQ(trace->skipped, 1) << "one garbled timestamp in the published file";
  const Followed run = follow(*trace, 140.0);
  EXPECT_GT(run.bounded, 0);
  EXPECT_LE(*std::max_element(run.dv.begin(), run.dv.end()), 1500.0);
  EXPECT_GE(*std::min_element(run.dv.begin(), run.dv.end()), -250.0);
}

}  // namespace
}  // namespace lungar::sim
