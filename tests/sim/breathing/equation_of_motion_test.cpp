// Tests of spontaneous breathing by the equation of motion (sim/breathing/equation_of_motion.h): the exhale path
// against 4-D CT, the exact tidal volume and period, the physics (P_mus = R dV/dt + (V - V_rel)/C, a passive tail of
// time constant R C), the muscle pressure's documented relaxation, and the presets' order of expiratory speed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "breathing_measure.h"
#include "sim/breathing/driver.h"
#include "sim/breathing/equation_of_motion.h"
#include "sim/breathing/exhale_path.h"

using namespace lungar::sim;
using namespace lungar::sim::testing;

namespace {

Pattern solved(const BreathingParams& p) {
  Pattern pat;
  pat.params = p;
  EXPECT_TRUE(solve(pat).ok());
  return pat;
}

/// The exhale path measured from a sampled trace, as 4-D CT does: the end-inhale maximum of the fourth breath,
/// then the share of the path to half a breath later covered at 10, 20, 30, 40 % of the breath.
std::vector<double> exhale_path_from_trace(const BreathingDriver& d, double period) {
  const auto tr = trace(d, 3.0 * period, 4.0 * period, period / 20000.0);
  const auto peak = std::max_element(tr.begin(), tr.end(),
                                     [](const BreathingSample& a, const BreathingSample& b) { return a.v_ml < b.v_ml; });
  const double half = peak->v_ml - d.at(peak->t_s + 0.5 * period).v_ml;
  std::vector<double> out;
  for (double x : {0.1, 0.2, 0.3, 0.4}) out.push_back((peak->v_ml - d.at(peak->t_s + x * period).v_ml) / half);
  return out;
}

}  // namespace

// At the defaults (12/min, I:E 1:2, 500 mL, normal), expiration covers 0.15 / 0.50 / 0.73 / 0.89 of its end-inhale
// -> half-a-breath-later path at 10 / 20 / 30 / 40 % of the breath in DIR-Lab's 4-D CT; the driver within 0.1.
TEST(EquationOfMotion, DefaultExhalePathFollows4dct) {
  const BreathingParams p;
  const std::vector<double> path = exhale_path_from_trace(make(p), 60.0 / p.rate_bpm);
  auto measured = measure_exhale_path(p);
  ASSERT_TRUE(measured) << measured.error();
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(path[i], kExhalePath4dct[i], 0.1) << "at " << 10 * (i + 1) << " % of the breath";
    EXPECT_NEAR(measured->path[i], path[i], 1e-3) << "measure_exhale_path at " << 10 * (i + 1) << " %";
  }
  // Expiration starts slowly (post-inspiratory braking), unlike a bare RC decay, which would be past half way at 10 %.
  EXPECT_LT(path[0], 0.3);
}

// Emphysema (high R, high C: long tau) exhales more slowly than normal; fibrosis (low C: short tau) faster.
TEST(EquationOfMotion, EmphysemaExhalesSlowerAndFibrosisFasterThanNormal) {
  auto path = [](Preset id) {
    BreathingParams p;
    p.preset = id;
    auto m = measure_exhale_path(p);
    EXPECT_TRUE(m) << m.error();
    return m->path;
  };
  const auto normal = path(Preset::Normal), emphysema = path(Preset::Emphysema), fibrosis = path(Preset::Fibrosis);
  EXPECT_LT(emphysema[1], normal[1] - 0.1);
  EXPECT_GT(fibrosis[1], normal[1]);
  // And why: tau = R C is longest for emphysema, shortest for fibrosis.
  const double tau_n = solved({}).cycle.tau_s;
  BreathingParams e, f;
  e.preset = Preset::Emphysema;
  f.preset = Preset::Fibrosis;
  EXPECT_GT(solved(e).cycle.tau_s, 2.0 * tau_n);
  EXPECT_LT(solved(f).cycle.tau_s, tau_n);
  EXPECT_GT(solved(e).resistance_cmh2o_s_per_l, solved({}).resistance_cmh2o_s_per_l);
  EXPECT_GT(solved(e).compliance_ml_per_cmh2o, solved({}).compliance_ml_per_cmh2o);
  EXPECT_LT(solved(f).compliance_ml_per_cmh2o, solved({}).compliance_ml_per_cmh2o);
}

