/// @file pathology_test_support.h
/// @brief What the pathology, ARDS, lung-shape and breath-share suites share: gravity in each posture, the sliding
///        bake with pathologies applied, a lung found by name, and what a breath of an asset does to each lung. One definition here, since the suites are
///        compiled in unity batches where two files' own copies would clash.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <span>
#include <string>
#include <vector>

#include "sim/mesh/tri_mesh.h"
#include "sim/motion/motion_figures.h"
#include "sim/pathology/pathology.h"
#include "sim_test_support.h"

namespace lungar::sim::test {

/// Gravity in the patient's frame (LPS): lying on the back it points to the posterior (+y), prone to the anterior,
/// on the left side to the left (+x), upright to the feet (-z).
inline const Eigen::Vector3d kSupine(0, 1, 0), kProne(0, -1, 0), kLeftSideDown(1, 0, 0), kRightSideDown(-1, 0, 0),
    kUpright(0, 0, -1);

/// The pathology models' figures (the plug-ins' own constants, sim/pathology/<name>.cpp), as the tests expect them:
/// a collapsed lung's weight in the split, a tension pneumothorax's shift, a consolidated region's response and its
/// ramp (a share of the height), an emphysema's larger rest at severity 1.
inline constexpr double kCollapsedLungBreathWeight = 0.05, kTensionShiftMm = 20.0, kConsolidatedResponse = 0.1,
                        kConsolidationRamp = 0.05, kEmphysemaFrcGain = 0.4;

/// An asset as lungar loads one, with the patient its pathologies make (sim/patient/patient_state.h). A test
/// hands both to what it measures; a Sick is not converted back to a bare asset, whose patient would be healthy.
struct Sick : BakedAsset {
  PatientState patient;
};

/// `a` with `specs` applied (a failed spec fails the test that asked).
inline Sick sick(const BakedAsset& a, const std::vector<std::string>& specs) {
  Sick out{a, PatientState::of(a)};
  const Status s = apply_pathologies(out, out.patient, specs);
  EXPECT_TRUE(s) << s.error();
  return out;
}

/// The sliding bake with `specs` applied.
inline Sick with(const std::vector<std::string>& specs) { return sick(sliding_asset(), specs); }

/// The index of the lung called `name` (0, with a failure, when there is none).
inline std::size_t index_of(const BakedAsset& a, const std::string& name) {
  for (std::size_t l = 0; l < a.lungs.size(); ++l)
    if (a.lungs[l].name == name) return l;
  ADD_FAILURE() << "no lung named " << name;
  return 0;
}

/// How far `map` (a lung's shape as a map of its loaded one, sim/pathology/lung_shapes.h) puts the worst of `lung`'s
/// vertices from where `changed` has it, mm: every vertex, not only those a fit used.
inline double worst_map_error(const BakedAsset& loaded, const BakedAsset& changed, const Eigen::Affine3d& map,
                              const BakedLung& lung) {
  double worst = 0;
  for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i) {
    const Eigen::Vector3d p(loaded.positions[3 * i], loaded.positions[3 * i + 1], loaded.positions[3 * i + 2]);
    const Eigen::Vector3d q(changed.positions[3 * i], changed.positions[3 * i + 1], changed.positions[3 * i + 2]);
    worst = std::max(worst, (map * p - q).norm());
  }
  return worst;
}

/// A lung's triangles in the asset's index array.
inline std::span<const std::uint32_t> triangles_of(const BakedAsset& a, const BakedLung& lung) {
  return {a.triangles.data() + lung.first_index, lung.index_count};
}

/// What a user reads from the asset breathing `ml` supine: each lung's rest volume and volume change (mL), and the
/// volume each third of a lung's height sweeps (mL; triangles by their rest height, swept volume = area vector
/// times mean displacement).
struct Breath {
  std::vector<double> rest_ml, change_ml;
  std::vector<std::array<double, 3>> thirds_ml;
};

inline Breath breathe(const Sick& a, double ml) {
  const std::vector<float> d = displacement_vectors(a, a.patient, kSupine, ml);
  std::vector<float> moved(a.positions.size());
  for (std::size_t i = 0; i < moved.size(); ++i) moved[i] = a.positions[i] + d[i];
  Breath b;
  for (const BakedLung& lung : a.lungs) {
    const auto tris = triangles_of(a, lung);
    const double rest = enclosed_volume(tris, a.positions.data());
    b.rest_ml.push_back(rest / 1000.0);
    b.change_ml.push_back((enclosed_volume(tris, moved.data()) - rest) / 1000.0);
    double lo = 1e300, hi = -1e300;
    for (std::uint32_t v : tris) {
      lo = std::min(lo, double{a.positions[3 * v + 2]});
      hi = std::max(hi, double{a.positions[3 * v + 2]});
    }
    std::array<double, 3> thirds{};
    for (std::size_t t = 0; t + 2 < tris.size(); t += 3) {
      Eigen::Vector3d p[3], mean_d = Eigen::Vector3d::Zero();
      for (int k = 0; k < 3; ++k) {
        p[k] = Eigen::Vector3d(a.positions[3 * tris[t + k]], a.positions[3 * tris[t + k] + 1],
                               a.positions[3 * tris[t + k] + 2]);
        mean_d += Eigen::Vector3d(d[3 * tris[t + k]], d[3 * tris[t + k] + 1], d[3 * tris[t + k] + 2]) / 3.0;
      }
      const double z = (p[0].z() + p[1].z() + p[2].z()) / 3.0;
      const int third = std::min(2, static_cast<int>(3.0 * (z - lo) / (hi - lo)));
      thirds[third] += 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).dot(mean_d) / 1000.0;
    }
    b.thirds_ml.push_back(thirds);
  }
  return b;
}

}  // namespace lungar::sim::test
