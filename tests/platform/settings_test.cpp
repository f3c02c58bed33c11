// Tests of config/: the shipped profile, the overlay on defaults, and one specific error per kind of bad input.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <string>

#include "config/scenario_load.h"
#include "drivers/tracker/tracker_config.h"
#include "platform/app/console_run.h"
#include "platform/app/settings_load.h"
#include "platform/sync/class_scenario.h"

using lungar::platform::load_settings;
using lungar::platform::load_settings_from_string;
using lungar::platform::Settings;

namespace {

const std::string kDefaultToml = std::string(LUNGAR_SOURCE_DIR) + "/config/default.toml";

std::string error_of(const std::string& toml) {
  auto r = load_settings_from_string(toml, "bad.toml");
  EXPECT_FALSE(r) << "expected an error for:\n" << toml;
  return r.error();
}

}  // namespace

// [trackers] sits behind a pointer in Settings (settings.h): a copy must still be a value, not a second name for
// the same table, or a station's edited copy would change the settings it came from.
TEST(Settings, ACopyHasItsOwnTrackersTable) {
  auto loaded =
      load_settings_from_string("[trackers]\nsource = \"igtl\"\n[trackers.igtl]\nhost = \"plus.lab\"\n", "copy.toml");
  ASSERT_TRUE(loaded) << loaded.error();
  Settings copy = *loaded;
  EXPECT_EQ(copy.trackers(), loaded->trackers());
  copy.trackers().igtl.host = "other.lab";
  EXPECT_EQ(loaded->trackers().igtl.host, "plus.lab");

  Settings assigned;
  assigned = *loaded;
  EXPECT_EQ(assigned.trackers().source, lungar::drivers::TrackerSource::Igtl);
  assigned.trackers().source = lungar::drivers::TrackerSource::Mock;
  EXPECT_EQ(loaded->trackers().source, lungar::drivers::TrackerSource::Igtl);
  EXPECT_EQ(assigned.source, loaded->source);
}

TEST(Settings, ShippedDefaultProfileMatchesBuiltInDefaults) {
  auto r = load_settings(kDefaultToml);
  ASSERT_TRUE(r) << r.error();
  const Settings d;
  const Settings& s = *r;
  EXPECT_EQ(s.display.width_px, d.display.width_px);
  EXPECT_EQ(s.hmd.eye_width_px, d.hmd.eye_width_px);
  EXPECT_DOUBLE_EQ(s.hmd.ipd_mm, d.hmd.ipd_mm);
  EXPECT_EQ(s.hmd.head_to_eye_mm, d.hmd.head_to_eye_mm);
  EXPECT_EQ(s.hmd.lens.k1, d.hmd.lens.k1);
  EXPECT_DOUBLE_EQ(s.render.point_size_px, d.render.point_size_px);
  EXPECT_EQ(s.render.color_left, d.render.color_left);
  EXPECT_EQ(s.breathing.preset, d.breathing.preset);
  EXPECT_DOUBLE_EQ(s.breathing.tidal_volume_ml, d.breathing.tidal_volume_ml);
  EXPECT_EQ(s.breathing.rpm_flagged, d.breathing.rpm_flagged);
  EXPECT_EQ(s.sync.role, d.sync.role);
  EXPECT_EQ(s.sync.classroom, d.sync.classroom);
  EXPECT_EQ(s.sync.domain, d.sync.domain);
  EXPECT_DOUBLE_EQ(s.sync.lost_after_ms, d.sync.lost_after_ms);
  EXPECT_DOUBLE_EQ(s.trackers().stale_ms, d.trackers().stale_ms);
  EXPECT_EQ(s.registration.rotation_wxyz, d.registration.rotation_wxyz);
  EXPECT_EQ(s.registration.xr_space_translation_mm, d.registration.xr_space_translation_mm);
  EXPECT_EQ(s.registration.xr_space_rotation_wxyz, d.registration.xr_space_rotation_wxyz);
  EXPECT_EQ(s.display.openxr.head, d.display.openxr.head);
  EXPECT_EQ(s.display.openxr.reference_space, d.display.openxr.reference_space);
  EXPECT_EQ(s.sim.orientation_mode, d.sim.orientation_mode);
  EXPECT_EQ(s.sim.pathologies, d.sim.pathologies);
}

