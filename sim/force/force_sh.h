/// @file force_sh.h
/// @brief The applied force's SH coefficients per lung for the current orientation, in both modes:
///        exact (linear in g, docs/design.md "Applied force") and the paper's eq. (8)-(9) interpolation. Cheap,
///        no allocation.
#pragma once

#include <array>

#include <Eigen/Core>

#include "config/base/enum_names.h"
#include "sim/asset/baked_asset.h"
#include "sim/force/gravity.h"
#include "sim/patient/patient_state.h"

namespace lungar::sim {

enum class ForceMode { Exact, Paper };
/// The names TOML, the command line and logs give the modes.
inline constexpr EnumNames<ForceMode, 2> kForceModeNames{
    {{{ForceMode::Exact, "exact"}, {ForceMode::Paper, "paper_interp"}}}};
inline const char* to_string(ForceMode v) { return kForceModeNames.name(v); }

/// The paper's rotation angles a, b, c about X, Y, Z in [0, 2 pi), with R = Rz(c) Ry(b) Rx(a).
struct EulerXYZ {
  double a = 0, b = 0, c = 0;
};
EulerXYZ euler_xyz(const Eigen::Quaterniond& lung_in_world);

/// Exact mode: f(g) = (p0 f0 + gamma g.f) * 1000 / (p0 v0 + gamma g.v), L^2 values into out: the force SH of
/// one mL of swept volume, so that D = sum_lm f_lm T^I_lm is in mm per mL: f0 and f are the baked lung's, v0 and
/// v the lung's now (`now`). A lung with ARDS (LungState::collapse) takes its collapsed pattern's SH instead, and
/// linear_weights and swept_volume_mm3 follow it (sim/force/dependent_collapse.h).
void force_sh_exact(const BakedAsset& asset, const BakedLung& lung, const LungState& now, const Eigen::Vector3d& g_lung,
                    float* out);

/// Paper mode, eq. (8)-(9) as written: f = f^a + f^b + f^c, f^a = [p^{a0} cos(a - a0) + p^{a1} cos(a - a1)] / 3,
/// with a0, a1 the baked angles (pi/2, pi, 3pi/2, 2pi) around a (0 counts as 2pi).
void force_sh_paper(const BakedLung& lung, std::uint32_t coefficients, const Eigen::Quaterniond& lung_in_world, float* out);

/// Both lungs' force SH (lungs x L^2 values, lung-major) in the selected mode, for the patient as `patient` is now.
void force_sh(const BakedAsset& asset, const PatientState& patient, ForceMode mode,
              const Eigen::Quaterniond& lung_in_world, float* out);

/// The weights of the linear basis for g, mm per mL per unit of tau: (p0, gamma g_x, gamma g_y, gamma g_z) *
/// 1000 / V(g). D = w . tau is the exact linear displacement along e_I; r . w the off-axis part.
std::array<float, 4> linear_weights(const BakedAsset& asset, const LungState& lung, const Eigen::Vector3d& g_lung);

/// The swept volume (mm^3) that the unnormalised force produces for g: p0 v0 + gamma g.v.
double swept_volume_mm3(const BakedAsset& asset, const LungState& lung, const Eigen::Vector3d& g_lung);

}  // namespace lungar::sim
