// The runtime end to end, headless on Mesa llvmpipe: a few frames with each tracker source and deformation
// path, checking the stats JSON and the snapshot that a user gets, and clean errors for bad inputs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "drivers/plus/plus_sequence.h"
#include "drivers/plus/plus_sequence_writer.h"
#include "drivers/tracker/tracker_config.h"
#include "platform/app/run.h"
#include "platform/app/runtime_options.h"
#include "sim/asset/asset_io.h"
#include "sim/bake/bake.h"
#include "sim/motion/interior_displacement.h"
#include "sim/motion/lesion.h"
#include "tests/lung_axis.h"

using namespace lungar;

namespace {

const std::string kData = std::string(LUNGAR_SOURCE_DIR) + "/tests/data/";

/// A small procedural pair in the current asset format (with the sphere points ARDS needs), baked once per run.
const std::string& small_current_asset() {
  static const std::string path = [] {
    const std::string p = (std::filesystem::temp_directory_path() / "lungar_runtime_small_v3.lungbake").string();
    sim::BakeOptions options;
    options.threads = 2;
    options.evaluate = false;
    options.transfer_rows = false;
    Result<sim::BakeOutput> out = sim::bake_procedural(4000, 7, options, nullptr);
    if (!out) throw std::runtime_error(out.error());
    if (Status s = sim::write_asset(out->asset, p); !s) throw std::runtime_error(s.error());
    return p;
  }();
  return path;
}

class RuntimeRun : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = std::filesystem::temp_directory_path() /
          ("lungar_runtime_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::remove_all(dir);
    settings.sim.asset = kData + "hil_lungs.lungbake";
    settings.display.output = platform::Output::Headless;
    options.frames = 6;
    options.snapshot_path = (dir / "shot.png").string();
    options.stats_json_path = (dir / "stats.json").string();
  }
  void TearDown() override { std::filesystem::remove_all(dir); }

  /// A scenario that lays the mock patient in `pose` (a start pose and no turn) breathing 30 times a minute, for a
  /// run of `seconds`.
  void lay_patient(const std::string& pose, double seconds) {
    const std::string path = (dir / (pose + ".toml")).string();
    std::filesystem::create_directories(dir);
    std::ofstream(path) << "duration_s = 10.0\n[start]\nrate_bpm = 30.0\npose = \"" << pose << "\"\n";
    settings.breathing.scenario = path;
    options.frames.reset();
    options.seconds = seconds;
  }

  nlohmann::json stats() const {
    std::ifstream in(options.stats_json_path);
    return nlohmann::json::parse(in);
  }
  /// True when the PNG exists, has the PNG signature and more than a blank frame's worth of bytes.
  bool snapshot_written() const {
    std::ifstream in(options.snapshot_path, std::ios::binary);
    char sig[8] = {};
    in.read(sig, 8);
    return in && std::string(sig + 1, 3) == "PNG" && std::filesystem::file_size(options.snapshot_path) > 2000;
  }

  std::filesystem::path dir;
  platform::Settings settings;
  platform::RuntimeOptions options;
};

}  // namespace

TEST_F(RuntimeRun, StereoWithTheMockTrackerWritesStatsAndASnapshot) {
  ASSERT_EQ(platform::run_runtime(settings, options), 0);
  const auto j = stats();
  EXPECT_EQ(j["frames"], 6);
  EXPECT_EQ(j["view"], "stereo");
  EXPECT_EQ(j["deform"], "gpu");
  EXPECT_EQ(j["nodes"], 2032);  // tests/data/hil_lungs.lungbake
  EXPECT_EQ(j["asset"], settings.sim.asset);
  EXPECT_GT(j["frame_ms_p50"].get<double>(), 0.0);
  EXPECT_EQ(j["tracker_malformed"], 0);
  EXPECT_TRUE(snapshot_written());
}