TEST(Settings, EveryKeyOfTheShippedProfileIsDocumentedWithAComment) {
  std::ifstream in(kDefaultToml);
  ASSERT_TRUE(in) << kDefaultToml;
  std::string line;
  int keys = 0;
  while (std::getline(in, line)) {
    // A key line: optional blanks, then [a-z0-9_]+, blanks, '=' (no std::regex: GCC 12 warns inside it under ASan).
    const std::size_t start = line.find_first_not_of(' ');
    if (start == std::string::npos) continue;
    std::size_t end = start;
    while (end < line.size() && (std::islower(static_cast<unsigned char>(line[end])) ||
                                 std::isdigit(static_cast<unsigned char>(line[end])) || line[end] == '_')) {
      ++end;
    }
    const std::size_t eq = line.find_first_not_of(' ', end);
    if (end > start && eq != std::string::npos && line[eq] == '=') {
      ++keys;
      EXPECT_NE(line.find('#'), std::string::npos) << "undocumented key: " << line;
    }
  }
  EXPECT_GT(keys, 40);
}

// An empty sim.asset draws the demo's CT lungs (platform/app/demo_asset.h); the profile said the procedural pair.
TEST(Settings, TheShippedProfileSaysWhatAnEmptyAssetDraws) {
  std::ifstream in(kDefaultToml);
  std::string line;
  while (std::getline(in, line) && line.rfind("asset = ", 0) != 0) {
  }
  ASSERT_EQ(line.rfind("asset = \"\"", 0), 0u) << "no empty [sim] asset in " << kDefaultToml;
  const std::string comment = line.substr(line.find('#'));
  EXPECT_NE(comment.find("\"\" = the demo's CT lungs"), std::string::npos) << comment;
  EXPECT_EQ(comment.find("\"\" = the cached procedural pair"), std::string::npos) << comment;
}

TEST(Settings, OverlayChangesOnlyTheKeysGiven) {
  auto r = load_settings_from_string("[render]\npoint_size_px = 3\n[hmd]\nview = \"mono\"\n", "x.toml");
  ASSERT_TRUE(r) << r.error();
  EXPECT_DOUBLE_EQ(r->render.point_size_px, 3.0);
  EXPECT_EQ(r->hmd.view, lungar::platform::View::Mono);
  EXPECT_DOUBLE_EQ(r->hmd.ipd_mm, Settings{}.hmd.ipd_mm);
  EXPECT_EQ(r->source, "x.toml");
}

TEST(Settings, PathologiesAreReadAndABadOneNamesTheFileTheFieldAndTheSpec) {
  auto r = load_settings_from_string(
      "[sim]\npathology = [\"pneumothorax:right:30\", \"consolidation:left:lower\"]\n", "x.toml");
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r->sim.pathologies, (std::vector<std::string>{"pneumothorax:right:30", "consolidation:left:lower"}));
  EXPECT_TRUE(Settings{}.sim.pathologies.empty()) << "healthy by default";
  const std::string e = error_of("[sim]\npathology = [\"pneumothorax:right:300\"]\n");
  EXPECT_NE(e.find("bad.toml"), std::string::npos) << e;
  EXPECT_NE(e.find("pathology"), std::string::npos) << e;
  EXPECT_NE(e.find("'pneumothorax:right:300'"), std::string::npos) << e;
  EXPECT_NE(e.find("PERCENT"), std::string::npos) << e;
  const std::string twice = error_of("[sim]\npathology = [\"emphysema:0.4\", \"emphysema:0.6:left\"]\n");
  EXPECT_NE(twice.find("bad.toml"), std::string::npos) << twice;
  EXPECT_NE(twice.find("'emphysema:0.6:left': repeats 'emphysema:0.4'"), std::string::npos) << twice;
}

