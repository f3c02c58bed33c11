/// @file lung_bake.h
/// @brief One lung's working state during a bake (internal to sim/bake): the mesh in LOD order, K and its
///        factor, and the double-precision solves the report reuses.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <string>

#include "sim/motion/motion_model.h"
#include "sim/mesh/spherical_map.h"
#include "sim/mesh/tri_mesh.h"
#include "sim/transfer/transfer_rows.h"
#include "sim/transfer/transfer_solver.h"

namespace lungar::sim {

struct LungWork {
  std::string name;
  LungSource source;
  TriMesh mesh;
  bool has_centre = false;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  VertexGeometry geometry;
  double rest_volume_mm3 = 0;
  Eigen::VectorXd areas;          ///< A_I
  double midline_x = 0;           ///< x of the body's midline (the lungs' mean), for a lung with another name
  std::vector<SurfaceRegion> regions;  ///< each vertex's face (sim/motion/surface_regions.h)
  Eigen::MatrixXd directions;     ///< N x 3, e_I: the direction each vertex moves along (the normal: paper)
  Eigen::VectorXd volume_weights; ///< A_I (e_I . n_I): D's first-order swept volume is volume_weights . D
  Eigen::MatrixXd drive;          ///< N x 3, b_J (sliding; empty for the paper's model)
  /// Sliding: the exact vector displacements of the four linear pressures, N x 12, component c's tau0, tau_x,
  /// tau_y, tau_z in columns 4c .. 4c + 3 (the report measures the projection onto e_I against them).
  Eigen::MatrixXd vector_linear;
  /// Sliding: r = tau_vec - e (e . tau_vec), N x 12 in the asset's layout (row c: r0_c, r_x c, r_y c, r_z c), and
  /// its swept volumes sum_I A_I n_I . r_j (4), which join the volume basis.
  Eigen::MatrixXd off_axis;
  Eigen::Vector4d off_axis_volume = Eigen::Vector4d::Zero();
  SphereMapResult sphere;         ///< u_I of the SH fit, its folds and area distortion
  int c_solved = 0;               ///< SH fields solved: L^2, or 64 when the report sweeps the bands
  Eigen::MatrixXd y;              ///< N x c_solved, Y_lm(u_I)
  Eigen::MatrixXd offsets;        ///< N x 3, x_I - c
  Eigen::MatrixXd gram;           ///< c_solved x c_solved, G = sum A Y Y^T
  Eigen::MatrixXd x;              ///< N x (c_solved + 4): T_lm fields, then tau0, tau_x, tau_y, tau_z (along e_I)
  Eigen::MatrixXd force_basis;    ///< L^2 x 4: f0, f_x, f_y, f_z
  Eigen::VectorXd volume_basis;   ///< 4: v0, v_x, v_y, v_z (mm^3 per unit pressure)
  Eigen::SparseMatrix<double> k;
  std::unique_ptr<TransferSolver> solver;
  TransferRows rows;              ///< this lung's truncated rows, global column indices
};

/// Y_lm(u_I) for l < bands, one row per vertex (N x bands^2).
Eigen::MatrixXd sh_rows(const std::vector<Eigen::Vector3d>& u, int bands);

}  // namespace lungar::sim