TEST_F(RuntimeRun, TheMockPatientTurnsSupineWhileTheLungsBreatheTheirTidalVolume) {
  // 5.6 s: the mock turns the patient from upright to supine between 1 s and 5 s; at 30 breaths/min that is
  // more than two whole breaths of the configured 500 mL.
  settings.breathing.rate_bpm = 30.0;
  options.frames.reset();
  options.seconds = 5.6;
  ASSERT_EQ(platform::run_runtime(settings, options), 0);
  const auto j = stats();
  EXPECT_LT(j["volume_ml_min"].get<double>(), 0.02 * 500.0);
  EXPECT_GT(j["volume_ml_max"].get<double>(), 0.98 * 500.0);
  EXPECT_LT(j["volume_ml_max"].get<double>(), 1.01 * 500.0);
  // Upright: gravity along -z (inferior) in the lung frame; supine: along +y (posterior).
  EXPECT_NEAR(j["gravity_lung_first"][2].get<double>(), -1.0, 0.01);
  EXPECT_NEAR(j["gravity_lung_last"][1].get<double>(), 1.0, 0.01);
  // Every frame of the 5.6 s was counted: frames at their mean rate fill the run (each frame's time runs from
  // the previous frame's submission, the first from the start), whatever the load.
  EXPECT_NEAR(j["frames"].get<double>() * j["frame_ms_mean"].get<double>() * 1e-3, j["wall_s"].get<double>(),
              0.05 * j["wall_s"].get<double>());
  EXPECT_NEAR(j["wall_s"].get<double>(), 5.6, 0.5);
  EXPECT_GT(j["tracker_rate_hz"].get<double>(), 0.8 * 2 * settings.trackers().mock.rate_hz);  // head and patient
}

TEST_F(RuntimeRun, LyingOnTheLeftSideTheLeftLungTakesMoreOfEachBreath) {
  // A scenario holds the mock patient on one side for more than a breath at 30 breaths/min; the stats give each
  // lung's swing. Supine the split is the lungs' rest volumes; on the left side the left (lower) lung gains.
  const auto left_share = [&](const char* pose) {
    lay_patient(pose, 2.5);  // a start pose and no turn: the scenario still lays the mock patient down
    EXPECT_EQ(platform::run_runtime(settings, options), 0) << pose;
    const auto j = stats();
    EXPECT_EQ(j["per_lung"].size(), 2u) << pose;
    double left = 0, total = 0;
    for (const auto& lung : j["per_lung"]) {
      total += lung["tidal_ml"].get<double>();
      if (lung["name"] == "left") left = lung["tidal_ml"].get<double>();
    }
    EXPECT_NEAR(total, 500.0, 25.0) << pose << ": the pair still breathes the tidal volume";
    return total > 0 ? left / total : 0.0;
  };
  const double supine = left_share("supine");
  const double left_side = left_share("left_lateral");
  EXPECT_GT(left_side, supine + 0.08) << "supine " << supine << ", left side down " << left_side;
}

TEST_F(RuntimeRun, ProneTheVentralHalfTakesMoreOfTheBreathThanSupine) {
  const auto ventral = [&](const char* pose) {
    lay_patient(pose, 1.0);
    EXPECT_EQ(platform::run_runtime(settings, options), 0) << pose;
    return stats()["ventral_share"].get<double>();
  };
  const double supine = ventral("supine"), prone = ventral("prone");
  // EIT, awake adults: about 0.38 supine and 0.49 prone (docs/design.md, "Posture and the split between the lungs").
  EXPECT_GT(supine, 0.30);
  EXPECT_LT(supine, 0.45);
  EXPECT_GT(prone, supine + 0.03) << "supine " << supine << ", prone " << prone;
}

TEST_F(RuntimeRun, ARightPneumothoraxLeavesTheRightLungUnderATenthOfEachBreath) {
  lay_patient("supine", 2.5);
  settings.sim.pathologies = {"pneumothorax:right:30"};
  ASSERT_EQ(platform::run_runtime(settings, options), 0);
  const auto j = stats();
  EXPECT_NE(j["asset"].get<std::string>().find("with pneumothorax:right:30"), std::string::npos) << j["asset"];
  double right = -1, total = 0;
  for (const auto& lung : j["per_lung"]) {
    total += lung["tidal_ml"].get<double>();
    if (lung["name"] == "right") right = lung["tidal_ml"].get<double>();
  }
  EXPECT_NEAR(total, 500.0, 25.0) << "the pair still breathes the tidal volume";
  EXPECT_GE(right, 0.0);
  EXPECT_LE(right, 0.10 * total) << "the collapsed lung";
  settings.sim.pathologies = {"pneumothorax:middle:30"};
  EXPECT_NE(platform::run_runtime(settings, options), 0) << "a bad spec stops the run before it starts";
}

