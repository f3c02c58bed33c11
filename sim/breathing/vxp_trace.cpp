/// @file vxp_trace.cpp
/// @brief Varian RPM's `.vxp` respiratory traces (breath_trace.h): the header's keys, the data layout's columns,
/// invalid samples skipped and counted, the peaks RPM marked.
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>

#include "sim/breathing/breath_trace.h"

namespace lungar::sim {
namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream s(line);
  std::string cell;
  while (std::getline(s, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

bool number(const std::string& text, double& out) {
  char* end = nullptr;
  out = std::strtod(text.c_str(), &end);
  return !text.empty() && *end == '\0' && std::isfinite(out);
}

}  // namespace

Result<BreathTrace> parse_vxp_trace(std::istream& in, const std::string& path) {
  std::string line;
  int line_no = 0;
  const auto at = [&](const std::string& why) { return fail(path + ":" + std::to_string(line_no) + ": " + why); };
  enum class Part { start, header, data } part = Part::start;
  std::map<std::string, std::string> header;
  std::vector<std::string> layout;
  int amplitude = -1, timestamp = -1, validflag = -1, mark = -1;
  BreathTrace out;
  out.format = "vxp";
  double t0_ms = 0, last_ms = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    if (part == Part::start) {
      if (line != "[Header]") return at("expected a Varian RPM file starting with [Header], got '" + line + "'");
      part = Part::header;
      continue;
    }
    if (part == Part::header) {
      if (line == "[Data]") {
        const auto positive = [&](const char* key, double& v) {
          return header.count(key) && number(header[key], v) && v > 0;
        };
        double scale = 0;
        if (!positive("Samples_per_second", out.samples_per_second))
          return at("Samples_per_second: expected a positive number in the header, got '" +
                    header["Samples_per_second"] + "'");
        if (!positive("Scale_factor", scale))
          return at("Scale_factor: expected a positive number in the header, got '" + header["Scale_factor"] + "'");
        layout = split(header["Data_layout"]);
        for (int i = 0; i < static_cast<int>(layout.size()); ++i) {
          const std::string& c = layout[static_cast<std::size_t>(i)];
          if (c == "amplitude") amplitude = i;
          if (c == "timestamp") timestamp = i;
          if (c == "validflag") validflag = i;
          if (c == "mark") mark = i;
        }
        if (amplitude < 0 || timestamp < 0)
          return at(
              "Data_layout: expected columns amplitude and timestamp (RPM 1.6: "
              "amplitude,phase,timestamp,validflag,ttlin,mark,ttlout), got '" +
              header["Data_layout"] + "'");
        part = Part::data;
        continue;
      }
      const auto eq = line.find('=');
      if (eq == std::string::npos) return at("expected Key=Value in the header or [Data], got '" + line + "'");
      header[line.substr(0, eq)] = line.substr(eq + 1);
      continue;
    }
    const std::vector<std::string> cells = split(line);
    if (cells.size() != layout.size())
      return at("expected " + std::to_string(layout.size()) + " columns (" + header["Data_layout"] + "), got '" + line +
                "'");
    double amp = 0, ms = 0, valid = 0;
    if (!number(cells[static_cast<std::size_t>(amplitude)], amp))
      return at("amplitude: expected a number, got '" + line + "'");
    if (!number(cells[static_cast<std::size_t>(timestamp)], ms))
      return at("timestamp: expected a number of milliseconds, got '" + line + "'");
    if (validflag >= 0 && !number(cells[static_cast<std::size_t>(validflag)], valid))
      return at("validflag: expected a number, got '" + line + "'");
    if (mark >= 0) {
      const std::string& m = cells[static_cast<std::size_t>(mark)];
      if (!m.empty() && m != "P" && m != "Z") return at("mark: expected P, Z or nothing, got '" + m + "'");
      out.peaks_marked += m == "P" ? 1 : 0;
    }
    if (out.samples.empty() && out.invalid == 0)
      t0_ms = last_ms = ms;
    else if (!(ms > last_ms))
      return at("timestamp: expected times that increase, got '" + line + "'");
    last_ms = ms;
    if (valid < 0) {
      ++out.invalid;
      continue;
    }
    out.samples.push_back({(ms - t0_ms) / 1000.0, amp});
  }
  if (part != Part::data)
    return fail(path + ": expected a [Header] and a [Data] section, got " +
                (part == Part::start ? std::string("neither") : std::string("no [Data]")));
  if (out.samples.size() < 2)
    return fail(path + ": expected at least two valid samples, got " + std::to_string(out.samples.size()) + " (" +
                std::to_string(out.invalid) + " flagged invalid)");
  return out;
}

}  // namespace lungar::sim
