/// @file tracker_test_support.h
/// @brief What the tracker suites share: waiting for the tracker thread, collecting the samples it publishes, and
/// options that keep its log quiet (set LUNGAR_TEST_LOG to see it), replaying a log and comparing two runs.
#pragma once

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "drivers/tracker_factory/tracker_factory.h"

namespace lungar::testing {

/// Polls `pred` every millisecond for up to `seconds`: the tracker thread works asynchronously. A generous bound,
/// not a timing assertion.
template <typename Pred>
bool eventually(Pred pred, double seconds = 10.0) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (pred()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return pred();
}

/// Every accepted sample, as the tracker thread hands it over.
struct Collector {
  std::mutex mutex;
  std::vector<drivers::PoseSample> samples;
  std::size_t size() {
    std::lock_guard lock(mutex);
    return samples.size();
  }
  std::vector<drivers::PoseSample> copy() {
    std::lock_guard lock(mutex);
    return samples;
  }
};

/// Tracker options whose log is silent unless LUNGAR_TEST_LOG is set: the tests assert states instead.
inline drivers::TrackerOptions quiet() {
  drivers::TrackerOptions o;
  o.log = [](const std::string& line) {
    if (std::getenv("LUNGAR_TEST_LOG")) std::fprintf(stderr, "%s\n", line.c_str());
  };
  return o;
}

/// quiet(), and every sample into `c`.
inline drivers::TrackerOptions collecting(Collector& c) {
  drivers::TrackerOptions o = quiet();
  o.on_sample = [&c](const drivers::PoseSample& s) {
    std::lock_guard lock(c.mutex);
    c.samples.push_back(s);
  };
  return o;
}

/// Every sample of `file` replayed as fast as possible through make_tracker(), as a live run would publish them.
inline std::vector<drivers::PoseSample> replay_all(const std::string& file) {
  drivers::TrackerConfig rs;
  rs.source = drivers::TrackerSource::Replay;
  rs.replay_file = file;
  rs.replay_realtime = false;
  Collector replayed;
  auto replay = drivers::make_tracker(rs, collecting(replayed));
  EXPECT_TRUE(replay) << replay.error();
  if (!replay) return {};
  EXPECT_TRUE(eventually([&] { return (*replay)->finished(); }));
  (*replay)->stop();
  return replayed.copy();
}

/// Same bytes through the same decoder: the same role, device time, position and orientation, to the last bit.
inline void expect_bit_identical(const std::vector<drivers::PoseSample>& a, const std::vector<drivers::PoseSample>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    SCOPED_TRACE(k);
    EXPECT_EQ(a[k].role, b[k].role);
    EXPECT_EQ(a[k].t_device_ns, b[k].t_device_ns);
    EXPECT_EQ(a[k].position_mm, b[k].position_mm);
    EXPECT_EQ(a[k].orientation_wxyz, b[k].orientation_wxyz);
  }
}

}  // namespace lungar::testing