TEST_F(RuntimeRun, AScenariosArdsPatientTurnedProneBreathesIntoItsBackAgain) {
  settings.sim.asset = small_current_asset();
  const auto ventral = [&](const char* pose, const char* pathology) {
    lay_patient(pose, 1.0);
    if (pathology != nullptr) {  // the scenario brings the patient's lungs
      const std::string text = "duration_s = 10.0\npathology = [\"" + std::string(pathology) +
                               "\"]\n[start]\nrate_bpm = 30.0\npose = \"" + pose + "\"\n";
      std::ofstream(settings.breathing.scenario, std::ios::trunc) << text;
    }
    EXPECT_EQ(platform::run_runtime(settings, options), 0) << pose;
    const auto j = stats();
    if (pathology != nullptr) {
      EXPECT_NE(j["asset"].get<std::string>().find(pathology), std::string::npos) << j["asset"];
      EXPECT_EQ(j["pathologies"], std::vector<std::string>{pathology});
    } else {
      EXPECT_TRUE(j["pathologies"].empty()) << j.dump();
    }
    return j["ventral_share"].get<double>();
  };
  const double healthy = ventral("supine", nullptr), supine = ventral("supine", "ards:0.6"),
               prone = ventral("prone", "ards:0.6");
  EXPECT_GT(supine, healthy + 0.05) << "supine the back collapses: the breath goes to the front";
  EXPECT_GT(1.0 - prone, (1.0 - supine) + 0.10) << "prone the back takes the breath again";
  settings.sim.asset = kData + "hil_lungs.lungbake";  // format 1: no sphere points
  settings.sim.pathologies = {"ards:0.6"};
  EXPECT_NE(platform::run_runtime(settings, options), 0) << "an old asset refuses ARDS before the first frame";
}

TEST_F(RuntimeRun, AScenarioWithoutSecondsRunsForItsOwnLength) {
  // A 1.5 s scenario: the run ends with it, not at the demo's 10 s.
  lay_patient("supine", 1.0);
  std::ofstream(settings.breathing.scenario, std::ios::trunc) << "duration_s = 1.5\n[start]\nrate_bpm = 30.0\n";
  options.seconds.reset();
  ASSERT_EQ(platform::run_runtime(settings, options), 0);
  const double wall_s = stats()["wall_s"].get<double>();
  EXPECT_GE(wall_s, 1.5);
  EXPECT_LT(wall_s, 8.0) << "ran past the scenario's end";
}

TEST_F(RuntimeRun, TheLogAndTheStatsSayTheBreathingAndAPneumothoraxWhileItComes) {
  // The scenario breathes 20/min at 420 mL; a right tension pneumothorax starts coming at 0.5 s, over 20 s.
  const std::string path = (dir / "coming.toml").string();
  std::filesystem::create_directories(dir);
  std::ofstream(path) << "duration_s = 30.0\n[start]\nrate_bpm = 20.0\ntidal_volume_ml = 420.0\npose = \"supine\"\n"
                         "[[event]]\nat_s = 0.5\nkind = \"pathology\"\nadd = \"pneumothorax:right:30:tension\"\n"
                         "over_s = 20.0\n";
  settings.breathing.scenario = path;
  options.frames.reset();
  options.seconds = 1.5;
  ::testing::internal::CaptureStderr();
  const int exit_code = platform::run_runtime(settings, options);
  const std::string log = ::testing::internal::GetCapturedStderr();
  ASSERT_EQ(exit_code, 0) << log;
  EXPECT_NE(log.find("in force: breathing normal 20/min 420 mL, pathologies none\n"), std::string::npos) << log;
  EXPECT_NE(log.find("in force: breathing normal 20/min 420 mL, pathologies pneumothorax:right:30:tension (coming)"),
            std::string::npos)
      << log;
  const auto j = stats();
  const std::vector<std::string> ptx{"pneumothorax:right:30:tension"};
  EXPECT_EQ(j["pathologies"], ptx) << "it shows from its onset: " << j.dump();
  EXPECT_EQ(j["pathologies_changing"], ptx) << j.dump();
}

