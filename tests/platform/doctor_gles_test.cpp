// `lungar doctor` on this machine's real EGL (Mesa llvmpipe in CI): the graphics check reads the versions and names
// software rendering as such, and the whole doctor on a headless mock set-up has no failure.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "platform/app/doctor/checks.h"
#include "platform/app/doctor/doctor.h"
#include "tests/scratch_dir.h"

namespace fs = std::filesystem;
using namespace lungar::platform::doctor;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST(DoctorGles, ReadsTheVersionsAndNamesSoftwareRenderingAsSuch) {
  const Check c = check_gles();
  ASSERT_NE(c.verdict, Verdict::Fail) << format_check(c);
  EXPECT_TRUE(contains(c.detail, "EGL 1.")) << c.detail;
  EXPECT_TRUE(contains(c.detail, "OpenGL ES 3.")) << c.detail;
  const bool llvmpipe = contains(c.detail, "llvmpipe");
  EXPECT_EQ(c.verdict == Verdict::Warn, llvmpipe) << format_check(c);
  if (llvmpipe) {
    EXPECT_TRUE(contains(c.detail, "software rendering (llvmpipe)")) << c.detail;
  }
  std::printf("[ MEASURED ] %s\n", format_check(c).c_str());
}

TEST(DoctorGles, AHeadlessMockSetUpHasNoFailureAndABrokenConfigFailsOnlyItsCheck) {
  const lungar::testing::ScratchDir root("lungar_doctor_all");
  fs::create_directories(root / "home");
  DoctorEnv env;
  env.xdg.home = (root / "home").string();
  env.xdg.system_config_dir = (root / "etc/lungar").string();
  env.min_free_bytes = 1;
  const fs::path profile = root / "headless.toml";
  std::ofstream(profile) << "[display]\noutput = \"headless\"\n[trackers]\nsource = \"mock\"\n";
  auto checks = run_checks(profile.string(), env);
  ASSERT_EQ(checks.size(), 7u);
  for (const auto& c : checks) EXPECT_NE(c.verdict, Verdict::Fail) << format_check(c);

  std::ofstream(profile) << "[display]\noutput = \"sideways\"\n";
  checks = run_checks(profile.string(), env);
  EXPECT_EQ(checks[0].name, "config");
  EXPECT_EQ(checks[0].verdict, Verdict::Fail) << format_check(checks[0]);
  for (std::size_t k = 1; k < checks.size(); ++k)
    EXPECT_NE(checks[k].verdict, Verdict::Fail) << format_check(checks[k]);
}
