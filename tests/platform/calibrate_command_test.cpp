// `lungar calibrate` from a tracker log: a stylus dwelling on each fiducial of a patient simulator that sits at a
// known pose, recorded as raw reports; the recovered model -> patient-tracker transform and its error must match.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "drivers/decode/encoder.h"
#include "drivers/decode/report_layout.h"
#include "drivers/tracker/tracker_config_toml.h"
#include "drivers/trk/trk_writer.h"
#include "platform/app/calibrate_command.h"
#include "platform/app/settings_load.h"
#include "platform/registration/pivot_calibration.h"
#include "tests/scratch_dir.h"

using namespace lungar;

namespace {

/// A .trk log of poses as the layout of `t` encodes them into raw reports, one report period (16 ms) a step.
class PoseLogWriter {
 public:
  void open(const drivers::TrackerConfig& t, const std::string& path) {
    auto layout = drivers::make_layout(t);
    ASSERT_TRUE(layout) << layout.error();
    layout_ = *layout;
    report_.assign(static_cast<std::size_t>(t.report.length), 0);
    drivers::TrkHeader header;
    header.description = "source=test";
    header.layout_toml = drivers::tracker_config_to_toml(t);
    ASSERT_EQ(writer_.open(path, header, drivers::TrkWriter::Mode::Atomic).error(), "");
  }
  /// One report of `role` at the current step.
  void emit(drivers::Role role, const Eigen::Vector3d& p, const Eigen::Quaterniond& q) {
    drivers::PoseSample pose;
    pose.role = role;
    pose.set_position(p);
    pose.set_orientation(q);
    std::fill(report_.begin(), report_.end(), 0);
    ASSERT_TRUE(drivers::encode_report(layout_, std::span(&pose, 1), ticks_, report_));
    ASSERT_TRUE(writer_.append(drivers::TrkSource::Hid, t_ns_, report_));
  }
  void step() {
    t_ns_ += 16'000'000;
    ticks_ += 16000;
  }
  void commit() { ASSERT_EQ(writer_.commit().error(), ""); }

 private:
  drivers::ReportLayout layout_;
  drivers::TrkWriter writer_;
  std::vector<std::uint8_t> report_;
  std::int64_t t_ns_ = 1'000'000'000;
  std::uint32_t ticks_ = 0;
};

/// A synthetic stylus whose sensor sits at its tip, said so (an offset nobody gives is refused as missing).
const Eigen::Vector3d kTipAtTheSensor = Eigen::Vector3d::Zero();

/// The model's fiducials as `lungar calibrate --model` reads them.
void write_model_csv(const std::filesystem::path& path, const std::vector<Eigen::Vector3d>& model) {
  std::ofstream o(path);
  for (const auto& m : model) o << m.x() << ", " << m.y() << ", " << m.z() << "\n";
}

}  // namespace

