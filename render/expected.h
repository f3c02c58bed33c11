/// @file expected.h
/// @brief A value or one error line: how render/ and platform/egl report failures at their boundaries.
#pragma once

#include <optional>
#include <string>
#include <utility>

namespace lungar::render {

/// Either a T or a human-readable error ("what: expected ..., got ..."). C++20 has no std::expected.
template <typename T>
class Expected {
 public:
  Expected(T value) : value_(std::move(value)) {}  // NOLINT: implicit on purpose, like std::expected
  static Expected failure(std::string error) {
    Expected e;
    e.error_ = std::move(error);
    return e;
  }
  explicit operator bool() const { return value_.has_value(); }
  T& operator*() { return *value_; }
  const T& operator*() const { return *value_; }
  T* operator->() { return &*value_; }
  const T* operator->() const { return &*value_; }
  T take() { return std::move(*value_); }
  const std::string& error() const { return error_; }

 private:
  Expected() = default;
  std::optional<T> value_;
  std::string error_;
};

/// Success or one error line.
struct Status {
  std::string error;  ///< empty on success
  explicit operator bool() const { return error.empty(); }
  static Status ok() { return {}; }
};

}  // namespace lungar::render