TEST(Settings, LesionsAndTheirColourAreReadAndABadOneNamesTheFileTheFieldAndTheSpec) {
  auto r = load_settings_from_string(
      "[sim]\nlesion = [\"tumour=-60,-120,-250,5\"]\n[render]\ncolor_lesion = [0.2, 1.0, 0.2]\n", "x.toml");
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r->sim.lesions, (std::vector<std::string>{"tumour=-60,-120,-250,5"}));
  EXPECT_EQ(r->render.color_lesion, (std::array<double, 3>{0.2, 1.0, 0.2}));
  EXPECT_TRUE(Settings{}.sim.lesions.empty()) << "none by default";
  const std::string e = error_of("[sim]\nlesion = [\"tumour=1,2,3\"]\n");
  EXPECT_NE(e.find("bad.toml:2: key 'sim.lesion': lesion: expected NAME=x,y,z,radius_mm"), std::string::npos) << e;
  EXPECT_NE(e.find("got 'tumour=1,2,3'"), std::string::npos) << e;
  const std::string huge = error_of("[sim]\nlesion = [\"t=1,2,3,80\"]\n");
  EXPECT_NE(huge.find("lesion t: expected a radius above 0 and at most 50 mm, got 80 mm"), std::string::npos) << huge;
}

TEST(Settings, TheConsolesAddressIsReadAndABadOneNamesTheFileTheFieldAndTheForm) {
  auto r = load_settings_from_string("[console]\nlisten = \"127.0.0.1:8443\"\nkeys = \"/k/console\"\n", "x.toml");
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r->console.listen, "127.0.0.1:8443");
  EXPECT_EQ(r->console.keys, "/k/console");
  EXPECT_TRUE(Settings{}.console.listen.empty()) << "no console by default";
  for (const char* bad : {"8443x", "host:", ":8443", "70000", "a:b:c"}) {
    const std::string e = error_of(std::string("[console]\nlisten = \"") + bad + "\"\n");
    EXPECT_NE(e.find("bad.toml:2: key 'console.listen': expected [ADDR:]PORT"), std::string::npos) << e;
  }
  auto port = lungar::platform::parse_listen("[::1]:8443");
  ASSERT_TRUE(port) << port.error();
  EXPECT_EQ(port->address, "::1");
  EXPECT_EQ(port->port, 8443);
  EXPECT_EQ(lungar::platform::parse_listen("8443")->address, "0.0.0.0") << "every interface: the classroom's network";
}

// The console's scenarios: the shipped ones by default; from [console] scenarios a folder of the site's own, where
// a file that does not load is one line and left out, and a folder that is not there is one error.
TEST(Settings, TheConsolesScenariosAreTheShippedOnesOrAFolderOfTheSitesOwn) {
  std::vector<std::string> lines;
  const auto log = [&](const std::string& line) { lines.push_back(line); };
  auto shipped = lungar::platform::console_scenarios(Settings{}, log);
  ASSERT_TRUE(shipped) << shipped.error();
  std::vector<std::string> names;
  for (const auto& c : *shipped) names.push_back(c.name());
  EXPECT_NE(std::find(names.begin(), names.end(), "tension pneumothorax"), names.end())
      << ::testing::PrintToString(names);

  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("lungar_scenarios_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "drill.toml") << "name = \"drill\"\nduration_s = 20.0\n[[event]]\nat_s = 5.0\nkind = \"sigh\"\n";
  std::ofstream(dir / "broken.toml") << "name = \"broken\"\n[[event]]\nat_s = 5.0\nkind = \"dance\"\n";
  std::ofstream(dir / "notes.txt") << "not a scenario\n";
  auto r = load_settings_from_string("[console]\nscenarios = \"" + dir.string() + "\"\n", "x.toml");
  ASSERT_TRUE(r) << r.error();
  lines.clear();
  auto own = lungar::platform::console_scenarios(*r, log);
  ASSERT_TRUE(own) << own.error();
  ASSERT_EQ(own->size(), 1u);
  EXPECT_EQ(own->front().name(), "drill");
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines.front().rfind("console: scenario left out: " + (dir / "broken.toml").string() + ":", 0), 0u)
      << lines.front();
  r->console.scenarios = (dir / "missing").string();
  auto missing = lungar::platform::console_scenarios(*r, log);
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error(), "console.scenarios: expected a folder of scenario TOML files; '" +
                                 (dir / "missing").string() + "' is not one");
  std::filesystem::remove_all(dir);
}

