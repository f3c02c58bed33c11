/// @file bake_evaluate.cpp
/// @brief RMS relative errors over all vertices and the 26 report directions, alpha, the bands sweep, and the
///        tidal-volume, base/apex and posterior/anterior figures.
#include "sim/bake/bake_evaluate.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "config/base/patient_names.h"
#include "sim/bake/motion_fields.h"
#include "sim/deform/deform_eq1.h"
#include "sim/deform/deform_eq7.h"
#include "sim/force/breath_share.h"
#include "sim/force/dependent_collapse.h"
#include "sim/force/force_sh.h"
#include "sim/motion/interior_displacement.h"
#include "sim/parallel/parallel_for.h"
#include "sim/sh/real_sh.h"

namespace lungar::sim {
namespace {

/// Accumulates sum (approx - exact)^2, sum exact^2, and the cross terms for alpha.
struct ErrorSum {
  double diff2 = 0, exact2 = 0, cross = 0, approx2 = 0;
  void add(double approx, double exact) {
    diff2 += (approx - exact) * (approx - exact);
    exact2 += exact * exact;
    cross += approx * exact;
    approx2 += approx * approx;
  }
  double rms_rel() const { return exact2 > 0 ? std::sqrt(diff2 / exact2) : 0.0; }
  double alpha() const { return approx2 > 0 ? cross / approx2 : 0.0; }  // least squares: exact ~ alpha approx
};

/// The orientation (lung frame in world) of least rotation that makes g the lung-frame gravity.
Eigen::Quaterniond orientation_for(const Eigen::Vector3d& g) {
  return Eigen::Quaterniond::FromTwoVectors(g, Eigen::Vector3d(0, 0, -1));
}

/// Mean displacement over vertices in the top and bottom `fraction` of each lung's extent along `axis`.
double end_ratio(const BakedAsset& a, const std::vector<float>& d, int axis, double fraction) {
  double high_sum = 0, low_sum = 0;
  std::size_t high_n = 0, low_n = 0;
  for (const BakedLung& lung : a.lungs) {
    double lo = 1e300, hi = -1e300;
    for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i) {
      lo = std::min<double>(lo, a.positions[3 * i + axis]);
      hi = std::max<double>(hi, a.positions[3 * i + axis]);
    }
    const double band = fraction * (hi - lo);
    for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i) {
      const double x = a.positions[3 * i + axis];
      const double v = d[i] * lung.volume_share;
      if (x >= hi - band) { high_sum += v; ++high_n; }
      if (x <= lo + band) { low_sum += v; ++low_n; }
    }
  }
  if (high_n == 0 || low_n == 0 || low_sum == 0) return 0;
  return (high_sum / high_n) / (low_sum / low_n);  // high end over low end
}

/// The exact eq. (1) for every report direction, D = K^-1 (A o p_g) / V(g) * 1000 (mm per mL). p is linear in g,
/// so in exact arithmetic this is p0 tau0 + gamma tau g from the double-precision solves (no rounding to float,
/// unlike the asset's linear basis); tests check it against fresh solves.
struct ExactEq1 {
  Eigen::MatrixXd d;                        ///< N x directions
  std::vector<Eigen::MatrixXd> pressures;   ///< per lung, N_l x directions
  std::vector<Eigen::RowVectorXd> scales;   ///< per lung, 1000 / V(g)
};

ExactEq1 exact_eq1(const std::vector<std::unique_ptr<LungWork>>& work, const BakedAsset& a, const BakeOptions& opt,
                   const Eigen::MatrixXd& g_mat) {
  const Eigen::Index nd = g_mat.cols();
  ExactEq1 e;
  e.d.resize(a.vertex_count(), nd);
  for (std::size_t l = 0; l < work.size(); ++l) {
    const LungWork& w = *work[l];
    const BakedLung& lung = a.lungs[l];
    Eigen::MatrixXd p = (w.offsets * g_mat * opt.gamma_per_mm).array() + opt.p0;
    const Eigen::MatrixXd d = (w.x.col(w.c_solved) * opt.p0).replicate(1, nd) +
                              opt.gamma_per_mm * w.x.middleCols(w.c_solved + 1, 3) * g_mat;
    Eigen::RowVectorXd s(nd);
    const LungState now = LungState::healthy(lung);
    for (Eigen::Index k = 0; k < nd; ++k) s[k] = 1000.0 / swept_volume_mm3(a, now, g_mat.col(k));
    e.d.middleRows(lung.first_vertex, lung.vertex_count) = d * s.asDiagonal();
    e.pressures.push_back(std::move(p));
    e.scales.push_back(std::move(s));
  }
  return e;
}

