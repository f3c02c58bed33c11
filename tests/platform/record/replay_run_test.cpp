// `lungar --session-record` and `lungar replay` as a user runs them (headless, EGL on llvmpipe): a short session with
// a pathology coming replays with the same dV and the same pathologies frame by frame; an instructor killed mid-session
// leaves a record that replays up to the kill; a bad record and an unwritable path are one line each.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "platform/record/session_record.h"
#include "tests/file_text.h"
#include "tests/platform/sync/station_process.h"
#include "tests/platform/sync/stations_test.h"

using lungar::testing::StationProcess;

namespace {

/// A replay's --trace-csv row.
struct TraceRow {
  double s = 0, t_s = 0, dv_ml = 0, left_ml = 0, right_ml = 0;
  std::string pathologies;
};

std::vector<TraceRow> trace_rows(const std::filesystem::path& csv) {
  std::vector<TraceRow> rows;
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // the header
  while (std::getline(in, line)) {
    TraceRow r;
    std::istringstream fields(line);
    char comma = 0;
    fields >> r.s >> comma >> r.t_s >> comma >> r.dv_ml >> comma >> r.left_ml >> comma >> r.right_ml >> comma;
    std::getline(fields, r.pathologies);
    if (r.pathologies.size() >= 2 && r.pathologies.front() == '"')
      r.pathologies = r.pathologies.substr(1, r.pathologies.size() - 2);
    rows.push_back(r);
  }
  return rows;
}

/// The indices at which `label_of(k)` differs from `label_of(k - 1)`.
template <class Label>
std::vector<std::size_t> changes(std::size_t n, const Label& label_of) {
  std::vector<std::size_t> at;
  for (std::size_t k = 1; k < n; ++k)
    if (label_of(k) != label_of(k - 1)) at.push_back(k);
  return at;
}

class SessionReplay : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = lungar::testing::test_dir(std::string("record_") +
                                    ::testing::UnitTest::GetInstance()->current_test_info()->name());
    // 30 breaths a minute (a breath every 2 s); a right tension pneumothorax comes at 1.0 s over 1.0 s.
    scenario = (dir / "ptx.toml").string();
    std::ofstream(scenario) << "duration_s = 30.0\n[start]\nrate_bpm = 30.0\ntidal_volume_ml = 500.0\n"
                               "pose = \"supine\"\n[[event]]\nat_s = 1.0\nkind = \"pathology\"\n"
                               "add = \"pneumothorax:right:30:tension\"\nover_s = 1.0\n";
  }
  void TearDown() override { std::filesystem::remove_all(dir); }

  /// A station recording `seconds` of the scenario into `record`, with `extra` options.
  std::unique_ptr<StationProcess> record_session(const std::string& record, double seconds, const std::string& name,
                                                 std::vector<std::string> extra = {}) {
    std::vector<std::string> a{"--config",         lungar::testing::kConfig,
                               "--asset",          lungar::testing::kAsset,
                               "--output",         "headless",
                               "--tracker",        "mock",
                               "--scenario",       scenario,
                               "--seconds",        std::to_string(seconds),
                               "--session-record", record,
                               "--stats-json",     (dir / (name + ".json")).string(),
                               "--snapshot",       (dir / (name + ".png")).string()};
    a.insert(a.end(), extra.begin(), extra.end());
    return std::make_unique<StationProcess>(lungar::testing::kLungar, a, dir / name);
  }
  /// `lungar replay` of `record` with `extra` options.
  std::unique_ptr<StationProcess> replay(const std::string& record, const std::string& name,
                                         std::vector<std::string> extra) {
    std::vector<std::string> a = {"--config",     lungar::testing::kConfig,
                                  "replay",       record,
                                  "--output",     "headless",
                                  "--stats-json", (dir / (name + ".json")).string(),
                                  "--snapshot",   (dir / (name + ".png")).string()};
    a.insert(a.end(), extra.begin(), extra.end());
    return std::make_unique<StationProcess>(lungar::testing::kLungar, a, dir / name);
  }

  std::filesystem::path dir;
  std::string scenario;
};

}  // namespace

