/// @file transfer_rows.h
/// @brief Explicit, truncated rows of the transfer matrix T = K^-1 for the paper's CPU eq. (1) baseline.
///
/// The paper shares each unit force with the neighbours until equilibrium; that is a local iterative solve of
/// K t = e_I. We run it as a residual push (Gauss-Southwell-like, FIFO) confined to where the residual still
/// matters, then drop entries below epsilon * T_II. With the chest-wall tether as weak as docs/design.md's
/// ("Transfer matrix"), most of a row's weight lies in a long, faint tail that truncation drops; so each kept row
/// is rescaled so that its weight sum_J T(I,J) A_J equals the exact tau0_I = (K^-1 A)_I from the factorised
/// solve, which makes uniform pressure exact and keeps eq. (1)'s error a few per cent instead of tens. Rows are
/// independent, so they run on many threads.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "sim/parallel/parallel_for.h"

namespace lungar::sim {

/// Default truncation: entries below this fraction of the diagonal T_II are dropped.
inline constexpr double kTransferEpsilon = 0.02;

/// Rows of T in compressed sparse row form; columns are global vertex indices (offset added).
struct TransferRows {
  std::vector<std::uint32_t> row_ptr;  ///< rows + 1
  std::vector<std::uint32_t> cols;
  std::vector<float> vals;             ///< mm per unit force
};

/// For the sliding model (sim/motion/motion_model.h): row I's entry J is K^-1(I,J) (e_I . b_J), the displacement
/// of I along its direction e_I under a unit pressure at J pushing along b_J. Both null: the paper's K^-1 rows.
struct RowProjection {
  const Eigen::MatrixXd* directions = nullptr;  ///< N x 3, e_I
  const Eigen::MatrixXd* drive = nullptr;       ///< N x 3, b_J
};

/// Appends the truncated rows of K^-1 (one lung, vertices offset .. offset + K.rows()) to `out`.
/// `progress(rows_done)` is called now and then from the calling thread only.
/// `areas` are A_J and `row_weight` the exact tau0 along e_I (both local to the lung). Throws Cancelled when cancelled.
void append_transfer_rows(const Eigen::SparseMatrix<double>& k, const Eigen::VectorXd& areas,
                          const Eigen::VectorXd& row_weight, double epsilon, const Workers& workers,
                          std::uint32_t offset, TransferRows& out, const RowProjection& projection,
                          const std::function<void(std::size_t)>& progress);

}  // namespace lungar::sim
