/// @file vxp_trace_test.cpp
/// @brief Varian RPM .vxp traces: a file as RPM 1.6 writes it is read with its times, its amplitude in mm
///        (Scale_factor applied), its flagged samples kept, marked and counted and its peak marks counted, and the follower finds the breaths RPM marked; each way a file
///        can be wrong is one line naming the file, the line and what was expected.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "sim/breathing/breath_follower.h"
#include "sim/breathing/breath_trace.h"

namespace lungar::sim {
namespace {

/// 60 s at 30 samples/s, 15 breaths/min, amplitude in cm (0.8 deep), a P mark at each peak and a Z at each
/// end-exhale; samples 300-314 (half a second) flagged (-1): RPM's verdict, the amplitude still breathing.
std::string rpm_file(int* peaks = nullptr) {
  std::ostringstream o;
  o << "[Header]\r\nCRC=12345\r\nVersion=1.6\r\nData_layout=amplitude,phase,timestamp,validflag,ttlin,mark,ttlout\r\n"
       "Patient_ID=phantom\r\nDate=11-26-2026\r\nTotal_study_time=60.0\r\nSamples_per_second=30\r\n"
       "Scale_factor=10.0\r\nGating_min=0.2\r\nGating_max=0.5\r\nGating_mode=amplitude\r\n[Data]\r\n";
  int marked = 0;
  for (int i = 0; i < 1800; ++i) {
    const double t = i / 30.0, u = std::fmod(t, 4.0) / 4.0;
    const double amp = 0.8 * (0.5 - 0.5 * std::cos(2 * M_PI * u)) + 1.5;
    const bool peak = i % 120 == 60, trough = i % 120 == 0;
    marked += peak ? 1 : 0;
    o << amp << "," << 2 * M_PI * u << "," << 1000 * 1000 + i * 100 / 3 << "," << (i >= 300 && i < 315 ? -1 : 0)
      << ",0,"
      << (peak     ? "P"
          : trough ? "Z"
                   : "")
      << ",0\r\n";
  }
  if (peaks) *peaks = marked;
  return o.str();
}

TEST(VxpTrace, AnRpmFileIsReadAndFollowedBreathForBreath) {
  int marked = 0;
  std::istringstream in(rpm_file(&marked));
  auto trace = parse_vxp_trace(in, "rpm.vxp");
  ASSERT_TRUE(trace) << trace.error();
  EXPECT_EQ(trace->format, "vxp");
  EXPECT_EQ(trace->flagged, 15);
  ASSERT_EQ(trace->samples.size(), 1800u) << "flagged samples are kept: they are the patient's breathing";
  EXPECT_FALSE(trace->samples[299].flagged);
  EXPECT_TRUE(trace->samples[300].flagged);
  EXPECT_TRUE(trace->samples[314].flagged);
  EXPECT_FALSE(trace->samples[315].flagged);
  EXPECT_EQ(without_flagged(*trace).samples.size(), 1800u - 15u) << "rpm_flagged = \"skip\"";
  EXPECT_EQ(trace->peaks_marked, marked);
  EXPECT_DOUBLE_EQ(trace->samples_per_second, 30.0);
  EXPECT_DOUBLE_EQ(trace->samples.front().t_s, 0.0);
  EXPECT_NEAR(trace->samples.back().t_s, 1799 / 30.0, 0.002) << "timestamps in ms, from the first";
  EXPECT_NEAR(trace->samples.front().value, 15.0, 1e-9) << "1.5 cm times Scale_factor 10: mm";
  BreathFollower f;
  for (const TraceSample& s : trace->samples) f.add(s.t_s, s.value);
  EXPECT_NEAR(f.breaths(), marked, 1) << "the follower finds the breaths RPM marked";
  EXPECT_NEAR(f.rate_per_min(), 15.0, 0.3);
}

TEST(VxpTrace, ReadBreathTraceTakesAVxpByItsName) {
  const auto path = std::filesystem::temp_directory_path() / "lungar_vxp_test.vxp";
  std::ofstream(path) << rpm_file();
  auto trace = read_breath_trace(path.string());
  std::filesystem::remove(path);
  ASSERT_TRUE(trace) << trace.error();
  EXPECT_EQ(trace->format, "vxp");
}

TEST(VxpTrace, EachWrongFileIsOneLineNamingWhatWasExpected) {
  const std::string good = rpm_file();
  const auto replaced = [&](const std::string& from, const std::string& to) {
    std::string s = good;
    s.replace(s.find(from), from.size(), to);
    return s;
  };
  const std::pair<std::string, std::string> bad[] = {
      {"t_s,value\n0,1\n", "rpm.vxp:1: expected a Varian RPM file starting with [Header]"},
      {replaced("Samples_per_second=30", "Samples_per_second=0"), ": Samples_per_second: expected a positive number"},
      {replaced("Scale_factor=10.0", "Scale_factor=ten"), ": Scale_factor: expected a positive number"},
      {replaced("Data_layout=amplitude,phase,timestamp", "Data_layout=amp,phase,time"),
       ": Data_layout: expected columns amplitude and timestamp"},
      {replaced("Gating_mode=amplitude", "Gating mode amplitude"), "rpm.vxp:12: expected Key=Value"},
      {replaced(",0,P,0", ",0,Q,0"), ": mark: expected P, Z or nothing, got 'Q'"},
      {replaced("1000000,0,0,Z,0", "1000000,0,0,Z"), "rpm.vxp:14: expected 7 columns"},
      {replaced("1000033,0", "999000,0"), "rpm.vxp:15: timestamp: expected times that increase"},
      {replaced("1000033,0", "1000000,0"), "rpm.vxp:15: timestamp: expected times that increase"},  // repeated
      {replaced("Scale_factor=10.0", "Scale_factor=-10"), ": Scale_factor: expected a positive number"},
      {good.substr(0, good.find("[Data]")), "rpm.vxp: expected a [Header] and a [Data] section, got no [Data]"},
      {good.substr(0, good.find("[Data]") + 8), "rpm.vxp: expected at least two samples, got 0"},
  };
  for (const auto& [text, why] : bad) {
    std::istringstream in(text);
    auto r = parse_vxp_trace(in, "rpm.vxp");
    ASSERT_FALSE(r) << why;
    EXPECT_NE(r.error().find(why), std::string::npos) << r.error();
  }
}

}  // namespace
}  // namespace lungar::sim