TEST(CalibrateFromLog, StylusDwellsInALogGiveTheKnownRegistration) {
  drivers::TrackerConfig t;
  t.stylus.enabled = true;

  // The truth: model -> patient tracker, and the patient tracker's pose in the world.
  const Eigen::Quaterniond reg_q(Eigen::AngleAxisd(0.4, Eigen::Vector3d(0.2, 1.0, -0.3).normalized()));
  const Eigen::Vector3d reg_t(15.0, -220.0, 40.0);
  const Eigen::Quaterniond patient_q(Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitX()));  // supine
  const Eigen::Vector3d patient_p(100.0, 50.0, 900.0);
  const std::vector<Eigen::Vector3d> model = {
      {-80, -150, -100}, {90, -140, -110}, {0, -230, -300}, {-60, -60, -250}, {70, -90, -60}};

  const auto dir = std::filesystem::temp_directory_path() / "lungar_calibrate_test";
  std::filesystem::create_directories(dir);
  const std::string log_path = (dir / "stylus.trk").string();
  PoseLogWriter log;
  log.open(t, log_path);

  std::mt19937 rng(5);
  std::normal_distribution<double> tip_noise(0.0, 0.2);  // mm: a steady hand on a landmark
  for (const auto& m : model) {
    const Eigen::Vector3d world = patient_q * (reg_q * m + reg_t) + patient_p;
    for (int k = 0; k < 50; ++k, log.step()) {  // 0.8 s held on the landmark
      log.emit(drivers::Role::Patient, patient_p, patient_q);
      log.emit(drivers::Role::Stylus, world + Eigen::Vector3d(tip_noise(rng), tip_noise(rng), tip_noise(rng)),
               Eigen::Quaterniond::Identity());
    }
    for (int k = 0; k < 10; ++k, log.step()) {  // moving on: too short to count
      log.emit(drivers::Role::Stylus, world + Eigen::Vector3d(0, 0, 30.0 * (k + 1)), Eigen::Quaterniond::Identity());
    }
  }
  log.commit();

  auto touched = platform::stylus_points_from_log(log_path, {}, kTipAtTheSensor);
  ASSERT_TRUE(touched) << touched.error();
  ASSERT_EQ(touched->size(), model.size());
  auto fitted = platform::register_fiducials(model, *touched);
  ASSERT_TRUE(fitted) << fitted.error();
  const platform::Registration& r = *fitted;
  // Positions travel as 0.01 mm integers: the error is the hand's noise averaged over 50 samples, well under 0.2 mm.
  EXPECT_LT(r.fre_rms_mm, 0.2);
  EXPECT_LT(r.rotation.angularDistance(reg_q), 0.2 * M_PI / 180.0);
  EXPECT_LT((r.translation_mm - reg_t).norm(), 0.5);

  // The whole command writes a section that names the error, and refuses a log without a stylus.
  const auto model_csv = dir / "model.csv";
  write_model_csv(model_csv, model);
  platform::CalibrateOptions o;
  o.model_csv = model_csv.string();
  o.stylus_log = log_path;
  o.out_path = (dir / "registration.toml").string();
  o.stylus_tip_mm = kTipAtTheSensor;
  EXPECT_EQ(platform::run_calibrate(o), 0);
  EXPECT_TRUE(std::filesystem::exists(o.out_path));
  o.stylus_log = std::string(LUNGAR_SOURCE_DIR) + "/tests/data/upright_to_supine.trk";
  o.out_path = (dir / "none.toml").string();
  EXPECT_EQ(platform::run_calibrate(o), 2);
  EXPECT_FALSE(std::filesystem::exists(o.out_path));
  std::filesystem::remove_all(dir);
}

