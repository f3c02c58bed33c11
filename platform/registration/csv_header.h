/// @file csv_header.h
/// @brief The calibration CSVs' header rule, one for every reader: an optional first line naming the columns,
/// which, when present, must name exactly the expected ones; without it the first line is data.
/// @ingroup platform
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "config/base/result.h"

namespace lungar::platform {

/// What a calibration CSV holds: its columns' names and the words its first column may hold as data (e.g. "left").
struct CsvColumns {
  std::vector<std::string_view> names;
  std::vector<std::string_view> data_words;
  /// "x_mm,y_mm,z_mm": the header as it is written.
  std::string header() const;
};

/// The first line that holds something: true when it is the header (to be skipped), false when it is data. It is a
/// header when its first cell starts with a letter and is not a data word; then its cells (spaces around them
/// ignored) must be exactly the names, else the error "PATH:LINE: header: expected 'x_mm,y_mm,z_mm', got '...'".
Result<bool> is_csv_header(const std::string& line, const CsvColumns& columns, const std::string& path, int line_no);

}  // namespace lungar::platform
