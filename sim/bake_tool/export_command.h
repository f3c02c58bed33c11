/// @file export_command.h
/// @brief `lungar-bake export`: a baked asset's surface displaced for a posture and a volume change, as PLY
///        (sim/bake_tool/ply_writer.h), one file or one per phase of a breath; with --interior, points inside the
///        lungs moved by the harmonic extension of that surface motion (sim/motion/interior_displacement.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "config/base/result.h"
#include "sim/motion/motion_figures.h"

namespace lungar::sim {

struct ExportCommand {
  std::string asset;                       ///< the .lungbake to read
  std::string posture = "supine";          ///< upright, supine, prone, left-lateral, right-lateral
  std::optional<Eigen::Vector3d> gravity;  ///< lung-frame gravity instead of the posture's (normalised)
  double volume_ml = 500.0;                ///< the pair's enclosed volume change from rest (negative: below it)
  std::string out;                         ///< the .ply to write (with --series: the stem of each phase's file)
  int series = 0;                          ///< > 0: that many phases of one breath of `volume_ml` tidal volume
  std::vector<std::string> pathologies;    ///< specs of sim/pathology/pathology.h, applied in order
  std::optional<int> interior;             ///< that many points uniform over the lungs' volume (> 0; kInteriorSeed)
  std::string interior_out;                ///< their PLY, vertices only (with --series: the stem, as `out`)
  std::vector<std::string> lesions;        ///< "NAME=x,y,z,radius_mm" (sim/motion/lesion.h), each moved and reported
  std::string lesions_out;                 ///< a CSV of each lesion's position in each phase; needs --lesion
};

/// A lesion's displacement in one exported phase.
struct LesionAt {
  std::string name;
  std::string lung;                 ///< the asset's lung name, "left" or "right"
  Eigen::Vector3d centre_mm;        ///< its centre at rest (LPS)
  Eigen::Vector3d displacement_mm;  ///< its centre's, from rest (LPS)
};

/// A lesion's excursion over what was exported (the rest shape included: every breath passes through it).
struct LesionExcursion {
  std::string name;
  std::string lung;
  double peak_to_peak_mm = 0;  ///< the largest distance between two of its positions
  double si_mm = 0;            ///< the cranio-caudal range
};

/// What was written: each file with its volume change.
struct ExportedFile {
  std::string path;
  double phase = 0;      ///< fraction of the breath (0 with no series)
  double volume_ml = 0;  ///< the pair's volume change from rest
  std::string interior_path;               ///< the interior points' PLY written beside it ("" without --interior)
  MotionFigures interior;                  ///< their figures (sim/motion/motion_figures.h), no faces
  std::size_t interior_points = 0;
  std::vector<LesionAt> lesions;  ///< --lesion's, in the order given
};

/// The options' own consistency, before any file is read (the command line exits 2 on it): --interior N needs
/// N > 0 and --interior-out, --interior-out needs --interior, --lesions-out needs --lesion, and the outputs
/// differ. One line naming the option and what was expected.
Status check_export_command(const ExportCommand& command);

/// Writes the PLY file(s), whole or not at all (the interior points' file too: when either of a phase's two files
/// cannot be written, neither is left); the error is one line naming the file and the field.
Result<std::vector<ExportedFile>> run_export_command(const ExportCommand& command);

/// Each lesion's excursion over the exported files: over one breath with --series, from rest to --volume-ml
/// without.
std::vector<LesionExcursion> lesion_excursions(const std::vector<ExportedFile>& written);

/// --lesions-out's CSV: "phase,volume_ml,name,lung,x_mm,y_mm,z_mm,dx_mm,dy_mm,dz_mm", one row per lesion per
/// exported phase, the position displaced (LPS, mm).
std::string lesions_csv(const std::vector<ExportedFile>& written);

/// "FILE.ply" with --series: FILE_000.ply, FILE_001.ply, ...
std::string series_path(const std::string& out, int index);

/// The postures as --posture spells them: the pose names (config/base/patient_names.h) with '-' for '_'
/// ("left-lateral"), in their table's order.
std::vector<std::string> posture_names();

/// "x,y,z" -> a unit vector, or why not (three finite numbers, not all zero).
Result<Eigen::Vector3d> parse_gravity(const std::string& text);

}  // namespace lungar::sim
