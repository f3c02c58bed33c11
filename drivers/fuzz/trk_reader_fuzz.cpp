/// @file trk_reader_fuzz.cpp
/// @brief libFuzzer target: parse_trk() on arbitrary bytes. It must return a log or an error, never crash or
/// read out of bounds, and every record it returns must lie inside the input.
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "drivers/trk/trk_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace lungar::drivers;
  auto r = parse_trk(std::vector<std::uint8_t>(data, data + size), "fuzz.trk");
  if (r) {
    const auto& bytes = r->bytes;
    for (const TrkRecord& rec : r->records) {
      if (rec.report.data() < bytes.data() || rec.report.data() + rec.report.size() > bytes.data() + bytes.size()) {
        std::abort();
      }
    }
    (void)r->header.field("vendor_id");
  } else if (r.error().empty()) {
    std::abort();
  }
  return 0;
}