TEST_F(RuntimeRun, ANeedleDecompressionReExpandsTheLungDuringTheRun) {
  // A right tension pneumothorax from the start, breathing once a second; with the needle at 0.5 s the right lung
  // re-expands over 0.5 s and takes its share of the breaths after it, without it stays under a tenth.
  const auto right_share = [&](bool needle) {
    const std::string path = (dir / "ptx.toml").string();
    std::filesystem::create_directories(dir);
    std::ofstream(path, std::ios::trunc)
        << "duration_s = 10.0\npathology = [\"pneumothorax:right:30:tension\"]\n[start]\nrate_bpm = 60.0\n"
           "pose = \"supine\"\n"
        << (needle ? "[[event]]\nat_s = 0.5\nkind = \"pathology\"\nremove = \"pneumothorax:right:30:tension\"\n"
                     "over_s = 0.5\n"
                   : "");
    settings.breathing.scenario = path;
    options.frames.reset();
    options.seconds = 3.0;
    EXPECT_EQ(platform::run_runtime(settings, options), 0);
    double right = 0, total = 0;
    const auto j = stats();
    for (const auto& lung : j["per_lung"]) {
      total += lung["tidal_ml"].get<double>();
      if (lung["name"] == "right") right = lung["tidal_ml"].get<double>();
    }
    EXPECT_GT(total, 0.0) << j.dump();
    return total > 0 ? right / total : -1.0;
  };
  EXPECT_LE(right_share(false), 0.10) << "collapsed all along";
  EXPECT_GE(right_share(true), 0.35) << "re-expanded: it breathes again";
}

TEST_F(RuntimeRun, TheVentilationMapIsTheShadersAndSaysSoInTheStats) {
  settings.render.ventilation_map = true;  // --view ventilation (runtime_options_test reads the option)
  ASSERT_EQ(platform::run_runtime(settings, options), 0);
  EXPECT_TRUE(stats()["ventilation_map"].get<bool>());
  EXPECT_EQ(stats()["view"], "stereo");
  EXPECT_TRUE(snapshot_written());
  settings.render.deform = platform::Deform::Cpu7;
  EXPECT_NE(platform::run_runtime(settings, options), 0) << "the CPU paths cannot colour by the shader's sweep";
  settings = {};
  settings.sim.asset = kData + "hil_lungs.lungbake";
  settings.display.output = platform::Output::Headless;
  ASSERT_EQ(platform::run_runtime(settings, options), 0);
  EXPECT_FALSE(stats()["ventilation_map"].get<bool>()) << "off by default";
}

// --breath: the lungs breathe with a recorded trace (30 breaths a minute here, where the model breathes 12), then
// hand over towards the model when the trace ends; a bad trace stops the run before it starts.
TEST_F(RuntimeRun, OfSeveralRecordingsGivenTheClearestBreathingIsFollowed) {
  // Two markers of one session: the chest breathing 15 a minute, and one that mostly sways twice a minute (a shift
  // on the table), its breath a tenth of the sway. Given in either order, lungar follows the chest.
  std::filesystem::create_directories(dir);
  const std::string chest = (dir / "chest.csv").string(), sway = (dir / "sway.csv").string();
  {
    std::ofstream c(chest), w(sway);
    c << "t_s,value\n";
    w << "t_s,value\n";
    for (int i = 0; i < 60 * 20; ++i) {
      const double t = i / 20.0, breath = std::pow(std::sin(M_PI * t / 4.0), 2);
      c << t << "," << 4.0 * breath << "\n";
      w << t << "," << 4.0 * std::sin(2 * M_PI * t / 30.0) + 0.4 * breath << "\n";
    }
  }
  options.frames.reset();
  options.seconds = 1.0;
  for (const auto& given : {std::vector<std::string>{sway, chest}, std::vector<std::string>{chest, sway}}) {
    options.breath_paths = given;
    ASSERT_EQ(platform::run_runtime(settings, options), 0);
    EXPECT_EQ(stats()["breath_file"], chest);
  }
  // Several sources are compared only as recordings: a live one among them is one error, and no run.
  options.breath_paths = {chest, "marker:stylus"};
  EXPECT_NE(platform::run_runtime(settings, options), 0);
}