TEST_F(SessionReplay, ARecordedSessionReplaysWithTheSameDvAndPathologiesFrameByFrame) {
  const std::string record = (dir / "class.lungarsession").string();
  auto live = record_session(record, 3.0, "live");
  ASSERT_EQ(live->wait(60), 0) << live->err();
  auto read = lungar::platform::record::read_session_record(record);
  ASSERT_TRUE(read) << read.error();
  const auto& frames = read->frames;
  ASSERT_TRUE(read->ended && read->cut.empty()) << read->cut;
  ASSERT_GT(frames.size(), 30u) << live->err();
  const auto recorded_changes = changes(frames.size(), [&](std::size_t k) { return frames[k].pathologies; });
  ASSERT_FALSE(recorded_changes.empty()) << "the pneumothorax came during the session: " << frames.back().pathologies;

  const std::filesystem::path trace = dir / "trace.csv", timeline = dir / "timeline.csv";
  auto played = replay(record, "replay",
                       {"--pace", "frames", "--trace-csv", trace.string(), "--timeline-csv", timeline.string(),
                        "--snapshot-every", "1.0", "--snapshot-dir", (dir / "shots").string()});
  ASSERT_EQ(played->wait(60), 0) << played->err();
  const std::vector<TraceRow> rows = trace_rows(trace);
  ASSERT_EQ(rows.size(), frames.size()) << "each recorded frame replayed once";
  double worst_ml = 0;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    SCOPED_TRACE(k);
    EXPECT_NEAR(rows[k].s, frames[k].s, 1e-5);
    worst_ml = std::max({worst_ml, std::abs(rows[k].dv_ml - frames[k].breath.dv_ml),
                         std::abs(rows[k].left_ml - frames[k].lung_dv_ml[0]),
                         std::abs(rows[k].right_ml - frames[k].lung_dv_ml[1])});
  }
  EXPECT_LE(worst_ml, 1.0) << "dV and each lung's (the right one's share follows the replayed course)";
  const auto replayed_changes = changes(rows.size(), [&](std::size_t k) { return rows[k].pathologies; });
  ASSERT_EQ(replayed_changes.size(), recorded_changes.size());
  for (std::size_t c = 0; c < recorded_changes.size(); ++c) {
    EXPECT_LE(std::abs(static_cast<long>(replayed_changes[c]) - static_cast<long>(recorded_changes[c])), 1)
        << "change " << c << " to " << rows[replayed_changes[c]].pathologies;
    EXPECT_EQ(rows[replayed_changes[c]].pathologies, frames[recorded_changes[c]].pathologies);
  }
  EXPECT_NE(lungar::testing::file_text(timeline).find("pathologies drawn"), std::string::npos);
  std::size_t shots = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "shots"))
    shots += entry.path().extension() == ".png";
  // One at each whole second the session's frames reach.
  const auto whole_seconds = static_cast<std::size_t>(std::floor(frames.back().s) - std::ceil(frames.front().s) + 1);
  EXPECT_EQ(shots, whole_seconds) << frames.front().s << " to " << frames.back().s << " s";
  std::cout << "[ replay ] " << frames.size() << " frames, largest dV difference " << worst_ml << " mL\n";
}

TEST_F(SessionReplay, AnInstructorKilledMidSessionLeavesARecordThatReplaysUpToTheKill) {
  const std::string record = (dir / "killed.lungarsession").string();
  auto live = record_session(
      record, 30.0, "killed",
      {"--sync", "instructor", "--station", "instructor", "--classroom", lungar::testing::test_classroom("killed"),
       "--sync-domain", std::to_string(lungar::testing::test_domain())});
  ASSERT_TRUE(live->wait_for("session record: ", 60)) << live->err();
  lungar::testing::sleep_s(2.0);
  live->kill_now();
  auto read = lungar::platform::record::read_session_record(record);
  ASSERT_TRUE(read) << read.error();
  EXPECT_FALSE(read->ended);
  ASSERT_GT(read->frames.size(), 10u);
  EXPECT_GT(read->frames.back().s, 1.0) << "at most a fraction of a second lost before the kill";

  const std::filesystem::path trace = dir / "trace.csv";
  auto played = replay(record, "replay", {"--pace", "frames", "--trace-csv", trace.string()});
  ASSERT_EQ(played->wait(60), 0) << played->err();
  EXPECT_NE(played->err().find("killed?"), std::string::npos) << played->err();
  const std::vector<TraceRow> rows = trace_rows(trace);
  ASSERT_EQ(rows.size(), read->frames.size());
  EXPECT_NEAR(rows.back().s, read->frames.back().s, 1e-5);
  EXPECT_NEAR(rows.back().dv_ml, read->frames.back().breath.dv_ml, 1.0);
}

TEST_F(SessionReplay, ABadRecordAndAnUnwritablePathAreOneLineEach) {
  const std::string bad = (dir / "bad.lungarsession").string();
  std::ofstream(bad) << "t_s,value\n0,1\n";
  auto played = replay(bad, "bad", {});
  EXPECT_EQ(played->wait(30), 2);
  EXPECT_NE(played->err().find(bad + ":1: not a lungar session record"), std::string::npos) << played->err();

  auto refused = record_session((dir / "no-such-folder" / "x.lungarsession").string(), 1.0, "refused");
  EXPECT_EQ(refused->wait(30), 2);
  EXPECT_NE(refused->err().find("lungar: --session-record: "), std::string::npos) << refused->err();
  EXPECT_EQ(refused->err().find("asset:"), std::string::npos) << "refused before the lungs load: " << refused->err();
}
