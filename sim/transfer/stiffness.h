/// @file stiffness.h
/// @brief The stiffness K = L_E + diag(kappa) of stage 2 (docs/design.md, "Transfer matrix"): its inverse is the
///        transfer matrix T.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "sim/mesh/tri_mesh.h"

namespace lungar::sim {

/// Apex-to-base stiffness ratio of the regional expandability model: alveoli at the apex are already more
/// expanded, so the tissue there is stiffer (E_apex = ratio * E_base, linear in height in between).
inline constexpr double kApexBaseStiffnessRatio = 2.0;

/// Young's modulus E_I (relative units: only ratios matter after the volume normalisation), linear in the
/// vertex's height z between the lung's lowest (1) and highest (kApexBaseStiffnessRatio) point.
Eigen::VectorXd youngs_modulus(const TriMesh& mesh);

/// K: edge weights (E_I + E_J) / 2 / |x_I - x_J| (graph Laplacian L_E) plus the chest-wall tether
/// kappa_I = E_I A_I / l^2 on the diagonal. Symmetric positive definite for any connected mesh.
Eigen::SparseMatrix<double> stiffness_matrix(const TriMesh& mesh, const Eigen::VectorXd& youngs,
                                             const std::vector<double>& areas, double decay_length_mm);

}  // namespace lungar::sim
