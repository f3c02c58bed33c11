/// @file transfer_solver.cpp
/// @brief Sparse LDL^T of K (AMD ordering) and column-parallel solves.
#include "sim/transfer/transfer_solver.h"

#include <algorithm>
#include <thread>
#include <vector>

namespace lungar::sim {

TransferSolver::TransferSolver(const Eigen::SparseMatrix<double>& k) {
  ldlt_.compute(k);
  if (ldlt_.info() != Eigen::Success) error_ = "stiffness matrix K is not positive definite";
}

Eigen::MatrixXd TransferSolver::solve(const Eigen::MatrixXd& b, int threads) const {
  Eigen::MatrixXd x(b.rows(), b.cols());
  const int workers = std::clamp<int>(threads, 1, static_cast<int>(std::max<Eigen::Index>(1, b.cols())));
  auto work = [&](int w) {
    for (Eigen::Index c = w; c < b.cols(); c += workers) x.col(c) = ldlt_.solve(b.col(c));
  };
  std::vector<std::thread> pool;
  for (int w = 1; w < workers; ++w) pool.emplace_back(work, w);
  work(0);
  for (auto& t : pool) t.join();
  return x;
}

}  // namespace lungar::sim
