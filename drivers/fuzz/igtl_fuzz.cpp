/// @file igtl_fuzz.cpp
/// @brief libFuzzer target: the OpenIGTLink message path (header info, decode_igtl_message) on random bytes.
///
/// Byte 0 chooses the layout (axis remap, scale, which names feed roles) and what to do with the rest: take it
/// as one message as it is, or first give it a valid CRC-64 and a body size that matches (through the library's
/// header struct), so that the fuzzer reaches the TRANSFORM, TDATA and QTDATA bodies instead of stopping at the
/// CRC. Properties: no crash or out-of-bounds read (ASan); header info and decoder agree on which bodies are
/// readable; a rejected message carries no pose; an accepted pose is finite, unit and inside the workspace;
/// decoding is deterministic (the same bytes give the same poses, bit for bit, as replay relies on).
#include <igtl_header.h>
#include <igtl_util.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "drivers/igtl/igtl_decoder.h"
#include "drivers/igtl/igtl_messages.h"
#include "drivers/tracker/tracker_config.h"

using namespace lungar;

namespace {

const char* const kRemaps[] = {"x,y,z", "x,-z,y", "-y,x,z", "z,x,y"};
// Short names, so that random bytes name them now and then.
const char* const kNames[] = {"A", "B", "HeadToTracker", ""};

/// Gives `msg` (header + body) a header body size equal to its body and the body's CRC-64.
void fix_header(std::vector<std::uint8_t>& msg) {
  igtl_header h;
  std::memcpy(&h, msg.data(), IGTL_HEADER_SIZE);
  igtl_header_convert_byte_order(&h);  // network -> host
  h.body_size = msg.size() - IGTL_HEADER_SIZE;
  h.crc = crc64(msg.data() + IGTL_HEADER_SIZE, h.body_size, 0);
  igtl_header_convert_byte_order(&h);  // host -> network
  std::memcpy(msg.data(), &h, IGTL_HEADER_SIZE);
}

void check(const drivers::DecodedReport& d, const drivers::IgtlLayout& l) {
  if (d.error != drivers::DecodeError::None && d.count != 0) std::abort();
  if (d.count < 0 || d.count > static_cast<int>(drivers::kRoleCount)) std::abort();
  for (int k = 0; k < d.count; ++k) {
    const auto& p = d.poses[k];
    for (int i = 0; i < 3; ++i) {
      if (!(p.position_mm[i] >= l.world.workspace_min_mm[i] && p.position_mm[i] <= l.world.workspace_max_mm[i])) {
        std::abort();
      }
    }
    if (!(std::abs(p.orientation().norm() - 1.0) <= 1e-9) || p.orientation_wxyz[0] < 0) std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::uint8_t c = data[0];
  drivers::TrackerConfig t;
  t.axis_remap = kRemaps[c & 3];
  t.igtl.scale = (c & 4) ? 1000.0 : 1.0;
  t.igtl.head = kNames[(c >> 3) & 3];
  t.igtl.patient = "PatientToTracker";
  t.igtl.stylus = kNames[(c >> 5) & 3];
  const auto made = drivers::make_igtl_layout(t.igtl, t);
  if (!made) std::abort();  // every layout above is valid
  const drivers::IgtlLayout& l = *made;
  std::vector<std::uint8_t> msg(data + 1, data + size);
  if ((c & 0x80) && msg.size() >= IGTL_HEADER_SIZE) fix_header(msg);
  const auto d = drivers::decode_igtl_message(msg, l);
  check(d, l);
  if (msg.size() >= drivers::kIgtlHeaderBytes) {
    const auto info = drivers::igtl_header_info(
        std::span<const std::uint8_t, drivers::kIgtlHeaderBytes>(msg.data(), drivers::kIgtlHeaderBytes));
    // A message the reader would not buffer never decodes to poses (the reader feeds its header alone).
    if (!info.readable && d.count > 0) std::abort();
    if (info.readable && info.body_size > drivers::kIgtlMaxBody) std::abort();
  }
  const auto again = drivers::decode_igtl_message(msg, l);
  if (again.error != d.error || again.count != d.count || again.device_ticks != d.device_ticks) std::abort();
  for (int k = 0; k < d.count; ++k) {
    const auto &a = again.poses[k], &b = d.poses[k];
    if (a.role != b.role || a.position_mm != b.position_mm || a.orientation_wxyz != b.orientation_wxyz) std::abort();
  }
  return 0;
}

/// With LUNGAR_FUZZ_WRITE_SEEDS=DIR, writes one seed per message type, packed by the library's own classes
/// (scripts/fuzz does this before the first run), each behind a layout byte that keeps its CRC as sent.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  const char* dir = std::getenv("LUNGAR_FUZZ_WRITE_SEEDS");
  if (!dir) return 0;
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  m.topRightCorner<3, 1>() = Eigen::Vector3d(12.5, -300, 1000);
  const std::vector<drivers::IgtlTool> tools = {{"HeadToTracker", m}, {"PatientToTracker", m}, {"B", m}};
  const auto time = drivers::IgtlTime::from_ns(1'700'000'000'000'000'000ull);
  const std::vector<std::vector<std::uint8_t>> seeds = {
      drivers::igtl_transform_message("PatientToTracker", m, time), drivers::igtl_tdata_message("T", tools, time),
      drivers::igtl_qtdata_message("T", tools, time), drivers::igtl_status_message("S", time)};
  for (std::size_t k = 0; k < seeds.size(); ++k) {
    const std::string path = std::string(dir) + "/seed" + std::to_string(k);
    if (std::FILE* f = std::fopen(path.c_str(), "wb")) {
      const std::uint8_t layout = 0x08;  // identity remap, mm, head named, CRC as sent
      std::fwrite(&layout, 1, 1, f);
      std::fwrite(seeds[k].data(), 1, seeds[k].size(), f);
      std::fclose(f);
    }
  }
  return 0;
}
