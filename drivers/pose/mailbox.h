/// @file mailbox.h
/// @brief A single-writer, many-reader latest-value mailbox: the writer never waits, and a reader never waits
/// for a writer that is stalled mid-write (the frame loop cannot be held up by the tracker thread).
/// @ingroup drivers
///
/// Four slots, each a small seqlock. The writer fills the slot after the published one and then publishes its
/// number; a reader copies the published slot and checks its sequence. A reader retries only when the writer
/// has lapped it (written three more values during one copy), so a retry always means the writer progressed:
/// lock-free. Values live in relaxed atomic 64-bit words, so that a copy racing a write is not a data race in
/// the C++ memory model (Boehm, "Can seqlocks get along with programming language memory models?", 2012).
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
  LatestMailbox() { write_slot(slots_[0], T{}, 0); }

  /// Publishes `value`. One writer only (the tracker thread); wait-free.
  void publish(const T& value) {
    const std::uint64_t n = published_.load(std::memory_order_relaxed) + 1;
    write_slot(slots_[n % kSlots], value, n);
    published_.store(n, std::memory_order_release);
  }

  /// The latest published value (T{} before the first). Lock-free.
  T read() const {
    std::array<std::uint64_t, kWords> words;
    for (;;) {
      const std::uint64_t n = published_.load(std::memory_order_acquire);
      const Slot& slot = slots_[n % kSlots];
      const std::uint64_t s1 = slot.seq.load(std::memory_order_acquire);
      if (s1 != 2 * n) continue;  // lapped: the slot already holds (or is taking) a newer value
      for (std::size_t k = 0; k < kWords; ++k) words[k] = slot.words[k].load(std::memory_order_relaxed);
      std::atomic_thread_fence(std::memory_order_acquire);
      if (slot.seq.load(std::memory_order_relaxed) == s1) break;
    }
    T out;
    std::memcpy(static_cast<void*>(&out), words.data(), sizeof(T));
    return out;
  }

  /// How many values were published.
  std::uint64_t published() const { return published_.load(std::memory_order_acquire); }

 private:
  static constexpr std::size_t kWords = (sizeof(T) + 7) / 8;
  static constexpr std::size_t kSlots = 4;
  struct Slot {
    std::atomic<std::uint64_t> seq{0};  ///< 2n when value n is complete, odd while it is written
    std::array<std::atomic<std::uint64_t>, kWords> words{};
  };

  static void write_slot(Slot& slot, const T& value, std::uint64_t n) {
    std::array<std::uint64_t, kWords> words{};
    std::memcpy(words.data(), &value, sizeof(T));
    slot.seq.store(2 * n - 1, std::memory_order_relaxed);  // n = 0 only in the constructor, before any reader
    std::atomic_thread_fence(std::memory_order_release);
    for (std::size_t k = 0; k < kWords; ++k) slot.words[k].store(words[k], std::memory_order_relaxed);
    slot.seq.store(2 * n, std::memory_order_release);
  }

  std::atomic<std::uint64_t> published_{0};
  std::array<Slot, kSlots> slots_{};
};

}  // namespace lungar::drivers
