/// @file breath_share_test.cpp
/// @brief The posture's split of the breath between the lungs: the model on its own (EIT's lateral decubitus
///        figures, shares summing to one, side by side across gravity), then through the deformation of a baked
///        pair, measured as each lung's enclosed volume change.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "sim/force/breath_share.h"
#include "sim/mesh/tri_mesh.h"
#include "sim/motion/motion_figures.h"
#include "pathology_test_support.h"
#include "sim_test_support.h"

namespace lungar::sim {
namespace {

using test::kLeftSideDown;
using test::kRightSideDown;
using test::kSupine;
using test::kUpright;
using test::index_of;

/// Gravity in the lung frame (LPS, +x the patient's left): lying on the left side, on the right side, on the back.

/// Two lungs placed like the CT demo's: the left one smaller (47 % of the rest volume), a hand's width apart.
BakedAsset demo_like_pair() {
  BakedAsset a;
  BakedLung left, right;
  left.name = "left";
  left.centre = {95.f, 5.f, 10.f};
  left.volume_share = 0.47;
  right.name = "right";
  right.centre = {-90.f, 0.f, 0.f};
  right.volume_share = 0.53;
  a.lungs = {left, right};
  return a;
}

/// Lung l's share for the healthy patient of `a` (its baked figures as they are).
double healthy_share(const BakedAsset& a, std::size_t l, const Eigen::Vector3d& g) {
  return breath_share(a, PatientState::of(a), l, g);
}

TEST(BreathShare, TheDependentLungTakesWhatEitMeasuresLyingOnEitherSide) {
  const BakedAsset a = demo_like_pair();
  const double left_down = healthy_share(a, 0, kLeftSideDown);
  const double right_down = healthy_share(a, 1, kRightSideDown);
  // Volk et al. 2011: 57.6 % left side down, 64.7 % right side down (awake, spontaneous breathing).
  EXPECT_GE(left_down, 0.55);
  EXPECT_LE(left_down, 0.62);
  EXPECT_GE(right_down, 0.60);
  EXPECT_LE(right_down, 0.70);
  EXPECT_GT(right_down, left_down) << "the larger right lung gains more when it is the lower one";
  EXPECT_NEAR(healthy_share(a, 1, kLeftSideDown), 1.0 - left_down, 1e-12) << "the upper lung takes the rest";
}

TEST(BreathShare, SideBySideAcrossGravityTheSplitIsTheRestVolumes) {
  BakedAsset a = demo_like_pair();
  a.lungs[0].centre = {95.f, 0.f, 0.f};
  a.lungs[1].centre = {-90.f, 0.f, 0.f};
  for (const Eigen::Vector3d& g : {kSupine, Eigen::Vector3d(-kSupine), kUpright}) {
    EXPECT_NEAR(healthy_share(a, 0, g), 0.47, 1e-12) << "g = " << g.transpose();
    EXPECT_NEAR(healthy_share(a, 1, g), 0.53, 1e-12) << "g = " << g.transpose();
  }
}

TEST(BreathShare, SharesSumToOneInEveryDirectionAndFallBackWithoutGravity) {
  const BakedAsset a = demo_like_pair();
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j)
      for (int k = -1; k <= 1; ++k) {
        const Eigen::Vector3d g(i, j, k);
        const double sum = healthy_share(a, 0, g) + healthy_share(a, 1, g);
        EXPECT_NEAR(sum, 1.0, 1e-12) << "g = " << g.transpose();
      }
  EXPECT_DOUBLE_EQ(healthy_share(a, 0, Eigen::Vector3d::Zero()), 0.47);
  EXPECT_DOUBLE_EQ(healthy_share(a, 0, Eigen::Vector3d(NAN, 0, 0)), 0.47);
  BakedAsset one = a;
  one.lungs.resize(1);
  one.lungs[0].volume_share = 1.0;
  EXPECT_DOUBLE_EQ(healthy_share(one, 0, kLeftSideDown), 1.0);
}

TEST(BreathShare, SharesThatSumToLessThanOneKeepTheirProportions) {
  // The pair's centre is volume-weighted whatever the shares add up to (a file's rounded shares need not sum to 1):
  // halving every share halves each lung's answer and leaves the posture's split as it was.
  const BakedAsset a = demo_like_pair();
  BakedAsset half = a;
  for (BakedLung& l : half.lungs) l.volume_share *= 0.5;
  for (const Eigen::Vector3d& g : {kLeftSideDown, kRightSideDown, Eigen::Vector3d(0.6, 0.3, -0.7)})
    for (std::size_t l = 0; l < 2; ++l)
      EXPECT_NEAR(healthy_share(half, l, g), 0.5 * healthy_share(a, l, g), 1e-12)
          << "lung " << l << ", g " << g.transpose();
}

TEST(BreathShare, ALungWhosePathologyLeftItsResponseAsItWasTakesItsHealthyShareInEveryPosture) {
  // V(g) = p0 v0 + gamma g.v for both lungs; the left lung's healthy volumes are recorded, unchanged: its
  // V / V_healthy is 1 in every posture, with gravity along any axis, and the split is the healthy pair's.
  BakedAsset healthy = demo_like_pair();
  healthy.p0 = 10.0;
  healthy.gamma_per_mm = 0.025;
  for (BakedLung& l : healthy.lungs) {
    l.volume_const = 2.0e5;
    l.volume_grad = {3.0e6, -2.0e6, 4.0e6};
  }
  PatientState recorded = PatientState::of(healthy);
  const BakedLung& left = healthy.lungs[0];
  recorded.lungs[0].healthy_volumes =
      std::array<double, 4>{left.volume_const, left.volume_grad[0], left.volume_grad[1], left.volume_grad[2]};
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j)
      for (int k = -1; k <= 1; ++k) {
        const Eigen::Vector3d g(i, j, k);
        EXPECT_NEAR(breath_share(healthy, recorded, 0, g), healthy_share(healthy, 0, g), 1e-12)
            << "g = " << g.transpose();
      }
  // Recorded larger than now (a response a pathology halved), the lung takes less in every posture.
  recorded.lungs[0].volume_const *= 0.5;
  for (double& v : recorded.lungs[0].volume_grad) v *= 0.5;
  EXPECT_LT(breath_share(healthy, recorded, 0, kSupine), healthy_share(healthy, 0, kSupine) - 0.1);
}

