/// @file asset_io.h
/// @brief Reads and writes `.lungbake` files.
///
/// Layout (little-endian): magic "LUNGBAKE", u32 version, then sections, each a 4-character tag, a u64
/// payload length, the payload and the payload's CRC-32. Sections, in order: HEAD (bands, vertex, triangle and
/// lung counts, transfer nnz, p0, gamma, l, epsilon), MODL (u32 motion model: 0 paper, 1 sliding), LUNG (per-lung
/// records), POSI, NORM, MDIR (each vertex's direction of motion), AREA, LOFV, SHCO, LINC, OFFA (the sliding model's
/// off-axis linear basis, 12 floats a vertex; empty for the paper's model), SDIR (each vertex's point u_I on the
/// sphere of the SH fit, 3 floats a vertex, or empty), TRIS, TROW, TCOL, TVAL (the last three empty when the asset
/// holds no explicit transfer rows). Version 1 files (no MODL, no MDIR) still load, as the paper's model with
/// directions equal to the normals; version 1 and 2 files (no SDIR) load without sphere points, so that no force
/// pattern beyond the linear pressure (ARDS) can be projected onto their SH (sim/force/dependent_collapse.h).
/// Version 4 adds LESN after TVAL: a u32 count, then per lesion a u32 name length, the name, the u32 lung index and
/// a u32 of flags (1: from a
/// label), four f64 (centre x, y, z, radius; mm); earlier versions load with no lesion.
#pragma once

#include <string>

#include "sim/asset/baked_asset.h"
#include "config/base/result.h"

namespace lungar::sim {

inline constexpr char kAssetMagic[8] = {'L', 'U', 'N', 'G', 'B', 'A', 'K', 'E'};
inline constexpr std::uint32_t kAssetVersion = 4;

/// Writes `asset` to a temporary file beside `path` and renames it into place: `path` is either the whole new
/// asset or untouched. The error names the file.
Status write_asset(const BakedAsset& asset, const std::string& path);

/// Reads and validates every count, size, CRC and index; the error is one line naming the file, the section
/// or field, and what was expected.
Result<BakedAsset> load_asset(const std::string& path);

/// Checks an in-memory asset's internal consistency (array sizes, ranges, indices); "" when sound.
std::string validate_asset(const BakedAsset& asset);

}  // namespace lungar::sim
