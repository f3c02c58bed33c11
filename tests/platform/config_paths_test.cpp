// Tests of config/config_paths: --config, then $XDG_CONFIG_HOME (or ~/.config), then /etc/lungar, then the defaults;
// the cache and state folders; on real temporary folders standing in for HOME, the XDG variables and /etc/lungar.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "config/config_paths.h"
#include "platform/app/settings_load.h"
#include "tests/scratch_dir.h"

namespace fs = std::filesystem;
using lungar::config::XdgDirs;

namespace {

class ConfigPaths : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::create_directories(root / "home");
    dirs.home = (root / "home").string();
    dirs.system_config_dir = (root / "etc/lungar").string();
  }
  /// A settings file with one recognisable value.
  static void write_profile(const fs::path& path, double ipd_mm) {
    fs::create_directories(path.parent_path());
    std::ofstream(path) << "[hmd]\nipd_mm = " << ipd_mm << "\n";
  }

  lungar::testing::ScratchDir root{"lungar_config_paths"};
  XdgDirs dirs;
};

}  // namespace

TEST_F(ConfigPaths, DefaultsWhenNoFileExistsAndTheLineSaysWhatWasLookedFor) {
  const auto choice = lungar::config::choose_config("", dirs);
  EXPECT_TRUE(choice.paths.empty());
  const std::string line = choice.describe();
  EXPECT_NE(line.find("built-in defaults"), std::string::npos) << line;
  EXPECT_NE(line.find(dirs.home + "/.config/lungar/lungar.toml"), std::string::npos) << line;
  EXPECT_NE(line.find(dirs.system_config_dir + "/lungar.toml"), std::string::npos) << line;
  auto s = lungar::platform::load_chosen_settings(choice);
  ASSERT_TRUE(s) << s.error();
  EXPECT_DOUBLE_EQ(s->hmd.ipd_mm, lungar::platform::Settings{}.hmd.ipd_mm);
}

TEST_F(ConfigPaths, SystemFileIsUsedWhenTheUserHasNone) {
  write_profile(root / "etc/lungar/lungar.toml", 61);
  const auto choice = lungar::config::choose_config("", dirs);
  EXPECT_EQ(choice.paths, std::vector<std::string>{(root / "etc/lungar/lungar.toml").string()});
  auto s = lungar::platform::load_chosen_settings(choice);
  ASSERT_TRUE(s) << s.error();
  EXPECT_DOUBLE_EQ(s->hmd.ipd_mm, 61);
}

TEST_F(ConfigPaths, UserFileUnderDotConfigWinsOverTheSystemFile) {
  write_profile(root / "etc/lungar/lungar.toml", 61);
  write_profile(root / "home/.config/lungar/lungar.toml", 62);
  const auto choice = lungar::config::choose_config("", dirs);
  EXPECT_EQ(choice.paths, std::vector<std::string>{(root / "home/.config/lungar/lungar.toml").string()});
  auto s = lungar::platform::load_chosen_settings(choice);
  ASSERT_TRUE(s) << s.error();
  EXPECT_DOUBLE_EQ(s->hmd.ipd_mm, 62);
}

TEST_F(ConfigPaths, XdgConfigHomeReplacesDotConfig) {
  write_profile(root / "home/.config/lungar/lungar.toml", 62);
  write_profile(root / "xdg/lungar/lungar.toml", 64);
  dirs.config_home = (root / "xdg").string();
  const auto choice = lungar::config::choose_config("", dirs);
  EXPECT_EQ(choice.paths, std::vector<std::string>{(root / "xdg/lungar/lungar.toml").string()});
  EXPECT_NE(choice.describe().find("$XDG_CONFIG_HOME"), std::string::npos) << choice.describe();
}

TEST_F(ConfigPaths, CommandLineWinsEvenOverAnExistingUserFile) {
  write_profile(root / "home/.config/lungar/lungar.toml", 62);
  write_profile(root / "mine.toml", 66);
  const auto choice = lungar::config::choose_config((root / "mine.toml").string(), dirs);
  EXPECT_EQ(choice.paths, std::vector<std::string>{(root / "mine.toml").string()});
  auto s = lungar::platform::load_chosen_settings(choice);
  ASSERT_TRUE(s) << s.error();
  EXPECT_DOUBLE_EQ(s->hmd.ipd_mm, 66);
}

TEST_F(ConfigPaths, AMissingCommandLineFileIsAnErrorNotASilentFallback) {
  write_profile(root / "home/.config/lungar/lungar.toml", 62);
  const std::string missing = (root / "nope.toml").string();
  auto s = lungar::platform::load_chosen_settings(lungar::config::choose_config(missing, dirs));
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().find(missing), std::string::npos) << s.error();
}

TEST_F(ConfigPaths, ABadFoundFileIsAnErrorNamingIt) {
  const fs::path bad = root / "home/.config/lungar/lungar.toml";
  write_profile(bad, 500);  // ipd_mm outside [40, 90]
  auto s = lungar::platform::load_chosen_settings(lungar::config::choose_config("", dirs));
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().find(bad.string()), std::string::npos) << s.error();
  EXPECT_NE(s.error().find("ipd_mm"), std::string::npos) << s.error();
}

TEST_F(ConfigPaths, StateAndCacheFollowXdgThenHome) {
  EXPECT_EQ(lungar::config::state_dir(dirs), dirs.home + "/.local/state/lungar");
  EXPECT_EQ(lungar::config::cache_dir(dirs), dirs.home + "/.cache/lungar");
  dirs.state_home = (root / "state").string();
  dirs.cache_home = (root / "cache").string();
  EXPECT_EQ(lungar::config::state_dir(dirs), (root / "state/lungar").string());
  EXPECT_EQ(lungar::config::cache_dir(dirs), (root / "cache/lungar").string());
  dirs.cache_override = (root / "ci-cache").string();
  EXPECT_EQ(lungar::config::cache_dir(dirs), (root / "ci-cache").string());
}

TEST_F(ConfigPaths, RelativeXdgVariablesAreIgnoredAsTheSpecSays) {
  // The variables are the process's: set them for the read, then put back what the test runner had.
  const char* names[] = {"XDG_STATE_HOME", "XDG_CONFIG_HOME"};
  std::string saved[2];
  bool had[2];
  for (int k = 0; k < 2; ++k) {
    const char* v = std::getenv(names[k]);
    had[k] = v != nullptr;
    if (had[k]) saved[k] = v;
  }
  ::setenv("XDG_STATE_HOME", "relative/state", 1);
  ::setenv("XDG_CONFIG_HOME", (root / "xdg").c_str(), 1);
  const XdgDirs env = XdgDirs::from_environment();
  for (int k = 0; k < 2; ++k) {
    if (had[k]) {
      ::setenv(names[k], saved[k].c_str(), 1);
    } else {
      ::unsetenv(names[k]);
    }
  }
  EXPECT_TRUE(env.state_home.empty());
  EXPECT_EQ(env.config_home, (root / "xdg").string());
}
