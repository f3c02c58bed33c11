/// @file bake.cpp
/// @brief Per lung: LOD order, geometry, K and its factor, the L^2 + 4 exact solves, SH projection, force
///        bases, the paper's arrays and the truncated rows; lungs run in parallel.
#include "sim/bake/bake.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <memory>
#include <mutex>
#include <numbers>

#include "sim/asset/asset_io.h"
#include "sim/bake/bake_evaluate.h"
#include "sim/bake/lung_bake.h"
#include "sim/bake/motion_fields.h"
#include "sim/force/force_sh.h"
#include "sim/force/gravity.h"
#include "sim/mesh/lod_order.h"
#include "sim/mesh/procedural_lungs.h"
#include "sim/parallel/parallel_for.h"
#include "sim/sh/real_sh.h"

namespace lungar::sim {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

/// Maps the lung onto the sphere and sets up the SH fit's basis Y and Gram matrix G = sum_J A_J Y Y^T (the
/// area-weighted least squares of docs/design.md, "SH deformation (eq. 7)"), which must resolve the asset's bands.
Status fit_basis(LungWork& w, const BakeOptions& opt, int bands_solved) {
  const std::string who = "lung '" + w.name + "'";
  lungar::Result<SphereMapResult> mapped = map_to_sphere(w.mesh, w.centre, opt.sphere);
  if (!mapped) return fail(who + ": " + mapped.error());
  w.sphere = mapped.take();
  const auto n = static_cast<Eigen::Index>(w.mesh.positions.size());
  w.c_solved = bands_solved * bands_solved;
  w.y = sh_rows(w.sphere.u, bands_solved);
  w.offsets.resize(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) w.offsets.row(i) = (w.mesh.positions[i] - w.centre).transpose();
  w.gram = w.y.transpose() * w.areas.asDiagonal() * w.y;
  const int c = static_cast<int>(opt.bands * opt.bands);
  Eigen::LDLT<Eigen::MatrixXd> g(w.gram.topLeftCorner(c, c));
  const Eigen::VectorXd diag = g.vectorD();
  if (g.info() != Eigen::Success || !(diag.minCoeff() > 1e-9 * diag.maxCoeff()))
    return fail(who + ": its " + std::to_string(n) + " vertices cannot resolve " + std::to_string(opt.bands) +
                " SH bands; expected a finer, closed surface around its centre");
  return ok();
}

/// Everything one lung's bake computes; the evaluation reuses the factor and the double-precision fields.
Status bake_one(LungWork& w, const BakeOptions& opt, const Workers& workers, std::uint32_t offset,
                const BakeProgress& progress, BakeReport& timing, std::mutex& timing_mutex) {
  const std::string who = "lung '" + w.name + "'";
  auto t0 = Clock::now();
  reorder_vertices(w.mesh, lod_order(w.mesh.positions));
  w.geometry = vertex_geometry(w.mesh);
  w.rest_volume_mm3 = enclosed_volume(w.mesh);
  if (!w.has_centre) w.centre = volume_centroid(w.mesh);
  const auto n = static_cast<Eigen::Index>(w.mesh.positions.size());
  w.areas = Eigen::Map<const Eigen::VectorXd>(w.geometry.areas.data(), n);
  if (progress) progress("sphere map", 0.0);
  const int bands_solved = opt.evaluate && opt.bands_sweep ? kMaxBands : static_cast<int>(opt.bands);
  const int c_solved = bands_solved * bands_solved;
  if (Status s = fit_basis(w, opt, bands_solved); !s) return s;
  const double map_s = seconds_since(t0);
  check_cancel(workers);

  t0 = Clock::now();
  w.regions = surface_regions(w, opt);
  w.k = model_stiffness(w, opt.model, opt, w.drive);
  if (progress) progress("factorise", 0.0);
  w.solver = std::make_unique<TransferSolver>(w.k);
  if (!w.solver->error().empty()) return fail(who + ": " + w.solver->error());
  const double factor_s = seconds_since(t0);
  check_cancel(workers);

  auto t1 = Clock::now();
  if (progress) progress("solve", 0.0);
  solve_motion_fields(w, opt.model, opt, workers);
  const double solve_s = seconds_since(t1);

  // Force bases: the pressure's SH projections f0 (of 1) and f_k (of (x - c)_k); swept volumes v0 and v_k.
  const int c = static_cast<int>(opt.bands * opt.bands);
  const Eigen::LDLT<Eigen::MatrixXd> gram(w.gram.topLeftCorner(c, c));
  Eigen::MatrixXd moments(c, 4);
  moments.col(0) = w.y.leftCols(c).transpose() * w.areas;
  moments.rightCols(3) = w.y.leftCols(c).transpose() * w.areas.asDiagonal() * w.offsets;
  w.force_basis = gram.solve(moments);
  // sum_I A_I n_I . (e_I tau_I + r_I): the swept volume of the whole displacement, mm^3 per unit pressure
  w.volume_basis = w.x.rightCols(4).transpose() * w.volume_weights + w.off_axis_volume;

  auto t2 = Clock::now();
  if (opt.transfer_rows)
    append_transfer_rows(w.k, w.areas, w.x.col(c_solved), opt.transfer_epsilon, workers, offset, w.rows,
                         opt.model == MotionModel::sliding ? RowProjection{&w.directions, &w.drive} : RowProjection{},
                         [&](std::size_t done) {
      if (progress) progress("transfer rows", static_cast<double>(done) / static_cast<double>(n));
    });
  std::lock_guard lock(timing_mutex);
  timing.sphere_map_s = std::max(timing.sphere_map_s, map_s);
  timing.factorise_s = std::max(timing.factorise_s, factor_s);
  timing.solve_s = std::max(timing.solve_s, solve_s);
  timing.transfer_rows_s = std::max(timing.transfer_rows_s, seconds_since(t2));
  return {};
}

}  // namespace

