/// @file spsc_ring.h
/// @brief A fixed ring from one producer thread to one consumer thread (a device's reading thread to the frame):
///        neither side blocks or allocates; when the consumer falls behind a full ring's worth, new items are
///        dropped and counted rather than overwriting what the consumer is reading.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>

namespace lungar {

template <class T, std::size_t N>
class SpscRing {
 public:
  /// The producer: false (and counted) when the ring is full.
  bool push(const T& item) {
    const std::uint64_t w = written_.load(std::memory_order_relaxed);
    if (w - read_.load(std::memory_order_acquire) == N) {
      dropped_.fetch_add(1, std::memory_order_relaxed);
      return false;
    }
    items_[w % N] = item;
    written_.store(w + 1, std::memory_order_release);
    return true;
  }
  /// The consumer: `on(item)` for every item pushed before the call, oldest first.
  template <class F>
  void drain(F&& on) {
    const std::uint64_t w = written_.load(std::memory_order_acquire);
    for (std::uint64_t r = read_.load(std::memory_order_relaxed); r < w; ++r) {
      const T item = items_[r % N];
      read_.store(r + 1, std::memory_order_release);
      on(item);
    }
  }
  /// Items the producer dropped because the ring was full; any thread.
  std::uint64_t dropped() const { return dropped_.load(std::memory_order_relaxed); }

 private:
  std::array<T, N> items_{};
  std::atomic<std::uint64_t> written_{0}, read_{0};
  std::atomic<std::uint64_t> dropped_{0};
};

}  // namespace lungar
