// Tests of `lungar doctor`'s checks that need neither GL nor an emulated device: the line format, the settings
// file, the OpenXR runtime lookup (on temporary XDG folders), the output (X display and named output when an X
// server is there), the asset and the free disk. Each failure must name what to fix.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "config/config_paths.h"
#include "drivers/igtl/tcp_socket.h"
#include "drivers/tracker/tracker_config.h"
#include "platform/app/demo_asset.h"
#include "platform/app/settings_load.h"
#include "platform/doctor/checks.h"
#include "tests/scratch_dir.h"

namespace fs = std::filesystem;
using namespace lungar::platform::doctor;

namespace {

const std::string kData = std::string(LUNGAR_SOURCE_DIR) + "/tests/data/";

class Doctor : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::create_directories(root / "home");
    env.xdg.home = (root / "home").string();
    env.xdg.system_config_dir = (root / "etc/lungar").string();
    env.xdg_config_dirs = {(root / "etc/xdg").string()};
    env.sysconf_dir = (root / "etc").string();
    env.display.clear();
  }
  /// A runtime manifest at `path` naming `library` (written relative or absolute as given).
  static void write_manifest(const fs::path& path, const std::string& name, const std::string& library) {
    fs::create_directories(path.parent_path());
    std::ofstream(path) << R"({"file_format_version": "1.0.0", "runtime": {"name": ")" << name
                        << R"(", "library_path": ")" << library << R"("}})";
  }
  fs::path make_library(const std::string& name) const {
    const fs::path lib = root / "lib" / name;
    fs::create_directories(lib.parent_path());
    std::ofstream(lib) << "not really a library: only its presence is checked";
    return lib;
  }

  lungar::testing::ScratchDir root{"lungar_doctor"};
  DoctorEnv env;
};

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST(DoctorFormat, OneLinePerCheckWithTheFixOnlyWhenThereIsOne) {
  EXPECT_EQ(format_check(passed("disk", "12.0 GiB free")), "ok    disk     12.0 GiB free");
  const std::string line = format_check(failed("tracker", "/dev/hidraw0 not readable", "sudo udevadm trigger"));
  EXPECT_EQ(line.rfind("FAIL  tracker  /dev/hidraw0 not readable -- fix: sudo udevadm trigger", 0), 0u) << line;
  EXPECT_EQ(line.find('\n'), std::string::npos);
  EXPECT_TRUE(contains(format_check(warned("gles", "llvmpipe", "get a GPU")), "warn  gles     llvmpipe -- get a GPU"));
}

TEST_F(Doctor, ConfigCheckNamesTheFileUsedAndFailsOnABadOneNamingTheKey) {
  const fs::path user = root / "home/.config/lungar/lungar.toml";
  fs::create_directories(user.parent_path());
  std::ofstream(user) << "[render]\npoint_size_px = 5.0\n";
  auto choice = lungar::config::choose_config("", env.xdg);
  Check c = check_config(choice, lungar::platform::load_chosen_settings(choice));
  EXPECT_EQ(c.verdict, Verdict::Pass) << format_check(c);
  EXPECT_TRUE(contains(c.detail, user.string())) << c.detail;

  std::ofstream(user) << "[render]\npoint_size_px = 0\n";
  c = check_config(choice, lungar::platform::load_chosen_settings(choice));
  EXPECT_EQ(c.verdict, Verdict::Fail);
  EXPECT_TRUE(contains(c.detail, user.string()) && contains(c.detail, "point_size_px")) << c.detail;
  EXPECT_TRUE(contains(c.fix, "default.toml")) << c.fix;
}

TEST_F(Doctor, OpenXrFailsWithTheInstallFixWhenNoRuntimeIsActive) {
  const Check c = check_openxr_runtime(env);
  EXPECT_EQ(c.verdict, Verdict::Fail);
  EXPECT_TRUE(contains(c.detail, (root / "home/.config/openxr/1/active_runtime.json").string())) << c.detail;
  EXPECT_TRUE(contains(c.detail, (root / "etc/xdg/openxr/1/active_runtime.json").string())) << c.detail;
  EXPECT_TRUE(contains(c.fix, "active_runtime.json") && contains(c.fix, "XR_RUNTIME_JSON")) << c.fix;
}

TEST_F(Doctor, OpenXrFindsTheUsersRuntimeBeforeTheSystemsAndResolvesARelativeLibrary) {
  const fs::path lib = make_library("libopenxr_user.so");
  write_manifest(root / "etc/xdg/openxr/1/active_runtime.json", "SystemXR", make_library("libsys.so").string());
  write_manifest(root / "home/.config/openxr/1/active_runtime.json", "UserXR", "../../../../lib/libopenxr_user.so");
  const Check c = check_openxr_runtime(env);
  EXPECT_EQ(c.verdict, Verdict::Pass) << format_check(c);
  EXPECT_TRUE(contains(c.detail, "UserXR") && contains(c.detail, lib.string())) << c.detail;
}

