/// @file unique_handle.h
/// @brief A move-only owner of a C library's handle (a file descriptor, an OpenXR handle, a GL name) that
/// releases it exactly once: the one place lungar writes the move-and-release rules such owners need.
#pragma once

#include <utility>

namespace lungar {

/// Owns one `Handle`; `Release(handle)` runs when the owner is destroyed, reset or assigned over. `Null` is the
/// value that owns nothing (-1 for a file descriptor, XR_NULL_HANDLE, GL's 0). Release's result is ignored: a
/// handle that fails to close is gone all the same.
template <typename Handle, auto Release, Handle Null = Handle{}>
class UniqueHandle {
 public:
  UniqueHandle() = default;
  explicit UniqueHandle(Handle h) : h_(h) {}
  ~UniqueHandle() { reset(); }
  UniqueHandle(UniqueHandle&& o) noexcept : h_(std::exchange(o.h_, Null)) {}
  UniqueHandle& operator=(UniqueHandle&& o) noexcept {
    if (this != &o) reset(std::exchange(o.h_, Null));
    return *this;
  }
  UniqueHandle(const UniqueHandle&) = delete;
  UniqueHandle& operator=(const UniqueHandle&) = delete;

  Handle get() const { return h_; }
  explicit operator bool() const { return h_ != Null; }
  /// Releases what is owned and owns `h` instead.
  void reset(Handle h = Null) {
    if (h_ != Null) static_cast<void>(Release(h_));
    h_ = h;
  }
  /// Where a C function that creates a handle writes it (xrCreateSession(..., &out)): releases what is owned first.
  Handle* out() {
    reset();
    return &h_;
  }

 private:
  Handle h_ = Null;
};

}  // namespace lungar
