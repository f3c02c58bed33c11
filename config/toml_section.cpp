/// @file toml_section.cpp
/// @brief Typed, range-checked reads of TOML tables with messages that name file, line and key.
#include "config/toml_section.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "config/base/number_text.h"
#include "config/toml_layers.h"

namespace lungar::config {

namespace {

std::string range_text(double lo, double hi, std::string_view unit) {
  std::string r = "[" + number_text(lo) + ", " + number_text(hi) + "]";
  if (!unit.empty()) r += " " + std::string(unit);
  return r;
}

}  // namespace

Result<toml::table> parse_toml(const std::string& text, const std::string& name) {
  try {
    return toml::parse(text, name);
  } catch (const toml::parse_error& e) {
    const auto& b = e.source().begin;
    return fail(name + ":" + std::to_string(b.line) + ":" + std::to_string(b.column) +
                ": TOML syntax error: " + std::string(e.description()));
  }
}

Result<std::string> read_toml_file(const std::string& path, const char* what) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    return fail(path + ": cannot read the " + what + ": expected a TOML file, " +
                (std::filesystem::exists(path, ec) ? std::string("got something that is not a regular file")
                                                   : std::string("got no such file")));
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream content;
  content << in.rdbuf();
  if (!in.good() && !in.eof()) return fail(path + ": cannot read the " + what + ": read error");
  return content.str();
}

std::string describe(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string: return "the string \"" + std::string(node.as_string()->get()) + "\"";
    case toml::node_type::integer: return "the integer " + std::to_string(node.as_integer()->get());
    case toml::node_type::floating_point:
      return "the number " + number_text(node.as_floating_point()->get());
    case toml::node_type::boolean: return node.as_boolean()->get() ? "true" : "false";
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array of " + std::to_string(node.as_array()->size());
    case toml::node_type::date:
    case toml::node_type::time:
    case toml::node_type::date_time: return "a date/time";
    default: return "nothing";
  }
}

TomlSection::TomlSection(const toml::table* table, std::string path, std::string file)
    : table_(table), path_(std::move(path)), file_(std::move(file)) {}

