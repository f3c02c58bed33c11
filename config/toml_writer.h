/// @file toml_writer.h
/// @brief Writes typed fields as TOML through the member functions TomlSection reads them with, so that one field
/// list, a template over the two, declares a schema once and what it writes reads back equal.
///
/// The ranges, units and choices a field list passes are for the reader; the writer writes the value as it is.
/// Doubles keep full precision (%.17g, always with a '.' or an exponent so they stay TOML floats), strings are TOML
/// basic strings, USB ids hexadecimal.
#pragma once

#include <array>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "config/base/enum_names.h"

namespace lungar::config {

class TomlWriter {
 public:
  /// An empty document; its tables come from section().
  TomlWriter();

  void number(std::string_view key, double value, double lo, double hi, std::string_view unit);
  void integer(std::string_view key, int value, std::int64_t lo, std::int64_t hi, std::string_view unit);
  /// A USB id, written in hexadecimal (0x1234).
  void integer(std::string_view key, std::uint16_t value);
  void boolean(std::string_view key, bool value);
  void text(std::string_view key, const std::string& value);
  void texts(std::string_view key, const std::vector<std::string>& values);
  void choice(std::string_view key, const std::string& value, std::initializer_list<std::string_view> choices);
  template <typename E, std::size_t N>
  void choice(std::string_view key, E value, const EnumNames<E, N>& names) {
    text(key, names.name(value));
  }
  template <std::size_t N>
  void numbers(std::string_view key, const std::array<double, N>& values, double lo, double hi,
               std::string_view unit) {
    numbers_impl(key, values.data(), N, lo, hi, unit);
  }

  /// The nested table `key` ([path.key]), written after this table's own keys; the same table when asked twice.
  /// The returned writer shares the document.
  TomlWriter section(std::string_view key);
  /// Nothing to check when writing (TomlSection's finish() rejects unknown keys).
  void finish() const {}

  /// The whole document: each table's keys under its header, nested tables after their parent's keys.
  std::string str() const;

 private:
  struct Table;
  explicit TomlWriter(std::shared_ptr<Table> table);
  void put(std::string_view key, const std::string& value);
  void numbers_impl(std::string_view key, const double* values, std::size_t n, double lo, double hi,
                    std::string_view unit);

  std::shared_ptr<Table> table_;
};

/// `v` as a TOML float with every digit needed to read it back exactly.
std::string toml_number(double v);
/// `v` as a TOML basic string: quotes and backslashes escaped, control characters as \uXXXX.
std::string toml_string(std::string_view v);

}  // namespace lungar::config
