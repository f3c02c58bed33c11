/// @file motion_fields.h
/// @brief One lung's stiffness and exact solves under either motion model (internal to sim/bake): the per-vertex
///        SH coefficient fields T_lm and the linear basis, both along each vertex's direction of motion e_I.
#pragma once

#include <Eigen/SparseCore>

#include "sim/bake/bake.h"
#include "sim/bake/lung_bake.h"

namespace lungar::sim {

/// The faces of w's surface (sim/motion/surface_regions.h), the same under either model.
std::vector<SurfaceRegion> surface_regions(const LungWork& w, const BakeOptions& opt);

/// K for `model` on w's faces (w.regions): the paper's tether everywhere, or the sliding model's per face, whose
/// drive directions b_J go to `drive` (N x 3; left empty for the paper's model).
Eigen::SparseMatrix<double> model_stiffness(const LungWork& w, MotionModel model, const BakeOptions& opt,
                                            Eigen::MatrixXd& drive);

/// With w.solver factorising model_stiffness(w, model, opt): w.x (the T_lm fields of the first c_solved columns
/// of w.y, then the linear basis), w.directions, w.volume_weights and, for the sliding model, w.vector_linear.
void solve_motion_fields(LungWork& w, MotionModel model, const BakeOptions& opt, const Workers& workers);

/// The fields T_lm along e_I for the basis functions `y` (N x m) with w's factor, directions and drive: the paper's
/// K^-1 (A o y), or the sliding model's sum_c e_c o K^-1 (A o b_c o y).
Eigen::MatrixXd solve_sh_fields(const LungWork& w, MotionModel model, const Eigen::MatrixXd& y, const Workers& workers);

/// The vector displacement p0 b_0 + gamma (g_x b_x + g_y b_y + g_z b_z) of a 12-column basis b (column 4c + j:
/// component c of basis vector j, as w.vector_linear, w.off_axis and exact_linear_motion's), N x 3.
Eigen::MatrixXd linear_displacement(const Eigen::MatrixXd& basis, double p0, double gamma, const Eigen::Vector3d& g);

/// The first-order swept volume of displacements u (N x 3) of w's vertices: sum_I A_I n_I . u_I.
double swept_volume(const LungWork& w, const Eigen::MatrixXd& u);

/// The exact vector displacement basis of `model` on this lung, N x 12 as w.vector_linear, from a factorisation
/// of its own (the report's comparison of the model the asset was not baked with).
Eigen::MatrixXd exact_linear_motion(const LungWork& w, MotionModel model, const BakeOptions& opt,
                                    const Workers& workers);

}  // namespace lungar::sim
