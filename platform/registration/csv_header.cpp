/// @file csv_header.cpp
/// @brief The calibration CSVs' optional header line (csv_header.h).
#include "platform/registration/csv_header.h"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace lungar::platform {

namespace {

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

}  // namespace

std::string CsvColumns::header() const {
  std::string h;
  for (std::string_view n : names) h += (h.empty() ? "" : ",") + std::string(n);
  return h;
}

Result<bool> is_csv_header(const std::string& line, const CsvColumns& columns, const std::string& path, int line_no) {
  std::vector<std::string> cells;
  std::stringstream fields(line);
  for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(trimmed(cell));
  if (cells.empty() || cells.front().empty()) return false;
  const std::string& first = cells.front();
  const bool is_word = std::isalpha(static_cast<unsigned char>(first.front())) != 0;
  if (!is_word || std::find(columns.data_words.begin(), columns.data_words.end(), first) != columns.data_words.end()) {
    return false;
  }
  if (std::equal(cells.begin(), cells.end(), columns.names.begin(), columns.names.end())) return true;
  return fail(path + ":" + std::to_string(line_no) + ": header: expected '" + columns.header() + "', got '" +
              trimmed(line) + "'");
}

}  // namespace lungar::platform