TEST_F(RuntimeRun, ARecordedTraceDrivesTheBreathThenTheModelTakesOver) {
  std::filesystem::create_directories(dir);
  const std::string trace = (dir / "trace.csv").string();
  {
    std::ofstream o(trace);
    o << "t_s,value\n";
    for (int i = 0; i < 7 * 40; ++i) o << i / 40.0 << "," << 6.0 * std::pow(std::sin(M_PI * i / 40.0 / 2.0), 2) << "\n";
  }
  options.breath_paths = {trace};
  options.frames.reset();
  options.seconds = 8.0;
  ASSERT_EQ(platform::run_runtime(settings, options), 0);
  const auto j = stats();
  EXPECT_EQ(j["breath_source"], "trace");
  EXPECT_NEAR(j["breath_rate_per_min"].get<double>(), 30.0, 1.5);
  EXPECT_GT(j["breath_following_s"].get<double>(), 2.0);
  EXPECT_NE(j["breath_state"], "following") << "the trace ended at 7 s";
  EXPECT_NEAR(j["volume_ml_max"].get<double>(), 500.0, 30.0);
  EXPECT_EQ(j["breath_flagged_samples"].get<long>(), 0);
  EXPECT_EQ(j["breath_bounded_samples"].get<long>(), 0) << "a clean trace never reaches dV's bounds";
  EXPECT_GT(j["breath_max_ml"].get<double>(), 1000.0) << "the normal preset's inspiratory capacity, at most 3 V_T";
  EXPECT_LE(j["breath_max_ml"].get<double>(), 1500.0);
  // The same trace named in the settings ([breathing] source) rather than on the command line.
  options.breath_paths.clear();
  settings.breathing.source = trace;
  options.seconds = 1.0;
  ASSERT_EQ(platform::run_runtime(settings, options), 0);
  EXPECT_EQ(stats()["breath_source"], "trace");
  settings.breathing.source = "model";
  options.breath_paths = {trace};
  std::ofstream(trace) << "t_s,value\n0,1\n0,2\n";
  options.seconds = 1.0;
  EXPECT_NE(platform::run_runtime(settings, options), 0);
}

// An RPM trace whose middle breaths RPM flagged (a negative validflag: its gating verdict, the amplitude still
// breathing): followed through them and counted by default; with [breathing] rpm_flagged = "skip" the follower
// loses the signal there and follows for less of the run.
TEST_F(RuntimeRun, AnRpmTracesFlaggedBreathsAreFollowedUnlessTheSiteSkipsThem) {
  std::filesystem::create_directories(dir);
  const std::string trace = (dir / "rpm.vxp").string();
  {
    std::ofstream o(trace);
    o << "[Header]\nData_layout=amplitude,phase,timestamp,validflag,ttlin,mark,ttlout\nSamples_per_second=25\n"
         "Scale_factor=10.0\n[Data]\n";
    for (int i = 0; i < 12 * 25; ++i)  // 30 breaths a minute for 12 s, 6 mm deep, the breaths of 6-9 s flagged
      o << 2.0 + 0.6 * std::pow(std::sin(M_PI * i / 25.0 / 2.0), 2) << ",0," << 40 * i << ","
        << (i >= 6 * 25 && i < 9 * 25 ? -1 : 0) << ",0,,0\n";
  }
  options.breath_paths = {trace};
  options.frames.reset();
  options.seconds = 11.5;
  ASSERT_EQ(platform::run_runtime(settings, options), 0);
  const auto followed = stats();
  EXPECT_EQ(followed["breath_format"], "vxp");
  EXPECT_EQ(followed["breath_flagged_samples"].get<long>(), 75);
  settings.breathing.rpm_flagged = "skip";
  ASSERT_EQ(platform::run_runtime(settings, options), 0);
  const auto skipped = stats();
  settings.breathing.rpm_flagged = "follow";
  EXPECT_EQ(skipped["breath_flagged_samples"].get<long>(), 0) << "none left to follow";
  // Following from the second breath (~5 s) to the end, against losing it at 6.5 s until a breath after 9 s.
  EXPECT_GT(followed["breath_following_s"].get<double>(), skipped["breath_following_s"].get<double>() + 2.5);
}

