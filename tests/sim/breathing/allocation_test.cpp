// The per-frame calls, BreathingDriver::at and OrientationTrack::at, allocate nothing (STYLE.md: the frame loop
// allocates nothing). Counted by replacing the global operator new in this test binary; skipped under
// AddressSanitizer, which owns operator new there.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>

#include "sim/breathing/driver.h"
#include "sim/breathing/orientation.h"

#include "../allocation_counter.h"

using namespace lungar::sim;

TEST(Allocation, PerFrameEvaluationAllocatesNothing) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "operator new belongs to AddressSanitizer in this build";
#else
  auto c = BreathingDriver::create({});
  ASSERT_TRUE(c) << c.error();
  BreathingDriver& d = *c;
  PatternChange fib;
  fib.preset = Preset::Fibrosis;
  ASSERT_TRUE(d.apply(Event::set(5.3, fib)).ok());
  ASSERT_TRUE(d.apply(Event::sigh(8.0)).ok());
  PatternChange vent;
  vent.mode = Mode::Ventilator;
  ASSERT_TRUE(d.apply(Event::set(9.1, vent)).ok());
  auto track = OrientationTrack::create(Eigen::Quaterniond::Identity(), {{2.0, 5.0, pose_rotation(Pose::Supine)}});
  ASSERT_TRUE(track);

  const long before = lungar::testing::g_allocations.load();
  double sink = 0;
  for (int k = 0; k < 20000; ++k) {
    const double t = 0.0017 * k;
    sink += d.at(t).dv_ml;
    sink += gravity_in_lung_frame(track->at(t)).y();
  }
  EXPECT_EQ(lungar::testing::g_allocations.load() - before, 0);
  EXPECT_TRUE(std::isfinite(sink));
  // The counter does count: applying an event allocates (a segment, the limiter's table).
  const long mid = lungar::testing::g_allocations.load();
  ASSERT_TRUE(d.apply(Event::set(40.0, fib)).ok());
  EXPECT_GT(lungar::testing::g_allocations.load(), mid);
#endif
}
