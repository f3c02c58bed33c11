// Tests of drivers/tracker/reopen_backoff.h: when a lost tracker is tried again.
#include <gtest/gtest.h>

#include "drivers/tracker/reopen_backoff.h"

namespace lungar::drivers {
namespace {

constexpr std::int64_t kMs = ReopenBackoff::kNsPerMs;

TEST(ReopenBackoff, FailedTriesWaitTwiceAsLongEachTimeUpToFourSeconds) {
  ReopenBackoff b(250.0);
  EXPECT_TRUE(b.due(0)) << "the first try is at once";
  std::int64_t now = 0;
  const std::int64_t waits_ms[] = {250, 500, 1000, 2000, 4000, 4000};
  for (std::int64_t wait : waits_ms) {
    b.failed(now);
    EXPECT_FALSE(b.due(now + wait * kMs - 1)) << "after a wait of " << wait << " ms";
    EXPECT_TRUE(b.due(now + wait * kMs));
    now += wait * kMs;
  }
}

TEST(ReopenBackoff, ALossAfterAnOpenWaitsTheFirstWaitAgain) {
  ReopenBackoff b(100.0);
  b.failed(0);
  b.failed(100 * kMs);  // the next wait would be 400 ms
  b.opened();
  b.lost(1000 * kMs);
  EXPECT_FALSE(b.due(1100 * kMs - 1));
  EXPECT_TRUE(b.due(1100 * kMs));
  b.failed(1100 * kMs);  // the first failure after the loss waits the first wait, then doubling resumes
  EXPECT_TRUE(b.due(1200 * kMs));
  b.failed(1200 * kMs);
  EXPECT_FALSE(b.due(1400 * kMs - 1));
  EXPECT_EQ(b.first_ms(), 100);
}

}  // namespace
}  // namespace lungar::drivers
