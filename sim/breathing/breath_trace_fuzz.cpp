/// @file breath_trace_fuzz.cpp
/// @brief libFuzzer target: the respiratory trace readers (breath_trace.h) on arbitrary bytes, as a CSV and as a
/// Varian RPM .vxp. Each must return a trace or one error line, never crash, hang or read out of bounds; a trace
/// must hold at least two samples, finite, at times that start at zero and increase.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "sim/breathing/breath_trace.h"

namespace {

void check(const lungar::Result<lungar::sim::BreathTrace>& r) {
  if (!r) {
    if (r.error().empty() || r.error().find('\n') != std::string::npos) std::abort();
    return;
  }
  const auto& s = r->samples;
  if (s.size() < 2 || s.front().t_s != 0.0) std::abort();
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!std::isfinite(s[i].t_s) || !std::isfinite(s[i].value)) std::abort();
    if (i > 0 && !(s[i].t_s > s[i - 1].t_s)) std::abort();
  }
  if (r->flagged < 0 || r->peaks_marked < 0) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::istringstream csv(text), vxp(text);
  check(lungar::sim::parse_csv_trace(csv, "fuzz.csv"));
  check(lungar::sim::parse_vxp_trace(vxp, "fuzz.vxp"));
  return 0;
}
