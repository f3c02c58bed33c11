/// @file freudenthal.cpp
/// @brief The simple-point table: 2^14 link patterns, each judged once by counting components in the link.
#include "sim/voxel/freudenthal.h"

#include <vector>

namespace lungar::sim {
namespace {

/// d is a grid edge when d or -d has components in {0, 1} (and d is not zero).
bool is_edge(int dx, int dy, int dz) {
  const bool up = dx >= 0 && dy >= 0 && dz >= 0 && dx <= 1 && dy <= 1 && dz <= 1;
  const bool down = dx <= 0 && dy <= 0 && dz <= 0 && dx >= -1 && dy >= -1 && dz >= -1;
  return (up || down) && (dx != 0 || dy != 0 || dz != 0);
}

/// The link's edges as neighbour bitmasks: bit m of link[n] is set when neighbours n and m are adjacent.
std::array<std::uint16_t, 14> link_adjacency() {
  std::array<std::uint16_t, 14> link{};
  for (int n = 0; n < 14; ++n)
    for (int m = 0; m < 14; ++m) {
      const auto& a = kFreudenthalOffsets[n];
      const auto& b = kFreudenthalOffsets[m];
      if (n != m && is_edge(a[0] - b[0], a[1] - b[1], a[2] - b[2])) link[n] |= static_cast<std::uint16_t>(1u << m);
    }
  return link;
}

/// Connected components of the neighbours in `set` (a bitmask), along link edges.
int components(std::uint16_t set, const std::array<std::uint16_t, 14>& link) {
  int count = 0;
  std::uint16_t left = set;
  while (left != 0) {
    ++count;
    std::uint16_t front = static_cast<std::uint16_t>(left & -left);  // lowest member
    std::uint16_t seen = front;
    while (front != 0) {
      const int n = __builtin_ctz(front);
      front = static_cast<std::uint16_t>(front & (front - 1));
      const std::uint16_t next = static_cast<std::uint16_t>(link[n] & set & ~seen);
      seen |= next;
      front |= next;
    }
    left = static_cast<std::uint16_t>(left & ~seen);
  }
  return count;
}

std::vector<bool> simple_table() {
  const auto link = link_adjacency();
  std::vector<bool> table(1u << 14);
  for (std::uint32_t p = 0; p < table.size(); ++p) {
    const auto inside = static_cast<std::uint16_t>(p), outside = static_cast<std::uint16_t>(~p & 0x3fffu);
    table[p] = components(inside, link) == 1 && components(outside, link) == 1;
  }
  return table;
}

}  // namespace

bool is_simple_point(std::uint16_t pattern) {
  static const std::vector<bool> table = simple_table();
  return table[pattern & 0x3fffu];
}

}  // namespace lungar::sim
