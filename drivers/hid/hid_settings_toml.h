/// @file hid_settings_toml.h
/// @brief [trackers.hid] as TOML, read and written from one field list (config/toml_visit.h); tracker_config_toml.h
/// visits it inside [trackers].
/// @ingroup drivers
#pragma once

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "config/toml_visit.h"
#include "drivers/hid/hid_settings.h"

namespace lungar::drivers {

namespace hid_toml {
/// "0x02 0x01", "02 01" or "0x02,0x01": one to 4096 bytes, each one or two hex digits with an optional 0x.
inline std::optional<std::vector<std::uint8_t>> parse_hex_bytes(std::string_view text) {
  std::vector<std::uint8_t> out;
  std::size_t pos = 0;
  while (pos < text.size()) {
    if (text[pos] == ' ' || text[pos] == ',' || text[pos] == '\t') {
      ++pos;
      continue;
    }
    if (text.substr(pos, 2) == "0x" || text.substr(pos, 2) == "0X") pos += 2;
    int digits = 0, value = 0;
    for (; pos < text.size() && std::isxdigit(static_cast<unsigned char>(text[pos])); ++pos, ++digits) {
      value = value * 16 +
              (std::isdigit(static_cast<unsigned char>(text[pos])) ? text[pos] - '0' : (text[pos] | 0x20) - 'a' + 10);
    }
    if (digits < 1 || digits > 2 || (pos < text.size() && text[pos] != ' ' && text[pos] != ',')) return std::nullopt;
    out.push_back(static_cast<std::uint8_t>(value));
  }
  if (out.empty() || out.size() > 4096) return std::nullopt;
  return out;
}

/// The reports as parse_hex_bytes() reads them: "0x02 0x01".
inline std::vector<std::string> hex_texts(const std::vector<std::vector<std::uint8_t>>& reports) {
  std::vector<std::string> out;
  for (const auto& bytes : reports) {
    std::string s;
    for (std::uint8_t b : bytes) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "%s0x%02x", s.empty() ? "" : " ", static_cast<unsigned>(b));
      s += buf;
    }
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace hid_toml

/// [trackers.hid].
template <class Io>
void visit(Io& s, HidConfig& h) {
  s.integer("vendor_id", h.vendor_id);
  s.integer("product_id", h.product_id);
  s.text("serial", h.serial);
  s.text("path", h.path);
  s.number("read_timeout_ms", h.read_timeout_ms, 1.0, 1000.0, "ms");
  std::vector<std::string> reports = hid_toml::hex_texts(h.init_feature_reports);
  s.texts("init_feature_reports", reports);
  if constexpr (config::kReads<Io>) {
    std::vector<std::vector<std::uint8_t>> parsed;
    for (std::size_t k = 0; k < reports.size(); ++k) {
      auto bytes = hid_toml::parse_hex_bytes(reports[k]);
      if (!bytes) {
        s.fail("init_feature_reports", "expected hex bytes, report id first (e.g. \"0x02 0x01\"), got \"" + reports[k] +
                                           "\" at index " + std::to_string(k));
      }
      parsed.push_back(std::move(*bytes));
    }
    h.init_feature_reports = std::move(parsed);
  }
  s.finish();
}

}  // namespace lungar::drivers
