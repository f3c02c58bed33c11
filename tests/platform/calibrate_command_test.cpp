// `lungar calibrate` from a tracker log: a stylus dwelling on each fiducial of a patient simulator that sits at a
// known pose, recorded as raw reports; the recovered model -> patient-tracker transform and its error must match.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "drivers/decode/encoder.h"
#include "drivers/decode/report_layout.h"
#include "drivers/tracker/tracker_config_toml.h"
#include "drivers/trk/trk_writer.h"
#include "platform/app/calibrate_command.h"

using namespace lungar;

TEST(CalibrateFromLog, StylusDwellsInALogGiveTheKnownRegistration) {
  drivers::TrackerConfig t;
  t.stylus.enabled = true;
  auto layout = drivers::make_layout(t);
  ASSERT_TRUE(layout) << layout.error();

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
  drivers::TrkWriter writer;
  drivers::TrkHeader header;
  header.description = "source=test";
  header.layout_toml = drivers::tracker_config_to_toml(t);
  ASSERT_EQ(writer.open(log_path, header, drivers::TrkWriter::Mode::Atomic).error(), "");

  std::mt19937 rng(5);
  std::normal_distribution<double> tip_noise(0.0, 0.2);  // mm: a steady hand on a landmark
  std::vector<std::uint8_t> report(static_cast<std::size_t>(t.report.length));
  std::int64_t t_ns = 1'000'000'000;
  std::uint32_t ticks = 0;
  auto emit = [&](drivers::Role role, const Eigen::Vector3d& p, const Eigen::Quaterniond& q) {
    drivers::PoseSample pose;
    pose.role = role;
    pose.set_position(p);
    pose.set_orientation(q);
    std::fill(report.begin(), report.end(), 0);
    ASSERT_TRUE(drivers::encode_report(*layout, std::span(&pose, 1), ticks, report));
    ASSERT_TRUE(writer.append(drivers::TrkSource::Hid, t_ns, report));
  };
  for (const auto& m : model) {
    const Eigen::Vector3d world = patient_q * (reg_q * m + reg_t) + patient_p;
    for (int k = 0; k < 50; ++k, t_ns += 16'000'000, ticks += 16000) {  // 0.8 s held on the landmark
      emit(drivers::Role::Patient, patient_p, patient_q);
      emit(drivers::Role::Stylus, world + Eigen::Vector3d(tip_noise(rng), tip_noise(rng), tip_noise(rng)),
           Eigen::Quaterniond::Identity());
    }
    for (int k = 0; k < 10; ++k, t_ns += 16'000'000, ticks += 16000) {  // moving on: too short to count
      emit(drivers::Role::Stylus, world + Eigen::Vector3d(0, 0, 30.0 * (k + 1)), Eigen::Quaterniond::Identity());
    }
  }
  ASSERT_EQ(writer.commit().error(), "");

  auto touched = platform::stylus_points_from_log(log_path, "");
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
  {
    std::ofstream o(model_csv);
    for (const auto& m : model) o << m.x() << ", " << m.y() << ", " << m.z() << "\n";
  }
  platform::CalibrateOptions o;
  o.model_csv = model_csv.string();
  o.stylus_log = log_path;
  o.out_path = (dir / "registration.toml").string();
  EXPECT_EQ(platform::run_calibrate(o), 0);
  EXPECT_TRUE(std::filesystem::exists(o.out_path));
  o.stylus_log = std::string(LUNGAR_SOURCE_DIR) + "/tests/data/upright_to_supine.trk";
  o.out_path = (dir / "none.toml").string();
  EXPECT_EQ(platform::run_calibrate(o), 2);
  EXPECT_FALSE(std::filesystem::exists(o.out_path));
  std::filesystem::remove_all(dir);
}
