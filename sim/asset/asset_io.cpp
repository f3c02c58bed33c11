/// @file asset_io.cpp
/// @brief `.lungbake` serialisation: sections with lengths known from the header before anything is allocated,
///        so that a damaged count can never make the loader read or reserve beyond the file.
#include "sim/asset/asset_io.h"

#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "config/base/atomic_file.h"
#include "config/base/crc32.h"

namespace lungar::sim {

static_assert(std::endian::native == std::endian::little, "the asset is little-endian; add byte swapping here");

namespace {

constexpr std::uint32_t kMaxLungs = 16;
constexpr std::uint32_t kMaxNameLength = 64;
constexpr std::uint64_t kMaxLesions = 64;
constexpr auto kMaxLesionName = static_cast<std::uint32_t>(kMaxLesionNameLength);
constexpr std::size_t kHeadSize = 4 * 4 + 8 + 4 * 8;

// ---- writing -----------------------------------------------------------------------------------------------

struct Bytes {
  std::string data;
  /// Appends the values' bytes in order, each as its own type (a record's fixed part in one line).
  template <class... T>
  void put(const T&... values) {
    (data.append(reinterpret_cast<const char*>(&values), sizeof values), ...);
  }
  template <class T>
  void put_array(const T* p, std::size_t n) {
    if (n == 0) return;
    data.append(reinterpret_cast<const char*>(p), n * sizeof(T));
  }
};

/// One section: tag, length, payload, CRC-32 of the payload.
void write_section(AtomicFile& out, const char tag[4], const void* payload, std::size_t size) {
  const std::uint64_t length = size;
  const std::uint32_t crc = crc32(payload, size);
  out.write(tag, 4);
  out.write(&length, sizeof length);
  out.write(payload, size);
  out.write(&crc, sizeof crc);
}
void write_section(AtomicFile& out, const char tag[4], const std::string& payload) {
  write_section(out, tag, payload.data(), payload.size());
}
template <class T>
void write_section(AtomicFile& out, const char tag[4], const std::vector<T>& v) {
  write_section(out, tag, v.data(), v.size() * sizeof(T));
}

std::size_t lung_record_size(std::uint32_t coefficients, std::size_t name_length) {
  return 4 + name_length + 3 * 4 + 4 * 4 + 3 * 8 + 3 * 8 + std::size_t{coefficients} * 4 * (1 + 3 + kPaperAxes * kPaperAngles);
}

// ---- reading -----------------------------------------------------------------------------------------------

class Reader {
 public:
  Reader(std::ifstream& in, std::string path, std::uint64_t file_size)
      : in_(in), path_(std::move(path)), left_(file_size) {}

  bool fail(std::string message) {
    if (error_.empty()) error_ = path_ + ": " + std::move(message);
    return false;
  }
  const std::string& error() const { return error_; }

  bool raw(void* dst, std::uint64_t n, const char* what) {
    if (n > left_) {
      std::ostringstream m;
      m << "truncated in " << what << ": expected " << n << " more bytes, the file has " << left_;
      return fail(m.str());
    }
    in_.read(static_cast<char*>(dst), static_cast<std::streamsize>(n));
    if (!in_) return fail(std::string("read error in ") + what);
    left_ -= n;
    return true;
  }

  /// Reads section `tag` whose payload must be exactly `expected` bytes (or `optional_empty` and none); checks its
  /// CRC.
  bool section(const char tag[4], std::uint64_t expected, std::string& payload, bool optional_empty = false) {
    return section_within(tag, expected, expected, payload, optional_empty);
  }

  /// The same for a section of variable length, from `least` to `most` bytes.
  bool section_within(const char tag[4], std::uint64_t least, std::uint64_t most, std::string& payload,
                      bool optional_empty = false) {
    const std::string name = std::string("section '") + std::string(tag, 4) + "'";
    char found[4];
    std::uint64_t length = 0;
    if (!raw(found, 4, (name + " tag").c_str())) return false;
    if (std::memcmp(found, tag, 4) != 0) {
      std::string shown;
      for (char c : found) shown += (c >= 32 && c < 127) ? c : '?';
      return fail(name + ": expected tag '" + std::string(tag, 4) + "', found '" + shown + "'");
    }
    if (!raw(&length, sizeof length, (name + " length").c_str())) return false;
    if ((length < least || length > most) && !(optional_empty && length == 0)) {
      std::ostringstream m;
      m << name << ": length " << length << " bytes; expected ";
      if (least == most)
        m << least << (optional_empty ? " (or 0)" : "") << " from the header's counts";
      else
        m << least << " to " << most;
      return fail(m.str());
    }
    if (length + 4 > left_) {
      std::ostringstream m;
      m << name << ": truncated: expected " << length + 4 << " bytes, the file has " << left_;
      return fail(m.str());
    }
    payload.resize(length);
    if (!raw(payload.data(), length, name.c_str())) return false;
    std::uint32_t stored = 0;
    if (!raw(&stored, sizeof stored, (name + " CRC").c_str())) return false;
    const std::uint32_t computed = crc32(payload.data(), payload.size());
    if (stored != computed) {
      char m[160];
      std::snprintf(m, sizeof m, "%s: CRC-32 mismatch (stored %08x, computed %08x); the file is damaged",
                    name.c_str(), stored, computed);
      return fail(m);
    }
    return true;
  }