TEST_F(Doctor, OpenXrPrefersTheArchitectureSpecificManifestInAFolder) {
  write_manifest(root / "etc/xdg/openxr/1/active_runtime.json", "Generic", make_library("libg.so").string());
#if defined(__x86_64__)
  write_manifest(root / "etc/xdg/openxr/1/active_runtime.x86_64.json", "ArchXR", make_library("liba.so").string());
#elif defined(__aarch64__)
  write_manifest(root / "etc/xdg/openxr/1/active_runtime.aarch64.json", "ArchXR", make_library("liba.so").string());
#endif
  const Check c = check_openxr_runtime(env);
  EXPECT_EQ(c.verdict, Verdict::Pass) << format_check(c);
  EXPECT_TRUE(contains(c.detail, "ArchXR")) << c.detail;
}

TEST_F(Doctor, OpenXrEnvironmentOverrideIsTheOnlyPlaceLookedAtAndAMissingLibraryFails) {
  write_manifest(root / "home/.config/openxr/1/active_runtime.json", "UserXR", make_library("libu.so").string());
  const fs::path forced = root / "forced.json";
  write_manifest(forced, "ForcedXR", (root / "lib/gone.so").string());
  env.xr_runtime_json = forced.string();
  Check c = check_openxr_runtime(env);
  EXPECT_EQ(c.verdict, Verdict::Fail);
  EXPECT_TRUE(contains(c.detail, "library_path") && contains(c.detail, "gone.so")) << c.detail;
  std::ofstream(forced) << "{ not json";
  c = check_openxr_runtime(env);
  EXPECT_EQ(c.verdict, Verdict::Fail);
  EXPECT_TRUE(contains(c.detail, forced.string())) << c.detail;
}

TEST_F(Doctor, TheOpenXrOutputNeedsAnActiveRuntimeNotAnXDisplay) {
  lungar::platform::Settings s;
  s.display.output = lungar::platform::Output::OpenXr;
  Check c = check_output(s, env);  // no DISPLAY, no runtime
  EXPECT_EQ(c.verdict, Verdict::Fail) << format_check(c);
  EXPECT_TRUE(contains(c.fix, "active_runtime.json")) << c.fix;
  write_manifest(root / "home/.config/openxr/1/active_runtime.json", "UserXR", make_library("libu.so").string());
  c = check_output(s, env);
  EXPECT_EQ(c.verdict, Verdict::Pass) << format_check(c);
  EXPECT_TRUE(contains(c.detail, "UserXR")) << c.detail;
}

TEST_F(Doctor, OutputNeedsNoDisplayHeadlessButAWindowNeedsOne) {
  lungar::platform::Settings s;
  s.display.output = lungar::platform::Output::Headless;
  EXPECT_EQ(check_output(s, env).verdict, Verdict::Pass);
  s.display.output = lungar::platform::Output::Auto;
  EXPECT_EQ(check_output(s, env).verdict, Verdict::Pass);  // auto without DISPLAY runs headless
  s.display.output = lungar::platform::Output::Fullscreen;
  const Check c = check_output(s, env);
  EXPECT_EQ(c.verdict, Verdict::Fail);
  EXPECT_TRUE(contains(c.detail, "DISPLAY") && contains(c.fix, "DISPLAY")) << format_check(c);
}

TEST_F(Doctor, FullscreenOnAnOutputTheXServerDoesNotHaveFailsListingTheOnesItHas) {
  const char* display = std::getenv("DISPLAY");
  if (display == nullptr || *display == '\0') GTEST_SKIP() << "no X server (CI starts Xvfb)";
  env.display = display;
  lungar::platform::Settings s;
  s.display.output = lungar::platform::Output::Fullscreen;
  s.display.x11_output = "NO-SUCH-OUTPUT-9";
  const Check c = check_output(s, env);
  EXPECT_EQ(c.verdict, Verdict::Fail) << format_check(c);
  EXPECT_TRUE(contains(c.detail, "NO-SUCH-OUTPUT-9")) << c.detail;
  EXPECT_TRUE(contains(c.fix, "xrandr --output NO-SUCH-OUTPUT-9 --auto")) << c.fix;
  s.display.x11_output.clear();
  const Check whole_screen = check_output(s, env);
  EXPECT_EQ(whole_screen.verdict, Verdict::Pass) << format_check(whole_screen);
}