Eigen::MatrixXd sh_rows(const std::vector<Eigen::Vector3d>& u, int bands) {
  Eigen::MatrixXd y(static_cast<Eigen::Index>(u.size()), bands * bands);
  Eigen::VectorXd sh(bands * bands);
  for (std::size_t i = 0; i < u.size(); ++i) {
    real_sh(bands, u[i], sh.data());
    y.row(static_cast<Eigen::Index>(i)) = sh.transpose();
  }
  return y;
}

namespace {

void fill_lung(const LungWork& w, const BakeOptions& opt, BakedAsset& a, std::size_t lung_index, double total_volume) {
  const std::uint32_t c = opt.bands * opt.bands;
  const auto n = static_cast<std::uint32_t>(w.mesh.positions.size());
  BakedLung lung;
  lung.name = w.name;
  for (int k = 0; k < 3; ++k) lung.centre[k] = static_cast<float>(w.centre[k]);
  lung.first_vertex = a.vertex_count();
  lung.vertex_count = n;
  lung.first_index = static_cast<std::uint32_t>(a.triangles.size());
  lung.index_count = static_cast<std::uint32_t>(3 * w.mesh.triangles.size());
  lung.rest_volume_ml = w.rest_volume_mm3 / 1000.0;
  lung.volume_share = w.rest_volume_mm3 / total_volume;
  lung.force_const.resize(c);
  for (auto& f : lung.force_grad) f.resize(c);
  for (std::uint32_t i = 0; i < c; ++i) {
    lung.force_const[i] = static_cast<float>(w.force_basis(i, 0));
    for (int k = 0; k < 3; ++k) lung.force_grad[k][i] = static_cast<float>(w.force_basis(i, 1 + k));
  }
  lung.volume_const = w.volume_basis[0];
  for (int k = 0; k < 3; ++k) lung.volume_grad[k] = w.volume_basis[1 + k];

  for (std::uint32_t i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) {
      a.positions.push_back(static_cast<float>(w.mesh.positions[i][k]));
      a.normals.push_back(static_cast<float>(w.geometry.normals[i][k]));
      a.directions.push_back(static_cast<float>(w.directions(i, k)));
      a.sphere_dirs.push_back(static_cast<float>(w.sphere.u[i][k]));
    }
    a.areas.push_back(static_cast<float>(w.geometry.areas[i]));
    a.lung_of_vertex.push_back(static_cast<std::uint8_t>(lung_index));
    for (std::uint32_t j = 0; j < c; ++j) a.sh_coeffs.push_back(static_cast<float>(w.x(i, j)));
    for (Eigen::Index j = 0; j < w.off_axis.cols(); ++j) a.off_axis.push_back(static_cast<float>(w.off_axis(i, j)));
    for (int j = 0; j < 4; ++j) a.linear_coeffs.push_back(static_cast<float>(w.x(i, w.c_solved + j)));
  }
  for (const Triangle& t : w.mesh.triangles)
    for (std::uint32_t v : t) a.triangles.push_back(lung.first_vertex + v);
  a.lungs.push_back(std::move(lung));
}

