/// @file result.h
/// @brief lungar's one error convention: a value or one error line, for every layer (docs/design.md, "Contracts").
/// @ingroup base
///
/// Bad input at a boundary (a file, a field, a device) is a value, not an exception: a function that can fail on
/// what a user gave it returns `Result<T>` (or `Status`, a `Result<void>`), whose error is one line naming the file,
/// the field and what was expected. Programming errors stay asserts. C++20 has no std::expected; this is its shape.
#pragma once

#include <cassert>
#include <optional>
#include <string>
#include <utility>

namespace lungar {

/// One error line, e.g. "my.toml:7: key 'render.point_size_px': expected a number in [1, 64] pixels, got 0".
struct Error {
  std::string message;
};

/// The way to fail: `return fail(path + ": magic: expected 'LUNGBAKE'");` converts to any Result.
inline Error fail(std::string message) { return Error{std::move(message)}; }

/// Either a T or an Error. Converts implicitly from both, so a function returns either as it is.
template <class T>
class [[nodiscard]] Result {
 public:
  Result(T value) : value_(std::move(value)) {}             // NOLINT(google-explicit-constructor): like expected
  Result(Error error) : error_(std::move(error.message)) {  // NOLINT(google-explicit-constructor)
    assert(!error_.empty() && "an error needs its message");
  }

  bool ok() const { return value_.has_value(); }
  explicit operator bool() const { return ok(); }
  T& operator*() & { return *value_; }
  const T& operator*() const& { return *value_; }
  T* operator->() { return &*value_; }
  const T* operator->() const { return &*value_; }
  /// Moves the value out (the Result must hold one).
  T take() { return std::move(*value_); }
  /// The error line; empty when the Result holds a value.
  const std::string& error() const { return error_; }
  /// The same failure with `prefix` in front of its line ("asset: " + ...), for a caller that adds context.
  Error with_context(const std::string& prefix) const { return Error{prefix + error_}; }

 private:
  std::optional<T> value_;
  std::string error_;
};

/// Success, or an Error: what an operation with no value (writing a file, sending a report) returns.
template <>
class [[nodiscard]] Result<void> {
 public:
  Result() = default;
  Result(Error error) : error_(std::move(error.message)) {  // NOLINT(google-explicit-constructor)
    assert(!error_.empty() && "an error needs its message");
  }
  bool ok() const { return error_.empty(); }
  explicit operator bool() const { return ok(); }
  const std::string& error() const { return error_; }
  Error with_context(const std::string& prefix) const { return Error{prefix + error_}; }

 private:
  std::string error_;
};

using Status = Result<void>;

/// `return ok();` from a function returning Status.
inline Status ok() { return {}; }

}  // namespace lungar