TEST_F(Doctor, AssetCheckLoadsTheConfiguredAssetAndNamesABrokenOne) {
  lungar::platform::Settings s;
  s.sim.asset = kData + "hil_lungs.lungbake";
  Check c = check_asset(s, env);
  EXPECT_EQ(c.verdict, Verdict::Pass) << format_check(c);
  EXPECT_TRUE(contains(c.detail, "nodes")) << c.detail;

  const fs::path cut = root / "cut.lungbake";
  fs::copy_file(s.sim.asset, cut);
  fs::resize_file(cut, fs::file_size(cut) / 2);
  s.sim.asset = cut.string();
  c = check_asset(s, env);
  EXPECT_EQ(c.verdict, Verdict::Fail);
  EXPECT_TRUE(contains(c.detail, cut.string())) << c.detail;
  EXPECT_TRUE(contains(c.fix, "lungar-bake")) << c.fix;
}

TEST_F(Doctor, DemoAssetNotYetBakedPassesAndSaysWhereItWillGo) {
  env.xdg.cache_home = (root / "cache").string();
  const Check c = check_asset(lungar::platform::Settings{}, env);
  EXPECT_EQ(c.verdict, Verdict::Pass) << format_check(c);
  EXPECT_TRUE(contains(c.detail, (root / "cache/lungar").string())) << c.detail;
}

TEST_F(Doctor, DemoAssetCachedIsFoundWhereTheRuntimeCachesTheCtLungs) {
  env.xdg.cache_home = (root / "cache").string();
  lungar::platform::DemoAssetOptions demo;
  demo.cache_dir = (root / "cache/lungar").string();
  // The build tree has the shipped label map and lungar-bake, so the runtime's demo is the CT pair.
  const fs::path cached = lungar::platform::demo_cache_path(demo);
  ASSERT_EQ(cached.filename().string().rfind("ct-", 0), 0u) << cached;
  fs::create_directories(cached.parent_path());
  fs::copy_file(kData + "hil_lungs.lungbake", cached);
  const Check c = check_asset(lungar::platform::Settings{}, env);
  EXPECT_EQ(c.verdict, Verdict::Pass) << format_check(c);
  EXPECT_TRUE(contains(c.detail, "demo lungs cached at " + cached.string())) << c.detail;
}

TEST_F(Doctor, DiskFailsBelowTheMinimumNamingTheStateFolder) {
  env.xdg.state_home = (root / "state").string();
  env.min_free_bytes = 1;
  EXPECT_EQ(check_disk(env).verdict, Verdict::Pass);
  env.min_free_bytes = ~0ull;  // no disk has this much
  const Check c = check_disk(env);
  EXPECT_EQ(c.verdict, Verdict::Fail);
  EXPECT_TRUE(contains(c.detail, (root / "state/lungar").string())) << c.detail;
  EXPECT_TRUE(contains(c.fix, "XDG_STATE_HOME")) << c.fix;
}

TEST_F(Doctor, IgtlTrackerCheckConnectsToTheServer) {
  auto listener = lungar::drivers::TcpListener::listen("127.0.0.1", 0);  // a server on a port the OS picks
  ASSERT_TRUE(listener) << listener.error();
  lungar::drivers::TrackerConfig t;
  t.source = lungar::drivers::TrackerSource::Igtl;
  t.igtl.port = listener->port();
  EXPECT_EQ(check_tracker(t, env).verdict, Verdict::Pass);
  listener->close();  // PlusServer is not running
  const Check c = check_tracker(t, env);
  EXPECT_EQ(c.verdict, Verdict::Fail);
  EXPECT_TRUE(contains(c.detail, "127.0.0.1:" + std::to_string(t.igtl.port))) << c.detail;
  EXPECT_TRUE(contains(c.fix, "PlusServer")) << c.fix;
}

TEST_F(Doctor, ReplayTrackerCheckParsesTheLog) {
  lungar::drivers::TrackerConfig t;
  t.source = lungar::drivers::TrackerSource::Replay;
  t.replay_file = kData + "upright_to_supine.trk";
  EXPECT_EQ(check_tracker(t, env).verdict, Verdict::Pass);
  t.replay_file = (root / "missing.trk").string();
  const Check c = check_tracker(t, env);
  EXPECT_EQ(c.verdict, Verdict::Fail);
  EXPECT_TRUE(contains(c.detail, "missing.trk")) << c.detail;

  const fs::path cut = root / "cut.trk";  // a recording cut short: the runtime refuses it unless told
  fs::copy_file(kData + "upright_to_supine.trk", cut);
  fs::resize_file(cut, fs::file_size(cut) - 7);
  t.replay_file = cut.string();
  const Check truncated = check_tracker(t, env);
  EXPECT_EQ(truncated.verdict, Verdict::Fail) << format_check(truncated);
  EXPECT_TRUE(contains(truncated.detail, "truncated") && contains(truncated.fix, "--replay-truncated"))
      << format_check(truncated);
  t.replay_truncated = true;
  EXPECT_EQ(check_tracker(t, env).verdict, Verdict::Pass);
}
