/// @file motion_fields.cpp
/// @brief The paper's scalar solves (T_lm = K^-1 (A o Y_lm)), and the sliding model's three per component
///        (T^c_lm = K^-1 (A o b_c o Y_lm)) projected onto each vertex's principal direction.
#include "sim/bake/motion_fields.h"

#include "sim/transfer/stiffness.h"

namespace lungar::sim {
namespace {

/// The right-hand sides of the linear basis for one force density `a` (A, or A o b_c): a, a o (x - c).
Eigen::MatrixXd linear_rhs(const LungWork& w, const Eigen::VectorXd& a) {
  Eigen::MatrixXd rhs(a.size(), 4);
  rhs.col(0) = a;
  rhs.rightCols(3) = a.asDiagonal() * w.offsets;
  return rhs;
}

/// e_I of every vertex from the vector linear basis (sim/motion/motion_model.h, principal_direction).
Eigen::MatrixXd principal_directions(const LungWork& w, const Eigen::MatrixXd& vl, const BakeOptions& opt) {
  const Eigen::Index n = vl.rows();
  const double radius = std::sqrt(w.offsets.rowwise().squaredNorm().mean());
  Eigen::MatrixXd e(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    Eigen::Vector3d tau0;
    Eigen::Matrix3d grad;
    for (int c = 0; c < 3; ++c) {
      tau0[c] = vl(i, 4 * c);
      for (int k = 0; k < 3; ++k) grad(c, k) = vl(i, 4 * c + 1 + k);
    }
    e.row(i) = principal_direction(tau0, grad, opt.p0, opt.gamma_per_mm * radius,
                                   w.geometry.normals[static_cast<std::size_t>(i)])
                   .transpose();
  }
  return e;
}

Eigen::MatrixXd normals_matrix(const LungWork& w) {
  Eigen::MatrixXd n(static_cast<Eigen::Index>(w.geometry.normals.size()), 3);
  for (std::size_t i = 0; i < w.geometry.normals.size(); ++i) n.row(static_cast<Eigen::Index>(i)) = w.geometry.normals[i].transpose();
  return n;
}

}  // namespace

std::vector<SurfaceRegion> surface_regions(const LungWork& w, const BakeOptions& opt) {
  return classify_surface(w.mesh, w.geometry.normals, medial_direction(w.name, w.centre.x(), w.midline_x),
                          opt.regions);
}

Eigen::SparseMatrix<double> model_stiffness(const LungWork& w, MotionModel model, const BakeOptions& opt,
                                            Eigen::MatrixXd& drive) {
  std::vector<double> tether_areas = w.geometry.areas;
  drive.resize(0, 3);
  if (model == MotionModel::sliding) {
    MotionBoundary b = sliding_boundary(w.regions, w.mesh, w.geometry.normals, opt.faces);
    for (std::size_t i = 0; i < tether_areas.size(); ++i) tether_areas[i] *= b.tether_scale[i];
    drive = std::move(b.drive);
  }
  return stiffness_matrix(w.mesh, youngs_modulus(w.mesh), tether_areas, opt.decay_length_mm);
}

void solve_motion_fields(LungWork& w, MotionModel model, const BakeOptions& opt, const Workers& workers) {
  const Eigen::Index n = w.areas.size();
  const int c = w.c_solved;
  if (model == MotionModel::paper) {
    // L^2 + 4 solves: T_lm = K^-1 (A o Y_lm) and tau = K^-1 (A o [1, x - c]), along the normals.
    Eigen::MatrixXd rhs(n, c + 4);
    rhs.leftCols(c) = w.areas.asDiagonal() * w.y;
    rhs.rightCols(4) = linear_rhs(w, w.areas);
    w.x = w.solver->solve(rhs, workers);
    w.directions = normals_matrix(w);
    w.volume_weights = w.areas;
    return;
  }
  // The vector linear basis first (12 solves), which gives each vertex's direction e_I; then each component's
  // L^2 fields, projected onto e_I as they come, so that one component's fields are held at a time.
  Eigen::MatrixXd rhs(n, 12);
  for (int k = 0; k < 3; ++k) rhs.middleCols(4 * k, 4) = linear_rhs(w, w.areas.cwiseProduct(w.drive.col(k)));
  w.vector_linear = w.solver->solve(rhs, workers);
  w.directions = principal_directions(w, w.vector_linear, opt);
  w.x.resize(n, c + 4);
  w.x.leftCols(c) = solve_sh_fields(w, model, w.y, workers);
  w.x.rightCols(4).setZero();
  for (int k = 0; k < 3; ++k)
    w.x.rightCols(4) += w.directions.col(k).asDiagonal() * w.vector_linear.middleCols(4 * k, 4);
  const Eigen::MatrixXd normals = normals_matrix(w);
  w.volume_weights = w.areas.cwiseProduct(w.directions.cwiseProduct(normals).rowwise().sum());
  // The off-axis part: each basis vector less its projection onto e_I.
  w.off_axis.resize(n, 12);
  w.off_axis_volume.setZero();
  for (Eigen::Index i = 0; i < n; ++i)
    for (int j = 0; j < 4; ++j) {
      Eigen::Vector3d tau;
      for (int c = 0; c < 3; ++c) tau[c] = w.vector_linear(i, 4 * c + j);
      const Eigen::Vector3d e = w.directions.row(i).transpose();
      const Eigen::Vector3d r = tau - e * e.dot(tau);
      for (int c = 0; c < 3; ++c) w.off_axis(i, 4 * c + j) = r[c];
      w.off_axis_volume[j] += w.areas[i] * normals.row(i).dot(r);
    }
}

Eigen::MatrixXd solve_sh_fields(const LungWork& w, MotionModel model, const Eigen::MatrixXd& y,
                                const Workers& workers) {
  if (model == MotionModel::paper) return w.solver->solve(w.areas.asDiagonal() * y, workers);
  Eigen::MatrixXd x = Eigen::MatrixXd::Zero(y.rows(), y.cols());
  for (int k = 0; k < 3; ++k) {
    const Eigen::VectorXd density = w.areas.cwiseProduct(w.drive.col(k));
    x += w.directions.col(k).asDiagonal() * w.solver->solve(density.asDiagonal() * y, workers);
  }
  return x;
}

Eigen::MatrixXd linear_displacement(const Eigen::MatrixXd& basis, double p0, double gamma, const Eigen::Vector3d& g) {
  Eigen::MatrixXd u(basis.rows(), 3);
  for (int c = 0; c < 3; ++c) u.col(c) = p0 * basis.col(4 * c) + gamma * (basis.middleCols(4 * c + 1, 3) * g);
  return u;
}

double swept_volume(const LungWork& w, const Eigen::MatrixXd& u) {
  double v = 0;
  for (Eigen::Index i = 0; i < u.rows(); ++i)
    v += w.areas[i] * u.row(i).dot(w.geometry.normals[static_cast<std::size_t>(i)]);
  return v;
}

Eigen::MatrixXd exact_linear_motion(const LungWork& w, MotionModel model, const BakeOptions& opt,
                                    const Workers& workers) {
  Eigen::MatrixXd drive;
  const TransferSolver solver(model_stiffness(w, model, opt, drive));
  if (model == MotionModel::sliding) {
    Eigen::MatrixXd rhs(w.areas.size(), 12);
    for (int k = 0; k < 3; ++k) rhs.middleCols(4 * k, 4) = linear_rhs(w, w.areas.cwiseProduct(drive.col(k)));
    return solver.solve(rhs, workers);
  }
  const Eigen::MatrixXd tau = solver.solve(linear_rhs(w, w.areas), workers);
  const Eigen::MatrixXd normals = normals_matrix(w);
  Eigen::MatrixXd out(tau.rows(), 12);
  for (int k = 0; k < 3; ++k) out.middleCols(4 * k, 4) = normals.col(k).asDiagonal() * tau;
  return out;
}

}  // namespace lungar::sim
