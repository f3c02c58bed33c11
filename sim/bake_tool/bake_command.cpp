/// @file bake_command.cpp
/// @brief Input -> bake -> asset (atomic) -> report JSON (atomic).
#include "sim/bake_tool/bake_command.h"

#include "config/base/atomic_file.h"
#include "sim/asset/asset_io.h"
#include "sim/bake_tool/mesh_import.h"
#include "sim/bake_tool/report_json.h"

namespace lungar::sim {

Result<BakeReport> run_bake_command(const BakeCommand& cmd, const BakeProgress& progress,
                                    std::vector<std::string>& notes) {
  if (cmd.out.empty()) return fail("--out: expected the path of the .lungbake file to write");
  if (cmd.procedural == !cmd.meshes.empty()) return fail("expected either --procedural or --mesh FILE");
  std::vector<LungMesh> lungs;
  if (cmd.procedural) {
    lungs = procedural_lungs(cmd.nodes, cmd.seed);
  } else {
    const double mm = units_to_mm(cmd.units);
    if (mm == 0) return fail("--units: expected mm, cm or m, got '" + cmd.units + "'");
    Result<std::vector<LungMesh>> imported = import_lungs(cmd.meshes, mm, notes);
    if (!imported) return fail(imported.error());
    lungs = std::move(*imported);
  }
  Result<BakeOutput> baked = bake_lungs(std::move(lungs), cmd.options, progress);
  if (!baked) return fail((cmd.procedural ? std::string("procedural lungs") : cmd.meshes.front()) + ": " + baked.error());
  if (Status s = write_asset(baked->asset, cmd.out); !s) return fail(s.error());
  if (!cmd.report_json.empty()) {
    const std::string text = report_json(baked->report, notes).dump(2) + "\n";
    if (Status s = write_file_atomically(cmd.report_json, text); !s) return fail(s.error());
  }
  return std::move(baked->report);
}

}  // namespace lungar::sim