// --breath marker:stylus: a marker on the chest, replayed live from a PLUS sequence, moves 8 mm along an oblique
// axis in the patient's frame at 30 breaths a minute (inhalation a third of each breath), while the patient turns
// 30 degrees. The lungs follow it: its axis is found in the patient's frame, inhalation up, and its rate is read.
TEST_F(RuntimeRun, ALiveChestMarkerDrivesTheBreathAlongTheAxisItFinds) {
  std::filesystem::create_directories(dir);
  const Eigen::Vector3d axis = Eigen::Vector3d(0.2, -0.9, 0.4).normalized();
  drivers::PlusSequence seq;
  for (int i = 0; i < 18 * 50; ++i) {
    const double t = i / 50.0, u = std::fmod(t, 2.0) / 2.0;
    const double breath = u < 1.0 / 3 ? 0.5 - 0.5 * std::cos(3 * M_PI * u) : 0.5 + 0.5 * std::cos(1.5 * M_PI * (u - 1.0 / 3));
    Eigen::Isometry3d patient = Eigen::Isometry3d::Identity();
    patient.linear() = Eigen::AngleAxisd(M_PI / 6 * t / 18.0, Eigen::Vector3d::UnitX()).toRotationMatrix();
    patient.translation() = Eigen::Vector3d(0, 0, 1000);
    Eigen::Isometry3d marker = Eigen::Isometry3d::Identity();
    marker.translation() = patient * (Eigen::Vector3d(10, -150, 200) + 8.0 * breath * axis);
    drivers::PlusFrame f;
    f.timestamp_s = t;
    f.transforms = {{"Reference", "Tracker", true, patient.matrix()}, {"Stylus", "Tracker", true, marker.matrix()}};
    seq.frames.push_back(f);
  }
  const std::string path = (dir / "chest.igs.mha").string();
  ASSERT_TRUE(drivers::write_plus_sequence(path, seq));
  settings.trackers().source = drivers::TrackerSource::Replay;
  settings.trackers().replay_file = path;
  settings.trackers().replay_realtime = true;  // the breath is followed on the run's clock
  options.breath_paths = {"marker:stylus"};
  options.frames.reset();
  options.seconds = 17.0;
  ASSERT_EQ(platform::run_runtime(settings, options), 0);
  const auto j = stats();
  EXPECT_EQ(j["breath_source"], "marker:stylus");
  ASSERT_EQ(j["breath_marker_axis"].size(), 3u) << j.dump();
  const Eigen::Vector3d found(j["breath_marker_axis"][0], j["breath_marker_axis"][1], j["breath_marker_axis"][2]);
  EXPECT_GT(found.dot(axis), 0.99) << "the axis in the patient's frame, inhalation its positive direction";
  EXPECT_EQ(j["breath_state"], "following");
  EXPECT_NEAR(j["breath_rate_per_min"].get<double>(), 30.0, 2.0);
  options.breath_paths = {"marker:patient"};
  options.seconds = 1.0;
  EXPECT_NE(platform::run_runtime(settings, options), 0) << "the patient's pose is the frame, not a marker";
}

TEST_F(RuntimeRun, ReplayDrivesTheLoopUntilTheLogEnds) {
  settings.trackers().source = drivers::TrackerSource::Replay;
  settings.trackers().replay_file = kData + "upright_to_supine.trk";
  settings.trackers().replay_realtime = false;
  options.frames = 100000;  // the end of the log stops it
  options.seconds = 60.0;
  ASSERT_EQ(platform::run_runtime(settings, options), 0);
  const auto j = stats();
  EXPECT_LT(j["frames"].get<int>(), 100000);
  EXPECT_EQ(j["tracker_reports"], 750);  // every record of the log
  EXPECT_EQ(j["tracker_malformed"], 0);
}

// Emphysema: the lungs rest larger (the asset) and breathe with the emphysema preset (its slow recoil); a breathing
// chosen in the settings is kept.
TEST_F(RuntimeRun, EmphysemaBreathesWithTheEmphysemaPresetUnlessTheBreathingWasChosen) {
  ASSERT_EQ(platform::run_runtime(settings, options), 0);
  EXPECT_EQ(stats()["breathing_preset"], "normal");
  settings.sim.pathologies = {"emphysema:0.8"};
  ASSERT_EQ(platform::run_runtime(settings, options), 0);
  EXPECT_EQ(stats()["breathing_preset"], "emphysema");
  EXPECT_NE(stats()["asset"].get<std::string>().find("with emphysema:0.8"), std::string::npos);
  settings.breathing.preset = "fibrosis";
  ASSERT_EQ(platform::run_runtime(settings, options), 0);
  EXPECT_EQ(stats()["breathing_preset"], "fibrosis") << "the preset the user chose";
}

