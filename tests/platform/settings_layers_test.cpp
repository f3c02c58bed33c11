// Several --config files read as one: a later file's keys over an earlier one's, tables merged key by key, each
// relative path relative to the file that set it, and an error naming the file, line and key it came from.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "drivers/tracker/tracker_config.h"
#include "platform/app/settings_load.h"
#include "tests/scratch_dir.h"

using lungar::platform::load_settings;
namespace fs = std::filesystem;

namespace {

fs::path write(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
  return path;
}

}  // namespace

TEST(SettingsLayers, ALaterFileWinsKeyByKeyAndTablesMergeDeeply) {
  const lungar::testing::ScratchDir root("lungar_settings_layers");
  const fs::path profile = write(root / "profile.toml",
                                 "[render]\npoint_size_px = 3\nhud = false\n\n"
                                 "[trackers.stylus]\nenabled = true\n");
  const fs::path stylus = write(root / "stylus.toml", "[trackers.stylus]\ntip_offset_mm = [1.5, -2.0, -150.0]\n");
  const fs::path later = write(root / "later.toml", "[render]\nhud = true\n");
  auto s = load_settings(std::vector<std::string>{profile.string(), stylus.string(), later.string()});
  ASSERT_TRUE(s) << s.error();
  EXPECT_EQ(s->render.point_size_px, 3.0) << "a key only the first file sets stays";
  EXPECT_TRUE(s->render.hud) << "the later file's key wins";
  EXPECT_TRUE(s->trackers().stylus.enabled) << "[trackers.stylus] of the second file merges into the first's";
  EXPECT_EQ(s->trackers().stylus.tip_offset_mm, (std::array<double, 3>{1.5, -2.0, -150.0}));
  EXPECT_EQ(s->source, profile.string() + " + " + stylus.string() + " + " + later.string());
}

TEST(SettingsLayers, ARelativePathIsRelativeToTheFileThatSetIt) {
  const lungar::testing::ScratchDir root("lungar_settings_layers");
  const fs::path lab = write(root / "lab/profile.toml", "[sim]\nasset = \"lungs.lungbake\"\n");
  const fs::path course = write(root / "course/breathing.toml", "[breathing]\nscenario = \"ards.toml\"\n");
  auto s = load_settings(std::vector<std::string>{lab.string(), course.string()});
  ASSERT_TRUE(s) << s.error();
  EXPECT_EQ(s->sim.asset, (root / "lab/lungs.lungbake").string());
  EXPECT_EQ(s->breathing.scenario, (root / "course/ards.toml").string());
  // The same key set again by the later file: relative to the later file's folder.
  const fs::path moved = write(root / "moved/asset.toml", "[sim]\nasset = \"lungs.lungbake\"\n");
  s = load_settings(std::vector<std::string>{lab.string(), moved.string()});
  ASSERT_TRUE(s) << s.error();
  EXPECT_EQ(s->sim.asset, (root / "moved/lungs.lungbake").string());
}

TEST(SettingsLayers, AnErrorNamesTheFileTheLineAndTheKeyItCameFrom) {
  const lungar::testing::ScratchDir root("lungar_settings_layers");
  const fs::path good = write(root / "good.toml", "[render]\npoint_size_px = 3\n");
  const fs::path bad = write(root / "bad.toml", "# the second file\n[render]\n\npoint_size_px = 900\n");
  auto s = load_settings(std::vector<std::string>{good.string(), bad.string()});
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().rfind(bad.string() + ":4: key 'render.point_size_px': expected a number in [1, 64]", 0), 0u)
      << s.error();
  const fs::path unknown = write(root / "unknown.toml", "[render]\n\npoint_sise_px = 3\n");
  s = load_settings(std::vector<std::string>{good.string(), unknown.string()});
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().rfind(unknown.string() + ":3: unknown key 'render.point_sise_px'", 0), 0u) << s.error();
  s = load_settings(std::vector<std::string>{good.string(), (root / "missing.toml").string()});
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().rfind((root / "missing.toml").string() + ": cannot read the config", 0), 0u) << s.error();
}
