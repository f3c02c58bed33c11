/// @file export_command.cpp
/// @brief Loads the asset, computes the displacement by eq. (7) as the runtime does, and writes PLY.
#include "sim/bake_tool/export_command.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "config/base/atomic_file.h"
#include "sim/asset/asset_io.h"
#include "sim/bake_tool/ply_writer.h"
#include "sim/breathing/driver.h"
#include "sim/breathing/orientation.h"
#include "sim/mesh/tri_mesh.h"
#include "sim/motion/interior_displacement.h"
#include "sim/motion/lesion.h"
#include "sim/motion/motion_figures.h"
#include "sim/pathology/pathology.h"

namespace lungar::sim {
namespace {

Result<Eigen::Vector3d> command_gravity(const ExportCommand& c) {
  if (c.gravity) return *c.gravity;
  std::string name = c.posture;
  std::replace(name.begin(), name.end(), '-', '_');
  const std::optional<Pose> pose = pose_from_name(name);
  if (!pose) {
    const std::vector<std::string> names = posture_names();
    std::string expected;
    for (std::size_t i = 0; i < names.size(); ++i)
      expected += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
    return fail("--posture: expected " + expected + ", got '" + c.posture + "'");
  }
  return gravity_in_lung_frame(pose_rotation(*pose));
}

/// The displacement for `volume_ml`, rescaled so that the pair's enclosed volume changes by exactly that much:
/// the runtime's linear scaling is calibrated at +500 mL (docs/design.md, "Applied force") and drifts from the
/// enclosed volume by the surface's curvature term elsewhere (some 3 % at -300 mL). A few secant steps.
std::vector<float> exact_volume_displacement(const BakedAsset& a, const PatientState& patient, const Eigen::Vector3d& g,
                                             double volume_ml, std::vector<float>& moved) {
  std::vector<float> d = displacement_vectors(a, patient, g, volume_ml);
  const double rest = enclosed_volume(a.triangles, a.positions.data()), target = volume_ml * 1000.0;
  double k = 1.0;
  moved.resize(a.positions.size());
  for (int step = 0; step < 6; ++step) {
    for (std::size_t i = 0; i < moved.size(); ++i) moved[i] = a.positions[i] + static_cast<float>(k) * d[i];
    const double change = enclosed_volume(a.triangles, moved.data()) - rest;
    if (target == 0 || change == 0 || std::abs(change - target) <= 1e-6 * std::abs(target)) break;
    k *= target / change;
  }
  for (std::size_t i = 0; i < d.size(); ++i) d[i] = moved[i] - a.positions[i];
  return d;
}

/// The interior points, the lesions and the field that moves them, built once for every phase of an export.
struct InteriorExport {
  InteriorDisplacement field;
  InteriorPoints points;  ///< --interior's; empty without it
  std::vector<PlacedLesion> lesions;
  InteriorPoints lesion_centres;
  bool write_points = false;
};

/// Writes one phase: the interior points' file first (when asked), then the surface's; when the surface cannot be
/// written the interior file just written is removed, so that a failed phase leaves neither.
Status write_one(const BakedAsset& a, const PatientState& patient, const Eigen::Vector3d& g, double volume_ml,
                 const std::string& path, const std::string& what, const InteriorExport* interior,
                 const std::string& interior_path, ExportedFile& written) {
  std::vector<float> moved;
  const std::vector<float> d = exact_volume_displacement(a, patient, g, volume_ml, moved);
  char line[256];
  std::snprintf(line, sizeof line, "gravity in the lung frame %.4f %.4f %.4f; volume change %.1f mL; model %s",
                g.x(), g.y(), g.z(), volume_ml, kMotionModelNames.name(a.motion_model));
  const std::string frame = "frame: DICOM LPS (+x left, +y posterior, +z superior), mm; dx dy dz: displacement "
                            "from rest, mm";
  if (interior && !interior->lesions.empty()) {
    const std::vector<float> dl = interior->field.displacement(d, interior->lesion_centres);
    for (std::size_t k = 0; k < interior->lesions.size(); ++k) {
      const PlacedLesion& l = interior->lesions[k];
      written.lesions.push_back({l.lesion.name, a.lungs[l.lung].name, l.lesion.centre_mm,
                                 Eigen::Vector3d(dl[3 * k], dl[3 * k + 1], dl[3 * k + 2])});
    }
  }
  if (interior && interior->write_points) {
    const std::vector<float> di = interior->field.displacement(d, interior->points);
    std::vector<float> at(interior->points.positions.size());
    for (std::size_t i = 0; i < at.size(); ++i) at[i] = interior->points.positions[i] + di[i];
    char grid[256];
    std::snprintf(grid, sizeof grid, "%zu points uniform over the lungs' volume (seed %llu), moved by the harmonic "
                  "extension of the surface's motion on a %.2f mm grid", interior->points.size(),
                  static_cast<unsigned long long>(kInteriorSeed), interior->field.spacing_mm());
    PlySurface inside{at, di, {}, {"lungar-bake export of " + what + ": interior points", line, grid, frame}};
    if (Status s = write_ply(inside, interior_path); !s) return s.with_context("--interior-out: ");
    written.interior_path = interior_path;
    written.interior = point_motion_figures(interior->points.positions, di);
    written.interior_points = interior->points.size();
  }
  PlySurface s{moved, d, a.triangles, {"lungar-bake export of " + what, line, frame}};
  for (const BakedLung& lung : a.lungs)
    s.comments.push_back("lung " + lung.name + ": vertices " + std::to_string(lung.first_vertex) + " to " +
                         std::to_string(lung.first_vertex + lung.vertex_count - 1));
  Status status = write_ply(s, path);
  if (!status && interior && interior->write_points) {
    std::error_code ec;
    std::filesystem::remove(interior_path, ec);
  }
  return status;
}

}  // namespace

std::vector<LesionExcursion> lesion_excursions(const std::vector<ExportedFile>& written) {
  std::vector<LesionExcursion> out;
  if (written.empty()) return out;
  for (std::size_t k = 0; k < written.front().lesions.size(); ++k) {
    std::vector<Eigen::Vector3d> path{Eigen::Vector3d::Zero()};  // the rest shape
    for (const ExportedFile& f : written) path.push_back(f.lesions[k].displacement_mm);
    LesionExcursion e{written.front().lesions[k].name, written.front().lesions[k].lung, 0, 0};
    e.peak_to_peak_mm = peak_to_peak_mm(path, e.si_mm);
    out.push_back(e);
  }
  return out;
}

std::string lesions_csv(const std::vector<ExportedFile>& written) {
  std::string csv = "phase,volume_ml,name,lung,x_mm,y_mm,z_mm,dx_mm,dy_mm,dz_mm\n";
  char row[320];
  for (const ExportedFile& f : written)
    for (const LesionAt& l : f.lesions) {
      const Eigen::Vector3d at = l.centre_mm + l.displacement_mm;
      std::snprintf(row, sizeof row, "%.4f,%.3f,%s,%s,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f\n", f.phase, f.volume_ml,
                    l.name.c_str(), l.lung.c_str(), at.x(), at.y(), at.z(), l.displacement_mm.x(),
                    l.displacement_mm.y(), l.displacement_mm.z());
      csv += row;
    }
  return csv;
}

std::string series_path(const std::string& out, int index) {
  const std::size_t dot = out.rfind('.'), slash = out.rfind('/');
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  char number[16];
  std::snprintf(number, sizeof number, "_%03d", index);
  return has_ext ? out.substr(0, dot) + number + out.substr(dot) : out + number + ".ply";
}

std::vector<std::string> posture_names() {
  std::vector<std::string> names;
  for (const auto& [pose, name] : kPoseNames.entries) {
    names.emplace_back(name);
    std::replace(names.back().begin(), names.back().end(), '_', '-');
  }
  return names;
}

Result<Eigen::Vector3d> parse_gravity(const std::string& text) {
  std::istringstream in(text);
  Eigen::Vector3d g;
  char comma1 = 0, comma2 = 0;
  in >> g.x() >> comma1 >> g.y() >> comma2 >> g.z();
  if (!in || comma1 != ',' || comma2 != ',' || !(in >> std::ws).eof() || !g.allFinite() || !(g.norm() > 0))
    return fail("--gravity: expected x,y,z (three numbers, not all zero), got '" + text + "'");
  return Eigen::Vector3d(g.normalized());
}

Status check_export_command(const ExportCommand& c) {
  if (c.interior && *c.interior <= 0)
    return fail("--interior: expected a positive number of points, got " + std::to_string(*c.interior));
  if (!c.interior && !c.interior_out.empty())
    return fail("--interior-out: expected --interior N (the number of interior points to write) with it");
  if (c.interior && c.interior_out.empty())
    return fail("--interior: expected --interior-out FILE (the PLY to write the interior points to) with it");
  if (c.interior && std::filesystem::path(c.interior_out).lexically_normal() ==
                        std::filesystem::path(c.out).lexically_normal())
    return fail("--interior-out: expected a file other than --out's, got '" + c.interior_out + "' for both");
  if (!c.lesions_out.empty() && c.lesions.empty())
    return fail("--lesions-out: expected --lesion NAME=x,y,z,radius_mm (the lesions to write) with it");
  const auto same = [](const std::string& a, const std::string& b) {
    return !a.empty() && std::filesystem::path(a).lexically_normal() == std::filesystem::path(b).lexically_normal();
  };
  if (same(c.lesions_out, c.out) || same(c.lesions_out, c.interior_out))
    return fail("--lesions-out: expected a file other than --out's and --interior-out's, got '" + c.lesions_out + "'");
  return ok();
}

namespace {

/// The PLY file(s) of the export, one per phase, with what each measured; run_export_command() writes the CSV after.
Result<std::vector<ExportedFile>> export_phases(const ExportCommand& c) {
  auto g = command_gravity(c);
  if (!g) return g.with_context("");
  if (!std::isfinite(c.volume_ml)) return fail("--volume-ml: expected a finite number of millilitres");
  Result<BakedAsset> asset = load_asset(c.asset);
  if (!asset) return asset.with_context("");
  PatientState patient = PatientState::of(*asset);
  if (Status s = apply_pathologies(*asset, patient, c.pathologies); !s) return s.with_context("--pathology: ");
  std::string what = c.asset;
  for (const std::string& spec : c.pathologies) what += " with " + spec;
  std::vector<Lesion> lesions;
  for (const std::string& spec : c.lesions) {
    Result<Lesion> l = parse_lesion(spec);
    if (!l) return l.with_context("");
    lesions.push_back(*l);
  }
  std::optional<InteriorExport> interior;
  if (c.interior || !lesions.empty()) {
    interior.emplace(InteriorExport{InteriorDisplacement(*asset), {}, {}, {}, c.interior.has_value()});
    if (c.interior) interior->points = interior->field.sample(static_cast<std::size_t>(*c.interior), kInteriorSeed);
    Result<std::vector<PlacedLesion>> placed = place_lesions(interior->field, lesions);
    if (!placed) return placed.with_context(c.asset + ": ");
    interior->lesions = *placed;
    interior->lesion_centres = lesion_centres(interior->lesions);
  }
  const InteriorExport* inside = interior ? &*interior : nullptr;
  if (c.series <= 0) {
    ExportedFile f;
    f.path = c.out;
    f.volume_ml = c.volume_ml;
    if (Status s = write_one(*asset, patient, *g, c.volume_ml, c.out, what, inside, c.interior_out, f); !s)
      return s.with_context("");
    return std::vector<ExportedFile>{f};
  }
  // One breath of the default pattern with `volume_ml` as its tidal volume, sampled at N phases from the start of
  // an inspiration; the volume change is from the end-expiratory (rest) shape.
  BreathingParams params;
  params.tidal_volume_ml = c.volume_ml;
  Result<BreathingDriver> driver = BreathingDriver::create(params);
  if (!driver) return fail("--volume-ml with --series: " + driver.error());
  const double period = 60.0 / params.rate_bpm;
  std::vector<ExportedFile> written;
  for (int k = 0; k < c.series; ++k) {
    const double phase = static_cast<double>(k) / c.series;
    const double dv = driver->at(phase * period).dv_ml;
    const std::string path = series_path(c.out, k);
    ExportedFile f;
    f.path = path;
    f.phase = phase;
    f.volume_ml = dv;
    const std::string interior_path = c.interior ? series_path(c.interior_out, k) : std::string();
    if (Status s = write_one(*asset, patient, *g, dv, path, what, inside, interior_path, f); !s)
      return s.with_context("");
    written.push_back(f);
  }
  return written;
}

}  // namespace

Result<std::vector<ExportedFile>> run_export_command(const ExportCommand& c) {
  if (Status s = check_export_command(c); !s) return s.with_context("");
  // Checked first, so that an unwritable CSV costs no PLY: the CSV is written last, from what the phases measured.
  if (!c.lesions_out.empty())
    if (Status s = check_writable(c.lesions_out); !s) return s.with_context("--lesions-out: ");
  auto written = export_phases(c);
  if (!written || c.lesions_out.empty()) return written;
  if (Status s = write_file_atomically(c.lesions_out, lesions_csv(*written)); !s)
    return s.with_context("--lesions-out: ");
  return written;
}

}  // namespace lungar::sim