// A stylus whose sensor sits 150 mm up the handle from its tip: `lungar calibrate pivot` finds the tip from the
// stylus swinging about it in a dimple, and the registration from dwells read at that tip recovers the truth,
// where reading the sensor's origin does not.
TEST(CalibrateFromLog, PivotFindsTheTipAndTheRegistrationReadsTheStylusThere) {
  drivers::TrackerConfig t;
  t.stylus.enabled = true;
  const Eigen::Vector3d tip(2.0, -1.5, -150.0);  // stylus frame: the tip down the handle
  const Eigen::Quaterniond patient_q(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()));
  const Eigen::Vector3d patient_p(-40.0, 300.0, 700.0);
  const auto dir = std::filesystem::temp_directory_path() / "lungar_pivot_test";
  std::filesystem::create_directories(dir);
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0.0, 0.1);
  std::uniform_real_distribution<double> angle(-0.6, 0.6);

  // Writes a log of the stylus at the given tip positions (patient frame), each held with a random tilt.
  const auto record = [&](const std::string& path, const std::vector<Eigen::Vector3d>& tips_in_patient, int hold) {
    PoseLogWriter log;
    log.open(t, path);
    for (const Eigen::Vector3d& target : tips_in_patient) {
      for (int k = 0; k < hold; ++k, log.step()) {
        const Eigen::Quaterniond q_rel(Eigen::AngleAxisd(angle(rng), Eigen::Vector3d::UnitX()) *
                                       Eigen::AngleAxisd(angle(rng), Eigen::Vector3d::UnitY()));
        const Eigen::Vector3d sensor_rel = target - q_rel * tip;  // the tip stays on the target
        const Eigen::Vector3d jitter(noise(rng), noise(rng), noise(rng));
        log.emit(drivers::Role::Patient, patient_p, patient_q);
        log.emit(drivers::Role::Stylus, patient_q * (sensor_rel + jitter) + patient_p, patient_q * q_rel);
      }
    }
    log.commit();
  };

  // Pivoting: 200 poses about one dimple.
  const std::string pivot_log = (dir / "pivot.trk").string();
  record(pivot_log, {Eigen::Vector3d(10.0, -20.0, 30.0)}, 200);
  platform::PivotOptions p;
  p.stylus_log = pivot_log;
  p.out_path = (dir / "tip.toml").string();
  ASSERT_EQ(platform::run_pivot(p), 0);
  auto log = platform::stylus_poses_from_log(pivot_log, {});
  ASSERT_TRUE(log) << log.error();
  auto fit = platform::fit_pivot(log->poses);
  ASSERT_TRUE(fit) << fit.error();
  EXPECT_LT((fit->tip_mm - tip).norm(), 0.3) << fit->tip_mm.transpose();
  EXPECT_LT((fit->pivot_mm - Eigen::Vector3d(10.0, -20.0, 30.0)).norm(), 0.3);
  EXPECT_LT(fit->rms_mm, 0.5);
  std::ifstream written(p.out_path);
  const std::string toml((std::istreambuf_iterator<char>(written)), std::istreambuf_iterator<char>());
  EXPECT_NE(toml.find("[trackers.stylus]\ntip_offset_mm = ["), std::string::npos) << toml;

  // Touching four fiducials with the tilting stylus: read at the tip the registration is exact; read at the
  // sensor's origin it is not.
  const std::vector<Eigen::Vector3d> model = {{-80, -150, -100}, {90, -140, -110}, {0, -230, -300}, {70, -90, -60}};
  const std::string touch_log = (dir / "touch.trk").string();
  record(touch_log, model, 50);  // the model frame is the patient frame here: the registration is the identity
  auto at_tip = platform::stylus_points_from_log(touch_log, {}, fit->tip_mm);
  ASSERT_TRUE(at_tip) << at_tip.error();
  ASSERT_EQ(at_tip->size(), model.size());
  auto r = platform::register_fiducials(model, *at_tip);
  ASSERT_TRUE(r) << r.error();
  EXPECT_LT(r->fre_rms_mm, 0.5);
  EXPECT_LT(r->translation_mm.norm(), 1.0);
  auto at_origin = platform::stylus_points_from_log(touch_log, {}, kTipAtTheSensor);
  EXPECT_TRUE(!at_origin || at_origin->size() != model.size()) << "a tilting sensor 150 mm up the handle never dwells";
  // The file `calibrate pivot` wrote, given as --config, carries the tip into the registration command.
  const auto model_csv = dir / "model.csv";
  write_model_csv(model_csv, model);
  platform::CalibrateOptions c;
  c.model_csv = model_csv.string();
  c.stylus_log = touch_log;
  c.config_paths = {p.out_path};
  c.out_path = (dir / "registration.toml").string();
  EXPECT_EQ(platform::run_calibrate(c), 0);
  c.config_paths.clear();
  c.out_path = (dir / "without-tip.toml").string();
  EXPECT_EQ(platform::run_calibrate(c), 2) << "without the tip the dwells are not found";
  EXPECT_FALSE(std::filesystem::exists(c.out_path));
  std::filesystem::remove_all(dir);
}

TEST(PivotCalibration, RefusesTooFewPosesAndAStylusThatDidNotTurn) {
  std::vector<Eigen::Isometry3d> poses(5, Eigen::Isometry3d::Identity());
  auto few = platform::fit_pivot(poses);
  ASSERT_FALSE(few);
  EXPECT_NE(few.error().find("at least 8"), std::string::npos) << few.error();
  poses.resize(20, Eigen::Isometry3d::Identity());
  for (std::size_t i = 0; i < poses.size(); ++i) poses[i].translation() = Eigen::Vector3d(0.5 * i, 0, 0);
  auto still = platform::fit_pivot(poses);
  ASSERT_FALSE(still);
  EXPECT_NE(still.error().find("turned at most 0.0 degrees"), std::string::npos) << still.error();
}

