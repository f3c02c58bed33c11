/// @file ards_test.cpp
/// @brief ARDS's gravity-dependent collapse (sim/force/dependent_collapse.h) on the procedural sliding pair: where
///        the breath goes supine, prone and on a side, measured from the displaced surface as a user measures an
///        export (scripts/ply-shares), and what the SH carries that the linear basis cannot.
#include <gtest/gtest.h>

#include <cmath>
#include <span>
#include <string>

#include "sim/deform/deform_eq1.h"
#include "sim/force/dependent_collapse.h"
#include "sim/force/force_sh.h"
#include "sim/mesh/tri_mesh.h"
#include "sim/motion/motion_figures.h"
#include "sim/pathology/pathology.h"
#include "pathology_test_support.h"
#include "sim_test_support.h"

namespace lungar::sim {
namespace {

using test::kSupine;
using test::kProne;
using test::kLeftSideDown;
using test::with;



/// Where a breath of `ml` goes with gravity g: each lung's enclosed volume change, and the share of the pair's
/// swept volume the anterior half sweeps (triangles by their rest depth against the middle of the pair's extent in
/// y; anterior is -y), as scripts/ply-shares reads an export.
struct Where {
  std::vector<double> change_ml;
  double ventral_share = 0;
};

Where breathe(const test::Sick& a, const Eigen::Vector3d& g, double ml) {
  const std::vector<float> d = displacement_vectors(a, a.patient, g, ml);
  std::vector<float> moved(a.positions.size());
  for (std::size_t i = 0; i < moved.size(); ++i) moved[i] = a.positions[i] + d[i];
  Where w;
  for (const BakedLung& lung : a.lungs) {
    const std::span<const std::uint32_t> tris(a.triangles.data() + lung.first_index, lung.index_count);
    w.change_ml.push_back((enclosed_volume(tris, moved.data()) - enclosed_volume(tris, a.positions.data())) / 1000.0);
  }
  double lo = 1e300, hi = -1e300;
  for (std::size_t i = 0; i < a.vertex_count(); ++i) {
    lo = std::min(lo, double{a.positions[3 * i + 1]});
    hi = std::max(hi, double{a.positions[3 * i + 1]});
  }
  double front = 0, all = 0;
  for (std::size_t t = 0; t + 2 < a.triangles.size(); t += 3) {
    Eigen::Vector3d p[3], mean_d = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = a.triangles[t + k];
      p[k] = Eigen::Vector3d(a.positions[3 * v], a.positions[3 * v + 1], a.positions[3 * v + 2]);
      mean_d += Eigen::Vector3d(d[3 * v], d[3 * v + 1], d[3 * v + 2]) / 3.0;
    }
    const double swept = 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).dot(mean_d);
    all += swept;
    if ((p[0].y() + p[1].y() + p[2].y()) / 3.0 < 0.5 * (lo + hi)) front += swept;
  }
  w.ventral_share = front / all;
  return w;
}

double total(const Where& w) { return w.change_ml[0] + w.change_ml[1]; }

std::size_t left_of(const BakedAsset& a) { return a.lungs[0].name == "left" ? 0 : 1; }

TEST(Ards, SupineTheBreathMovesVentralAndProneTheDorsalLungTakesItBack) {
  const test::Sick healthy = with({}), ards = with({"ards:0.6"});
  const Where healthy_supine = breathe(healthy, kSupine, 500), supine = breathe(ards, kSupine, 500),
              prone = breathe(ards, kProne, 500);
  EXPECT_GE(supine.ventral_share, healthy_supine.ventral_share + 0.05)
      << "supine the dorsal lung collapses: healthy " << healthy_supine.ventral_share << ", ARDS "
      << supine.ventral_share;
  EXPECT_GE(1.0 - prone.ventral_share, (1.0 - supine.ventral_share) + 0.10)
      << "prone recruits the dorsal lung: dorsal share supine " << 1.0 - supine.ventral_share << ", prone "
      << 1.0 - prone.ventral_share;
  for (const Where* w : {&supine, &prone}) EXPECT_NEAR(total(*w), 500.0, 15.0) << "the breath stays the breath";
}

TEST(Ards, LyingOnASideTheLowerLungCollapsesAndTheUpperTakesMore) {
  const test::Sick healthy = with({}), ards = with({"ards:0.6"});
  const std::size_t left = left_of(healthy);
  const Where before = breathe(healthy, kLeftSideDown, 500), after = breathe(ards, kLeftSideDown, 500);
  EXPECT_LT(after.change_ml[left] / total(after), before.change_ml[left] / total(before) - 0.05)
      << "healthy and awake the lower lung takes more; with ARDS it is the one that collapses";
  EXPECT_NEAR(total(after), 500.0, 15.0);
}

TEST(Ards, ProneCollapsesLessOfTheLungThanSupineAsThePorcineCtShows) {
  const test::Sick ards = with({"ards:0.6"});
  const DependentCollapse& c = *ards.patient.lungs[0].collapse;
  EXPECT_NEAR(c.collapsed_share(kSupine), 0.51, 0.005) << "non- and poorly aerated, supine: 4 + 47 %";
  EXPECT_NEAR(c.collapsed_share(kProne), 0.31, 0.005) << "prone: 1 + 30 %";
  // The plane lies deeper (further along gravity) the less collapses: supine it cuts the back at depth t.
  EXPECT_LT(c.threshold_mm(kSupine), with({"ards:0.2"}).patient.lungs[0].collapse->threshold_mm(kSupine));
}

