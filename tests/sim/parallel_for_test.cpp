/// @file parallel_for_test.cpp
/// @brief sim/parallel: a body's exception reaches the caller and stops the rest (nested loops too), the cancel
///        flag stops a loop early, worker slots are private, and results equal a serial loop's (the transfer rows
///        bit for bit on 1 and 3 threads).
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <thread>
#include <vector>

#include "sim/parallel/parallel_for.h"
#include "sim/transfer/stiffness.h"
#include "sim/transfer/transfer_rows.h"
#include "sim/transfer/transfer_solver.h"
#include "test_meshes.h"

namespace lungar::sim {
namespace {

using namespace std::chrono_literals;

/// Some work per body, so that a loop takes long enough to be stopped part-way.
double busy(std::size_t i) {
  double x = static_cast<double>(i);
  for (int k = 0; k < 2000; ++k) x = std::sqrt(x + k);
  return x;
}

TEST(ParallelFor, AnExceptionInOneBodyReachesTheCallerAndStopsTheOthers) {
  for (const int threads : {1, 4}) {
    constexpr std::size_t kBodies = 200000;
    std::atomic<std::size_t> ran{0};
    try {
      parallel_for(kBodies, threads, [&](std::size_t i) {
        ++ran;
        if (i == 50) throw std::runtime_error("body 50 failed");
        if (i % 1000 == 999) throw std::logic_error("a later body failed");  // many fail: still one reaches the caller
        busy(i);
      });
      ADD_FAILURE() << threads << " threads: no exception reached the caller";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "body 50 failed") << threads << " threads";
    } catch (const std::logic_error&) {
      EXPECT_GT(threads, 1) << "one thread reaches body 50 first";  // another thread's may throw first
    }
    EXPECT_LT(ran.load(), kBodies / 10) << threads << " threads: the other bodies went on";
  }
}

TEST(ParallelFor, AnExceptionStopsTheLoopsNestedInTheOtherBodies) {
  constexpr std::size_t kInner = 20000;
  std::atomic<bool> inner_started{false};
  std::atomic<std::size_t> inner_ran{0};
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_THROW(parallel_for(2, 2, [&](std::size_t outer) {
                 if (outer == 0) {  // waits (at most 5 s) until the other body's loop runs, then fails
                   while (!inner_started && std::chrono::steady_clock::now() - t0 < 5s) std::this_thread::yield();
                   throw std::runtime_error("outer body 0 failed");
                 }
                 parallel_for(kInner, 2, [&](std::size_t) {
                   inner_started = true;
                   ++inner_ran;
                   std::this_thread::sleep_for(100us);
                 });
               }),
               std::runtime_error);
  EXPECT_LT(inner_ran.load(), kInner / 2) << "the nested loop ran on after its parent failed";
}

TEST(ParallelFor, CancellingStopsTheLoopEarly) {
  for (const int threads : {1, 4}) {
    constexpr std::size_t kBodies = 1000000;
    std::atomic<bool> cancel{false};
    std::atomic<std::size_t> ran{0};
    EXPECT_THROW(parallel_for(kBodies, Workers{threads, &cancel}, [&](std::size_t) {
                   if (++ran == 100) cancel = true;
                 }),
                 Cancelled)
        << threads << " threads";
    EXPECT_LT(ran.load(), kBodies / 100) << threads << " threads: far fewer bodies than asked";
    EXPECT_THROW(check_cancel(Workers{threads, &cancel}), Cancelled);
  }
}

TEST(ParallelFor, ResultsEqualASerialLoop) {
  constexpr std::size_t kBodies = 5000;
  std::vector<double> serial(kBodies);
  for (std::size_t i = 0; i < kBodies; ++i) serial[i] = busy(i);
  for (const int threads : {1, 3, 8}) {
    std::vector<double> parallel(kBodies, -1.0);
    parallel_for(kBodies, threads, [&](std::size_t i) { parallel[i] = busy(i); });
    EXPECT_EQ(parallel, serial) << threads << " threads";
  }
  parallel_for(0, 4, [](std::size_t) { ADD_FAILURE() << "a body of an empty loop ran"; });
}

TEST(ParallelFor, WorkerSlotsAreBelowTheThreadCountAndNotShared) {
  constexpr int kThreads = 3;
  std::vector<std::atomic<bool>> busy_slot(kThreads);
  std::atomic<int> bad_slot{0}, shared{0};
  parallel_for(3000, kThreads, [&](std::size_t) {
    const int slot = worker_slot();
    if (slot < 0 || slot >= kThreads) {
      ++bad_slot;
      return;
    }
    if (busy_slot[static_cast<std::size_t>(slot)].exchange(true)) ++shared;
    std::this_thread::sleep_for(10us);
    busy_slot[static_cast<std::size_t>(slot)] = false;
  });
  EXPECT_EQ(bad_slot.load(), 0);
  EXPECT_EQ(shared.load(), 0) << "two bodies ran at once on one slot";
  const int hardware = thread_count(Workers{});
  EXPECT_GE(hardware, 1) << "0: every hardware thread";
  EXPECT_EQ(thread_count(Workers{kThreads}), std::min(kThreads, hardware));
  EXPECT_EQ(thread_count(Workers{1000}), hardware) << "no more than the hardware has";
}

TEST(ParallelFor, TransferRowsAndSolvesAreTheSameOnOneThreadAndOnThree) {
  const TriMesh m = test::icosphere(4, [](const Eigen::Vector3d& p) -> Eigen::Vector3d { return 80.0 * p; });
  const VertexGeometry geo = vertex_geometry(m);
  const Eigen::SparseMatrix<double> k = stiffness_matrix(m, youngs_modulus(m), geo.areas, 10.0);
  const Eigen::VectorXd areas = Eigen::Map<const Eigen::VectorXd>(geo.areas.data(), k.rows());
  const TransferSolver solver(k);
  ASSERT_EQ(solver.error(), "");
  const Eigen::MatrixXd b = areas.asDiagonal() * Eigen::MatrixXd::Random(k.rows(), 5);
  const Eigen::MatrixXd x1 = solver.solve(b, 1), x3 = solver.solve(b, 3);
  EXPECT_TRUE(x1 == x3) << "column solves differ between 1 and 3 threads";
  const Eigen::VectorXd tau0 = solver.solve(areas, 1);
  TransferRows one, three;
  append_transfer_rows(k, areas, tau0, kTransferEpsilon, 1, 7, one, {}, nullptr);
  append_transfer_rows(k, areas, tau0, kTransferEpsilon, 3, 7, three, {}, nullptr);
  ASSERT_GT(one.row_ptr.size(), 1000u) << "enough rows for several blocks";
  EXPECT_EQ(one.row_ptr, three.row_ptr);
  EXPECT_EQ(one.cols, three.cols);
  EXPECT_EQ(one.vals, three.vals);
}

}  // namespace
}  // namespace lungar::sim
