/// @file extmarker_trace.cpp
/// @brief The ExtMarker data set's marker files (breath_trace.h): real chest and abdomen markers of supine
/// volunteers (Krilavicius et al. 2013/2015, CC BY 4.0), read as they were published so that a user can follow one
/// without converting it, and the tests hold the follower against them.
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "sim/breathing/breath_trace.h"

namespace lungar::sim {
namespace {

/// The share of rows whose time goes back that a file may hold and still be read.
constexpr double kMaxSkippedShare = 0.01;

/// One `;`-separated cell as a number: quotes dropped, a decimal comma read as a point.
bool cell_number(std::string cell, double& out) {
  std::erase(cell, '"');
  for (char& c : cell)
    if (c == ',') c = '.';
  char* end = nullptr;
  out = std::strtod(cell.c_str(), &end);
  return !cell.empty() && *end == '\0' && std::isfinite(out);
}

}  // namespace

Result<BreathTrace> parse_extmarker_trace(std::istream& in, const std::string& path) {
  std::string line;
  int line_no = 0;
  const auto at = [&](const std::string& why) { return fail(path + ":" + std::to_string(line_no) + ": " + why); };
  std::vector<double> t;
  std::vector<Eigen::Vector3d> p;
  BreathTrace out;
  bool header = false;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    if (!header) {
      std::string plain = line;
      std::erase(plain, '"');
      if (plain != "Frame;Timestamp;x;y;z")
        return at("header: expected ExtMarker's \"Frame\";\"Timestamp\";\"x\";\"y\";\"z\", got '" + line + "'");
      header = true;
      continue;
    }
    std::stringstream fields(line);
    std::string cell;
    double v[5];
    int got = 0;
    for (; got < 5 && std::getline(fields, cell, ';'); ++got)
      if (!cell_number(cell, v[got])) return at("expected numbers with decimal commas, got '" + line + "'");
    if (got != 5 || std::getline(fields, cell, ';'))
      return at("expected 5 fields (Frame;Timestamp;x;y;z), got '" + line + "'");
    // Some files of the set end in a row of zeros: the recorder's, not a sample.
    if (v[0] == 0 && v[1] == 0 && v[2] == 0 && v[3] == 0 && v[4] == 0 && !t.empty()) continue;
    const double t_s = v[1] / 1000.0;
    if (!t.empty() && !(t_s > t.back())) {
      // The published files hold a few garbled timestamps (one in ~1,300 rows, e.g. 89,03 amid 44417 and 44617):
      // such a row is dropped and counted, and a file with more of them than kMaxSkippedShare is refused.
      if (out.skipped == 0) out.first_skipped_line = line_no;
      ++out.skipped;
      continue;
    }
    t.push_back(t_s);
    p.emplace_back(v[2], v[3], v[4]);
  }
  if (!header) return fail(path + ": expected ExtMarker's header and samples, got none");
  if (t.size() < 2) return fail(path + ": expected at least two samples, got " + std::to_string(t.size()));
  if (static_cast<double>(out.skipped) > kMaxSkippedShare * static_cast<double>(t.size() + out.skipped))
    return fail(path + ":" + std::to_string(out.first_skipped_line) + ": Timestamp: expected times (ms) that " +
                "increase, got " + std::to_string(out.skipped) + " rows whose time went back (more than 1 %)");
  out.format = "extmarker";
  out.marker = true;
  out.samples = marker_excursion(t, p);
  return out;
}

}  // namespace lungar::sim
