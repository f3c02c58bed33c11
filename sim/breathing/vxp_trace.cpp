/// @file vxp_trace.cpp
/// @brief Varian RPM's `.vxp` respiratory traces (breath_trace.h): the header's keys, the data layout's columns,
/// flagged samples kept and counted, the amplitude in mm, the peaks RPM marked.
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

/// Where the columns lungar reads sit in each data row, from the header's Data_layout.
struct VxpColumns {
  std::string layout;
  std::size_t count = 0;
  int amplitude = -1, timestamp = -1, validflag = -1, mark = -1;
};

/// The header's checks at [Data]: the rate and scale positive, the layout naming amplitude and timestamp.
Result<VxpColumns> vxp_columns(std::map<std::string, std::string>& header, BreathTrace& out) {
  const auto positive = [&](const char* key, double& v) {
    return header.count(key) && number(header[key], v) && v > 0;
  };
  if (!positive("Samples_per_second", out.samples_per_second))
    return fail("Samples_per_second: expected a positive number in the header, got '" + header["Samples_per_second"] +
                "'");
  if (!positive("Scale_factor", out.scale_to_mm))
    return fail("Scale_factor: expected a positive number in the header, got '" + header["Scale_factor"] + "'");
  VxpColumns c;
  c.layout = header["Data_layout"];
  const std::vector<std::string> names = split(c.layout);
  c.count = names.size();
  for (int i = 0; i < static_cast<int>(names.size()); ++i) {
    const std::string& name = names[static_cast<std::size_t>(i)];
    if (name == "amplitude") c.amplitude = i;
    if (name == "timestamp") c.timestamp = i;
    if (name == "validflag") c.validflag = i;
    if (name == "mark") c.mark = i;
  }
  if (c.amplitude < 0 || c.timestamp < 0)
    return fail(
        "Data_layout: expected columns amplitude and timestamp (RPM 1.6: "
        "amplitude,phase,timestamp,validflag,ttlin,mark,ttlout), got '" +
        c.layout + "'");
  return c;
}

/// One data row into `out`: its sample, or its invalid flag counted; `last_ms` the previous row's timestamp.
Status vxp_row(const std::string& line, const VxpColumns& c, BreathTrace& out, double& t0_ms, double& last_ms) {
  const std::vector<std::string> cells = split(line);
  if (cells.size() != c.count)
    return fail("expected " + std::to_string(c.count) + " columns (" + c.layout + "), got '" + line + "'");
  const auto cell = [&](int i) -> const std::string& { return cells[static_cast<std::size_t>(i)]; };
  double amp = 0, ms = 0, valid = 0;
  if (!number(cell(c.amplitude), amp)) return fail("amplitude: expected a number, got '" + line + "'");
  if (!number(cell(c.timestamp), ms)) return fail("timestamp: expected a number of milliseconds, got '" + line + "'");
  if (c.validflag >= 0 && !number(cell(c.validflag), valid))
    return fail("validflag: expected a number, got '" + line + "'");
  if (c.mark >= 0) {
    const std::string& m = cell(c.mark);
    if (!m.empty() && m != "P" && m != "Z") return fail("mark: expected P, Z or nothing, got '" + m + "'");
    out.peaks_marked += m == "P" ? 1 : 0;
  }
  if (out.samples.empty()) {
    t0_ms = last_ms = ms;
  } else if (!(ms > last_ms)) {
    return fail("timestamp: expected times that increase, got '" + line + "'");
  }
  last_ms = ms;
  // A negative validflag is RPM's gating verdict (the breath off its expected pattern or baseline), not a lost
  // signal: the amplitude is still the patient's breathing. Kept, marked, counted.
  out.flagged += valid < 0 ? 1 : 0;
  out.samples.push_back({(ms - t0_ms) / 1000.0, amp * out.scale_to_mm, valid < 0});
  return ok();
}

}  // namespace

Result<BreathTrace> parse_vxp_trace(std::istream& in, const std::string& path) {
  std::string line;
  int line_no = 0;
  const auto at = [&](const std::string& why) { return fail(path + ":" + std::to_string(line_no) + ": " + why); };
  enum class Part { Start, Header, Data } part = Part::Start;
  std::map<std::string, std::string> header;
  VxpColumns columns;
  BreathTrace out;
  out.format = "vxp";
  double t0_ms = 0, last_ms = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    if (part == Part::Start) {
      if (line != "[Header]") return at("expected a Varian RPM file starting with [Header], got '" + line + "'");
      part = Part::Header;
    } else if (part == Part::Header && line == "[Data]") {
      auto c = vxp_columns(header, out);
      if (!c) return at(c.error());
      columns = *c;
      part = Part::Data;
    } else if (part == Part::Header) {
      const auto eq = line.find('=');
      if (eq == std::string::npos) return at("expected Key=Value in the header or [Data], got '" + line + "'");
      header[line.substr(0, eq)] = line.substr(eq + 1);
    } else if (Status row = vxp_row(line, columns, out, t0_ms, last_ms); !row) {
      return at(row.error());
    }
  }
  if (part != Part::Data)
    return fail(path + ": expected a [Header] and a [Data] section, got " +
                (part == Part::Start ? std::string("neither") : std::string("no [Data]")));
  if (out.samples.size() < 2)
    return fail(path + ": expected at least two samples, got " + std::to_string(out.samples.size()));
  return out;
}

}  // namespace lungar::sim
