/// @file enum_names.h
/// @brief One enum <-> name table per enum, used by the config loader, to_string() and CLI11's
/// CheckedTransformer alike, so a name is spelled in one place.
/// @ingroup base
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace lungar {

template <class E, std::size_t N>
struct EnumNames {
  std::array<std::pair<E, const char*>, N> entries;

  /// The name of `e` ("?" for a value not in the table, which is a programming error).
  const char* name(E e) const {
    for (const auto& [value, text] : entries) {
      if (value == e) return text;
    }
    return "?";
  }
  std::optional<E> parse(std::string_view text) const {
    for (const auto& [value, name] : entries) {
      if (text == name) return value;
    }
    return std::nullopt;
  }
  /// "a, b or c": what an error message says was expected.
  std::string expected() const {
    std::string out;
    for (std::size_t i = 0; i < N; ++i) {
      if (i > 0) out += i + 1 == N ? " or " : ", ";
      out += entries[i].second;
    }
    return out;
  }
  /// name -> value, the shape CLI11's CheckedTransformer takes.
  std::map<std::string, E> map() const {
    std::map<std::string, E> m;
    for (const auto& [value, text] : entries) m.emplace(text, value);
    return m;
  }
};

}  // namespace lungar