// Literature ranges: a healthy adult's respiratory system has R of 2-4 cmH2O.s/L and C about 0.1 L/cmH2O.
TEST(EquationOfMotion, NormalMechanicsAreThoseOfAHealthyAdult) {
  const Pattern n = solved({});
  EXPECT_GE(n.resistance_cmh2o_s_per_l, 2.0);
  EXPECT_LE(n.resistance_cmh2o_s_per_l, 4.0);
  EXPECT_NEAR(n.compliance_ml_per_cmh2o, 100.0, 20.0);
}

// Tidal volume exact, the minimum at phase 0 is the FRC and the maximum at the end of inspiration, for every preset
// and across rates and I:E ratios, including those where the mechanical I:E needs the cycle stretched in time.
TEST(EquationOfMotion, TidalVolumeIsExactAndTheMinimumIsTheFrc) {
  for (Preset id : kAllPresets) {
    for (double rate : {4.0, 12.0, 25.0, 60.0}) {
      for (double ie : {0.2, 0.5, 1.0, 3.0}) {
        BreathingParams p;
        p.preset = id;
        p.rate_bpm = rate;
        p.ie_ratio = ie;
        p.tidal_volume_ml = 650.0;
        const Pattern pat = solved(p);
        const double rho = inspiratory_fraction(ie);
        const double frc = pv_preset(id).frc_ml();
        EXPECT_NEAR(evaluate(pat, 7.0).v_ml, frc, 1e-9);
        EXPECT_NEAR(evaluate(pat, 7.0 + rho).v_ml, frc + 650.0, 1e-9);
        double lo = 1e300, hi = -1e300;
        for (int k = 0; k < 4000; ++k) {
          const double v = evaluate(pat, 7.0 + k / 4000.0).v_ml;
          lo = std::min(lo, v);
          hi = std::max(hi, v);
        }
        const std::string where = std::string(to_string(id)) + " " + std::to_string(rate) + "/min I:E " +
                                  std::to_string(ie);
        EXPECT_NEAR(hi - lo, 650.0, 0.005 * 650.0) << where;
        EXPECT_GE(lo, frc - 1e-6) << where;
        EXPECT_LE(hi, frc + 650.0 + 1e-6) << where;
      }
    }
  }
}

// The volume at the end of a breath equals that at its start: V(t) = V(t + T) to rounding, and the flow is
// continuous across the join (zero on both sides).
TEST(EquationOfMotion, BreathingIsPeriodic) {
  for (Preset id : kAllPresets) {
    BreathingParams p;
    p.preset = id;
    p.rate_bpm = 15.0;
    const BreathingDriver d = make(p);
    const double period = 4.0;
    for (double t = 0.0; t < 8.0; t += 0.0371) {
      EXPECT_NEAR(d.at(t + period).v_ml, d.at(t).v_ml, 1e-9) << to_string(id) << " at " << t;
      EXPECT_NEAR(d.at(t + 3 * period).v_ml, d.at(t).v_ml, 1e-9) << to_string(id) << " at " << t;
    }
    const double h = 1e-5;
    const double flow_before = (d.at(period).v_ml - d.at(period - h).v_ml) / h;
    const double flow_after = (d.at(period + h).v_ml - d.at(period).v_ml) / h;
    EXPECT_NEAR(flow_before, 0.0, 0.5) << to_string(id);  // mL/s; the peak flow is several hundred
    EXPECT_NEAR(flow_after, 0.0, 0.5) << to_string(id);
  }
}

