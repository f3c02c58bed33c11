/// @file toml_writer.cpp
/// @brief TOML text from typed fields: tables as a tree, rendered parent keys first.
#include "config/toml_writer.h"

#include <cstdio>

namespace lungar::config {

struct TomlWriter::Table {
  std::string path;  ///< dotted, as in the header: "trackers.report"; empty for the document
  std::string keys;  ///< "key = value\n" lines
  std::vector<std::pair<std::string, std::shared_ptr<Table>>> children;
};

namespace {

/// A key as TOML spells it: bare when it may be, else quoted.
std::string toml_key(std::string_view key) {
  const bool bare = !key.empty() && key.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                                          "0123456789_-") == std::string_view::npos;
  return bare ? std::string(key) : toml_string(key);
}

}  // namespace

std::string toml_number(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  std::string s = buf;
  if (s.find_first_of(".en") == std::string::npos) s += ".0";  // keep TOML floats floats ("nan", "inf" have 'n')
  return s;
}

std::string toml_string(std::string_view v) {
  std::string out = "\"";
  for (char c : v) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

TomlWriter::TomlWriter() : table_(std::make_shared<Table>()) {}
TomlWriter::TomlWriter(std::shared_ptr<Table> table) : table_(std::move(table)) {}

void TomlWriter::put(std::string_view key, const std::string& value) {
  table_->keys += toml_key(key) + " = " + value + "\n";
}

void TomlWriter::number(std::string_view key, double value, double, double, std::string_view) {
  put(key, toml_number(value));
}

void TomlWriter::integer(std::string_view key, int value, std::int64_t, std::int64_t, std::string_view) {
  put(key, std::to_string(value));
}

void TomlWriter::integer(std::string_view key, std::uint16_t value) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%04x", static_cast<unsigned>(value));
  put(key, buf);
}

void TomlWriter::boolean(std::string_view key, bool value) { put(key, value ? "true" : "false"); }

void TomlWriter::text(std::string_view key, const std::string& value) { put(key, toml_string(value)); }

void TomlWriter::texts(std::string_view key, const std::vector<std::string>& values) {
  std::string out = "[";
  for (std::size_t k = 0; k < values.size(); ++k) out += (k > 0 ? ", " : "") + toml_string(values[k]);
  put(key, out + "]");
}

void TomlWriter::choice(std::string_view key, const std::string& value, std::initializer_list<std::string_view>) {
  text(key, value);
}

void TomlWriter::numbers_impl(std::string_view key, const double* values, std::size_t n, double, double,
                              std::string_view) {
  std::string out = "[";
  for (std::size_t k = 0; k < n; ++k) out += (k > 0 ? ", " : "") + toml_number(values[k]);
  put(key, out + "]");
}

TomlWriter TomlWriter::section(std::string_view key) {
  for (const auto& [name, child] : table_->children) {
    if (name == key) return TomlWriter(child);
  }
  auto child = std::make_shared<Table>();
  child->path = (table_->path.empty() ? "" : table_->path + ".") + toml_key(key);
  table_->children.emplace_back(std::string(key), child);
  return TomlWriter(child);
}

std::string TomlWriter::str() const {
  std::string out;
  // A table with no keys of its own but with tables inside ([trackers] above [trackers.stylus]) needs no header:
  // TOML makes it from its children's.
  const bool implicit = table_->keys.empty() && !table_->children.empty();
  if (!table_->path.empty() && !implicit) out += "[" + table_->path + "]\n";
  out += table_->keys;
  for (const auto& [name, child] : table_->children) {
    if (!out.empty()) out += "\n";
    out += TomlWriter(child).str();
  }
  return out;
}

}  // namespace lungar::config
