/// @file transfer_rows.cpp
/// @brief Local push solves of K t = e_I with per-thread dense workspaces (reset through a touched list, so a
///        row costs what it touches, not the mesh size).
#include "sim/transfer/transfer_rows.h"

#include <algorithm>
#include <atomic>
#include <memory>

#include "sim/parallel/parallel_for.h"

namespace lungar::sim {
namespace {

struct RowBlock {
  std::vector<std::uint32_t> counts;
  std::vector<std::uint32_t> cols;
  std::vector<float> vals;
};

class PushSolver {
 public:
  PushSolver(const Eigen::SparseMatrix<double>& k, const Eigen::VectorXd& areas, const Eigen::VectorXd& weight,
             const RowProjection& projection)
      : k_(k), areas_(areas), weight_(weight), projection_(projection), t_(k.rows(), 0.0), r_(k.rows(), 0.0), queued_(k.rows(), 0), diag_(k.rows()) {
    for (Eigen::Index j = 0; j < k.outerSize(); ++j) diag_[j] = k.coeff(j, j);
  }

  /// Row I, truncated at epsilon * T_II, appended to `block` (local column indices + offset).
  void row(std::uint32_t i, double epsilon, std::uint32_t offset, RowBlock& block) {
    // Stop pushing node j once the update it would make, r_j / K_jj, is below epsilon times the diagonal's
    // first estimate 1/K_II: finer pushes would only feed the tail that the truncation drops.
    const double stop = epsilon / diag_[i];
    r_[i] = 1.0;
    touch(i);
    queue_.clear();
    queue_.push_back(i);
    queued_[i] = 1;
    for (std::size_t head = 0; head < queue_.size(); ++head) {
      const std::uint32_t j = queue_[head];
      queued_[j] = 0;
      const double delta = r_[j] / diag_[j];
      if (delta < stop) continue;
      t_[j] += delta;
      r_[j] = 0;
      const int* inner = k_.innerIndexPtr();
      const double* val = k_.valuePtr();
      for (int p = k_.outerIndexPtr()[j]; p < k_.outerIndexPtr()[j + 1]; ++p) {
        const auto n = static_cast<std::uint32_t>(inner[p]);
        if (n == j) continue;
        if (r_[n] == 0 && t_[n] == 0) touch(n);
        r_[n] -= val[p] * delta;  // off-diagonals are negative: the neighbours receive a share
        if (!queued_[n] && r_[n] / diag_[n] >= stop) {
          queued_[n] = 1;
          queue_.push_back(n);
        }
      }
      // Bound the queue's memory: compact it when the consumed part dominates.
      if (head > 4096 && head * 2 > queue_.size()) {
        queue_.erase(queue_.begin(), queue_.begin() + static_cast<std::ptrdiff_t>(head) + 1);
        head = static_cast<std::size_t>(-1);
      }
    }
    const double keep = epsilon * t_[i];
    std::sort(touched_.begin(), touched_.end());
    double kept_weight = 0;
    for (std::uint32_t j : touched_)
      if (t_[j] >= keep && t_[j] > 0) kept_weight += t_[j] * factor(i, j) * areas_[j];
    const double scale = kept_weight > 0 ? weight_[i] / kept_weight : 1.0;
    std::uint32_t count = 0;
    for (std::uint32_t j : touched_) {
      const double f = factor(i, j);
      if (t_[j] >= keep && t_[j] > 0 && f != 0) {
        block.cols.push_back(j + offset);
        block.vals.push_back(static_cast<float>(t_[j] * f * scale));
        ++count;
      }
      t_[j] = 0;
      r_[j] = 0;
      queued_[j] = 0;
    }
    touched_.clear();
    block.counts.push_back(count);
  }

 private:
  void touch(std::uint32_t j) { touched_.push_back(j); }
  /// e_I . b_J for the sliding model's rows, 1 for the paper's.
  double factor(std::uint32_t i, std::uint32_t j) const {
    if (projection_.directions == nullptr) return 1.0;
    return projection_.directions->row(i).dot(projection_.drive->row(j));
  }

  const Eigen::SparseMatrix<double>& k_;
  const Eigen::VectorXd& areas_;
  const Eigen::VectorXd& weight_;
  RowProjection projection_;
  std::vector<double> t_, r_;
  std::vector<char> queued_;
  std::vector<double> diag_;
  std::vector<std::uint32_t> queue_, touched_;
};

}  // namespace

void append_transfer_rows(const Eigen::SparseMatrix<double>& k, const Eigen::VectorXd& areas,
                          const Eigen::VectorXd& row_weight, double epsilon, const Workers& workers,
                          std::uint32_t offset, TransferRows& out, const RowProjection& projection,
                          const std::function<void(std::size_t)>& progress) {
  const auto rows = static_cast<std::uint32_t>(k.rows());
  const int threads = std::clamp(thread_count(workers), 1, 64);
  // Blocks of consecutive rows, each with its own output, joined in row order below; many more blocks than
  // threads balance the load.
  const std::uint32_t block_rows = std::max<std::uint32_t>(256, rows / (threads * 16) + 1);
  const std::uint32_t block_count = (rows + block_rows - 1) / block_rows;
  std::vector<RowBlock> blocks(block_count);
  std::vector<std::unique_ptr<PushSolver>> solvers(static_cast<std::size_t>(threads));  // one per worker slot
  std::atomic<std::size_t> done{0};
  parallel_for(block_count, Workers{threads, workers.cancel}, [&](std::size_t b) {
    std::unique_ptr<PushSolver>& solver = solvers[static_cast<std::size_t>(worker_slot())];
    if (!solver) solver = std::make_unique<PushSolver>(k, areas, row_weight, projection);
    const auto first = static_cast<std::uint32_t>(b * block_rows), last = std::min(rows, first + block_rows);
    for (std::uint32_t i = first; i < last; ++i) solver->row(i, epsilon, offset, blocks[b]);
    done += last - first;
    if (progress && on_calling_thread()) progress(done.load());
  });
  if (progress) progress(rows);

  if (out.row_ptr.empty()) out.row_ptr.push_back(0);
  for (RowBlock& b : blocks) {
    for (std::uint32_t c : b.counts) out.row_ptr.push_back(out.row_ptr.back() + c);
    out.cols.insert(out.cols.end(), b.cols.begin(), b.cols.end());
    out.vals.insert(out.vals.end(), b.vals.begin(), b.vals.end());
  }
}

}  // namespace lungar::sim
