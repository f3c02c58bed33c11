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
  nlohmann::json sweep = nlohmann::json::array();
  for (const BandsSweepEntry& e : r.bands_sweep)
    sweep.push_back({{"bands", e.bands}, {"coefficients", e.coefficients}, {"eq7_rms_rel_error", e.eq7_rms_rel_error}});
  j["bands_sweep"] = sweep;
  j["notes"] = notes;
  return j;
}

}  // namespace lungar::sim