/// Each lung's enclosed volume change, mL, when the baked pair breathes 500 mL with gravity g.
std::vector<double> lung_volume_changes(const BakedAsset& a, const Eigen::Vector3d& g) {
  const std::vector<float> d = displacement_vectors(a, PatientState::of(a), g, 500);
  std::vector<float> moved(a.positions.size());
  for (std::size_t i = 0; i < moved.size(); ++i) moved[i] = a.positions[i] + d[i];
  std::vector<double> out;
  for (const BakedLung& lung : a.lungs) {
    const std::span<const std::uint32_t> tris(a.triangles.data() + lung.first_index, lung.index_count);
    out.push_back((enclosed_volume(tris, moved.data()) - enclosed_volume(tris, a.positions.data())) / 1000.0);
  }
  return out;
}

TEST(BreathShare, TheBakedPairBreathesIntoItsLowerLungAndKeepsTheTidalVolume) {
  const BakedAsset& a = test::sliding_asset();
  ASSERT_EQ(a.lungs.size(), 2u);
  const std::size_t left = index_of(a, "left"), right = index_of(a, "right");
  const std::vector<double> left_down = lung_volume_changes(a, kLeftSideDown);
  const std::vector<double> right_down = lung_volume_changes(a, kRightSideDown);
  const std::vector<double> supine = lung_volume_changes(a, kSupine);
  for (const auto* v : {&left_down, &right_down, &supine}) EXPECT_NEAR((*v)[0] + (*v)[1], 500.0, 10.0);
  EXPECT_GE(left_down[left] / 500.0, a.lungs[left].volume_share + 0.08) << "left side down, the left lung gains";
  EXPECT_GE(right_down[right] / 500.0, a.lungs[right].volume_share + 0.08) << "right side down, the right lung gains";
  EXPECT_NEAR(supine[left] / 500.0, healthy_share(a, left, kSupine), 0.02);
  EXPECT_NEAR(healthy_share(a, left, kSupine), a.lungs[left].volume_share, 0.03) << "on the back, about the volumes";
}

}  // namespace
}  // namespace lungar::sim