TEST(Settings, OpenXrOutputAndItsHead) {
  auto r = load_settings_from_string(
      "[display]\noutput = \"openxr\"\n[display.openxr]\nhead = \"tracker\"\nreference_space = \"stage\"\n"
      "[registration]\nxr_space_translation_mm = [10.0, 20.0, 30.0]\nxr_space_rotation_wxyz = [0.0, 0.0, 1.0, 0.0]\n",
      "x.toml");
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r->display.output, lungar::platform::Output::OpenXr);
  EXPECT_EQ(r->display.openxr.head, lungar::platform::XrHead::Tracker);
  EXPECT_EQ(r->display.openxr.reference_space, lungar::platform::XrReferenceSpace::Stage);
  EXPECT_EQ(r->registration.xr_space_translation_mm, (std::array<double, 3>{10.0, 20.0, 30.0}));
  EXPECT_EQ(r->registration.xr_space_rotation_wxyz, (std::array<double, 4>{0.0, 0.0, 1.0, 0.0}));
}

TEST(Settings, HexUsbIdsAreAccepted) {
  auto r = load_settings_from_string("[trackers.hid]\nvendor_id = 0x1234\nproduct_id = 0xBEEF\n", "x.toml");
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r->trackers().hid.vendor_id, 0x1234);
  EXPECT_EQ(r->trackers().hid.product_id, 0xBEEF);
}

TEST(Settings, RelativePathsResolveAgainstTheConfigFolder) {
  const auto dir = std::filesystem::temp_directory_path() / "lungar_settings_test";
  std::filesystem::create_directories(dir / "profiles");
  const auto file = dir / "profiles" / "p.toml";
  std::ofstream(file) << "[trackers]\nsource = \"replay\"\nreplay_file = \"../logs/a.trk\"\n";
  auto r = load_settings(file.string());
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r->trackers().replay_file, (dir / "logs" / "a.trk").string());
  // The breath's source: a trace file resolves the same way; "model" and a live marker are not paths.
  for (const auto& [given, read] : {std::pair<std::string, std::string>{"breath.vxp", (dir / "profiles" / "breath.vxp").string()},
                                    {"model", "model"},
                                    {"marker:stylus", "marker:stylus"}}) {
    std::ofstream(file) << "[breathing]\nsource = \"" << given << "\"\n";
    auto b = load_settings(file.string());
    ASSERT_TRUE(b) << b.error();
    EXPECT_EQ(b->breathing.source, read);
  }
  std::filesystem::remove_all(dir);
}

// --- bad input: each case asserts the whole message, which names the file, line, key and expectation ---

TEST(BadConfig, UnknownTopLevelSection) {
  EXPECT_EQ(error_of("[displya]\nwidth_px = 3\n"),
            "bad.toml:1: unknown key 'displya'; expected one of: breathing, console, display, hmd, registration, "
            "render, sim, sync, "
            "trackers");
}

TEST(BadConfig, UnknownKeyInSection) {
  EXPECT_EQ(
      error_of("[render]\nmode = \"points\"\npointsize = 5\n"),
      "bad.toml:3: unknown key 'render.pointsize'; expected one of: background, color_left, color_lesion, color_right, "
      "deform, half_float, hud, lod, mode, overlay_rest, point_size_px, stereo_strategy, "
      "ventilation_full_scale_mm, ventilation_map");
}

TEST(BadConfig, UnknownKeyInNestedTable) {
  EXPECT_EQ(error_of("[hmd.lens]\nenabled = true\nk3 = [0.0, 0.0, 0.0]\n"),
            "bad.toml:3: unknown key 'hmd.lens.k3'; expected one of: enabled, k1, k2");
}

TEST(BadConfig, WrongTypeStringForNumber) {
  EXPECT_EQ(error_of("[hmd]\nipd_mm = \"63\"\n"),
            "bad.toml:2: key 'hmd.ipd_mm': expected a number in [40, 90] mm, got the string \"63\"");
}

