/// @file bake_command.cpp
/// @brief Input -> lungs (simplified to --nodes) -> bake -> asset (atomic) -> report JSON (atomic).
#include "sim/bake_tool/bake_command.h"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "config/base/atomic_file.h"
#include "config/base/number_text.h"
#include "sim/asset/asset_io.h"
#include "sim/bake_tool/label_map_io.h"
#include "sim/bake_tool/mesh_import.h"
#include "sim/bake_tool/report_json.h"
#include "sim/bake_tool/surface_simplify.h"
#include "sim/mesh/spherical_map.h"
#include "sim/mesh/surface_distance.h"
#include "sim/motion/interior_displacement.h"
#include "sim/motion/lesion.h"
#include "sim/parallel/parallel_for.h"
#include "sim/voxel/label_surface.h"
#include "sim/voxel/voxelize.h"

namespace lungar::sim {
namespace {

/// `total` vertices shared out in proportion to `areas`.
std::vector<std::uint32_t> share_by_area(std::uint32_t total, const std::vector<double>& areas) {
  double sum = 0;
  for (double a : areas) sum += a;
  std::vector<std::uint32_t> out;
  for (double a : areas) out.push_back(static_cast<std::uint32_t>(std::lround(total * (sum > 0 ? a / sum : 1.0 / areas.size()))));
  return out;
}

/// Simplifies `lung` to `target` vertices when it has more than 5 % over, and (with `measure`) how far it strays.
Status simplify_lung(LungMesh& lung, std::uint32_t target, const Workers& workers, bool measure = true) {
  if (lung.source.input_vertices == 0) lung.source.input_vertices = static_cast<std::uint32_t>(lung.mesh.positions.size());
  if (target == 0 || static_cast<double>(lung.mesh.positions.size()) <= 1.05 * target) return ok();
  lungar::Result<TriMesh> simple = simplify_surface(lung.mesh, target);
  if (!simple) return fail("lung '" + lung.name + "': " + simple.error());
  lung.source.simplified = true;
  if (measure) lung.source.hausdorff_mm = hausdorff_mm(lung.mesh, *simple, workers);
  lung.mesh = simple.take();
  return ok();
}

/// --lesion, split: labels of the label map (NAME=VALUE) and balls given by their centre and radius.
struct LesionSpecs {
  std::vector<LabelRequest> labels;
  std::vector<Lesion> balls;
};

Result<LesionSpecs> lesion_specs(const BakeCommand& cmd) {
  LesionSpecs out;
  for (const std::string& spec : cmd.lesions) {
    if (lungar::Result<LabelRequest> label = parse_label_request(spec); label) {
      if (cmd.labelmap.empty())
        return fail("--lesion " + spec + ": a label needs --labelmap; expected NAME=x,y,z,radius_mm (LPS, mm) for " +
                    (cmd.procedural ? "the procedural pair" : "a mesh"));
      if (!lesion_name_ok(label->name))
        return fail("--lesion " + spec + ": expected NAME of 1 to 32 letters, digits, '_' or '-'");
      out.labels.push_back(label.take());
      continue;
    }
    Result<Lesion> ball = parse_lesion(spec);
    if (!ball) return fail(ball.error() + " or NAME=LABEL with --labelmap");
    out.balls.push_back(ball.take());
  }
  return out;
}

/// The ball of a segmented lesion's volume at its centroid.
Result<Lesion> label_lesion_ball(const std::string& map, const LabelLesion& l) {
  const Lesion ball{l.label.name, l.centroid_mm, std::cbrt(3.0 * l.volume_ml * 1000.0 / (4.0 * std::numbers::pi)),
                    true};
  if (ball.radius_mm > kMaxLesionRadiusMm) {
    char text[200];
    std::snprintf(text, sizeof text, "%.0f mL, the volume of a ball of radius %.0f mm; expected at most %.0f mm",
                  l.volume_ml, ball.radius_mm, kMaxLesionRadiusMm);
    return fail(map + ": --lesion " + l.label.name + "=" + std::to_string(l.label.value) + ": " + text);
  }
  return ball;
}

/// The lesions placed in the baked lungs, into the asset; a note each (the report's and the log's).
Status bake_lesions(const std::vector<Lesion>& lesions, BakedAsset& asset, std::vector<std::string>& notes) {
  if (lesions.empty()) return ok();
  const InteriorDisplacement field(asset);
  Result<std::vector<PlacedLesion>> placed = place_lesions(field, lesions);
  if (!placed) return fail(placed.error());
  for (const PlacedLesion& p : *placed) {
    asset.lesions.push_back(baked_lesion(p));
    notes.push_back(describe_lesion(p, asset));
  }
  return ok();
}

/// Surfaces from a label map: one lung per --label, each sized by its share of --nodes; each lesion label's
/// voxels inside the lung around it (label_map_io.h), its ball into `lesions`.
Result<std::vector<LungMesh>> label_map_lungs(const BakeCommand& cmd, const BakeProgress& progress,
                                              std::vector<std::string>& notes,
                                              const std::vector<LabelRequest>& lesion_labels,
                                              std::vector<Lesion>& lesions) {
  std::vector<LabelRequest> requests;
  for (const std::string& text : cmd.labels) {
    lungar::Result<LabelRequest> r = parse_label_request(text);
    if (!r) return fail(r.error());
    for (const LabelRequest& other : requests)
      if (other.name == r->name) return fail("--label: the name '" + r->name + "' is given twice; expected one per lung");
    requests.push_back(r.take());
  }
  if (progress) progress("label map", 0.0);
  std::vector<LabelLesion> segmented;
  lungar::Result<std::vector<LabelMask>> masks = read_label_masks(cmd.labelmap, requests, lesion_labels, segmented);
  if (!masks) return fail(masks.error());
  for (const LabelLesion& l : segmented) {
    Result<Lesion> ball = label_lesion_ball(cmd.labelmap, l);
    if (!ball) return fail(ball.error());
    lesions.push_back(ball.take());
  }
  std::vector<double> areas;
  for (const LabelMask& m : *masks) areas.push_back(mask_surface_area_mm2(m.mask));
  const std::vector<std::uint32_t> target = share_by_area(cmd.nodes > 0 ? cmd.nodes : kDefaultLabelMapNodes, areas);
  std::vector<LungMesh> lungs(masks->size());
  std::vector<std::string> error(masks->size());
  if (progress) progress("surface", 0.0);
  // The lungs in parallel, each on one thread.
  parallel_for(masks->size(), Workers{cmd.options.threads, cmd.options.cancel}, [&](std::size_t l) {
    const LabelMask& m = (*masks)[l];
    lungar::Result<LabelSurface> s = label_surface(m.mask, target[l]);
    if (!s) {
      error[l] = cmd.labelmap + ": --label " + m.label.name + "=" + std::to_string(m.label.value) + ": " + s.error();
      return;
    }
    LungMesh& lung = lungs[l];
    lung.name = m.label.name;
    lung.mesh = std::move(s->mesh);
    lung.source = {0, false, 0, true, false, 0, m.label.value, m.voxels, s->grid_mm, s->repair.components,
                   s->repair.removed_voxels, s->repair.filled_voxels, s->removed_ml, s->filled_ml};
    if (Status st = simplify_lung(lung, target[l], Workers{1, cmd.options.cancel}); !st)
      error[l] = cmd.labelmap + ": " + st.error();
  });
  for (const std::string& e : error)
    if (!e.empty()) return fail(e);
  for (const LungMesh& lung : lungs) {
    const double x = volume_centroid(lung.mesh).x();
    if ((lung.name == "right" && x > 0) || (lung.name == "left" && x < 0))
      notes.push_back(cmd.labelmap + ": lung '" + lung.name + "' lies at x " + (x > 0 ? "> 0" : "< 0") +
                      " (LPS: +x is the patient's left); check its --label value");
  }
  return lungs;
}

/// A surface with handles (a raw segmentation export: marching cubes leaves tunnels where voxels touch along an
/// edge) cannot be mapped one-to-one onto the sphere: it is voxelised at its own edge length, closed to a ball in
/// voxel space and extracted again with `target` vertices (its own count when 0), as a label map would be.
Status rebuild_without_handles(LungMesh& lung, std::uint32_t target) {
  const long handles = (2 - euler_characteristic(lung.mesh)) / 2;
  lungar::Result<LabelSurface> s = label_surface(voxelize(lung.mesh, voxel_step_for(lung.mesh)),
                                                 target > 0 ? target : static_cast<std::uint32_t>(lung.mesh.positions.size()));
  if (!s) return fail("lung '" + lung.name + "': rebuilding it from its voxels: " + s.error());
  lung.source = {static_cast<std::uint32_t>(lung.mesh.positions.size()), true, 0, false, true, handles, 0, 0,
                 s->grid_mm, s->repair.components, s->repair.removed_voxels, s->repair.filled_voxels, s->removed_ml,
                 s->filled_ml};
  lung.mesh = std::move(s->mesh);
  return ok();
}

/// The note that says a lung was rebuilt, and how far it moved.
std::string rebuild_note(const std::string& file, const LungMesh& lung) {
  const LungSource& src = lung.source;
  char line[360];
  std::snprintf(line, sizeof line,
                "%s: lung '%s' had %ld handle%s (the conformal map needs a genus-0 surface); rebuilt from its voxels "
                "on a %.2f mm grid: %lld voxels (%.2f mL) filled, %.2f mm from the input at most",
                file.c_str(), lung.name.c_str(), src.handles, src.handles == 1 ? "" : "s", src.grid_mm,
                static_cast<long long>(src.filled_voxels), src.filled_ml, src.hausdorff_mm);
  return line;
}

/// Surfaces from mesh files, simplified to --nodes when they have more.
Result<std::vector<LungMesh>> mesh_lungs(const BakeCommand& cmd, const BakeProgress& progress,
                                         std::vector<std::string>& notes) {
  const double mm = units_to_mm(cmd.units);
  if (mm == 0) return fail("--units: expected mm, cm or m, got '" + cmd.units + "'");
  Result<std::vector<LungMesh>> imported = import_lungs(cmd.meshes, mm, notes);
  if (!imported) return imported;
  std::vector<LungMesh>& lungs = *imported;
  std::vector<double> areas;
  std::size_t vertices = 0;
  for (const LungMesh& l : lungs) {
    areas.push_back(surface_area(l.mesh));
    vertices += l.mesh.positions.size();
  }
  if (cmd.nodes > 0 && vertices < cmd.nodes)
    notes.push_back(cmd.meshes.front() + ": kept all " + std::to_string(vertices) + " vertices (--nodes asks for " +
                    std::to_string(cmd.nodes) + "; surfaces are simplified, never refined)");
  const std::vector<std::uint32_t> target = share_by_area(cmd.nodes, areas);
  if (progress && cmd.nodes > 0) progress("simplify", 0.0);
  std::vector<Status> status(lungs.size());
  const Workers workers{cmd.options.threads, cmd.options.cancel};
  for (std::size_t l = 0; l < lungs.size(); ++l) {
    check_cancel(workers);
    const std::uint32_t want = cmd.nodes > 0 ? target[l] : 0;
    if (cmd.options.sphere.map == SphereMap::radial || euler_characteristic(lungs[l].mesh) == 2) {
      status[l] = simplify_lung(lungs[l], want, workers);
      continue;
    }
    const TriMesh input = lungs[l].mesh;
    status[l] = rebuild_without_handles(lungs[l], want);
    if (status[l]) status[l] = simplify_lung(lungs[l], want, workers, false);
    if (!status[l]) continue;
    lungs[l].source.hausdorff_mm = hausdorff_mm(input, lungs[l].mesh, workers);  // against the input
    notes.push_back(rebuild_note(cmd.meshes.front(), lungs[l]));
  }
  for (const Status& s : status)
    if (!s) return fail(cmd.meshes.front() + ": " + s.error());
  return imported;
}

/// Each imported lung encloses what a human lung can (kMinLungVolumeMl to kMaxLungVolumeMl), unless --any-volume.
Status check_lung_volumes(const BakeCommand& cmd, const std::string& source, const std::vector<LungMesh>& lungs) {
  if (cmd.any_volume) return ok();
  for (const LungMesh& lung : lungs) {
    const double ml = std::abs(enclosed_volume(lung.mesh)) / 1000.0;
    if (ml >= kMinLungVolumeMl && ml <= kMaxLungVolumeMl) continue;
    char volume[64];
    std::snprintf(volume, sizeof volume, "%.3g mL", ml);
    const std::string hint = cmd.labelmap.empty() ? "check --units (the mesh was read in " + cmd.units + ")"
                                                  : std::string("check the label map's voxel spacing and --label");
    return fail(source + ": lung '" + lung.name + "' encloses " + volume + "; expected " +
                number_text(kMinLungVolumeMl) + " to " + number_text(kMaxLungVolumeMl) +
                " mL a lung (a newborn's to beyond an adult's at total lung capacity): " + hint +
                ", or give --any-volume to bake it as it is");
  }
  return ok();
}

/// run_bake_command without the catch of Cancelled.
Result<BakeReport> bake_and_write(const BakeCommand& cmd, const BakeProgress& progress,
                                  std::vector<std::string>& notes) {
  if (cmd.out.empty()) return fail("--out: expected the path of the .lungbake file to write");
  const int inputs = int{cmd.procedural} + int{!cmd.meshes.empty()} + int{!cmd.labelmap.empty()};
  if (inputs != 1) return fail("expected one of --procedural, --mesh FILE or --labelmap FILE");
  // Minutes of baking for an output that cannot be written would be lost: ask the outputs' folders first.
  if (Status s = check_writable(cmd.out); !s) return fail("--out: " + s.error());
  if (!cmd.report_json.empty())
    if (Status s = check_writable(cmd.report_json); !s) return fail("--report-json: " + s.error());
  Result<LesionSpecs> specs = lesion_specs(cmd);
  if (!specs) return fail(specs.error());
  std::vector<Lesion> lesions;
  std::vector<LungMesh> lungs;
  std::string source = cmd.procedural ? std::string("procedural lungs") : cmd.labelmap;
  if (cmd.procedural) {
    lungs = procedural_lungs(cmd.nodes > 0 ? cmd.nodes : kDefaultProceduralNodes, cmd.seed);
  } else {
    Result<std::vector<LungMesh>> got = cmd.labelmap.empty()
                                            ? mesh_lungs(cmd, progress, notes)
                                            : label_map_lungs(cmd, progress, notes, specs->labels, lesions);
    if (!got) return fail(got.error());
    lungs = std::move(*got);
    if (cmd.labelmap.empty()) source = cmd.meshes.front();
    if (cmd.meshes.size() > 1) source += " and " + cmd.meshes.back();
    if (Status volumes = check_lung_volumes(cmd, source, lungs); !volumes) return fail(volumes.error());
  }
  Result<BakeOutput> baked = bake_lungs(std::move(lungs), cmd.options, progress);
  if (!baked) return fail(source + ": " + baked.error());
  lesions.insert(lesions.end(), specs->balls.begin(), specs->balls.end());
  if (Status placed = bake_lesions(lesions, baked->asset, notes); !placed) return fail(placed.error());
  check_cancel(Workers{0, cmd.options.cancel});  // the last chance to leave nothing behind
  if (Status s = write_asset(baked->asset, cmd.out); !s) return fail(s.error());
  if (!cmd.report_json.empty()) {
    const std::string text = report_json(baked->report, notes).dump(2) + "\n";
    if (Status s = write_file_atomically(cmd.report_json, text); !s) return fail(s.error());
  }
  return std::move(baked->report);
}

}  // namespace

Result<BakeReport> run_bake_command(const BakeCommand& cmd, const BakeProgress& progress,
                                    std::vector<std::string>& notes) {
  try {
    return bake_and_write(cmd, progress, notes);
  } catch (const Cancelled&) {
    return fail("interrupted; nothing was written");
  }
}

}  // namespace lungar::sim
