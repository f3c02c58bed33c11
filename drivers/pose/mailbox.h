/// @file mailbox.h
/// @brief A single-writer, many-reader latest-value mailbox (a seqlock): the writer never waits, readers never lock.
/// @ingroup drivers
///
/// The value is kept as relaxed atomic 64-bit words so that a read racing a write is not a data race in the
/// C++ memory model (Boehm, "Can seqlocks get along with programming language memory models?", 2012); the
/// sequence number tells the reader to retry a torn copy.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace lungar::drivers {

template <typename T>
class LatestMailbox {
  static_assert(std::is_trivially_copyable_v<T>, "a mailbox holds plain data");

 public:
  LatestMailbox() { store(T{}, /*count=*/false); }

  /// Publishes `value`. One writer only (the tracker thread); wait-free.
  void publish(const T& value) { store(value, true); }

  /// The latest published value (T{} before the first). Lock-free; retries only while a write is in flight.
  T read() const {
    std::array<std::uint64_t, kWords> words;
    for (;;) {
      const std::uint64_t s1 = seq_.load(std::memory_order_acquire);
      if (s1 & 1u) continue;  // a write is in progress
      for (std::size_t k = 0; k < kWords; ++k) words[k] = words_[k].load(std::memory_order_relaxed);
      std::atomic_thread_fence(std::memory_order_acquire);
      if (seq_.load(std::memory_order_relaxed) == s1) break;
    }
    T out;
    std::memcpy(static_cast<void*>(&out), words.data(), sizeof(T));
    return out;
  }

  /// How many values were published.
  std::uint64_t published() const { return seq_.load(std::memory_order_acquire) / 2; }

 private:
  static constexpr std::size_t kWords = (sizeof(T) + 7) / 8;

  void store(const T& value, bool count) {
    std::array<std::uint64_t, kWords> words{};
    std::memcpy(words.data(), &value, sizeof(T));
    const std::uint64_t s = seq_.load(std::memory_order_relaxed);
    seq_.store(s + 1, std::memory_order_relaxed);
    std::atomic_thread_fence(std::memory_order_release);
    for (std::size_t k = 0; k < kWords; ++k) words_[k].store(words[k], std::memory_order_relaxed);
    seq_.store(count ? s + 2 : s, std::memory_order_release);
  }

  std::atomic<std::uint64_t> seq_{0};
  std::array<std::atomic<std::uint64_t>, kWords> words_{};
};

}  // namespace lungar::drivers
