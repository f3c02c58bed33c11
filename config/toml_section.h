/// @file toml_section.h
/// @brief Reads one TOML table into typed fields, checking type and range, and reports keys it was not asked for.
///
/// Every problem is thrown as a ConfigError carrying "FILE:LINE: key 'path': expected ..., got ..."; the
/// loader turns it into a value at its boundary.
#pragma once

#include <array>
#include <cstdint>
#include <initializer_list>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <toml++/toml.h>

#include "config/base/enum_names.h"
#include "config/base/result.h"

namespace lungar::config {

struct ConfigError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class TomlSection {
 public:
  /// `table` may be null: a missing section reads as all-defaults.
  TomlSection(const toml::table* table, std::string path, std::string file);

  void number(std::string_view key, double& out, double lo, double hi, std::string_view unit);
  void integer(std::string_view key, int& out, std::int64_t lo, std::int64_t hi, std::string_view unit);
  void integer(std::string_view key, std::uint16_t& out);
  void boolean(std::string_view key, bool& out);
  void text(std::string_view key, std::string& out);
  /// An array of strings (any length).
  void texts(std::string_view key, std::vector<std::string>& out);
  /// A string that must be one of `choices`.
  void choice(std::string_view key, std::string& out, std::initializer_list<std::string_view> choices);
  /// A string that must be one of the names in `names` (each owner's table, config/base/enum_names.h).
  template <typename E, std::size_t N>
  void choice(std::string_view key, E& out, const EnumNames<E, N>& names);
  /// The same, kept as the name (settings that carry the name on to another layer, as the breathing preset does).
  template <typename E, std::size_t N>
  void choice(std::string_view key, std::string& out, const EnumNames<E, N>& names);
  /// A fixed-length array of numbers, each within [lo, hi].
  template <std::size_t N>
  void numbers(std::string_view key, std::array<double, N>& out, double lo, double hi, std::string_view unit);

  /// A nested table (absent: defaults). Marks the key as known.
  TomlSection section(std::string_view key);
  /// Fails on the first key of this table that no read above asked for.
  void finish() const;

  /// Throws "FILE:LINE: key 'path.key': message" for a key of this table (or the table itself if absent).
  [[noreturn]] void fail(std::string_view key, const std::string& message) const;
  std::string key_path(std::string_view key) const;

 private:
  const toml::node* find(std::string_view key);
  [[noreturn]] void fail_numbers(std::string_view key, std::size_t n, double lo, double hi, std::string_view unit,
                                 const std::string& got) const;
  void numbers_impl(std::string_view key, double* out, std::size_t n, double lo, double hi, std::string_view unit);

  const toml::table* table_;
  std::string path_;
  std::string file_;
  std::set<std::string, std::less<>> known_;
};

/// Parses TOML text; a syntax error is "NAME:LINE:COLUMN: TOML syntax error: ...".
Result<toml::table> parse_toml(const std::string& text, const std::string& name);

/// Reads a whole text file for a loader; "PATH: cannot read the WHAT: expected a TOML file, got ..." when it is
/// missing, not a regular file or unreadable.
Result<std::string> read_toml_file(const std::string& path, const char* what);

/// How a node is named in "got ..." messages: "a string", "an integer 7", ...
std::string describe(const toml::node& node);

template <typename E, std::size_t N>
void TomlSection::choice(std::string_view key, E& out, const EnumNames<E, N>& names) {
  const toml::node* node = find(key);
  if (!node) return;
  if (const auto* s = node->as_string()) {
    if (auto value = names.parse(s->get())) {
      out = *value;
      return;
    }
  }
  std::string expected;
  for (const auto& [value, name] : names.entries) {
    if (!expected.empty()) expected += " | ";
    expected += '"' + std::string(name) + '"';
  }
  fail(key, "expected one of " + expected + ", got " + describe(*node));
}

template <typename E, std::size_t N>
void TomlSection::choice(std::string_view key, std::string& out, const EnumNames<E, N>& names) {
  if (!find(key)) return;
  E value{};
  choice(key, value, names);
  out = names.name(value);
}

template <std::size_t N>
void TomlSection::numbers(std::string_view key, std::array<double, N>& out, double lo, double hi,
                          std::string_view unit) {
  numbers_impl(key, out.data(), N, lo, hi, unit);
}

}  // namespace lungar::config
