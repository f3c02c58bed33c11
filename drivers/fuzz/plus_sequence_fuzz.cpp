/// @file plus_sequence_fuzz.cpp
/// @brief libFuzzer target: parse_plus_sequence() on arbitrary bytes. It must return a sequence or an error,
/// never crash, hang or read out of bounds, and every transform it returns must be finite.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "drivers/plus/plus_sequence.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  auto r = lungar::drivers::parse_plus_sequence(in, "fuzz.igs.mha");
  if (r) {
    for (const auto& f : r->frames) {
      if (!std::isfinite(f.timestamp_s)) std::abort();
      for (const auto& t : f.transforms)
        if (!t.matrix.allFinite() || t.tool.empty() || t.frame.empty()) std::abort();
    }
  } else if (r.error().empty()) {
    std::abort();
  }
  return 0;
}
