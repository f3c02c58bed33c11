/// @file result.h
/// @brief A value or one error line: how sim/ reports bad input at its boundaries (files, meshes, assets).
#pragma once

#include <optional>
#include <string>
#include <utility>

namespace lungar::sim {

/// Either a value or one human-readable error line naming the file, the field and what was expected.
template <class T>
struct Result {
  std::optional<T> value;
  std::string error;

  static Result ok(T v) { return Result{std::move(v), {}}; }
  static Result fail(std::string message) { return Result{std::nullopt, std::move(message)}; }
  explicit operator bool() const { return value.has_value(); }
  T& operator*() { return *value; }
  const T& operator*() const { return *value; }
  T* operator->() { return &*value; }
  const T* operator->() const { return &*value; }
};

/// Success or one error line, for operations with no value (writing a file).
struct Status {
  std::string error;
  bool ok() const { return error.empty(); }
  explicit operator bool() const { return ok(); }
};

}  // namespace lungar::sim