/// eq. (7), the paper's interpolation, the linear basis and the truncated rows through the float asset, as the
/// runtime computes them, against the exact eq. (1); eq. (7) also per lung. For the sliding model eq. (7) is the
/// vector the runtime moves a vertex by, D e_I plus the off-axis part, against the exact vector Green's function;
/// what e_I alone would leave out is reported apart (direction_rms_rel_error), and the linear basis and the
/// truncated rows are measured along e_I.
void float_errors(const std::vector<std::unique_ptr<LungWork>>& work, const BakedAsset& a, const BakeOptions& opt,
                  const std::vector<Eigen::Vector3d>& dirs, const ExactEq1& exact, BakeReport& report) {
  ErrorSum eq7, paper, linear, eq1, direction;
  std::vector<ErrorSum> eq7_lung(a.lungs.size());
  const std::uint32_t c = a.coefficients();
  const std::size_t n = a.vertex_count();
  std::vector<float> force(a.lungs.size() * c), paper_force(a.lungs.size() * c);
  std::vector<float> d7(n), dp(n), dl(n), d1(n), f1(n);
  const PatientState healthy = PatientState::of(a);
  for (std::size_t k = 0; k < dirs.size(); ++k) {
    const Eigen::Vector3d& g = dirs[k];
    for (std::size_t l = 0; l < a.lungs.size(); ++l)
      force_sh_exact(a, a.lungs[l], healthy.lungs[l], g, force.data() + l * c);
    force_sh(a, healthy, ForceMode::Paper, orientation_for(g), paper_force.data());
    displacement_eq7(a, force, d7);
    displacement_eq7(a, paper_force, dp);
    displacement_linear(a, healthy, g, dl);
    std::vector<std::array<float, 4>> weights;
    std::vector<Eigen::MatrixXd> exact_vectors;  // sliding: each lung's exact vector displacement, mm per mL
    for (std::size_t l = 0; l < a.lungs.size(); ++l) {
      weights.push_back(linear_weights(a, healthy.lungs[l], g));
      if (opt.model == MotionModel::sliding)
        exact_vectors.push_back(exact.scales[l][static_cast<Eigen::Index>(k)] *
                                linear_displacement(work[l]->vector_linear, opt.p0, opt.gamma_per_mm, g));
    }
    if (a.has_transfer_rows()) {
      applied_force(a, healthy, g, f1);
      displacement_eq1(a, f1, d1);
    }
    const auto col = static_cast<Eigen::Index>(k);
    for (std::size_t i = 0; i < n; ++i) {
      const double e = exact.d(static_cast<Eigen::Index>(i), col);
      if (opt.model == MotionModel::sliding) {
        // The vector as the runtime moves the vertex, D e + r . w, against the exact vector displacement.
        const std::size_t l = a.lung_of_vertex[i];
        const auto local = static_cast<Eigen::Index>(i - a.lungs[l].first_vertex);
        const Eigen::Vector3d u = exact_vectors[l].row(local).transpose();
        const Eigen::Vector3d dir = work[l]->directions.row(local).transpose();
        float moved[3] = {d7[i] * a.directions[3 * i], d7[i] * a.directions[3 * i + 1], d7[i] * a.directions[3 * i + 2]};
        add_off_axis(a, i, weights[l], 1.0f, moved);
        for (int c = 0; c < 3; ++c) {
          eq7.add(moved[c], u[c]);
          eq7_lung[l].add(moved[c], u[c]);
          direction.add(dir[c] * dir.dot(u), u[c]);
        }
      } else {
        eq7.add(d7[i], e);
        eq7_lung[a.lung_of_vertex[i]].add(d7[i], e);
      }
      paper.add(dp[i], d7[i]);
      linear.add(dl[i], e);
      if (a.has_transfer_rows()) eq1.add(d1[i], e);
    }
  }
  report.gravity_directions = static_cast<std::uint32_t>(dirs.size());
  report.eq7_rms_rel_error = eq7.rms_rel();
  report.alpha = eq7.alpha();
  report.paper_interp_rms_rel_error = paper.rms_rel();
  report.linear_basis_rms_rel_error = linear.rms_rel();
  report.direction_rms_rel_error = direction.rms_rel();
  report.eq1_truncated_rms_rel_error = a.has_transfer_rows() ? eq1.rms_rel() : 0.0;
  report.maps.front().eq7_rms_rel_error = eq7.rms_rel();
  for (std::size_t l = 0; l < a.lungs.size(); ++l) {
    report.per_lung[l].eq7_rms_rel_error = eq7_lung[l].rms_rel();
    report.per_lung[l].maps.front().eq7_rms_rel_error = eq7_lung[l].rms_rel();
  }
}

