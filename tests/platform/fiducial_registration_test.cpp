// Calibration on synthetic fiducials with a known transform and noise: the recovered transform and the reported
// fiducial registration error must match what was put in.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "platform/app/settings_load.h"
#include "platform/registration/fiducial_registration.h"
#include "platform/registration/landmark_matching.h"
#include "tests/partial_files.h"

using lungar::platform::Registration;

namespace {

struct Synthetic {
  std::vector<Eigen::Vector3d> model, tracked;
  Eigen::Quaterniond q;
  Eigen::Vector3d t;
};

Synthetic make(int n, double noise_mm, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-150.0, 150.0);
  std::normal_distribution<double> noise(0.0, noise_mm);
  Synthetic s;
  s.q = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.3, -0.5, 0.8).normalized()));
  s.t = Eigen::Vector3d(120.0, -35.0, 910.0);
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector3d m(u(rng), u(rng), u(rng));
    s.model.push_back(m);
    s.tracked.push_back(s.q * m + s.t + Eigen::Vector3d(noise(rng), noise(rng), noise(rng)));
  }
  return s;
}

}  // namespace

TEST(FiducialRegistration, RecoversAnExactTransform) {
  const Synthetic s = make(6, 0.0, 1);
  auto fitted = lungar::platform::register_fiducials(s.model, s.tracked);
  ASSERT_TRUE(fitted) << fitted.error();
  const Registration& r = *fitted;
  EXPECT_LT(r.rotation.angularDistance(s.q), 1e-9);
  EXPECT_LT((r.translation_mm - s.t).norm(), 1e-8);
  EXPECT_LT(r.fre_rms_mm, 1e-8);
  EXPECT_EQ(r.fiducials, 6);
}

// Three points not on a line fix a rigid transform: the fewest the registration takes.
TEST(FiducialRegistration, ThreeExactPointsAreEnough) {
  const Synthetic s = make(3, 0.0, 2);
  auto fitted = lungar::platform::register_fiducials(s.model, s.tracked);
  ASSERT_TRUE(fitted) << fitted.error();
  EXPECT_LT(fitted->rotation.angularDistance(s.q), 1e-9);
  EXPECT_LT((fitted->translation_mm - s.t).norm(), 1e-8);
  EXPECT_EQ(fitted->fiducials, 3);
}

TEST(FiducialRegistration, NoisyFiducialsGiveTheExpectedErrorAndAClosedTransform) {
  // Fitzpatrick et al. 1998: E[FRE^2] = (1 - 2/N) E[FLE^2] for a rigid fit in 3-D; FLE^2 = 3 sigma^2.
  const double sigma = 0.5;
  const int n = 200;
  const Synthetic s = make(n, sigma, 7);
  auto fitted = lungar::platform::register_fiducials(s.model, s.tracked);
  ASSERT_TRUE(fitted) << fitted.error();
  const Registration& r = *fitted;
  const double expected_fre = std::sqrt((1.0 - 2.0 / n) * 3.0 * sigma * sigma);
  EXPECT_NEAR(r.fre_rms_mm, expected_fre, 0.1 * expected_fre);
  EXPECT_GT(r.fre_max_mm, r.fre_rms_mm);
  EXPECT_LT(r.rotation.angularDistance(s.q), 0.2 * M_PI / 180.0);  // radians
  EXPECT_LT((r.translation_mm - s.t).norm(), 0.3);                  // mm
}

TEST(FiducialRegistration, RejectsDegenerateInput) {
  using lungar::platform::register_fiducials;
  const std::vector<Eigen::Vector3d> two = {{0, 0, 0}, {1, 0, 0}};
  EXPECT_EQ(register_fiducials(two, two).error(), "fiducials: expected at least 3 point pairs, got 2");
  const std::vector<Eigen::Vector3d> line = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {5, 0, 0}};
  EXPECT_EQ(register_fiducials(line, line).error(),
            "fiducials: expected model points spanning a plane, got collinear points");
  const std::vector<Eigen::Vector3d> three = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_EQ(register_fiducials(three, line).error(),
            "fiducials: expected as many tracked points as model points, got 4 tracked and 3 model points");
}

TEST(FiducialRegistration, StylusDwellsBecomeFiducialsInOrder) {
  std::vector<lungar::platform::StylusSample> samples;
  std::mt19937 rng(3);
  std::normal_distribution<double> jitter(0.0, 0.1);
  const std::vector<Eigen::Vector3d> touches = {{10, 0, 0}, {0, 50, 0}, {0, 0, 90}};
  double t = 0;
  for (const auto& p : touches) {
    for (int k = 0; k < 60; ++k, t += 0.016) {  // ~1 s held still
      samples.push_back({t, p + Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng))});
    }
    for (int k = 0; k < 10; ++k, t += 0.016) {  // moving to the next landmark: too short to count
      samples.push_back({t, Eigen::Vector3d(200.0 + 30.0 * k, -100.0, 5.0 * k)});
    }
  }
  const auto found = lungar::platform::find_dwells(samples);
  ASSERT_EQ(found.size(), touches.size());
  for (std::size_t k = 0; k < touches.size(); ++k) {
    EXPECT_LT((found[k].position_mm - touches[k]).norm(), 0.1) << k;
    EXPECT_NEAR(found[k].duration_s, 59 * 0.016, 1e-9) << k;
  }
}

TEST(FiducialRegistration, PointsFileErrorsNameTheLine) {
  const auto path = (std::filesystem::temp_directory_path() / "lungar_fiducials_test.csv").string();
  std::ofstream(path) << "# model fiducials\n1, 2, 3\n4, 5\n";
  EXPECT_EQ(lungar::platform::read_points_csv(path).error(),
            path + ":3: expected three finite numbers x, y, z (mm), got '4  5'");
  std::ofstream(path) << "1, 2, 3\n4, 5, 6 # a comment\n\n7,8,9\n";
  auto points = lungar::platform::read_points_csv(path);
  ASSERT_TRUE(points) << points.error();
  ASSERT_EQ(points->size(), 3u);
  EXPECT_EQ((*points)[2], Eigen::Vector3d(7, 8, 9));
  std::filesystem::remove(path);
}

TEST(FiducialRegistration, WrittenSectionLoadsAsTheSameRegistration) {
  const Synthetic s = make(8, 0.2, 11);
  auto fitted = lungar::platform::register_fiducials(s.model, s.tracked);
  ASSERT_TRUE(fitted) << fitted.error();
  const Registration& r = *fitted;
  const auto path = (std::filesystem::temp_directory_path() / "lungar_registration_test.toml").string();
  const lungar::Status written = lungar::platform::write_registration_toml(path, r);
  ASSERT_TRUE(written) << written.error();
  EXPECT_EQ(lungar::testing::partial_files_beside(path), std::vector<std::string>{});
  const auto loaded = lungar::platform::load_settings(path);
  ASSERT_TRUE(loaded) << loaded.error();
  const auto& q = loaded->registration.rotation_wxyz;
  const auto& t = loaded->registration.translation_mm;
  EXPECT_LT(Eigen::Quaterniond(q[0], q[1], q[2], q[3]).angularDistance(r.rotation), 1e-8);
  EXPECT_LT((Eigen::Vector3d(t[0], t[1], t[2]) - r.translation_mm).norm(), 1e-5);
  std::filesystem::remove(path);
}