// --record FILE.igs.mha: the replayed log's 750 reports come out as a PLUS sequence of as many frames (the .trk it
// was recorded through is gone), which replays as a tracker.
TEST_F(RuntimeRun, ARecordingAsAPlusSequenceHoldsEveryReportAndReplays) {
  std::filesystem::create_directories(dir);
  const std::string recording = (dir / "session.igs.mha").string();
  settings.trackers().source = drivers::TrackerSource::Replay;
  settings.trackers().replay_file = kData + "upright_to_supine.trk";
  settings.trackers().replay_realtime = false;
  options.frames = 100000;
  options.seconds = 60.0;
  options.record_path = recording;
  ASSERT_EQ(platform::run_runtime(settings, options), 0);
  EXPECT_FALSE(std::filesystem::exists(recording + ".trk"));
  auto seq = drivers::read_plus_sequence(recording);
  ASSERT_TRUE(seq) << seq.error();
  EXPECT_EQ(seq->frames.size(), 750u);
  ASSERT_NE(seq->frames.back().find("Reference"), nullptr);
  options.record_path.clear();
  settings.trackers().replay_file = recording;
  ASSERT_EQ(platform::run_runtime(settings, options), 0);
  EXPECT_EQ(stats()["tracker_malformed"], 0);
  EXPECT_GT(stats()["tracker_reports"].get<int>(), 750);  // a report per valid tool in each frame
}

TEST_F(RuntimeRun, CpuEq7MonoMeshRuns) {
  options.deform = "cpu7";
  settings.render.deform = platform::Deform::Cpu7;
  settings.hmd.view = platform::View::Mono;
  settings.render.mode = render::DrawMode::Mesh;
  ASSERT_EQ(platform::run_runtime(settings, options), 0);
  const auto j = stats();
  EXPECT_EQ(j["deform"], "cpu7");
  EXPECT_EQ(j["view"], "mono");
  EXPECT_TRUE(snapshot_written());
}

TEST_F(RuntimeRun, LensDistortionPassRuns) {
  settings.hmd.lens.enabled = true;
  ASSERT_EQ(platform::run_runtime(settings, options), 0);
  EXPECT_EQ(stats()["frames"], 6);
  EXPECT_TRUE(snapshot_written());
}

/// A lesion spec `up` of the way from the bottom to the top of `lung_name`'s inside, on the vertical through its
/// vertices' centroid, of radius `radius` mm.
std::string lesion_in(const sim::BakedAsset& a, const sim::InteriorDisplacement& field, const std::string& lung_name,
                      const std::string& name, double up, double radius) {
  for (std::size_t l = 0; l < a.lungs.size(); ++l) {
    if (a.lungs[l].name != lung_name) continue;
    const Eigen::Vector3d p = lungar::testing::lung_axis(a, field, l).at(up);
    char spec[160];
    std::snprintf(spec, sizeof spec, "%s=%.2f,%.2f,%.2f,%g", name.c_str(), p.x(), p.y(), p.z(), radius);
    return spec;
  }
  ADD_FAILURE() << "no lung " << lung_name;
  return {};
}

