/// @file ply_writer.cpp
/// @brief The PLY header in ASCII, then the vertex records and the faces in little-endian binary.
#include "sim/bake_tool/ply_writer.h"

#include <bit>
#include <cstdint>
#include <cstring>

#include "config/base/atomic_file.h"

namespace lungar::sim {

Status write_ply(const PlySurface& s, const std::string& path) {
  static_assert(std::endian::native == std::endian::little, "the PLY body is written as the machine stores it");
  const std::size_t n = s.positions.size() / 3, faces = s.triangles.size() / 3;
  if (s.displacements.size() != 3 * n || s.positions.size() % 3 != 0 || s.triangles.size() % 3 != 0)
    return fail(path + ": internal error: positions, displacements and triangles disagree in size");
  AtomicFile out;
  if (Status opened = out.open(path); !opened) return opened;
  std::string head = "ply\nformat binary_little_endian 1.0\n";
  for (const std::string& c : s.comments) head += "comment " + c + "\n";
  head += "element vertex " + std::to_string(n) + "\n";
  for (const char* p : {"x", "y", "z", "dx", "dy", "dz"}) head += std::string("property float ") + p + "\n";
  if (faces > 0) head += "element face " + std::to_string(faces) + "\nproperty list uchar int vertex_indices\n";
  head += "end_header\n";
  out.write(head);
  std::vector<char> body(n * 24 + faces * 13);
  char* at = body.data();
  for (std::size_t i = 0; i < n; ++i) {
    std::memcpy(at, s.positions.data() + 3 * i, 12);
    std::memcpy(at + 12, s.displacements.data() + 3 * i, 12);
    at += 24;
  }
  for (std::size_t t = 0; t < faces; ++t) {
    *at++ = 3;
    for (int k = 0; k < 3; ++k) {
      const auto index = static_cast<std::int32_t>(s.triangles[3 * t + k]);
      std::memcpy(at, &index, 4);
      at += 4;
    }
  }
  out.write(body.data(), body.size());
  return out.commit();
}

}  // namespace lungar::sim
