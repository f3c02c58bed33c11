/// @file report_json.cpp
/// @brief BakeReport -> JSON.
#include "sim/bake_tool/report_json.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "lungar/version.h"

namespace lungar::sim {

namespace {

/// {"bands", "coefficients", "eq7_rms_rel_error" (the asset's map), "by_map": {map: error}} per band count.
nlohmann::json sweep_json(const std::vector<BandsSweepEntry>& sweep) {
  nlohmann::json out = nlohmann::json::array();
  for (const BandsSweepEntry& e : sweep) {
    nlohmann::json by_map = nlohmann::json::object();
    for (const MapError& m : e.by_map) by_map[kSphereMapNames.name(m.map)] = m.eq7_rms_rel_error;
    out.push_back({{"bands", e.bands}, {"coefficients", e.coefficients}, {"eq7_rms_rel_error", e.eq7_rms_rel_error},
                   {"by_map", by_map}});
  }
  return out;
}

/// The import's figures: the input's vertex count and, when simplified, the Hausdorff distance; for a label
/// map, or a surface rebuilt from its voxels to close its handles, what the voxel repair changed.
void add_source(const LungSource& s, nlohmann::json& lung) {
  if (s.input_vertices > 0) lung["input_nodes"] = s.input_vertices;
  if (s.simplified) lung["hausdorff_mm"] = s.hausdorff_mm;
  if (!s.from_label_map && !s.rebuilt_from_voxels) return;
  nlohmann::json voxels = {{"grid_mm", s.grid_mm},
                           {"components", s.components},
                           {"removed_voxels", s.removed_voxels},
                           {"removed_ml", s.removed_ml},
                           {"filled_voxels", s.filled_voxels},
                           {"filled_ml", s.filled_ml}};
  if (s.from_label_map) {
    voxels["label"] = s.label;
    voxels["label_voxels"] = s.label_voxels;
    lung["label_map"] = voxels;
  } else {
    voxels["handles"] = s.handles;
    lung["voxel_rebuild"] = voxels;
  }
}

nlohmann::json maps_json(const std::vector<MapFigures>& maps) {
  nlohmann::json out = nlohmann::json::array();
  for (const MapFigures& m : maps)
    out.push_back({{"map", kSphereMapNames.name(m.map)}, {"folded_triangles", m.folded_triangles},
                   {"area_distortion", m.area_distortion}, {"eq7_rms_rel_error", m.eq7_rms_rel_error}});
  return out;
}

/// One posture's figures (sim/motion/motion_figures.h), with the faces when `regions`.
nlohmann::json posture_json(const MotionFigures& f, bool regions) {
  nlohmann::json j = {{"si_share", f.si_share},
                      {"apex_base_ratio", f.apex_base_ratio},
                      {"dorsal_ventral_ratio", f.dorsal_ventral_ratio},
                      {"mean_displacement_mm", f.mean_displacement_mm},
                      {"max_displacement_mm", f.max_displacement_mm}};
  if (!regions) return j;
  nlohmann::json faces = nlohmann::json::object();
  for (std::size_t r = 0; r < kSurfaceRegionCount; ++r) {
    const RegionMotion& m = f.regions[r];
    faces[kSurfaceRegionNames.name(static_cast<SurfaceRegion>(r))] = {
        {"area_mm2", m.area_mm2}, {"area_share", m.area_share}, {"volume_share", m.volume_share},
        {"mean_displacement_mm", m.mean_displacement_mm}};
  }
  j["regions"] = faces;
  return j;
}

/// "motion": the asset's model supine at the top level (the 4-D CT figures), then prone and upright, and the
/// other model's figures on the same lungs for the side-by-side comparison.
nlohmann::json motion_json(const BakeReport& r) {
  nlohmann::json j = posture_json(r.motion_supine, true);
  j["model"] = kMotionModelNames.name(r.model);
  j["volume_ml"] = kTidalVolumeMl;
  j["posture"] = "supine";
  // Inside the lungs (sim/motion/interior_displacement.h): the same definitions over interior points.
  j["interior_si_share"] = r.interior_supine.si_share;
  j["interior_apex_base_ratio"] = r.interior_supine.apex_base_ratio;
  j["interior_dorsal_ventral_ratio"] = r.interior_supine.dorsal_ventral_ratio;
  j["interior_mean_displacement_mm"] = r.interior_supine.mean_displacement_mm;
  j["interior_max_displacement_mm"] = r.interior_supine.max_displacement_mm;
  j["interior_points"] = r.interior_points;
  j["interior_grid_mm"] = r.interior_grid_mm;
  j["prone"] = posture_json(r.motion_prone, false);
  j["upright"] = posture_json(r.motion_upright, false);
  j["compared"] = {{"model", kMotionModelNames.name(r.compared_model)},
                   {"supine", posture_json(r.compared_supine, true)},
                   {"prone", posture_json(r.compared_prone, false)},
                   {"upright", posture_json(r.compared_upright, false)}};
  return j;
}

}  // namespace

nlohmann::json report_json(const BakeReport& r, const std::vector<std::string>& notes) {
  nlohmann::json j;
  j["version"] = LUNGAR_VERSION;
  j["nodes"] = r.nodes;
  j["triangles"] = r.triangles;
  j["lungs"] = r.lungs;
  j["lung_names"] = r.lung_names;
  j["bands"] = r.bands;
  j["coefficients"] = r.coefficients;
  j["rest_volume_ml"] = r.rest_volume_ml;
  j["transfer_nnz_per_row_mean"] = r.transfer_nnz_per_row_mean;
  j["transfer_truncation_epsilon"] = r.transfer_epsilon;
  j["bake_s"] = r.bake_s;
  j["factorise_s"] = r.factorise_s;
  j["solve_s"] = r.solve_s;
  j["transfer_rows_s"] = r.transfer_rows_s;
  j["evaluate_s"] = r.evaluate_s;
  j["folded_triangles"] = r.folded_triangles;
  j["gravity_directions"] = r.gravity_directions;
  j["eq7_rms_rel_error"] = r.eq7_rms_rel_error;
  j["alpha"] = r.alpha;
  j["paper_interp_rms_rel_error"] = r.paper_interp_rms_rel_error;
  j["linear_basis_rms_rel_error"] = r.linear_basis_rms_rel_error;
  j["eq1_truncated_rms_rel_error"] = r.eq1_truncated_rms_rel_error;
  j["displacement_max_mm_at_tidal"] = r.displacement_max_mm_at_tidal;
  j["tidal_volume_rel_error"] = r.tidal_volume_rel_error;
  j["base_apex_displacement_ratio"] = r.base_apex_displacement_ratio;
  j["posterior_anterior_displacement_ratio"] = r.posterior_anterior_displacement_ratio;
  j["sphere_map_s"] = r.sphere_map_s;
  j["map"] = kSphereMapNames.name(r.map);
  j["model"] = kMotionModelNames.name(r.model);
  if (r.evaluated) {
    j["direction_rms_rel_error"] = r.direction_rms_rel_error;
    j["motion"] = motion_json(r);
    nlohmann::json fits = nlohmann::json::array();
    for (const BakeReport::PatternFit& f : r.pathology_force)
      fits.push_back({{"pathology", f.pathology},
                      {"posture", f.posture},
                      {"sh_rms_rel_error", f.sh_rms_rel_error},
                      {"linear_rms_rel_error", f.linear_rms_rel_error}});
    j["pathology_force"] = fits;
  }
  j["bands_sweep"] = sweep_json(r.bands_sweep);
  j["maps"] = maps_json(r.maps);
  nlohmann::json lungs = nlohmann::json::array();
  for (const LungReport& l : r.per_lung) {
    lungs.push_back({{"name", l.name},
                     {"nodes", l.nodes},
                     {"triangles", l.triangles},
                     {"volume_ml", l.volume_ml},
                     {"centroid_mm", {l.centroid_mm.x(), l.centroid_mm.y(), l.centroid_mm.z()}},
                     {"map", kSphereMapNames.name(l.map)},
                     {"folded_triangles", l.folded_triangles},
                     {"area_distortion", l.area_distortion},
                     {"eq7_rms_rel_error", l.eq7_rms_rel_error},
                     {"maps", maps_json(l.maps)},
                     {"bands_sweep", sweep_json(l.bands_sweep)}});
    add_source(l.source, lungs.back());
  }
  j["per_lung"] = lungs;
  j["notes"] = notes;
  return j;
}

}  // namespace lungar::sim