/// The paper's eq. (8)-(9) arrays: exact normalised force at pi/2, pi, 3pi/2, 2pi about X, Y and Z.
void fill_paper_forces(BakedAsset& a) {
  const std::uint32_t c = a.coefficients();
  const PatientState healthy = PatientState::of(a);  // the bake's forces are the healthy patient's
  for (std::size_t l = 0; l < a.lungs.size(); ++l) {
    BakedLung& lung = a.lungs[l];
    lung.paper_force.assign(kPaperAxes * kPaperAngles, std::vector<float>(c));
    for (int axis = 0; axis < kPaperAxes; ++axis)
      for (int k = 0; k < kPaperAngles; ++k) {
        const Eigen::Vector3d g = gravity_in_lung_frame(axis_rotation(axis, (k + 1) * std::numbers::pi / 2));
        force_sh_exact(a, lung, healthy.lungs[l], g, lung.paper_force[axis * kPaperAngles + k].data());
      }
  }
}

/// The first-order swept volume sum_I A_I (e_I . n_I) D_I undercounts the enclosed volume change at tidal volume by the
/// surface's curvature term (about D/R, some 3 % on adult lungs at 500 mL). Returns the factor for v0 and v
/// that makes the upright displacement at the paper's tidal volume change this lung's enclosed volume by
/// exactly its share of 500 mL: the normalisation is the secant at V_T rather than the tangent at 0.
double tidal_calibration(const LungWork& w, const BakeOptions& opt, double share) {
  const Eigen::Index c = w.c_solved;
  const Eigen::VectorXd d = opt.p0 * w.x.col(c) - opt.gamma_per_mm * w.x.col(c + 3);  // g = (0, 0, -1)
  const Eigen::MatrixXd off = w.off_axis.size() > 0  // the off-axis part, upright
                                  ? linear_displacement(w.off_axis, opt.p0, opt.gamma_per_mm, Eigen::Vector3d(0, 0, -1))
                                  : Eigen::MatrixXd::Zero(d.size(), 3);
  const double linear = w.volume_weights.dot(d) + swept_volume(w, off);
  const double target = kTidalVolumeMl * 1000.0 * share;
  if (!(linear > 0)) return 1.0;
  TriMesh moved = w.mesh;
  const double rest = enclosed_volume(w.mesh);
  double t = target / linear;
  for (int iteration = 0; iteration < 6; ++iteration) {
    for (std::size_t i = 0; i < moved.positions.size(); ++i)
      moved.positions[i] = w.mesh.positions[i] + t * (d[static_cast<Eigen::Index>(i)] *
                                                         w.directions.row(static_cast<Eigen::Index>(i)).transpose() +
                                                     off.row(static_cast<Eigen::Index>(i)).transpose());
    const double change = enclosed_volume(moved) - rest;
    if (!(change > 0)) return 1.0;
    t *= target / change;
  }
  return (target / t) / linear;
}

/// The asset from the lungs' fields: per-lung blocks, the tidal calibration, the paper's arrays, the rows.
/// Returns the lungs' total rest volume, mm^3.
double assemble_asset(const std::vector<std::unique_ptr<LungWork>>& work, const BakeOptions& opt, BakedAsset& a) {
  a.bands = opt.bands;
  a.p0 = opt.p0;
  a.gamma_per_mm = opt.gamma_per_mm;
  a.decay_length_mm = opt.decay_length_mm;
  a.motion_model = opt.model;
  double total_volume = 0;
  for (const auto& w : work) total_volume += w->rest_volume_mm3;
  for (std::size_t l = 0; l < work.size(); ++l) {
    fill_lung(*work[l], opt, a, l, total_volume);
    const double k = tidal_calibration(*work[l], opt, a.lungs[l].volume_share);
    a.lungs[l].volume_const *= k;
    for (double& v : a.lungs[l].volume_grad) v *= k;
  }
  fill_paper_forces(a);
  if (opt.transfer_rows) {
    a.transfer_epsilon = opt.transfer_epsilon;
    a.transfer_row_ptr.push_back(0);
    for (const auto& w : work) {
      const std::uint32_t base = a.transfer_row_ptr.back();
      for (std::size_t i = 1; i < w->rows.row_ptr.size(); ++i) a.transfer_row_ptr.push_back(base + w->rows.row_ptr[i]);
      a.transfer_cols.insert(a.transfer_cols.end(), w->rows.cols.begin(), w->rows.cols.end());
      a.transfer_vals.insert(a.transfer_vals.end(), w->rows.vals.begin(), w->rows.vals.end());
    }
  }
  return total_volume;
}

