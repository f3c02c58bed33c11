// The NTP-style clock offset estimator: the on-wire formula, the least-delay choice, the spread, and the
// exchanges it must refuse.
#include <gtest/gtest.h>

#include "drivers/classroom/clock_offset.h"

using lungar::classroom::ClockExchange;
using lungar::classroom::ClockOffsetEstimator;

namespace {

/// An exchange with the instructor's clock `offset` ahead, `out` and `back` one-way delays, 50 us in the
/// instructor, starting at trainee time t1.
ClockExchange exchange(std::int64_t t1, std::int64_t offset, std::int64_t out, std::int64_t back) {
  const std::int64_t t2 = t1 + out + offset;
  const std::int64_t t3 = t2 + 50'000;
  const std::int64_t t4 = t3 - offset + back;
  return {t1, t2, t3, t4};
}

}  // namespace

TEST(ClockOffset, SymmetricPathGivesTheOffsetExactly) {
  const ClockExchange x = exchange(1'000'000'000, -250'000'000, 300'000, 300'000);
  EXPECT_EQ(x.offset_ns(), -250'000'000);
  EXPECT_EQ(x.delay_ns(), 600'000);
  ClockOffsetEstimator e;
  EXPECT_FALSE(e.estimate().has_value());
  ASSERT_TRUE(e.add(x));
  EXPECT_EQ(e.estimate()->offset_ns, -250'000'000);
  EXPECT_EQ(e.estimate()->samples, 1u);
}

TEST(ClockOffset, AnAsymmetricPathErrsByHalfTheDifference) {
  const ClockExchange x = exchange(0, 7'000'000, 4'000'000, 1'000'000);
  EXPECT_EQ(x.offset_ns(), 7'000'000 + (4'000'000 - 1'000'000) / 2);
}

TEST(ClockOffset, TheLeastDelayedExchangeWins) {
  ClockOffsetEstimator e;
  const std::int64_t truth = 42'000'000;
  ASSERT_TRUE(e.add(exchange(0, truth, 9'000'000, 1'000'000)));            // queued on the way out: +4 ms
  ASSERT_TRUE(e.add(exchange(100'000'000, truth, 200'000, 210'000)));      // the quiet one: -5 us
  ASSERT_TRUE(e.add(exchange(200'000'000, truth, 1'000'000, 7'000'000)));  // queued on the way back: -3 ms
  const auto est = e.estimate();
  ASSERT_TRUE(est.has_value());
  EXPECT_NEAR(static_cast<double>(est->offset_ns), static_cast<double>(truth), 10'000.0);
  EXPECT_EQ(est->delay_ns, 410'000);
  // Spread: RMS of the others about the best, (n - 1) in the denominator: sqrt((4.005^2 + 0 + 2.995^2) / 2) ms.
  EXPECT_NEAR(est->spread_ns * 1e-6, 3.536, 0.01);
}

TEST(ClockOffset, ImpossibleOrStalledExchangesAreRefused) {
  ClockOffsetEstimator e;
  ClockExchange backwards{1000, 5000, 6000, 900};  // received before it was sent
  EXPECT_FALSE(e.add(backwards));
  ClockExchange reply_before_request{1000, 5000, 4000, 9000};
  EXPECT_FALSE(e.add(reply_before_request));
  ClockExchange negative_delay{0, 0, 10'000'000, 1'000'000};  // the instructor took longer than the round trip
  EXPECT_FALSE(e.add(negative_delay));
  EXPECT_FALSE(e.add(exchange(0, 0, 150'000'000, 150'000'000)));  // a 300 ms stall is not a path
  EXPECT_FALSE(e.estimate().has_value());
}

TEST(ClockOffset, TheWindowForgetsOldExchangesAndResetForgetsAll) {
  ClockOffsetEstimator e;
  ASSERT_TRUE(e.add(exchange(0, 1'000'000, 10'000, 10'000)));  // the best of all, then pushed out
  for (std::size_t i = 1; i <= ClockOffsetEstimator::kWindow; ++i) {
    ASSERT_TRUE(e.add(exchange(static_cast<std::int64_t>(i) * 1'000'000'000, 2'000'000, 500'000, 500'000)));
  }
  EXPECT_EQ(e.estimate()->offset_ns, 2'000'000);
  EXPECT_EQ(e.estimate()->samples, ClockOffsetEstimator::kWindow);
  e.reset();
  EXPECT_FALSE(e.estimate().has_value());
}
