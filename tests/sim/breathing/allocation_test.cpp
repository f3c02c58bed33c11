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

#if !defined(__SANITIZE_ADDRESS__)
namespace {
std::atomic<long> g_allocations{0};
}  // namespace

void* operator new(std::size_t n) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return operator new(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
#endif

using namespace lungar::sim;

TEST(Allocation, PerFrameEvaluationAllocatesNothing) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "operator new belongs to AddressSanitizer in this build";
#else
  auto c = BreathingDriver::create({});
  ASSERT_TRUE(c) << c.error;
  BreathingDriver& d = *c.driver;
  PatternChange fib;
  fib.preset = Preset::Fibrosis;
  ASSERT_EQ(d.apply(Event::set(5.3, fib)), "");
  ASSERT_EQ(d.apply(Event::sigh(8.0)), "");
  PatternChange vent;
  vent.mode = Mode::Ventilator;
  ASSERT_EQ(d.apply(Event::set(9.1, vent)), "");
  auto track = OrientationTrack::create(Eigen::Quaterniond::Identity(), {{2.0, 5.0, pose_rotation(Pose::Supine)}});
  ASSERT_TRUE(track);

  const long before = g_allocations.load();
  double sink = 0;
  for (int k = 0; k < 20000; ++k) {
    const double t = 0.0017 * k;
    sink += d.at(t).dv_ml;
    sink += gravity_in_lung_frame(track.track->at(t)).y();
  }
  EXPECT_EQ(g_allocations.load() - before, 0);
  EXPECT_TRUE(std::isfinite(sink));
  // The counter does count: applying an event allocates (a segment, the limiter's table).
  const long mid = g_allocations.load();
  ASSERT_EQ(d.apply(Event::set(40.0, fib)), "");
  EXPECT_GT(g_allocations.load(), mid);
#endif
}