TEST(Ards, SeverityZeroIsTheHealthyForceWithinTheSamplesFit) {
  const test::Sick healthy = with({}), none = with({"ards:0"});
  for (const Eigen::Vector3d& g : {kSupine, kProne, kLeftSideDown, Eigen::Vector3d(0, 0, -1)}) {
    const std::vector<float> a = displacement_vectors(healthy, healthy.patient, g, 500),
                             b = displacement_vectors(none, none.patient, g, 500);
    double diff = 0, norm = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      diff += (a[i] - b[i]) * (a[i] - b[i]);
      norm += a[i] * a[i];
    }
    EXPECT_LT(std::sqrt(diff / norm), 0.03) << "g " << g.transpose();
  }
}

TEST(Ards, TheShCarriesThePatternWhereTheLinearBasisCannot) {
  const test::Sick ards = with({"ards:0.6"});
  for (const Eigen::Vector3d& g : {kSupine, kProne}) {
    const CollapseFitError e = ards.patient.lungs[0].collapse->fit_error(ards, g);
    EXPECT_LT(e.sh_rms_rel, 0.5 * e.linear_rms_rel) << "SH " << e.sh_rms_rel << ", linear " << e.linear_rms_rel;
    EXPECT_GT(e.linear_rms_rel, 0.15) << "a collapse is not linear in position";
  }
}

TEST(Ards, TheEq1BaselineTakesTheSamePatternAtEachVertex) {
  const test::Sick healthy = with({}), ards = with({"ards:0.6"});
  std::vector<float> healthy_f(ards.vertex_count()), sick_f(ards.vertex_count());
  applied_force(healthy, healthy.patient, kSupine, healthy_f);
  applied_force(ards, ards.patient, kSupine, sick_f);
  const double t = ards.patient.lungs[0].collapse->threshold_mm(kSupine);
  for (const BakedLung& lung : ards.lungs) {
    // Each lung's force is normalised by its own swept volume, so compare deep against shallow within a lung.
    double deep = 0, shallow = 0;
    std::size_t n_deep = 0, n_shallow = 0;
    for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i) {
      const double beyond = ards.positions[3 * i + 1] - t;  // supine: depth along gravity is +y
      const double ratio = sick_f[i] / healthy_f[i];
      if (beyond > kCollapseRampMm) deep += ratio, ++n_deep;
      if (beyond < -kCollapseRampMm) shallow += ratio, ++n_shallow;
    }
    ASSERT_GT(n_deep, 0u) << lung.name;
    ASSERT_GT(n_shallow, 0u) << lung.name;
    EXPECT_NEAR((deep / n_deep) / (shallow / n_shallow), kCollapsedPressure, 1e-3) << lung.name;
  }
}

TEST(Ards, SittingUpOrHeadDownTheBreathStaysTheBreath) {
  // Gravity along the body's axis: the pressure's gradient is along z, which the off-axis part's z column carries,
  // and each lung's swept volume (what its force is scaled by) must count that column for the breath to be 500 mL.
  // Measured: within 6.5 mL of 500 (the healthy pair within 2.3); without the z column 537, 491 and 534 mL.
  const test::Sick ards = with({"ards:0.6"});
  for (const Eigen::Vector3d& g :
       {Eigen::Vector3d(0, 0, -1), Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 0.6, -0.8)}) {
    EXPECT_NEAR(total(breathe(ards, g, 500)), 500.0, 15.0) << "g " << g.transpose();
  }
}

TEST(Ards, WithoutACollapseBothFitsCarryThePressureInEveryPosture) {
  // Severity 0 leaves the healthy pressure, linear in position: the linear fit carries it to rounding, and the SH
  // as closely as the bake's own fit does, whichever way gravity runs through the lungs. Measured: linear 1e-15,
  // SH at most 0.0081 (upright); a fit error that read a vertex's z from the vertex before gave SH 0.20 upright.
  const test::Sick none = with({"ards:0"});
  for (const Eigen::Vector3d& g :
       {kSupine, kProne, kLeftSideDown, Eigen::Vector3d(0, 0, -1), Eigen::Vector3d(0, 0, 1)}) {
    const CollapseFitError e = none.patient.lungs[0].collapse->fit_error(none, g);
    EXPECT_LT(e.linear_rms_rel, 1e-4) << "g " << g.transpose();
    EXPECT_LT(e.sh_rms_rel, 0.05) << "g " << g.transpose();
  }
}

TEST(Ards, ALungWithFewerVerticesThanTheFitHasUnknownsIsRefused) {
  // The fit solves for L^2 SH coefficients and 4 linear weights: a lung needs that many samples at the least.
  BakedAsset a = test::sliding_asset();
  const std::uint32_t unknowns = a.coefficients() + 4;
  a.lungs[0].vertex_count = unknowns - 1;
  const auto few = DependentCollapse::build(a, 0.6);
  ASSERT_FALSE(few);
  EXPECT_NE(few.error().find("'" + a.lungs[0].name + "' has too few vertices"), std::string::npos) << few.error();
}

TEST(Ards, AnAssetWithoutSpherePointsIsRefusedWithWhatToDo) {
  BakedAsset old = test::sliding_asset();
  old.sphere_dirs.clear();
  PatientState old_patient = PatientState::of(old);
  const Status s = apply_pathologies(old, old_patient, {"ards:0.5"});
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().find("'ards:0.5'"), std::string::npos) << s.error();
  EXPECT_NE(s.error().find("re-bake"), std::string::npos) << s.error();
  BakedAsset twice = test::sliding_asset();
  PatientState twice_patient = PatientState::of(twice);
  const Status s2 = apply_pathologies(twice, twice_patient, {"ards:0.5", "ards:0.2"});
  ASSERT_FALSE(s2);
  EXPECT_NE(s2.error().find("twice"), std::string::npos) << s2.error();
}

}  // namespace
}  // namespace lungar::sim
