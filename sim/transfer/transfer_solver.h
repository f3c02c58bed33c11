/// @file transfer_solver.h
/// @brief One sparse factorisation of K, then any number of exact solves T b = K^-1 b (docs/design.md,
///        "Transfer matrix").
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCholesky>

#include "config/base/result.h"
#include "sim/parallel/parallel_for.h"

namespace lungar::sim {

class TransferSolver {
 public:
  /// Factorises K (symmetric positive definite); error() is non-empty when that fails.
  explicit TransferSolver(const Eigen::SparseMatrix<double>& k);
  const std::string& error() const { return error_; }

  /// X = K^-1 B, columns solved in parallel (the factor is shared, read-only); throws Cancelled when cancelled.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& b, const Workers& workers) const;

 private:
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt_;
  std::string error_;
};

}  // namespace lungar::sim