// The physics: along the default breath, P_mus = R dV/dt + (V - V_rel)/C with the pattern's R, C and muscle
// pressure, V_rel the relaxed volume (the end-expiratory volume less what the breath has not yet exhaled).
TEST(EquationOfMotion, VolumeSolvesTheEquationOfMotion) {
  const Pattern pat = solved({});
  const MuscleCycle& c = pat.cycle;
  ASSERT_NEAR(c.s_max - c.s_min, c.inspiratory_share * c.period_s, 1e-9);  // no stretching at the defaults
  const double cp = pat.compliance_ml_per_cmh2o * pat.pmus_peak_cmh2o;  // mL per unit of the cycle's volume
  const double v_rel = pat.v_frc_ml - cp * c.x_min;
  const double r = pat.resistance_cmh2o_s_per_l * 1e-3;  // cmH2O.s/mL
  double worst = 0;
  for (int k = 1; k < 500; ++k) {
    const double u = k / 500.0, h = 1e-6;
    const double v = evaluate(pat, u).v_ml;
    const double flow = (evaluate(pat, u + h).v_ml - evaluate(pat, u - h).v_ml) / (2 * h * c.period_s);
    double s = c.s_min + u * c.period_s;
    if (s >= c.period_s) s -= c.period_s;
    const double pmus = pat.pmus_peak_cmh2o * muscle_pressure(c, s);
    worst = std::max(worst, std::abs(pmus - (r * flow + (v - v_rel) / pat.compliance_ml_per_cmh2o)));
  }
  EXPECT_LT(worst, 1e-4 * pat.pmus_peak_cmh2o);
  EXPECT_GT(pat.pmus_peak_cmh2o, 2.0);  // a quiet breath: a few cmH2O
  EXPECT_LT(pat.pmus_peak_cmh2o, 10.0);
}

// The muscle pressure: zero at the onset, its peak at the end of the rise, half at 23 % and zero at 79 % of the
// expiratory time (Shee et al. 1985), zero after; so the end of expiration is a passive decay of time constant R C.
TEST(EquationOfMotion, MusclesRelaxThroughEarlyExpirationThenExpirationIsPassive) {
  const Pattern pat = solved({});
  const MuscleCycle& c = pat.cycle;
  const double te = (1.0 - c.inspiratory_share) * c.period_s;
  EXPECT_NEAR(muscle_pressure(c, 0.0), 0.0, 1e-12);
  EXPECT_NEAR(muscle_pressure(c, c.rise_s - 1e-9), 1.0, 1e-9);
  EXPECT_NEAR(muscle_pressure(c, c.rise_s + 0.23 * te), 0.5, 1e-6);
  EXPECT_NEAR(muscle_pressure(c, c.rise_s + 0.79 * te - 1e-9), 0.0, 1e-8);
  EXPECT_EQ(muscle_pressure(c, c.rise_s + 0.8 * te), 0.0);
  // The passive tail: V - V_rel falls by exp(-dt / tau).
  const double cp = pat.compliance_ml_per_cmh2o * pat.pmus_peak_cmh2o;
  const double v_rel = pat.v_frc_ml - cp * c.x_min;
  const double tail = c.rise_s + c.relax_s;  // neural time where the muscles are off
  const double u0 = (tail - c.s_min) / c.period_s + 0.01, u1 = u0 + 0.05;
  ASSERT_LT(u1, 1.0);
  const double ratio = (evaluate(pat, u1).v_ml - v_rel) / (evaluate(pat, u0).v_ml - v_rel);
  EXPECT_NEAR(ratio, std::exp(-0.05 * c.period_s / c.tau_s), 1e-9);
}

// The preset's curve still holds: the transpulmonary pressure is the curve's pressure at the volume, and its swing
// over a breath is the curve's swing for the tidal volume.
TEST(EquationOfMotion, PressureIsThePresetCurveAtTheVolume) {
  for (Preset id : kAllPresets) {
    BreathingParams p;
    p.preset = id;
    const Pattern pat = solved(p);
    const PvPreset& preset = pv_preset(id);
    for (double u = 0.0; u < 1.0; u += 0.01) {
      const PatternPoint pt = evaluate(pat, u);
      EXPECT_NEAR(pt.p_cmh2o, preset.curve.pressure_cmh2o(pt.v_ml), 1e-12);
      EXPECT_EQ(pt.p_applied_cmh2o, pt.p_cmh2o);
    }
    EXPECT_NEAR(evaluate(pat, 0.0).p_cmh2o, preset.p_frc_cmh2o, 1e-9);
    EXPECT_NEAR(evaluate(pat, inspiratory_fraction(p.ie_ratio)).p_cmh2o - preset.p_frc_cmh2o, pat.swing_cmh2o, 1e-9);
  }
}
