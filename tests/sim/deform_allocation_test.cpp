/// @file deform_allocation_test.cpp
/// @brief The per-frame calls (force SH in both modes, CPU eq. 7, CPU eq. 1) allocate nothing through operator
///        new. Counted by replacing the global operator new in this test binary; skipped under AddressSanitizer,
///        which owns operator new there. (Eigen's own heap use goes through malloc; the products used here are
///        matrix-vector products into mapped buffers, which Eigen evaluates without temporaries.)
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "pathology_test_support.h"
#include "sim/deform/deform_eq1.h"
#include "sim/deform/deform_eq7.h"
#include "sim/force/force_sh.h"
#include "sim_test_support.h"

#include "allocation_counter.h"

namespace lungar::sim {
namespace {

TEST(Allocation, PerFrameDeformationAllocatesNothing) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "operator new belongs to AddressSanitizer in this build";
#else
  const BakedAsset& a = test::small_asset();
  std::vector<float> force(a.lungs.size() * a.coefficients()), positions(3 * a.vertex_count());
  Eq1Deformer eq1(a);
  PatientState patient = PatientState::of(a);
  const PatientState sick = test::sick(a, {"pneumothorax:right:30:tension", "consolidation:left:lower"}).patient;
  const long before = lungar::testing::g_allocations.load();
  for (int frame = 0; frame < 20; ++frame) {
    const Eigen::Quaterniond q = axis_rotation(frame % 3, 0.1 * frame);
    // The runtime's follow_course: a course's state copied into the patient in place.
    for (std::size_t l = 0; l < patient.lungs.size(); ++l) patient.lungs[l] = sick.lungs[l];
    force_sh(a, patient, ForceMode::Exact, q, force.data());
    force_sh(a, patient, ForceMode::Paper, q, force.data());
    deform_eq7(a, patient, force, gravity_in_lung_frame(q), 10.0 * frame, positions);
    eq1.deform(patient, gravity_in_lung_frame(q), 10.0 * frame, positions);
  }
  EXPECT_EQ(lungar::testing::g_allocations.load() - before, 0);
#endif
}

}  // namespace
}  // namespace lungar::sim