/// One map's eq. (7) errors on one lung, in double precision, indexed by the band count (2 to 8).
struct MapSweep {
  MapFigures figures;
  std::vector<ErrorSum> by_bands = std::vector<ErrorSum>(kMaxBands + 1);
};

/// The projection with the leading L^2 x L^2 block of G, for every L the fields x (N x >= L^2) allow.
void sweep_fit(const Eigen::MatrixXd& y, const Eigen::MatrixXd& gram, const Eigen::MatrixXd& x,
               const Eigen::MatrixXd& weighted_p, const Eigen::RowVectorXd& scale,
               const Eigen::Ref<const Eigen::MatrixXd>& exact, MapSweep& out) {
  for (int bands = 2; bands <= kMaxBands && bands * bands <= y.cols(); ++bands) {
    const int cb = bands * bands;
    const Eigen::LDLT<Eigen::MatrixXd> g(gram.topLeftCorner(cb, cb));
    const Eigen::MatrixXd f = g.solve(y.leftCols(cb).transpose() * weighted_p);
    const Eigen::MatrixXd d = (x.leftCols(cb) * f) * scale.asDiagonal();
    for (Eigen::Index k = 0; k < d.cols(); ++k)
      for (Eigen::Index i = 0; i < d.rows(); ++i) out.by_bands[bands].add(d(i, k), exact(i, k));
  }
}

/// The bands sweep of one lung with its asset's map, then with each compared map (its own map, basis and L^2
/// solves with the lung's factor, dropped once measured).
std::vector<MapSweep> sweep_lung(const LungWork& w, const BakedLung& lung, const BakeOptions& opt,
                                 const Workers& workers, const ExactEq1& exact, std::size_t l) {
  const Eigen::MatrixXd weighted = w.areas.asDiagonal() * exact.pressures[l];
  const auto block = exact.d.middleRows(lung.first_vertex, lung.vertex_count);
  std::vector<MapSweep> out(1);
  out[0].figures = {opt.sphere.map, w.sphere.folded, w.sphere.area_distortion, 0.0};
  sweep_fit(w.y, w.gram, w.x, weighted, exact.scales[l], block, out[0]);
  for (SphereMap map : opt.compare_maps) {
    if (map == opt.sphere.map) continue;
    SphereMapOptions o = opt.sphere;
    o.map = map;
    lungar::Result<SphereMapResult> other = map_to_sphere(w.mesh, w.centre, o);
    if (!other) continue;  // a surface with handles has only the radial map; the asset's map is measured anyway
    MapSweep s;
    s.figures = {map, other->folded, other->area_distortion, 0.0};
    const Eigen::MatrixXd y = sh_rows(other->u, kMaxBands);
    const Eigen::MatrixXd gram = y.transpose() * w.areas.asDiagonal() * y;
    const Eigen::MatrixXd x = solve_sh_fields(w, opt.model, y, workers);
    sweep_fit(y, gram, x, weighted, exact.scales[l], block, s);
    out.push_back(std::move(s));
  }
  return out;
}

