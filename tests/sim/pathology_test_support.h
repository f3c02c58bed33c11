/// @file pathology_test_support.h
/// @brief What the pathology, ARDS, lung-shape and breath-share suites share: gravity in each posture, the sliding
///        bake with pathologies applied, and a lung found by name. One definition here, since the suites are
///        compiled in unity batches where two files' own copies would clash.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <string>
#include <vector>

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

/// The sliding bake with `specs` applied (a failed spec fails the test that asked).
inline BakedAsset with(const std::vector<std::string>& specs) {
  BakedAsset a = sliding_asset();
  const Status s = apply_pathologies(a, specs);
  EXPECT_TRUE(s) << s.error();
  return a;
}

/// The index of the lung called `name` (0, with a failure, when there is none).
inline std::size_t index_of(const BakedAsset& a, const std::string& name) {
  for (std::size_t l = 0; l < a.lungs.size(); ++l)
    if (a.lungs[l].name == name) return l;
  ADD_FAILURE() << "no lung named " << name;
  return 0;
}

}  // namespace lungar::sim::test
