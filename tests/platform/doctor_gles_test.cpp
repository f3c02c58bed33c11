// `lungar doctor` on this machine's real EGL (Mesa llvmpipe in CI): the graphics check reads the versions and names
// software rendering as such, and the whole doctor on a headless mock set-up has no failure; the options given with
// `doctor` (before or after the word) are the ones checked, not the settings file's.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "platform/doctor/checks.h"
#include "platform/doctor/doctor.h"
#include "tests/scratch_dir.h"

namespace fs = std::filesystem;
using namespace lungar::platform::doctor;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

/// The check named `name` among `checks`; a failed test when it is not there.
Check named(const std::vector<Check>& checks, const std::string& name) {
  for (const Check& c : checks)
    if (c.name == name) return c;
  ADD_FAILURE() << "no check named " << name;
  return {};
}

/// The line of `out` for the check `name` ("ok    tracker  ...").
std::string line_of(const std::string& out, const std::string& name) {
  std::size_t at = 0;
  while ((at = out.find(" " + name + " ", at)) != std::string::npos) {
    const std::size_t start = out.rfind('\n', at) == std::string::npos ? 0 : out.rfind('\n', at) + 1;
    if (at - start == 5) return out.substr(start, out.find('\n', at) - start);
    ++at;
  }
  return "";
}

struct Ran {
  int rc = -1;
  std::string out;
};

/// `lungar ARGS` with its XDG folders under `root`; stdout and stderr together.
Ran run_lungar(const fs::path& root, const std::string& args) {
  const std::string command = "HOME=" + (root / "home").string() + " XDG_CONFIG_HOME=" + (root / "config").string() +
                              " XDG_STATE_HOME=" + (root / "state").string() + " XDG_CACHE_HOME=" +
                              (root / "cache").string() + " " + LUNGAR_BINARY_DIR + "/platform/lungar " + args +
                              " 2>&1";
  Ran r;
  FILE* p = ::popen(command.c_str(), "r");
  if (p == nullptr) return r;
  std::array<char, 4096> buf;
  for (std::size_t n; (n = std::fread(buf.data(), 1, buf.size(), p)) > 0;) r.out.append(buf.data(), n);
  const int status = ::pclose(p);
  r.rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

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

TEST(DoctorGles, TheOptionsGivenAreCheckedNotTheSettingsFiles) {
  const lungar::testing::ScratchDir root("lungar_doctor_options");
  fs::create_directories(root / "home");
  DoctorEnv env;
  env.xdg.home = (root / "home").string();
  env.xdg.system_config_dir = (root / "etc/lungar").string();
  env.min_free_bytes = 1;
  const fs::path profile = root / "headless.toml";
  std::ofstream(profile) << "[display]\noutput = \"headless\"\n[trackers]\nsource = \"mock\"\n";
  lungar::platform::RuntimeOptions o;
  o.config_paths = {profile.string()};
  o.tracker = "hid";
  o.asset_path = "/nonexistent.lungbake";
  o.sync = "trainee";
  const auto checks = run_checks(o, env);
  const Check tracker = named(checks, "tracker"), asset = named(checks, "asset"), sync = named(checks, "sync");
  EXPECT_TRUE(contains(tracker.detail, "HID")) << format_check(tracker);
  EXPECT_FALSE(contains(tracker.detail, "mock")) << format_check(tracker);
  EXPECT_EQ(asset.verdict, Verdict::Fail) << format_check(asset);
  EXPECT_TRUE(contains(asset.detail, "/nonexistent.lungbake")) << format_check(asset);
  EXPECT_TRUE(contains(sync.detail, "trainee")) << format_check(sync);

  o.tracker = "hdi";  // what the runtime refuses, the doctor fails
  const Check refused = named(run_checks(o, env), "options");
  EXPECT_EQ(refused.verdict, Verdict::Fail);
  EXPECT_TRUE(contains(refused.detail, "--tracker") && contains(refused.detail, "hdi")) << format_check(refused);
}

TEST(DoctorGles, TheCommandLineChecksTheOptionsGivenBeforeOrAfterTheWordDoctor) {
  const lungar::testing::ScratchDir root("lungar_doctor_cli");
  const fs::path profile = root / "headless.toml";
  std::ofstream(profile) << "[display]\noutput = \"headless\"\n[trackers]\nsource = \"mock\"\n";
  const std::string config = "--config " + profile.string();
  Ran r = run_lungar(root.path(), config + " doctor");
  EXPECT_TRUE(contains(line_of(r.out, "tracker"), "mock")) << r.out;
  EXPECT_TRUE(contains(line_of(r.out, "sync"), "not in a classroom")) << r.out;
  for (const std::string& args : {config + " --tracker hid doctor --asset /nonexistent.lungbake --sync trainee",
                                  config + " --sync trainee --asset /nonexistent.lungbake doctor --tracker hid"}) {
    r = run_lungar(root.path(), args);
    EXPECT_NE(r.rc, 0) << args << "\n" << r.out;
    EXPECT_TRUE(contains(line_of(r.out, "tracker"), "HID")) << args << "\n" << r.out;
    const std::string asset = line_of(r.out, "asset");
    EXPECT_EQ(asset.rfind("FAIL", 0), 0u) << args << "\n" << r.out;
    EXPECT_TRUE(contains(asset, "/nonexistent.lungbake")) << args << "\n" << r.out;
    EXPECT_TRUE(contains(line_of(r.out, "sync"), "trainee")) << args << "\n" << r.out;
  }
}