/// The report's counts and, per lung, its size, place and sphere map (the accuracy figures come from evaluate).
void fill_report(const std::vector<std::unique_ptr<LungWork>>& work, const BakedAsset& a, const BakeOptions& opt,
                 double total_volume, BakeReport& report) {
  report.nodes = a.vertex_count();
  report.triangles = static_cast<std::uint32_t>(a.triangles.size() / 3);
  report.lungs = static_cast<std::uint32_t>(a.lungs.size());
  report.bands = a.bands;
  report.coefficients = a.coefficients();
  report.transfer_epsilon = a.transfer_epsilon;
  report.transfer_nnz_per_row_mean =
      opt.transfer_rows ? static_cast<double>(a.transfer_vals.size()) / std::max<double>(1, a.vertex_count()) : 0;
  report.rest_volume_ml = total_volume / 1000.0;
  report.map = opt.sphere.map;
  report.model = opt.model;
  MapFigures all{opt.sphere.map, 0, 0, 0};
  for (const auto& w : work) {
    report.folded_triangles += w->sphere.folded;
    report.lung_names.push_back(w->name);
    const MapFigures mine{opt.sphere.map, w->sphere.folded, w->sphere.area_distortion, 0};
    report.per_lung.push_back({w->name, static_cast<std::uint32_t>(w->mesh.positions.size()),
                               static_cast<std::uint32_t>(w->mesh.triangles.size()), w->rest_volume_mm3 / 1000.0,
                               volume_centroid(w->mesh), opt.sphere.map, w->sphere.folded, w->sphere.area_distortion,
                               0, {mine}, {}, w->source});
    all.folded_triangles += mine.folded_triangles;
    all.area_distortion = std::max(all.area_distortion, mine.area_distortion);  // the worst lung's
  }
  report.maps = {all};
}

}  // namespace

std::vector<Eigen::Vector3d> report_directions() {
  std::vector<Eigen::Vector3d> dirs;
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z)
        if (x != 0 || y != 0 || z != 0) dirs.push_back(Eigen::Vector3d(x, y, z).normalized());
  return dirs;
}

Result<BakeOutput> bake_lungs(std::vector<LungMesh> lungs, const BakeOptions& opt, const BakeProgress& progress) {
  const auto start = Clock::now();
  if (lungs.empty() || lungs.size() > 16) return fail("bake: expected 1 to 16 lungs, got " + std::to_string(lungs.size()));
  if (opt.bands < 1 || opt.bands > static_cast<std::uint32_t>(kMaxBands))
    return fail("bake: bands: expected 1 to 8, got " + std::to_string(opt.bands));
  const Workers all{opt.threads, opt.cancel};

  std::mutex progress_mutex;
  BakeProgress serial = [&](std::string_view stage, double fraction) {
    if (!progress) return;
    std::lock_guard lock(progress_mutex);
    progress(stage, fraction);
  };

  std::vector<std::unique_ptr<LungWork>> work;
  std::vector<std::uint32_t> offsets;
  std::uint32_t offset = 0;
  double x_sum = 0;
  std::size_t x_count = 0;
  for (const LungMesh& l : lungs)
    for (const Eigen::Vector3d& p : l.mesh.positions) {
      x_sum += p.x();
      ++x_count;
    }
  for (LungMesh& l : lungs) {
    auto w = std::make_unique<LungWork>();
    w->name = l.name;
    w->source = l.source;
    w->mesh = std::move(l.mesh);
    w->has_centre = l.has_centre;
    w->centre = l.centre;
    w->midline_x = x_count > 0 ? x_sum / static_cast<double>(x_count) : 0.0;
    offsets.push_back(offset);
    offset += static_cast<std::uint32_t>(w->mesh.positions.size());
    work.push_back(std::move(w));
  }

  // Lungs in parallel (the factorisation is single-threaded), the threads shared out between them.
  BakeReport report;
  std::mutex timing_mutex;
  std::vector<Status> status(work.size());
  const Workers per_lung{std::max(1, thread_count(all) / static_cast<int>(work.size())), opt.cancel};
  parallel_for(work.size(), all, [&](std::size_t l) {
    status[l] = bake_one(*work[l], opt, per_lung, offsets[l], serial, report, timing_mutex);
  });
  for (const Status& s : status)
    if (!s.ok()) return fail(s.error());

  BakeOutput out;
  BakedAsset& a = out.asset;
  const double total_volume = assemble_asset(work, opt, a);
  if (std::string bad = validate_asset(a); !bad.empty()) return fail("bake: internal error: " + bad);

  fill_report(work, a, opt, total_volume, report);
  report.bake_s = seconds_since(start);
  if (opt.evaluate) {
    const auto t = Clock::now();
    evaluate_bake(work, a, opt, all, serial, report);
    report.evaluate_s = seconds_since(t);
  }
  out.report = std::move(report);
  return out;
}

Result<BakeOutput> bake_procedural(std::uint32_t nodes, std::uint64_t seed, const BakeOptions& options,
                                   const BakeProgress& progress) {
  return bake_lungs(procedural_lungs(nodes, seed), options, progress);
}

}  // namespace lungar::sim