// The landmarks from a PLUS tracked sequence (.igs.mha) as PlusServer saves it: the stylus and the reference both
// tracked by the tracker, the stylus 120 mm up the handle from its tip, one frame INVALID on each landmark.
TEST(CalibrateFromLog, APlusSequenceGivesTheKnownRegistration) {
  const Eigen::Vector3d tip(0.0, 0.0, -120.0);
  const Eigen::Isometry3d reference = Eigen::Translation3d(50, 80, -900) * Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ());
  const Eigen::Quaterniond reg_q(Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 0.5, 0).normalized()));
  const Eigen::Vector3d reg_t(-10.0, 120.0, 30.0);
  const std::vector<Eigen::Vector3d> model = {{-80, -150, -100}, {90, -140, -110}, {0, -230, -300}, {70, -90, -60},
                                              {-40, -60, -250}};
  const auto dir = std::filesystem::temp_directory_path() / "lungar_plus_calibrate";
  std::filesystem::create_directories(dir);
  const std::string seq = (dir / "landmarks.igs.mha").string();
  {
    std::ofstream o(seq);
    o << "ObjectType = Image\nNDims = 3\nDimSize = 1 1 1\nElementType = MET_UCHAR\n";
    const auto matrix = [&o](const Eigen::Matrix4d& m) {
      for (int i = 0; i < 16; ++i) o << (i ? " " : "") << m(i / 4, i % 4);
      o << "\n";
    };
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> tilt(-0.4, 0.4);
    int frame = 0;
    for (const Eigen::Vector3d& m : model) {
      const Eigen::Vector3d target = reference * (reg_q * m + reg_t);  // the landmark in the tracker's frame
      for (int k = 0; k < 40; ++k, ++frame) {
        const Eigen::Matrix3d r = (Eigen::AngleAxisd(tilt(rng), Eigen::Vector3d::UnitX()) *
                                   Eigen::AngleAxisd(tilt(rng), Eigen::Vector3d::UnitY())).toRotationMatrix();
        Eigen::Isometry3d stylus = Eigen::Isometry3d::Identity();
        stylus.linear() = r;
        stylus.translation() = target - r * tip;
        char n[16];
        std::snprintf(n, sizeof n, "%04d", frame);
        o << "Seq_Frame" << n << "_ReferenceToTrackerTransform = ";
        matrix(reference.matrix());
        o << "Seq_Frame" << n << "_StylusToTrackerTransform = ";
        matrix(k == 7 ? Eigen::Matrix4d::Identity().eval() : stylus.matrix());  // garbage, flagged INVALID
        o << "Seq_Frame" << n << "_StylusToTrackerTransformStatus = " << (k == 7 ? "INVALID" : "OK") << "\n";
        o << "Seq_Frame" << n << "_Timestamp = " << 100.0 + 0.02 * frame << "\n";
      }
      frame += 30;  // moving to the next landmark: no frames recorded
    }
    o << "ElementDataFile = LOCAL\n";
  }
  auto touched = platform::stylus_points_from_log(seq, {}, tip);
  ASSERT_TRUE(touched) << touched.error();
  ASSERT_EQ(touched->size(), model.size());
  auto r = platform::register_fiducials(model, *touched);
  ASSERT_TRUE(r) << r.error();
  EXPECT_LT(r->fre_rms_mm, 0.05);
  EXPECT_LT(r->rotation.angularDistance(reg_q), 1e-3);
  EXPECT_LT((r->translation_mm - reg_t).norm(), 0.05);
  std::filesystem::remove_all(dir);
}

