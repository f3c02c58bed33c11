/// @file versioned_flag.h
/// @brief A flag one thread sets and another reads only when it changed: the reader keeps the version it last saw
/// and is told the value once per change. Lock-free, allocates nothing: a frame asks every frame.
#pragma once

#include <atomic>
#include <cstdint>

namespace lungar {

class VersionedFlag {
 public:
  /// The writer (one thread).
  void set(bool value) {
    value_.store(value, std::memory_order_relaxed);
    version_.fetch_add(1, std::memory_order_release);
  }
  /// True when the flag was set since `version` (0 at first): `out` and `version` updated.
  bool since(std::uint64_t& version, bool& out) const {
    const std::uint64_t now = version_.load(std::memory_order_acquire);
    if (now == version) return false;
    out = value_.load(std::memory_order_relaxed);
    version = now;
    return true;
  }

 private:
  std::atomic<bool> value_{false};
  std::atomic<std::uint64_t> version_{0};
};

}  // namespace lungar