std::string TomlSection::key_path(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

void TomlSection::fail(std::string_view key, const std::string& message) const {
  // The node's own file: of several merged configs, the one that set the key.
  const toml::node* node = table_ ? table_->get(key) : nullptr;
  if (node == nullptr) node = table_;
  std::string where = node ? source_file(*node, file_) : file_;
  const std::uint32_t line = node ? node->source().begin.line : 0;
  if (line > 0) where += ":" + std::to_string(line);
  throw ConfigError(where + ": key '" + key_path(key) + "': " + message);
}

const toml::node* TomlSection::find(std::string_view key) {
  known_.emplace(key);
  return table_ ? table_->get(key) : nullptr;
}

void TomlSection::number(std::string_view key, double& out, double lo, double hi, std::string_view unit) {
  const toml::node* node = find(key);
  if (!node) return;
  double v = 0;
  if (const auto* i = node->as_integer()) {
    v = static_cast<double>(i->get());
  } else if (const auto* f = node->as_floating_point()) {
    v = f->get();
  } else {
    fail(key, "expected a number in " + range_text(lo, hi, unit) + ", got " + describe(*node));
  }
  if (!(std::isfinite(v) && v >= lo && v <= hi)) {
    fail(key, "expected a number in " + range_text(lo, hi, unit) + ", got " + describe(*node));
  }
  out = v;
}

void TomlSection::integer(std::string_view key, int& out, std::int64_t lo, std::int64_t hi, std::string_view unit) {
  const toml::node* node = find(key);
  if (!node) return;
  const auto* i = node->as_integer();
  const std::string expected = "expected an integer in " + range_text(static_cast<double>(lo), static_cast<double>(hi), unit);
  if (!i || i->get() < lo || i->get() > hi) fail(key, expected + ", got " + describe(*node));
  out = static_cast<int>(i->get());
}

void TomlSection::integer(std::string_view key, std::uint16_t& out) {
  const toml::node* node = find(key);
  if (!node) return;
  const auto* i = node->as_integer();
  if (!i || i->get() < 0 || i->get() > 0xFFFF) {
    fail(key, "expected an integer in [0, 0xFFFF] (a USB id, e.g. 0x1234), got " + describe(*node));
  }
  out = static_cast<std::uint16_t>(i->get());
}

void TomlSection::boolean(std::string_view key, bool& out) {
  const toml::node* node = find(key);
  if (!node) return;
  const auto* b = node->as_boolean();
  if (!b) fail(key, "expected true or false, got " + describe(*node));
  out = b->get();
}

void TomlSection::text(std::string_view key, std::string& out) {
  const toml::node* node = find(key);
  if (!node) return;
  const auto* s = node->as_string();
  if (!s) fail(key, "expected a string, got " + describe(*node));
  out = s->get();
}

void TomlSection::texts(std::string_view key, std::vector<std::string>& out) {
  const toml::node* node = find(key);
  if (!node) return;
  const auto* a = node->as_array();
  if (!a) fail(key, "expected an array of strings, got " + describe(*node));
  std::vector<std::string> v;
  for (std::size_t k = 0; k < a->size(); ++k) {
    const auto* s = (*a)[k].as_string();
    if (!s) fail(key, "expected an array of strings, got " + describe((*a)[k]) + " at index " + std::to_string(k));
    v.push_back(s->get());
  }
  out = std::move(v);
}

void TomlSection::choice(std::string_view key, std::string& out, std::initializer_list<std::string_view> choices) {
  const toml::node* node = find(key);
  if (!node) return;
  std::string expected;
  for (std::string_view c : choices) {
    if (!expected.empty()) expected += " | ";
    expected += '"' + std::string(c) + '"';
  }
  if (const auto* s = node->as_string()) {
    for (std::string_view c : choices) {
      if (s->get() == c) {
        out = s->get();
        return;
      }
    }
  }
  fail(key, "expected one of " + expected + ", got " + describe(*node));
}

void TomlSection::fail_numbers(std::string_view key, std::size_t n, double lo, double hi, std::string_view unit,
                               const std::string& got) const {
  fail(key, "expected an array of " + std::to_string(n) + " numbers in " + range_text(lo, hi, unit) + ", got " + got);
}

void TomlSection::numbers_impl(std::string_view key, double* out, std::size_t n, double lo, double hi,
                               std::string_view unit) {
  const toml::node* node = find(key);
  if (!node) return;
  const auto* arr = node->as_array();
  if (!arr || arr->size() != n) fail_numbers(key, n, lo, hi, unit, describe(*node));
  std::vector<double> values(n);
  for (std::size_t k = 0; k < n; ++k) {
    const toml::node& e = *arr->get(k);
    double v = 0;
    if (const auto* i = e.as_integer()) {
      v = static_cast<double>(i->get());
    } else if (const auto* f = e.as_floating_point()) {
      v = f->get();
    } else {
      fail_numbers(key, n, lo, hi, unit, describe(e) + " at index " + std::to_string(k));
    }
    if (!(std::isfinite(v) && v >= lo && v <= hi)) {
      fail_numbers(key, n, lo, hi, unit, describe(e) + " at index " + std::to_string(k));
    }
    values[k] = v;
  }
  for (std::size_t k = 0; k < n; ++k) out[k] = values[k];
}

TomlSection TomlSection::section(std::string_view key) {
  const toml::node* node = find(key);
  if (node && !node->is_table()) fail(key, "expected a table, got " + describe(*node));
  return TomlSection(node ? node->as_table() : nullptr, key_path(key), file_);
}

void TomlSection::finish() const {
  if (!table_) return;
  for (const auto& [k, v] : *table_) {
    if (known_.count(k.str()) == 0) {
      std::string expected;
      for (const auto& name : known_) {
        if (!expected.empty()) expected += ", ";
        expected += name;
      }
      std::string where = source_file(v, file_);
      const std::uint32_t line = v.source().begin.line > 0 ? v.source().begin.line : k.source().begin.line;
      if (line > 0) where += ":" + std::to_string(line);
      throw ConfigError(where + ": unknown key '" + key_path(k.str()) + "'; expected one of: " + expected);
    }
  }
}

}  // namespace lungar::config
