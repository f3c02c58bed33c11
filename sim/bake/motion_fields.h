/// @file motion_fields.h
/// @brief One lung's stiffness and exact solves under either motion model (internal to sim/bake): the per-vertex
///        SH coefficient fields T_lm and the linear basis, both along each vertex's direction of motion e_I.
#pragma once

#include <Eigen/SparseCore>

#include "sim/bake/bake.h"
#include "sim/bake/lung_bake.h"

namespace lungar::sim {

/// The faces of `w` (fills w.regions) and K for `model`: the paper's tether everywhere, or the sliding model's
/// per face (fills w.drive).
Eigen::SparseMatrix<double> model_stiffness(LungWork& w, MotionModel model, const BakeOptions& opt);

/// With w.solver factorising model_stiffness(w, model, opt): w.x (the T_lm fields of the first c_solved columns
/// of w.y, then the linear basis), w.directions, w.volume_weights and, for the sliding model, w.vector_linear.
void solve_motion_fields(LungWork& w, MotionModel model, const BakeOptions& opt, const Workers& workers);

/// The fields T_lm along e_I for the basis functions `y` (N x m) with w's factor, directions and drive: the paper's
/// K^-1 (A o y), or the sliding model's sum_c e_c o K^-1 (A o b_c o y).
Eigen::MatrixXd solve_sh_fields(const LungWork& w, MotionModel model, const Eigen::MatrixXd& y, const Workers& workers);

/// The exact vector displacement basis of `model` on this lung, N x 12 as w.vector_linear, from a factorisation
/// of its own (the report's comparison of the model the asset was not baked with). Leaves `w` as it was.
Eigen::MatrixXd exact_linear_motion(const LungWork& w, MotionModel model, const BakeOptions& opt,
                                    const Workers& workers);

}  // namespace lungar::sim