/// Runs sweep_lung on every lung (the lungs in parallel, the threads shared out between them) and writes the
/// sweeps and the per-map figures.
void sweep_errors(const std::vector<std::unique_ptr<LungWork>>& work, const BakedAsset& a, const BakeOptions& opt,
                  const Workers& workers, const ExactEq1& exact, BakeReport& report) {
  std::vector<std::vector<MapSweep>> sweeps(work.size());
  const Workers per_lung{std::max(1, thread_count(workers) / static_cast<int>(work.size())), workers.cancel};
  parallel_for(work.size(), workers, [&](std::size_t l) {
    sweeps[l] = sweep_lung(*work[l], a.lungs[l], opt, per_lung, exact, l);
  });
  const auto maps = sweeps.front().size();
  for (const auto& s : sweeps)
    if (s.size() != maps) return;  // a compared map failed on one lung only: no side-by-side figure for all
  // The asset's map keeps its figures from the float path (float_errors); the compared ones get the sweep's.
  report.maps.resize(1);
  for (LungReport& lung : report.per_lung) {
    lung.maps.resize(1);
    lung.bands_sweep.clear();
  }
  for (std::size_t m = 1; m < maps; ++m) {
    MapFigures total{sweeps[0][m].figures.map, 0, 0, 0};
    for (std::size_t l = 0; l < work.size(); ++l) {
      MapFigures f = sweeps[l][m].figures;
      f.eq7_rms_rel_error = sweeps[l][m].by_bands[static_cast<int>(opt.bands)].rms_rel();
      report.per_lung[l].maps.push_back(f);
      total.folded_triangles += f.folded_triangles;
      total.area_distortion = std::max(total.area_distortion, f.area_distortion);  // the worst lung's
    }
    report.maps.push_back(total);
  }
  for (int bands = 2; bands <= kMaxBands && bands * bands <= work.front()->c_solved; ++bands) {
    BandsSweepEntry all{static_cast<std::uint32_t>(bands), static_cast<std::uint32_t>(bands * bands), 0, {}};
    for (std::size_t l = 0; l < work.size(); ++l) report.per_lung[l].bands_sweep.push_back({all.bands, all.coefficients, 0, {}});
    for (std::size_t m = 0; m < maps; ++m) {
      ErrorSum e;
      for (std::size_t l = 0; l < work.size(); ++l) {
        const ErrorSum& part = sweeps[l][m].by_bands[bands];
        e.diff2 += part.diff2;
        e.exact2 += part.exact2;
        BandsSweepEntry& mine = report.per_lung[l].bands_sweep.back();
        if (m == 0) mine.eq7_rms_rel_error = part.rms_rel();
        mine.by_map.push_back({sweeps[l][m].figures.map, part.rms_rel()});
      }
      if (m == 0) all.eq7_rms_rel_error = e.rms_rel();
      all.by_map.push_back({sweeps[0][m].figures.map, e.rms_rel()});
      if (m > 0 && static_cast<std::uint32_t>(bands) == opt.bands) report.maps[m].eq7_rms_rel_error = e.rms_rel();
    }
    report.bands_sweep.push_back(std::move(all));
  }
}

/// Physiology at the tidal volume, upright and supine, through eq. (7).
void physiology(const BakedAsset& a, BakeReport& report) {
  constexpr double kTidalMl = kTidalVolumeMl;
  const std::uint32_t c = a.coefficients();
  const std::size_t n = a.vertex_count();
  std::vector<float> force(a.lungs.size() * c), d7(n);
  const Eigen::Vector3d upright(0, 0, -1), supine_g(0, 1, 0);
  const PatientState healthy = PatientState::of(a);
  for (std::size_t l = 0; l < a.lungs.size(); ++l)
    force_sh_exact(a, a.lungs[l], healthy.lungs[l], upright, force.data() + l * c);
  displacement_eq7(a, force, d7);
  double max_mm = 0;
  for (const BakedLung& lung : a.lungs)
    for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i)
      max_mm = std::max(max_mm, std::abs(d7[i] * kTidalMl * lung.volume_share));
  report.displacement_max_mm_at_tidal = max_mm;
  std::vector<float> displaced(3 * n);
  deform_eq7(a, healthy, force, upright, kTidalMl, displaced);
  const double rest = enclosed_volume(a.triangles, a.positions.data());
  const double moved = enclosed_volume(a.triangles, displaced.data());
  report.tidal_volume_rel_error = ((moved - rest) / 1000.0 - kTidalMl) / kTidalMl;
  const double apex_base = end_ratio(a, d7, 2, 0.15);  // apex is high z
  report.base_apex_displacement_ratio = apex_base > 0 ? 1.0 / apex_base : 0.0;
  for (std::size_t l = 0; l < a.lungs.size(); ++l)
    force_sh_exact(a, a.lungs[l], healthy.lungs[l], supine_g, force.data() + l * c);
  displacement_eq7(a, force, d7);
  report.posterior_anterior_displacement_ratio = end_ratio(a, d7, 1, 0.15);  // posterior is high y
}

/// The three postures' lung-frame gravity: supine (on the back, +y posterior), prone, upright.
const Eigen::Vector3d kSupine(0, 1, 0), kProne(0, -1, 0), kUpright(0, 0, -1);

/// The compared model's exact displacement vectors at the tidal volume for gravity g, each lung's first-order
/// swept volume its share of it.
std::vector<float> compared_displacements(const std::vector<Eigen::MatrixXd>& basis,
                                          const std::vector<std::unique_ptr<LungWork>>& work, const BakedAsset& a,
                                          const BakeOptions& opt, const Eigen::Vector3d& g) {
  std::vector<float> out(3 * std::size_t{a.vertex_count()});
  const PatientState healthy = PatientState::of(a);
  for (std::size_t l = 0; l < work.size(); ++l) {
    const BakedLung& lung = a.lungs[l];
    const Eigen::Index n = basis[l].rows();
    const Eigen::MatrixXd u = linear_displacement(basis[l], opt.p0, opt.gamma_per_mm, g);
    const double swept = swept_volume(*work[l], u);
    const double scale = swept > 0 ? kTidalVolumeMl * 1000.0 * breath_share(a, healthy, l, g) / swept : 0.0;
    for (Eigen::Index i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) out[3 * (lung.first_vertex + static_cast<std::size_t>(i)) + c] = static_cast<float>(scale * u(i, c));
  }
  return out;
}