TEST_F(RuntimeRun, ALesionLowInTheRightLungMovesCranioCaudallyMoreThanTwiceOneHighUp) {
  settings.sim.asset = small_current_asset();  // the sliding model's lungs (hil_lungs is the paper's)
  Result<sim::BakedAsset> a = sim::load_asset(settings.sim.asset);
  ASSERT_TRUE(a) << a.error();
  const sim::InteriorDisplacement field(*a);
  lay_patient("supine", 2.2);  // one whole breath at 30 a minute, and a little
  settings.sim.lesions = {lesion_in(*a, field, "right", "lower", 0.2, 4),
                          lesion_in(*a, field, "right", "upper", 0.8, 4)};
  ASSERT_EQ(platform::run_runtime(settings, options), 0);
  const auto j = stats();
  ASSERT_TRUE(j.contains("lesions")) << j.dump();
  ASSERT_EQ(j["lesions"].size(), 2u);
  const auto& lower = j["lesions"][0];
  const auto& upper = j["lesions"][1];
  EXPECT_EQ(lower["name"], "lower");
  EXPECT_EQ(lower["lung"], "right");
  EXPECT_EQ(upper["name"], "upper");
  EXPECT_EQ(lower["radius_mm"].get<double>(), 4.0);
  const double lower_si = lower["si_mm"].get<double>(), upper_si = upper["si_mm"].get<double>();
  EXPECT_GT(lower_si, 2.0) << "a 500 mL breath moves a lesion near the diaphragm";
  EXPECT_GT(lower_si, 2.0 * upper_si) << "lower " << lower_si << " mm, upper " << upper_si << " mm";
  EXPECT_GE(lower["peak_to_peak_mm"].get<double>(), lower_si - 1e-9);
  EXPECT_LT(lower["peak_to_peak_mm"].get<double>(), 1.5 * lower_si) << "supine, the base moves mostly along SI";
  EXPECT_TRUE(snapshot_written());

  // Drawn from rest (--deform none), a lesion does not move.
  settings.render.deform = platform::Deform::None;
  const std::optional<double> seconds = options.seconds;
  options.seconds.reset();
  options.frames = 20;
  ASSERT_EQ(platform::run_runtime(settings, options), 0);
  EXPECT_EQ(stats()["lesions"][0]["peak_to_peak_mm"].get<double>(), 0.0);
  options.frames.reset();
  options.seconds = seconds;

  // A lesion baked into the asset (lungar-bake --lesion) is drawn with no option, and a run's own come after it.
  Result<sim::Lesion> lower_spec = sim::parse_lesion(settings.sim.lesions[0]);
  ASSERT_TRUE(lower_spec);
  sim::BakedAsset with = *a;
  const Eigen::Vector3d& c = lower_spec->centre_mm;
  with.lesions = {{"baked", static_cast<std::uint32_t>(field.lung_containing(c)), {c.x(), c.y(), c.z()}, 4.0, false}};
  const std::string baked = (dir / "baked.lungbake").string();
  ASSERT_TRUE(sim::write_asset(with, baked));
  settings.sim.asset = baked;
  settings.sim.lesions = {settings.sim.lesions[1]};
  settings.render.deform = platform::Deform::Gpu;
  ASSERT_EQ(platform::run_runtime(settings, options), 0);
  const auto both = stats()["lesions"];
  ASSERT_EQ(both.size(), 2u);
  EXPECT_EQ(both[0]["name"], "baked");
  EXPECT_EQ(both[1]["name"], "upper");
  EXPECT_NEAR(both[0]["si_mm"].get<double>(), lower_si, 0.25 * lower_si) << "the baked lesion is the lower one";
}

TEST_F(RuntimeRun, ALesionOutsideEveryLungIsOneLineAndNoOutputs) {
  settings.sim.lesions = {"far=5000,5000,5000,5"};
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(platform::run_runtime(settings, options), 1);
  const std::string log = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(log.find("error: lesion far: its centre (5000.0, 5000.0, 5000.0) (LPS, mm) lies outside every lung"),
            std::string::npos)
      << log;
  EXPECT_FALSE(std::filesystem::exists(options.stats_json_path));
  EXPECT_FALSE(std::filesystem::exists(options.snapshot_path));
  // A spec that does not parse stops at the command line's reading.
  options.lesions = {"tumour=1,2,3"};
  platform::Settings s = settings;
  const Status bad = platform::apply_overrides(options, s);
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().find("--lesion: expected NAME=x,y,z,radius_mm"), std::string::npos) << bad.error();
}

TEST_F(RuntimeRun, BadInputsFailCleanlyWithoutOutputs) {
  settings.sim.asset = (dir / "missing.lungbake").string();
  EXPECT_EQ(platform::run_runtime(settings, options), 1);
  EXPECT_FALSE(std::filesystem::exists(options.stats_json_path));

  settings.sim.asset = kData + "upright_to_supine.trk";  // not an asset
  EXPECT_EQ(platform::run_runtime(settings, options), 1);

  settings.sim.asset = kData + "hil_lungs.lungbake";
  settings.trackers().source = drivers::TrackerSource::Replay;
  settings.trackers().replay_file = (dir / "missing.trk").string();
  EXPECT_EQ(platform::run_runtime(settings, options), 1);
  EXPECT_FALSE(std::filesystem::exists(options.snapshot_path));
}