  std::uint64_t left() const { return left_; }

 private:
  std::ifstream& in_;
  std::string path_;
  std::uint64_t left_;
  std::string error_;
};

/// Sequential reads from a validated payload.
struct Cursor {
  const std::string& s;
  std::size_t at = 0;
  template <class T>
  T get() {
    T v;
    std::memcpy(&v, s.data() + at, sizeof v);
    at += sizeof v;
    return v;
  }
  /// Reads the fields in order, each in its own type (a record's fixed part in one line).
  template <class... T>
  void get_all(T&... fields) {
    ((fields = get<T>()), ...);
  }
  template <class T>
  void get_array(std::vector<T>& v, std::size_t n) {
    v.resize(n);
    if (n > 0) std::memcpy(v.data(), s.data() + at, n * sizeof(T));
    at += n * sizeof(T);
  }
};

template <class T>
void payload_to(const std::string& payload, std::vector<T>& v) {
  v.resize(payload.size() / sizeof(T));
  if (!payload.empty()) std::memcpy(v.data(), payload.data(), payload.size());
}

bool all_finite(const std::vector<float>& v) {
  for (float x : v)
    if (!std::isfinite(x)) return false;
  return true;
}

}  // namespace

std::string validate_asset(const BakedAsset& a) {
  const std::size_t n = a.lung_of_vertex.size(), c = a.coefficients();
  if (a.bands < 1 || a.bands > 8) return "bands: expected 1 to 8, found " + std::to_string(a.bands);
  if (a.lungs.empty() || a.lungs.size() > kMaxLungs) return "lung count: expected 1 to 16";
  if (a.positions.size() != 3 * n || a.normals.size() != 3 * n || a.directions.size() != 3 * n || a.areas.size() != n ||
      a.sh_coeffs.size() != c * n || a.linear_coeffs.size() != 4 * n || (a.has_off_axis() && a.off_axis.size() != 12 * n) ||
      (a.has_sphere_dirs() && a.sphere_dirs.size() != 3 * n))
    return "per-vertex arrays: sizes disagree with the vertex count " + std::to_string(n);
  if ((a.motion_model == MotionModel::sliding) != a.has_off_axis())
    return "off_axis: expected 12 values a vertex for the sliding model and none for the paper's";
  if (a.triangles.size() % 3 != 0) return "triangles: expected 3 indices a triangle";
  for (std::size_t i = 0; i < a.triangles.size(); ++i)
    if (a.triangles[i] >= n)
      return "triangles: index " + std::to_string(a.triangles[i]) + " at " + std::to_string(i) +
             "; expected below the vertex count " + std::to_string(n);
  std::uint64_t next_vertex = 0, next_index = 0;
  for (std::size_t l = 0; l < a.lungs.size(); ++l) {
    const BakedLung& lung = a.lungs[l];
    const std::string who = "lung " + std::to_string(l) + " ('" + lung.name + "')";
    if (lung.first_vertex != next_vertex || lung.vertex_count == 0)
      return who + ": vertex range must follow the previous lung's and be non-empty";
    if (lung.first_index != next_index || lung.index_count % 3 != 0)
      return who + ": index range must follow the previous lung's, 3 indices a triangle";
    next_vertex += lung.vertex_count;
    next_index += lung.index_count;
    if (next_vertex > n || next_index > a.triangles.size()) return who + ": range beyond the arrays";
    for (std::size_t i = lung.first_vertex; i < next_vertex; ++i)
      if (a.lung_of_vertex[i] != l) return who + ": lung_of_vertex disagrees with the lung's vertex range";
    for (std::size_t i = lung.first_index; i < next_index; ++i)
      if (a.triangles[i] < lung.first_vertex || a.triangles[i] >= next_vertex)
        return who + ": a triangle uses another lung's vertex";
    if (lung.force_const.size() != c || lung.paper_force.size() != kPaperAxes * kPaperAngles)
      return who + ": force SH: expected " + std::to_string(c) + " coefficients";
    for (const auto& f : lung.force_grad)
      if (f.size() != c) return who + ": force gradient SH: expected " + std::to_string(c) + " coefficients";
    for (const auto& f : lung.paper_force)
      if (f.size() != c) return who + ": paper force SH: expected " + std::to_string(c) + " coefficients";
    if (!(lung.volume_const > 0) || !std::isfinite(lung.volume_const))
      return who + ": volume_const: expected a positive swept volume";
    if (!(lung.volume_share > 0 && lung.volume_share <= 1)) return who + ": volume_share: expected (0, 1]";
  }
  if (next_vertex != n || next_index != a.triangles.size()) return "lungs: ranges do not cover every vertex and triangle";
  if (!all_finite(a.positions) || !all_finite(a.normals) || !all_finite(a.directions) || !all_finite(a.areas) ||
      !all_finite(a.sh_coeffs) ||
      !all_finite(a.linear_coeffs) || !all_finite(a.off_axis) || !all_finite(a.sphere_dirs))
    return "per-vertex arrays: expected finite numbers";
  if (a.lesions.size() > kMaxLesions) return "lesions: expected at most " + std::to_string(kMaxLesions);
  for (std::size_t k = 0; k < a.lesions.size(); ++k) {
    const BakedLesion& l = a.lesions[k];
    const std::string who = "lesion " + std::to_string(k) + " '" + l.name + "'";
    if (!lesion_name_ok(l.name)) return who + ": expected a name of 1 to 32 letters, digits, '_' or '-'";
    if (l.lung >= a.lungs.size())
      return who + ": lung " + std::to_string(l.lung) + "; expected below " + std::to_string(a.lungs.size());
    if (!std::isfinite(l.centre_mm[0]) || !std::isfinite(l.centre_mm[1]) || !std::isfinite(l.centre_mm[2]))
      return who + ": expected a finite centre";
    if (!(l.radius_mm > 0 && l.radius_mm <= kMaxLesionRadiusMm))
      return who + ": radius: expected above 0 and at most " + std::to_string(static_cast<int>(kMaxLesionRadiusMm)) +
             " mm";
    for (std::size_t j = 0; j < k; ++j)
      if (a.lesions[j].name == l.name) return who + ": expected each name once";
  }
  if (a.has_transfer_rows()) {
    if (a.transfer_row_ptr.size() != n + 1 || a.transfer_row_ptr.front() != 0 ||
        a.transfer_row_ptr.back() != a.transfer_cols.size() || a.transfer_cols.size() != a.transfer_vals.size())
      return "transfer rows: row offsets disagree with the vertex count or the non-zero count";
    if (a.transfer_cols.size() >= (1u << 31)) return "transfer rows: expected fewer than 2^31 non-zeros";
    for (std::size_t i = 0; i < n; ++i)
      if (a.transfer_row_ptr[i] > a.transfer_row_ptr[i + 1]) return "transfer rows: row offsets must not decrease";
    for (std::uint32_t col : a.transfer_cols)
      if (col >= n) return "transfer rows: column " + std::to_string(col) + "; expected below the vertex count";
    if (!all_finite(a.transfer_vals)) return "transfer rows: expected finite values";
  } else if (!a.transfer_cols.empty() || !a.transfer_vals.empty()) {
    return "transfer rows: values without row offsets";
  }
  return "";
}

Status write_asset(const BakedAsset& a, const std::string& path) {
  if (std::string bad = validate_asset(a); !bad.empty()) {
    return fail(path + ": refusing to write an unsound asset: " + bad);
  }
  AtomicFile out;
  if (Status opened = out.open(path); !opened) return opened;
  const std::uint32_t c = a.coefficients();
  out.write(kAssetMagic, sizeof kAssetMagic);
  out.write(&kAssetVersion, sizeof kAssetVersion);
  Bytes head;
  head.put(a.bands, a.vertex_count(), static_cast<std::uint32_t>(a.triangles.size() / 3),
           static_cast<std::uint32_t>(a.lungs.size()), static_cast<std::uint64_t>(a.transfer_vals.size()), a.p0,
           a.gamma_per_mm, a.decay_length_mm, a.transfer_epsilon);
  write_section(out, "HEAD", head.data);
  Bytes model;
  model.put(static_cast<std::uint32_t>(a.motion_model));
  write_section(out, "MODL", model.data);
  Bytes lungs;
  for (const BakedLung& l : a.lungs) {
    const auto name_length = static_cast<std::uint32_t>(std::min<std::size_t>(l.name.size(), kMaxNameLength));
    lungs.put(name_length);
    lungs.data.append(l.name.data(), name_length);
    lungs.put_array(l.centre.data(), 3);
    lungs.put(l.first_vertex, l.vertex_count, l.first_index, l.index_count, l.rest_volume_ml, l.volume_share,
              l.volume_const);
    lungs.put_array(l.volume_grad.data(), 3);
    lungs.put_array(l.force_const.data(), c);
    for (const auto& f : l.force_grad) lungs.put_array(f.data(), c);
    for (const auto& f : l.paper_force) lungs.put_array(f.data(), c);
  }
  write_section(out, "LUNG", lungs.data);
  write_section(out, "POSI", a.positions);
  write_section(out, "NORM", a.normals);
  write_section(out, "MDIR", a.directions);
  write_section(out, "AREA", a.areas);
  write_section(out, "LOFV", a.lung_of_vertex);
  write_section(out, "SHCO", a.sh_coeffs);
  write_section(out, "LINC", a.linear_coeffs);
  write_section(out, "OFFA", a.off_axis);
  write_section(out, "SDIR", a.sphere_dirs);
  write_section(out, "TRIS", a.triangles);
  write_section(out, "TROW", a.transfer_row_ptr);
  write_section(out, "TCOL", a.transfer_cols);
  write_section(out, "TVAL", a.transfer_vals);
  Bytes lesions;
  lesions.put(static_cast<std::uint32_t>(a.lesions.size()));
  for (const BakedLesion& l : a.lesions) {
    lesions.put(static_cast<std::uint32_t>(l.name.size()));
    lesions.data.append(l.name);
    lesions.put(l.lung, static_cast<std::uint32_t>(l.from_label ? 1 : 0));
    lesions.put_array(l.centre_mm.data(), 3);
    lesions.put(l.radius_mm);
  }
  write_section(out, "LESN", lesions.data);
  return out.commit();
}

namespace {

/// The counts the header declares, checked against each other and the file's size before anything is allocated.
struct HeadCounts {
  std::uint32_t version = 0;
  std::uint32_t vertices = 0, triangles = 0, lungs = 0;
  std::uint64_t nnz = 0;
};

Result<HeadCounts> read_head(Reader& r, const std::string& path, BakedAsset& a) {
  char magic[8];
  if (!r.raw(magic, 8, "magic")) return fail(r.error());
  if (std::memcmp(magic, kAssetMagic, 8) != 0) {
    return fail(path + ": magic: expected 'LUNGBAKE'; this is not a lungar baked asset");
  }
  std::uint32_t version = 0;
  if (!r.raw(&version, 4, "version")) return fail(r.error());
  if (version < 1 || version > kAssetVersion) {
    return fail(path + ": version: expected 1 to " + std::to_string(kAssetVersion) + ", found " +
                std::to_string(version) + " (re-bake with this lungar-bake)");
  }
  std::string payload;
  if (!r.section("HEAD", kHeadSize, payload)) return fail(r.error());
  HeadCounts h;
  h.version = version;
  Cursor cur{payload};
  cur.get_all(a.bands, h.vertices, h.triangles, h.lungs, h.nnz, a.p0, a.gamma_per_mm, a.decay_length_mm,
              a.transfer_epsilon);
  if (a.bands < 1 || a.bands > 8) {
    return fail(path + ": header field 'bands': expected 1 to 8, found " + std::to_string(a.bands));
  }
  if (h.lungs < 1 || h.lungs > kMaxLungs) {
    return fail(path + ": header field 'lungs': expected 1 to 16, found " + std::to_string(h.lungs));
  }
  if (h.vertices == 0) return fail(path + ": header field 'vertices': expected at least one vertex");
  // Every vertex needs more than 16 bytes of the file; this bounds the counts before anything is allocated.
  const std::uint64_t c = a.bands * a.bands;
  if (std::uint64_t{h.vertices} * (29 + 4 * c) + std::uint64_t{h.triangles} * 12 + h.nnz * 8 > r.left()) {
    return fail(path + ": header counts (" + std::to_string(h.vertices) + " vertices, " + std::to_string(h.triangles) +
                " triangles, " + std::to_string(h.nnz) + " transfer non-zeros) need more bytes than the file has");
  }
  if (!std::isfinite(a.p0) || !std::isfinite(a.gamma_per_mm) || !(a.decay_length_mm > 0)) {
    return fail(path + ": header fields 'p0', 'gamma', 'decay_length': expected finite numbers, l > 0");
  }
  if (version >= 2) {
    if (!r.section("MODL", 4, payload)) return fail(r.error());
    std::uint32_t model = 0;
    std::memcpy(&model, payload.data(), 4);
    if (model > static_cast<std::uint32_t>(MotionModel::sliding))
      return fail(path + ": section 'MODL': motion model " + std::to_string(model) + "; expected 0 (paper) or 1 (sliding)");
    a.motion_model = static_cast<MotionModel>(model);
  }
  return h;
}

/// One lung's record of the LUNG section; `l` and `remaining` for the messages.
Result<BakedLung> read_lung(Cursor& lc, const std::string& payload, std::uint64_t c, std::uint32_t l,
                            const std::string& path) {
  BakedLung lung;
  const std::size_t remaining = payload.size() - lc.at;
  if (remaining < 4) return fail(path + ": section 'LUNG': lung " + std::to_string(l) + " record truncated");
  const auto name_length = lc.get<std::uint32_t>();
  if (name_length > kMaxNameLength || lung_record_size(static_cast<std::uint32_t>(c), name_length) > remaining) {
    return fail(path + ": section 'LUNG': lung " + std::to_string(l) + " name length " + std::to_string(name_length) +
                "; expected at most " + std::to_string(kMaxNameLength) + " within the section");
  }
  lung.name.assign(payload.data() + lc.at, name_length);
  lc.at += name_length;
  for (float& x : lung.centre) x = lc.get<float>();
  lc.get_all(lung.first_vertex, lung.vertex_count, lung.first_index, lung.index_count, lung.rest_volume_ml,
             lung.volume_share, lung.volume_const);
  for (double& x : lung.volume_grad) x = lc.get<double>();
  lc.get_array(lung.force_const, c);
  for (auto& f : lung.force_grad) lc.get_array(f, c);
  lung.paper_force.resize(kPaperAxes * kPaperAngles);
  for (auto& f : lung.paper_force) lc.get_array(f, c);
  return lung;
}

/// LUNG: variable-length names, so its length is read first and checked against the lung count.
Status read_lungs(Reader& r, const std::string& path, std::uint32_t count, std::uint64_t c, BakedAsset& a) {
  char tag[4];
  std::uint64_t length = 0;
  if (!r.raw(tag, 4, "section 'LUNG' tag")) return fail(r.error());
  if (std::memcmp(tag, "LUNG", 4) != 0) return fail(path + ": section 'LUNG': expected tag 'LUNG'");
  if (!r.raw(&length, 8, "section 'LUNG' length")) return fail(r.error());
  const std::uint64_t min_len = count * lung_record_size(static_cast<std::uint32_t>(c), 0);
  const std::uint64_t max_len = count * lung_record_size(static_cast<std::uint32_t>(c), kMaxNameLength);
  if (length < min_len || length > max_len) {
    return fail(path + ": section 'LUNG': length " + std::to_string(length) + " bytes; expected " +
                std::to_string(min_len) + " to " + std::to_string(max_len) + " for " + std::to_string(count) +
                " lungs");
  }
  std::string payload(length, '\0');
  if (!r.raw(payload.data(), length, "section 'LUNG'")) return fail(r.error());
  std::uint32_t stored = 0;
  if (!r.raw(&stored, 4, "section 'LUNG' CRC")) return fail(r.error());
  if (stored != crc32(payload.data(), payload.size())) {
    return fail(path + ": section 'LUNG': CRC-32 mismatch; the file is damaged");
  }
  Cursor lc{payload};
  for (std::uint32_t l = 0; l < count; ++l) {
    auto lung = read_lung(lc, payload, c, l, path);
    if (!lung) return lung.with_context("");
    a.lungs.push_back(lung.take());
  }
  if (lc.at != payload.size()) return fail(path + ": section 'LUNG': trailing bytes after the last lung");
  return ok();
}

/// The per-vertex, triangle and transfer-row sections, each of the size the header's counts give.
Status read_arrays(Reader& r, const HeadCounts& h, std::uint64_t c, BakedAsset& a) {
  const std::uint64_t n = h.vertices;
  const bool rows = h.nnz > 0;
  std::string payload;
  auto read_into = [&](const char* tag, std::uint64_t bytes, auto& vec, bool optional_empty = false) {
    if (!r.section(tag, bytes, payload, optional_empty)) return false;
    payload_to(payload, vec);
    return true;
  };
  if (!read_into("POSI", 12 * n, a.positions) || !read_into("NORM", 12 * n, a.normals) ||
      (h.version >= 2 && !read_into("MDIR", 12 * n, a.directions)) || !read_into("AREA", 4 * n, a.areas) || !read_into("LOFV", n, a.lung_of_vertex) ||
      !read_into("SHCO", 4 * n * c, a.sh_coeffs) || !read_into("LINC", 16 * n, a.linear_coeffs) ||
      (h.version >= 2 && !read_into("OFFA", a.motion_model == MotionModel::sliding ? 48 * n : 0, a.off_axis)) ||
      (h.version >= 3 && !read_into("SDIR", 12 * n, a.sphere_dirs, true)) ||
      !read_into("TRIS", 12ull * h.triangles, a.triangles) ||
      !read_into("TROW", rows ? 4 * (n + 1) : 0, a.transfer_row_ptr) || !read_into("TCOL", 4 * h.nnz, a.transfer_cols) ||
      !read_into("TVAL", 4 * h.nnz, a.transfer_vals)) {
    return fail(r.error());
  }
  if (h.version < 2) a.directions = a.normals;  // version 1: the paper's model, every vertex along its normal
  return ok();
}

/// LESN (version 4 on): the lesions baked with the lungs; each record's own bounds are checked here, what they mean
/// (a lung that exists, a radius in range) by validate_asset.
Status read_lesions(Reader& r, const std::string& path, BakedAsset& a) {
  constexpr std::uint64_t kFixed = 4 + 4 + 4 + 4 * 8;  // name length, lung, flags, centre and radius
  std::string payload;
  if (!r.section_within("LESN", 4, 4 + kMaxLesions * (kFixed + kMaxLesionName), payload)) return fail(r.error());
  Cursor lc{payload};
  const auto count = lc.get<std::uint32_t>();
  for (std::uint32_t k = 0; k < count; ++k) {
    const std::string who = path + ": section 'LESN': lesion " + std::to_string(k);
    if (payload.size() - lc.at < kFixed) return fail(who + ": record truncated");
    const auto name_length = lc.get<std::uint32_t>();
    if (name_length > kMaxLesionName || payload.size() - lc.at < name_length + kFixed - 4)
      return fail(who + ": name length " + std::to_string(name_length) + "; expected at most " +
                  std::to_string(kMaxLesionName) + " within the section");
    BakedLesion l;
    l.name.assign(payload.data() + lc.at, name_length);
    lc.at += name_length;
    l.lung = lc.get<std::uint32_t>();
    const auto flags = lc.get<std::uint32_t>();
    if (flags > 1) return fail(who + ": flags " + std::to_string(flags) + "; expected 0 or 1 (from a label)");
    l.from_label = flags == 1;
    for (double& x : l.centre_mm) x = lc.get<double>();
    l.radius_mm = lc.get<double>();
    a.lesions.push_back(std::move(l));
  }
  if (lc.at != payload.size()) return fail(path + ": section 'LESN': trailing bytes after the last lesion");
  return ok();
}

}  // namespace

Result<BakedAsset> load_asset(const std::string& path) {
  std::error_code ec;
  const std::uint64_t size = std::filesystem::file_size(path, ec);
  if (ec) return fail(path + ": cannot open: " + ec.message());
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(path + ": cannot open for reading");
  Reader r(in, path, size);
  BakedAsset a;
  auto head = read_head(r, path, a);
  if (!head) return head.with_context("");
  const std::uint64_t c = a.bands * a.bands;
  if (Status lungs = read_lungs(r, path, head->lungs, c, a); !lungs) return lungs.with_context("");
  if (Status arrays = read_arrays(r, *head, c, a); !arrays) return arrays.with_context("");
  if (head->version >= 4)
    if (Status lesions = read_lesions(r, path, a); !lesions) return lesions.with_context("");
  if (r.left() != 0) return fail(path + ": " + std::to_string(r.left()) + " unexpected bytes after the last section");
  if (std::string bad = validate_asset(a); !bad.empty()) return fail(path + ": " + bad);
  return a;
}

}  // namespace lungar::sim
