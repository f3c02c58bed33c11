/// @file transfer_solver.cpp
/// @brief Sparse LDL^T of K (AMD ordering) and column-parallel solves.
#include "sim/transfer/transfer_solver.h"

#include "sim/parallel/parallel_for.h"

namespace lungar::sim {

TransferSolver::TransferSolver(const Eigen::SparseMatrix<double>& k) {
  ldlt_.compute(k);
  if (ldlt_.info() != Eigen::Success) error_ = "stiffness matrix K is not positive definite";
}

Eigen::MatrixXd TransferSolver::solve(const Eigen::MatrixXd& b, const Workers& workers) const {
  Eigen::MatrixXd x(b.rows(), b.cols());
  parallel_for(static_cast<std::size_t>(b.cols()), workers, [&](std::size_t c) {
    const auto col = static_cast<Eigen::Index>(c);
    x.col(col) = ldlt_.solve(b.col(col));
  });
  return x;
}

}  // namespace lungar::sim