namespace {

/// A stylus with its tip 150 mm down the handle from its sensor, tilting while its tip holds still on each target.
struct TiltingStylus {
  drivers::TrackerConfig trackers;
  Eigen::Vector3d tip{2.0, -1.5, -150.0};  // stylus frame
  Eigen::Quaterniond patient_q{Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ())};
  Eigen::Vector3d patient_p{-40.0, 300.0, 700.0};
  std::mt19937 rng{17};

  TiltingStylus() { trackers.stylus.enabled = true; }

  /// A log of the tip held `hold` reports on each target (patient frame), the handle tilting about it.
  void record(const std::string& path, const std::vector<Eigen::Vector3d>& targets, int hold) {
    std::normal_distribution<double> noise(0.0, 0.1);
    std::uniform_real_distribution<double> angle(-0.6, 0.6);
    PoseLogWriter log;
    log.open(trackers, path);
    for (const Eigen::Vector3d& target : targets) {
      for (int k = 0; k < hold; ++k, log.step()) {
        const Eigen::Quaterniond q_rel(Eigen::AngleAxisd(angle(rng), Eigen::Vector3d::UnitX()) *
                                       Eigen::AngleAxisd(angle(rng), Eigen::Vector3d::UnitY()));
        const Eigen::Vector3d sensor = target - q_rel * tip + Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
        log.emit(drivers::Role::Patient, patient_p, patient_q);
        log.emit(drivers::Role::Stylus, patient_q * sensor + patient_p, patient_q * q_rel);
      }
    }
    log.commit();
  }
};

const std::vector<Eigen::Vector3d> kLandmarks = {{-80, -150, -100}, {90, -140, -110}, {0, -230, -300}, {70, -90, -60}};

/// `lungar ARGS` from the build tree as a user's shell runs it (its XDG folders under `root`): stdout, stderr, rc.
struct Ran {
  int rc = -1;
  std::string out, err;
};
Ran run_lungar(const std::string& args, const std::filesystem::path& root) {
  const auto err = root / "stderr";
  const std::string command = "HOME=" + root.string() + " XDG_CONFIG_HOME=" + (root / "config").string() +
                              " XDG_STATE_HOME=" + (root / "state").string() +
                              " XDG_CACHE_HOME=" + (root / "cache").string() + " " + LUNGAR_BINARY_DIR +
                              "/platform/lungar " + args + " 2>" + err.string();
  Ran r;
  FILE* p = ::popen(command.c_str(), "r");
  if (p == nullptr) return r;
  for (int c; (c = std::fgetc(p)) != EOF;) r.out += static_cast<char>(c);
  const int status = ::pclose(p);
  r.rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream e(err);
  r.err.assign(std::istreambuf_iterator<char>(e), std::istreambuf_iterator<char>());
  return r;
}

/// What follows `lead` on its line of `text`, "" when no line has it.
std::string after(const std::string& text, const std::string& lead) {
  const auto at = text.find(lead);
  if (at == std::string::npos) return "";
  const auto from = at + lead.size();
  return text.substr(from, text.find('\n', from) - from);
}

}  // namespace

// A stylus whose tip offset nobody gave (no pivot calibration passed on) is named as such, with the way to get it,
// and not blamed on a landmark that no touch fits.
TEST(CalibrateFromLog, AMissingStylusTipOffsetIsNamedAsSuchWithHowToFindIt) {
  const lungar::testing::ScratchDir dir("lungar_calibrate_no_tip");
  TiltingStylus stylus;
  const std::string touches = (dir / "touches.trk").string();
  stylus.record(touches, kLandmarks, 50);
  const auto model_csv = dir / "model.csv";
  write_model_csv(model_csv, kLandmarks);
  const auto profile = dir / "profile.toml";
  std::ofstream(profile) << "[render]\npoint_size_px = 3\n";
  platform::CalibrateOptions c;
  c.model_csv = model_csv.string();
  c.stylus_log = touches;
  c.config_paths = {profile.string()};
  c.out_path = (dir / "registration.toml").string();
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(platform::run_calibrate(c), 2);
  const std::string said = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(said, "lungar calibrate: " + touches +
                      ": the stylus tip offset is missing: [trackers.stylus] tip_offset_mm is [0, 0, 0] (in " +
                      profile.string() +
                      "); find it with `lungar calibrate pivot --stylus-log pivot.trk --out stylus.toml`, then add "
                      "`--config stylus.toml` here (or give --stylus-tip-mm x,y,z)\n");
  EXPECT_FALSE(std::filesystem::exists(c.out_path));
  // Said so, a tip at the sensor is taken (a synthetic stylus): the refusal is for the offset nobody gave.
  auto at_sensor = platform::stylus_points_from_log(touches, {}, kTipAtTheSensor);
  EXPECT_TRUE(at_sensor) << at_sensor.error();
}

