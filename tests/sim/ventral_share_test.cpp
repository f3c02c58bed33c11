/// @file ventral_share_test.cpp
/// @brief The ventral share folded from the force SH (what the runtime reports) against the same sum taken vertex by
///        vertex over the displaced surface, and its direction: prone, the front of the lungs takes more.
#include <gtest/gtest.h>

#include <vector>

#include "pathology_test_support.h"
#include "sim/force/force_sh.h"
#include "sim/motion/motion_figures.h"
#include "sim/motion/ventral_share.h"
#include "sim/pathology/pathology.h"
#include "sim_test_support.h"

namespace lungar::sim {
namespace {

/// The anterior half's first-order swept volume over the whole pair's, vertex by vertex from the displacement.
double ventral_by_vertex(const BakedAsset& a, const PatientState& patient, const Eigen::Vector3d& g) {
  const std::vector<float> d = displacement_vectors(a, patient, g, 500);
  double lo = 1e300, hi = -1e300;
  for (std::size_t i = 0; i < a.vertex_count(); ++i) {
    lo = std::min(lo, double{a.positions[3 * i + 1]});
    hi = std::max(hi, double{a.positions[3 * i + 1]});
  }
  double front = 0, all = 0;
  for (std::size_t i = 0; i < a.vertex_count(); ++i) {
    const double swept = a.areas[i] * (a.normals[3 * i] * d[3 * i] + a.normals[3 * i + 1] * d[3 * i + 1] +
                                       a.normals[3 * i + 2] * d[3 * i + 2]);
    all += swept;
    if (a.positions[3 * i + 1] < 0.5 * (lo + hi)) front += swept;
  }
  return front / all;
}

double ventral_folded(const BakedAsset& a, const PatientState& patient, const Eigen::Vector3d& g) {
  const std::uint32_t c = a.coefficients();
  std::vector<float> force(a.lungs.size() * c);
  for (std::size_t l = 0; l < a.lungs.size(); ++l)
    force_sh_exact(a, a.lungs[l], patient.lungs[l], g, force.data() + l * c);
  return VentralShare(a).share(a, patient, force, g);
}

TEST(VentralShare, FoldedFromTheForceItIsTheVertexSumAndProneRaisesIt) {
  const test::Sick a = test::with({});
  const Eigen::Vector3d supine(0, 1, 0), prone(0, -1, 0), left_down(1, 0, 0);
  for (const Eigen::Vector3d& g : {supine, prone, left_down})
    EXPECT_NEAR(ventral_folded(a, a.patient, g), ventral_by_vertex(a, a.patient, g), 1e-4) << g.transpose();
  EXPECT_GT(ventral_folded(a, a.patient, prone), ventral_folded(a, a.patient, supine) + 0.03);
  // A pathology changes the rows and the split: the fold still matches the vertex sum.
  const test::Sick sick = test::with({"consolidation:right:lower", "pneumothorax:left:20"});
  EXPECT_NEAR(ventral_folded(sick, sick.patient, supine), ventral_by_vertex(sick, sick.patient, supine), 1e-4);
}

}  // namespace
}  // namespace lungar::sim