TEST(BadConfig, OutOfRangeIsRejectedNotClamped) {
  EXPECT_EQ(error_of("[render]\npoint_size_px = 0\n"),
            "bad.toml:2: key 'render.point_size_px': expected a number in [1, 64] pixels, got the integer 0");
}

TEST(BadConfig, NegativeRate) {
  EXPECT_EQ(error_of("[breathing]\nrate_bpm = -12.5\n"),
            "bad.toml:2: key 'breathing.rate_bpm': expected a number in [2, 60] breaths/min, got the number -12.5");
}

TEST(BadConfig, NotANumber) {
  EXPECT_EQ(error_of("[breathing]\ntidal_volume_ml = nan\n"),
            "bad.toml:2: key 'breathing.tidal_volume_ml': expected a number in [50, 3000] mL, got the number nan");
}

TEST(BadConfig, FractionWhereAnIntegerIsExpected) {
  EXPECT_EQ(error_of("[hmd]\neye_width_px = 640.5\n"),
            "bad.toml:2: key 'hmd.eye_width_px': expected an integer in [16, 8192] pixels, got the number 640.5");
}

TEST(BadConfig, UnknownEnumValue) {
  EXPECT_EQ(error_of("[render]\ndeform = \"cuda\"\n"),
            "bad.toml:2: key 'render.deform': expected one of \"gpu\" | \"cpu7\" | \"cpu1\" | \"none\", got the string \"cuda\"");
}

TEST(BadConfig, UnknownPreset) {
  EXPECT_EQ(error_of("[breathing]\npreset = \"asthma\"\n"),
            "bad.toml:2: key 'breathing.preset': expected one of \"normal\" | \"emphysema\" | \"fibrosis\", got the "
            "string \"asthma\"");
}

TEST(BadConfig, RpmFlaggedIsFollowOrSkip) {
  EXPECT_EQ(error_of("[breathing]\nrpm_flagged = \"drop\"\n"),
            "bad.toml:2: key 'breathing.rpm_flagged': expected one of \"follow\" | \"skip\", got the string \"drop\"");
}

TEST(BadConfig, ArrayOfTheWrongLength) {
  EXPECT_EQ(error_of("[hmd]\nhead_to_eye_mm = [0.0, 80.0]\n"),
            "bad.toml:2: key 'hmd.head_to_eye_mm': expected an array of 3 numbers in [-500, 500] mm, got an array of 2");
}

TEST(BadConfig, ArrayElementOutOfRange) {
  EXPECT_EQ(error_of("[render]\ncolor_left = [0.5, 1.5, 0.5]\n"),
            "bad.toml:2: key 'render.color_left': expected an array of 3 numbers in [0, 1] (linear RGB), got the "
            "number 1.5 at index 1");
}

TEST(BadConfig, SyntaxErrorNamesLineAndColumn) {
  const std::string e = error_of("[render]\npoint_size_px = 5\nmode = \"points\n");
  EXPECT_EQ(e.rfind("bad.toml:3:", 0), 0u) << e;
  EXPECT_NE(e.find("TOML syntax error"), std::string::npos) << e;
}

TEST(BadConfig, FarPlaneBeforeNearPlane) {
  EXPECT_EQ(error_of("[hmd]\nnear_mm = 100.0\nfar_mm = 50.0\n"),
            "bad.toml:3: key 'hmd.far_mm': expected far_mm greater than near_mm (100.000000 mm)");
}

TEST(BadConfig, RegistrationRotationNotAUnitQuaternion) {
  EXPECT_EQ(error_of("[registration]\nrotation_wxyz = [1.0, 1.0, 0.0, 0.0]\n"),
            "bad.toml:2: key 'registration.rotation_wxyz': expected a unit quaternion (norm 1 within 1e-3), got norm "
            "1.414214");
}

TEST(BadConfig, OpenXrHeadFromNowhere) {
  EXPECT_EQ(error_of("[display.openxr]\nhead = \"eyes\"\n"),
            "bad.toml:2: key 'display.openxr.head': expected one of \"openxr\" | \"tracker\", got the string \"eyes\"");
}