// The three steps as a lab runs them, each reading the last one's output through one more --config, with the
// commands each step prints run as printed: pivot -> registration -> the runtime (`lungar doctor` checks what it
// would run). No file is edited by hand.
TEST(CalibrationSteps, EachStepReadsTheLastOnesOutputThroughAnotherConfigAsItsHintSays) {
  const lungar::testing::ScratchDir dir("lungar_calibration_steps");
  TiltingStylus stylus;
  const std::string pivot_log = (dir / "pivot.trk").string();
  stylus.record(pivot_log, {Eigen::Vector3d(10.0, -20.0, 30.0)}, 200);
  const std::string touches = (dir / "touches.trk").string();
  stylus.record(touches, kLandmarks, 50);  // the model frame is the patient frame: the registration is the identity
  const auto model_csv = dir / "model.csv";
  write_model_csv(model_csv, kLandmarks);
  std::filesystem::create_directories(dir / "lab");
  const auto profile = dir / "lab/profile.toml";
  std::ofstream(profile) << "[render]\npoint_size_px = 3\n\n[sim]\norientation_mode = \"paper_interp\"\n";

  const Ran pivot = run_lungar("--config " + profile.string() + " calibrate pivot --stylus-log " + pivot_log +
                                   " --out " + (dir / "stylus.toml").string(),
                               dir.path());
  ASSERT_EQ(pivot.rc, 0) << pivot.err;
  std::string next = after(pivot.out, "the registration reads it: lungar ");
  ASSERT_NE(next, "") << pivot.out;
  EXPECT_EQ(next, "calibrate --model MODEL.csv --stylus-log TOUCHES.trk --config " + profile.string() + " --config " +
                      (dir / "stylus.toml").string() + " --out registration.toml");
  next.replace(next.find("MODEL.csv"), 9, model_csv.string());
  next.replace(next.find("TOUCHES.trk"), 11, touches);
  next.replace(next.find("registration.toml"), 17, (dir / "registration.toml").string());
  const Ran registration = run_lungar(next, dir.path());
  ASSERT_EQ(registration.rc, 0) << next << ": " << registration.err;

  const std::string runtime = after(registration.out, "the runtime reads it: lungar ");
  const std::vector<std::string> files = {profile.string(), (dir / "stylus.toml").string(),
                                          (dir / "registration.toml").string()};
  EXPECT_EQ(runtime, "--config " + files[0] + " --config " + files[1] + " --config " + files[2]) << registration.out;
  const Ran doctor = run_lungar(runtime + " doctor", dir.path());
  EXPECT_EQ(after(doctor.out, "ok    config   "), files[0] + " + " + files[1] + " + " + files[2] + " (--config)")
      << doctor.out << doctor.err;

  // What the runtime gets from the three: the profile's keys, the tip, the registration near the truth.
  auto s = platform::load_settings(files);
  ASSERT_TRUE(s) << s.error();
  EXPECT_EQ(s->render.point_size_px, 3.0);
  const auto& tip = s->trackers().stylus.tip_offset_mm;
  EXPECT_LT((Eigen::Vector3d(tip[0], tip[1], tip[2]) - stylus.tip).norm(), 0.3);
  EXPECT_LT(Eigen::Vector3d(s->registration.translation_mm.data()).norm(), 1.0);
}
