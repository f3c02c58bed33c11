/// @file ply_writer.h
/// @brief A displaced lung surface as a binary PLY file, the form 3D Slicer, ParaView and MeshLab open.
///
/// Layout: `binary_little_endian 1.0`; `element vertex N` with float properties x y z (the displaced position,
/// mm, LPS) and dx dy dz (the displacement from rest, mm); `element face M` with `list uchar int
/// vertex_indices` (left out for points without triangles: the interior points of `export --interior`); comment
/// lines saying where the surface came from.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "config/base/result.h"

namespace lungar::sim {

struct PlySurface {
  std::span<const float> positions;         ///< 3 per vertex, displaced
  std::span<const float> displacements;     ///< 3 per vertex, from rest
  std::span<const std::uint32_t> triangles; ///< 3 per triangle; empty: a PLY of vertices only
  std::vector<std::string> comments;        ///< one line each, no newlines
};

/// Writes `surface` whole to `path` or leaves nothing there; the error names the file.
Status write_ply(const PlySurface& surface, const std::string& path);

}  // namespace lungar::sim