/// What the SH buys: the healthy pressure (linear: both fits carry it) and ARDS's collapse (not linear in
/// position), each fitted by the force SH and by the linear basis, supine and prone.
void pathology_force(const BakedAsset& a, BakeReport& report) {
  if (!a.has_sphere_dirs()) return;
  for (double severity : {0.0, 0.6}) {
    Result<std::shared_ptr<const DependentCollapse>> pattern = DependentCollapse::build(a, severity);
    if (!pattern) return;
    for (const auto& [name, g] : {std::pair{lungar::kPoseNames.name(lungar::Pose::Supine), kSupine},
                                  std::pair{lungar::kPoseNames.name(lungar::Pose::Prone), kProne}}) {
      const CollapseFitError e = (*pattern)->fit_error(a, g);
      report.pathology_force.push_back({severity == 0 ? "none" : "ards:0.6", name, e.sh_rms_rel, e.linear_rms_rel});
    }
  }
}

/// The motion object of the report: the asset's model through the float asset in three postures, and the other
/// model, exact, on the same lungs.
void motion(const std::vector<std::unique_ptr<LungWork>>& work, const BakedAsset& a, const BakeOptions& opt,
            const Workers& workers, BakeReport& report) {
  std::vector<SurfaceRegion> regions;
  for (const auto& w : work) regions.insert(regions.end(), w->regions.begin(), w->regions.end());
  const PatientState healthy = PatientState::of(a);
  const std::vector<float> supine = displacement_vectors(a, healthy, kSupine, kTidalVolumeMl);
  report.motion_supine = motion_figures(a, supine, regions);
  // Inside the lungs, supine: the points `lungar-bake export --interior 5000` writes, moving as it moves them.
  const InteriorDisplacement interior(a);
  const InteriorPoints points = interior.sample(kInteriorReportPoints, kInteriorSeed);
  report.interior_supine = point_motion_figures(points.positions, interior.displacement(supine, points));
  report.interior_points = points.size();
  report.interior_grid_mm = interior.spacing_mm();
  report.motion_prone = motion_figures(a, displacement_vectors(a, healthy, kProne, kTidalVolumeMl), regions);
  report.motion_upright = motion_figures(a, displacement_vectors(a, healthy, kUpright, kTidalVolumeMl), regions);
  report.compared_model = opt.model == MotionModel::sliding ? MotionModel::paper : MotionModel::sliding;
  std::vector<Eigen::MatrixXd> basis(work.size());
  const Workers per_lung{std::max(1, thread_count(workers) / static_cast<int>(work.size())), workers.cancel};
  parallel_for(work.size(), workers, [&](std::size_t l) {
    basis[l] = exact_linear_motion(*work[l], report.compared_model, opt, per_lung);
  });
  report.compared_supine = motion_figures(a, compared_displacements(basis, work, a, opt, kSupine), regions);
  report.compared_prone = motion_figures(a, compared_displacements(basis, work, a, opt, kProne), regions);
  report.compared_upright = motion_figures(a, compared_displacements(basis, work, a, opt, kUpright), regions);
}

}  // namespace

void evaluate_bake(const std::vector<std::unique_ptr<LungWork>>& work, const BakedAsset& a, const BakeOptions& opt,
                   const Workers& workers, const BakeProgress& progress, BakeReport& report) {
  const std::vector<Eigen::Vector3d> dirs = report_directions();
  Eigen::MatrixXd g_mat(3, static_cast<Eigen::Index>(dirs.size()));
  for (std::size_t k = 0; k < dirs.size(); ++k) g_mat.col(static_cast<Eigen::Index>(k)) = dirs[k];
  const ExactEq1 exact = exact_eq1(work, a, opt, g_mat);
  if (progress) progress("evaluate", 0.2);
  check_cancel(workers);
  float_errors(work, a, opt, dirs, exact, report);
  if (progress) progress("evaluate", 0.4);
  if (opt.bands_sweep) sweep_errors(work, a, opt, workers, exact, report);
  check_cancel(workers);
  if (progress) progress("evaluate", 0.9);
  physiology(a, report);
  motion(work, a, opt, workers, report);
  pathology_force(a, report);
  check_cancel(workers);
  report.evaluated = true;
  if (progress) progress("evaluate", 1.0);
}

}  // namespace lungar::sim