TEST(BadConfig, XrSpaceRotationNotAUnitQuaternion) {
  EXPECT_EQ(error_of("[registration]\nxr_space_rotation_wxyz = [0.5, 0.5, 0.0, 0.0]\n"),
            "bad.toml:2: key 'registration.xr_space_rotation_wxyz': expected a unit quaternion (norm 1 within 1e-3), "
            "got norm 0.707107");
}

TEST(BadConfig, UsbIdOutOfRange) {
  EXPECT_EQ(error_of("[trackers.hid]\nvendor_id = 0x12345\n"),
            "bad.toml:2: key 'trackers.hid.vendor_id': expected an integer in [0, 0xFFFF] (a USB id, e.g. 0x1234), "
            "got the integer 74565");
}

TEST(BadConfig, ReplayWithoutALog) {
  EXPECT_EQ(error_of("[trackers]\nsource = \"replay\"\n"),
            "bad.toml:1: key 'trackers.replay_file': expected a .trk file when source = \"replay\", got nothing");
}

TEST(BadConfig, ValueWhereASectionBelongs) {
  EXPECT_EQ(error_of("render = 5\n"), "bad.toml:1: key 'render': expected a table, got the integer 5");
}

TEST(BadConfig, BooleanWrittenAsString) {
  EXPECT_EQ(error_of("[render]\nlod = \"yes\"\n"),
            "bad.toml:2: key 'render.lod': expected true or false, got the string \"yes\"");
}

TEST(BadConfig, MissingFile) {
  auto r = load_settings("/nonexistent/lungar.toml");
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error(), "/nonexistent/lungar.toml: cannot read the config: expected a TOML file, got no such file");
}

TEST(Settings, AClassroomStationIsConfigured) {
  auto r = load_settings_from_string("[sync]\nrole = \"trainee\"\nclassroom = \"ward-3\"\ndomain = 17\n", "x.toml");
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r->sync.role, lungar::classroom::SyncRole::Trainee);
  EXPECT_EQ(r->sync.classroom, "ward-3");
  EXPECT_EQ(r->sync.domain, 17);
}

TEST(BadConfig, SyncKeysOutOfRange) {
  EXPECT_NE(error_of("[sync]\nrole = \"teacher\"\n").find("key 'sync.role': expected one of \"off\" | "
                                                             "\"instructor\" | \"trainee\""),
            std::string::npos);
  EXPECT_NE(error_of("[sync]\ndomain = 233\n").find("key 'sync.domain'"), std::string::npos);
  EXPECT_NE(error_of("[sync]\nclassroom = \"\"\n").find("key 'sync.classroom': expected a name"), std::string::npos);
  EXPECT_NE(error_of("[sync]\nclassroom = \"ward*\"\n").find("key 'sync.classroom'"), std::string::npos);
}

// The shipped tracker profiles are whole configs (a profile may set [hmd] or [display] too): each loads.
TEST(Settings, EveryShippedTrackerProfileLoadsAsAWholeConfig) {
  const std::filesystem::path dir = std::filesystem::path(LUNGAR_SOURCE_DIR) / "config" / "trackers";
  int n = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    auto r = lungar::platform::load_settings(entry.path().string());
    EXPECT_TRUE(r) << entry.path() << ": " << r.error();
    ++n;
  }
  EXPECT_GE(n, 3);
}

// The log line named the settings' breathing (12/min, 500 mL) while the ARDS scenario breathed 20/min, 420 mL.
TEST(Settings, TheSummaryNamesTheBreathingOfTheScenarioThatRuns) {
  const lungar::platform::Settings s;
  const auto scenario =
      lungar::config::load_scenario(std::string(LUNGAR_SOURCE_DIR) + "/config/scenarios/ards-proning.toml", s.breathing);
  ASSERT_TRUE(scenario) << scenario.error();
  const std::string line = lungar::platform::summarize(s, &*scenario);
  EXPECT_NE(line.find("breathing normal 20/min V_T 420 mL (the scenario ards proning's start)"), std::string::npos)
      << line;
  EXPECT_NE(lungar::platform::summarize(s).find("breathing normal 12/min V_T 500 mL, tracker"), std::string::npos)
      << lungar::platform::summarize(s);
}
