// Tests of sim/breathing/driver: tidal volume, period, continuity across every kind of change, and the
// behaviour of holds, sighs, apnoea and the ventilator, all measured from sampled traces.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "breathing_measure.h"
#include "sim/breathing/driver.h"

using namespace lungar::sim;
using namespace lungar::sim::testing;

namespace {

PatternChange preset(Preset p) {
  PatternChange c;
  c.preset = p;
  return c;
}

}  // namespace

// Done-when: for each preset, the tidal volume measured over ten breaths is within 1 % of the target.
TEST(BreathingDriver, TidalVolumeOverTenBreathsMatchesTheTargetForEveryPreset) {
  for (Preset id : kAllPresets) {
    for (double target : {350.0, 500.0, 800.0}) {
      BreathingParams p;
      p.preset = id;
      p.tidal_volume_ml = target;
      const BreathingDriver d = make(p);
      const std::vector<double> vt = tidal_volumes(d, 0.0, 60.0 / p.rate_bpm, 10, 0.005);
      double mean = 0;
      for (double v : vt) {
        EXPECT_NEAR(v, target, 0.01 * target) << to_string(id);
        mean += v / 10.0;
      }
      EXPECT_NEAR(mean, target, 0.01 * target) << to_string(id);
    }
  }
}

TEST(BreathingDriver, TidalVolumeOnTheVentilatorMatchesTheTarget) {
  for (Preset id : kAllPresets) {
    BreathingParams p;
    p.preset = id;
    p.mode = Mode::Ventilator;
    p.rate_bpm = 15;
    p.peep_cmh2o = 5;
    const BreathingDriver d = make(p);
    for (double v : tidal_volumes(d, 0.0, 4.0, 10, 0.002)) EXPECT_NEAR(v, 500.0, 5.0) << to_string(id);
  }
}

// Done-when: the period matches the rate to 0.1 %.
TEST(BreathingDriver, PeriodMatchesTheRate) {
  for (double rate : {6.0, 12.0, 17.3, 30.0}) {
    for (double ie : {0.5, 1.0, 0.25}) {
      BreathingParams p;
      p.rate_bpm = rate;
      p.ie_ratio = ie;
      const BreathingDriver d = make(p);
      const double period = 60.0 / rate;
      const auto tr = trace(d, 0.0, 10.5 * period, period / 2000.0);
      const double frc = d.at(0).v_frc_ml;
      const std::vector<double> up = rising_crossings(tr, frc + 250.0);
      ASSERT_GE(up.size(), 10u);
      const double measured = (up[9] - up[0]) / 9.0;
      EXPECT_NEAR(measured, period, 0.001 * period) << rate << "/min, I:E " << ie;
    }
  }
}

TEST(BreathingDriver, InspirationTakesTheConfiguredShareOfTheBreath) {
  BreathingParams p;
  p.rate_bpm = 10;
  p.ie_ratio = 0.5;  // 2 s in, 4 s out
  const BreathingDriver d = make(p);
  const auto tr = trace(d, 0.0, 6.0, 0.001);
  std::size_t peak = 0;
  for (std::size_t k = 0; k < tr.size(); ++k) {
    if (tr[k].v_ml > tr[peak].v_ml) peak = k;
  }
  EXPECT_NEAR(tr[peak].t_s, 2.0, 0.01);
  EXPECT_EQ(d.at(1.0).phase, BreathPhase::Inspiration);
  EXPECT_EQ(d.at(3.0).phase, BreathPhase::Expiration);
}

TEST(BreathingDriver, DeltaVolumeIsZeroAtTheEndOfExpirationAndPositiveBetween) {
  const BreathingDriver d = make({});
  EXPECT_NEAR(d.at(0.0).dv_ml, 0.0, 1e-9);
  EXPECT_NEAR(d.at(5.0).dv_ml, 0.0, 1e-6);
  EXPECT_NEAR(d.at(0.0).v_ml, pv_preset(Preset::Normal).frc_ml(), 1e-9);
  for (const auto& s : trace(d, 0.01, 4.99, 0.01)) EXPECT_GT(s.dv_ml, 0.0);
}

// A script with every kind of change, some mid-breath, some overlapping.
struct Scripted {
  BreathingDriver driver;
  std::vector<double> times;                     ///< 0, then the time of each event
  std::vector<BreathingParams> after;            ///< the steady pattern after each of those
  std::vector<double> settled;                   ///< when the transition of each has ended
  std::vector<BreathingParams> sighs;            ///< sigh breaths, as steady patterns of their volume
  double end_s;
};

Scripted every_kind_of_change() {
  BreathingParams p;
  Scripted s{make(p), {0.0}, {p}, {0.0}, {}, 200.0};
  auto add = [&](const Event& e) {
    const std::string err = s.driver.apply(e).error();
    EXPECT_EQ(err, "") << to_string(e.kind) << " at " << e.t_s;
    s.times.push_back(e.t_s);
    s.after.push_back(s.driver.params());
    s.settled.push_back(s.driver.settled_s());
  };
  PatternChange rate;
  rate.rate_bpm = 20.0;
  add(Event::set(11.3, rate));                      // mid-inspiration
  PatternChange vt;
  vt.tidal_volume_ml = 700.0;
  add(Event::set(17.9, vt));                        // mid-expiration
  add(Event::set(25.2, preset(Preset::Fibrosis)));  // FRC drops by 0.7 L
  add(Event::sigh(40.1));
  BreathingParams sigh = s.driver.params();
  sigh.tidal_volume_ml = 1400.0;
  s.sighs.push_back(sigh);
  add(Event::of(47.5, EventKind::HoldStart));
  add(Event::of(52.5, EventKind::HoldEnd));
  add(Event::of(60.4, EventKind::ApnoeaStart));
  add(Event::of(75.0, EventKind::ApnoeaEnd));
  PatternChange ie;
  ie.ie_ratio = 1.0;
  ie.rate_bpm = 12.0;
  add(Event::set(88.8, ie));
  PatternChange vent;
  vent.mode = Mode::Ventilator;
  vent.peep_cmh2o = 5.0;
  add(Event::set(100.7, vent));
  add(Event::set(104.0, preset(Preset::Normal)));   // while the ventilator still fades in
  PatternChange off;
  off.mode = Mode::Spontaneous;
  add(Event::set(130.2, off));
  add(Event::set(150.1, preset(Preset::Emphysema)));
  return s;
}

// Done-when: V(t) is continuous: no step larger than the largest step of steady breathing, across every change.
// Between two events, the steps are compared with the steady breathing of the patterns that can be fading there
// (this one, the one before, and the one before that if its transition is still running); the sigh breath is
// compared with steady breathing at the sigh's volume.
TEST(BreathingDriver, NoVolumeStepAcrossScriptedChangesExceedsTheLargestSteadyStep) {
  const Scripted s = every_kind_of_change();
  const double dt = 0.01;
  double sigh_step = 0;
  for (const BreathingParams& p : s.sighs) sigh_step = std::max(sigh_step, steady_max_step_ml(p, dt));
  for (std::size_t k = 0; k < s.times.size(); ++k) {
    const double t0 = s.times[k];
    const double t1 = k + 1 < s.times.size() ? s.times[k + 1] : s.end_s;
    double steady = 0;
    const std::size_t first = k >= 2 && s.settled[k - 1] > t0 ? k - 2 : (k >= 1 ? k - 1 : 0);
    for (std::size_t j = first; j <= k; ++j) steady = std::max(steady, steady_max_step_ml(s.after[j], dt));
    const bool sigh_window = t0 <= 40.1 && 40.1 < t1 + 10.0;
    const auto tr = trace(s.driver, t0, t1, dt);
    double worst = 0, when = 0;
    for (std::size_t i = 1; i < tr.size(); ++i) {
      const double step = std::abs(tr[i].v_ml - tr[i - 1].v_ml);
      if (step > worst) worst = step, when = tr[i].t_s;
    }
    EXPECT_LE(worst, sigh_window ? std::max(steady, sigh_step) : steady)
        << "between " << t0 << " and " << t1 << " s: " << worst << " mL at " << when << " s";
    std::printf("[%6.1f, %6.1f) s: largest step %7.3f mL, steady %7.3f mL%s\n", t0, t1, worst, steady,
                sigh_window ? " (sigh)" : "");
  }
}

// A jump would not shrink with the sampling step; a continuous trace's steps shrink in proportion.
TEST(BreathingDriver, StepsShrinkWithTheSamplingStepAcrossEveryChange) {
  const Scripted s = every_kind_of_change();
  const double coarse = max_step_ml(trace(s.driver, 0.0, s.end_s, 1e-2));
  const double fine = max_step_ml(trace(s.driver, 0.0, s.end_s, 1e-3));
  EXPECT_LT(fine, 0.12 * coarse);
  // Pressure and the FRC reference are continuous too.
  const auto tr = trace(s.driver, 0.0, s.end_s, 1e-3);
  for (std::size_t k = 1; k < tr.size(); ++k) {
    ASSERT_LT(std::abs(tr[k].p_cmh2o - tr[k - 1].p_cmh2o), 0.05) << tr[k].t_s;
    ASSERT_LT(std::abs(tr[k].v_frc_ml - tr[k - 1].v_frc_ml), 1.0) << tr[k].t_s;
  }
}

TEST(BreathingDriver, ChangesSettleOnTheNewPattern) {
  BreathingDriver d = make({});
  PatternChange c = preset(Preset::Fibrosis);
  c.tidal_volume_ml = 400.0;
  c.rate_bpm = 15.0;
  ASSERT_TRUE(d.apply(Event::set(7.7, c)).ok());
  const double settled = d.settled_s();
  EXPECT_GT(settled, 7.7);
  EXPECT_LT(settled, 7.7 + 20.0);
  const double start = std::ceil(settled / 4.0) * 4.0 + 4.0;
  // After the transition: the fibrotic FRC, 400 mL tidal volume and 4 s breaths (phase is arbitrary, so the
  // windows are one period long and the tidal volume is their peak-to-trough).
  EXPECT_NEAR(d.at(start).v_frc_ml, pv_preset(Preset::Fibrosis).frc_ml(), 1e-6);
  for (double v : tidal_volumes(d, start, 4.0, 5, 0.002)) EXPECT_NEAR(v, 400.0, 4.0);
  const auto tr = trace(d, start, start + 10 * 4.0 + 1.0, 0.002);
  double lo = 1e300;
  for (const auto& s : tr) lo = std::min(lo, s.v_ml);
  const std::vector<double> up = rising_crossings(tr, lo + 200.0);
  ASSERT_GE(up.size(), 10u);
  EXPECT_NEAR((up[9] - up[0]) / 9.0, 4.0, 0.004);
}

TEST(BreathingDriver, ABreathHoldFreezesTheVolume) {
  BreathingDriver d = make({});
  // 1.667 s is the end of inspiration at 12/min, I:E 1:2: an inspiratory hold.
  ASSERT_TRUE(d.apply(Event::of(60.0 / 36.0, EventKind::HoldStart)).ok());
  ASSERT_TRUE(d.apply(Event::of(12.0, EventKind::HoldEnd)).ok());
  // The cycle stops within kHoldRampS (0.2 s) without a step in flow, so the volume stays near the peak: the
  // phase runs on for 0.1 s of breathing, in which expiration (braked, but under way) gives back about 1 % of V_T.
  const double v = d.at(3.0).v_ml;
  EXPECT_NEAR(v, pv_preset(Preset::Normal).frc_ml() + 500.0, 10.0);
  for (double t = 2.0; t < 12.0; t += 0.5) {
    EXPECT_NEAR(d.at(t).v_ml, v, 1e-9) << t;
    EXPECT_EQ(d.at(t).phase, BreathPhase::Hold);
  }
  // After the hold, breathing resumes with the same tidal volume.
  for (double tv : tidal_volumes(d, 13.0, 5.0, 3, 0.005)) EXPECT_NEAR(tv, 500.0, 5.0);
}

TEST(BreathingDriver, ASighIsOneDeeperBreath) {
  BreathingDriver d = make({});
  ASSERT_TRUE(d.apply(Event::sigh(12.0)).ok());  // mid-breath 2: breath 3 (15-20 s) is the sigh
  const std::vector<double> vt = tidal_volumes(d, 0.0, 5.0, 6, 0.005);
  EXPECT_NEAR(vt[2], 500.0, 5.0);
  EXPECT_NEAR(vt[3], 1000.0, 10.0);  // twice the tidal volume by default
  EXPECT_NEAR(vt[4], 500.0, 5.0);
  BreathingDriver e = make({});
  ASSERT_TRUE(e.apply(Event::sigh(0.5, 1200.0)).ok());
  EXPECT_NEAR(tidal_volumes(e, 5.0, 5.0, 1, 0.005)[0], 1200.0, 12.0);
}

TEST(BreathingDriver, ApnoeaSettlesAtTheFrcAndBreathingReturns) {
  BreathingDriver d = make({});
  ASSERT_TRUE(d.apply(Event::of(6.0, EventKind::ApnoeaStart)).ok());
  const double quiet = d.settled_s();
  ASSERT_TRUE(d.apply(Event::of(40.0, EventKind::ApnoeaEnd)).ok());
  ASSERT_LT(quiet, 30.0);
  for (double t = quiet; t < 40.0; t += 0.25) {
    EXPECT_NEAR(d.at(t).dv_ml, 0.0, 1e-9) << t;
    EXPECT_EQ(d.at(t).phase, BreathPhase::Apnoea);
  }
  for (double tv : tidal_volumes(d, d.settled_s() + 5.0, 5.0, 3, 0.005)) EXPECT_NEAR(tv, 500.0, 5.0);
}

TEST(BreathingDriver, TheVentilatorAppliesASquarePressureWave) {
  BreathingParams p;
  p.mode = Mode::Ventilator;
  p.peep_cmh2o = 5.0;
  const BreathingDriver d = make(p);
  // Applied pressure takes two values only: low through expiration, high through inspiration.
  const double low = pv_preset(Preset::Normal).p_frc_cmh2o + 5.0;
  const double high = d.at(0.5).p_applied_cmh2o;
  EXPECT_GT(high, low + 1.0);
  for (const auto& s : trace(d, 0.0, 10.0, 0.01)) {
    const double expected = s.phase == BreathPhase::Inspiration ? high : low;
    EXPECT_NEAR(s.p_applied_cmh2o, expected, 1e-9) << s.t_s;
    EXPECT_LE(s.p_cmh2o, high + 1e-9);  // alveolar pressure lags behind, between the two
    EXPECT_GE(s.p_cmh2o, low - 1e-9);
  }
  // PEEP holds the end-expiratory volume above the relaxed FRC.
  EXPECT_GT(d.at(4.99).dv_ml, 100.0);
}

TEST(BreathingDriver, AShortInspirationOnTheVentilatorIsDrivenToADeepBreathWhileTheAlveoliStayUnderTheCap) {
  // kMaxTranspulmonaryCmH2O caps the alveolar peak, not the drive: with 1.2 s of inspiration against tau 1 s the
  // alveoli reach about 70 % of the drive, so the drive may go to the cap's margin over 0.7 and a breath near the
  // curve's reach (2.3 L, the alveoli at about 30 cmH2O) is breathed.
  BreathingParams p;
  p.mode = Mode::Ventilator;
  p.rate_bpm = 10;
  p.ie_ratio = 0.25;
  p.ventilator_tau_s = 1.0;
  p.peep_cmh2o = 5;
  p.tidal_volume_ml = 2300;
  const BreathingDriver d = make(p);
  for (double v : tidal_volumes(d, 0.0, 6.0, 5, 0.002)) EXPECT_NEAR(v, p.tidal_volume_ml, 0.01 * p.tidal_volume_ml);
  double alveolar = 0;
  for (const auto& s : trace(d, 0.0, 30.0, 0.01)) alveolar = std::max(alveolar, s.p_cmh2o);
  EXPECT_LE(alveolar, kMaxTranspulmonaryCmH2O);
}

TEST(BreathingDriver, RejectsEventsOutOfOrderAndUnreachableTargets) {
  BreathingDriver d = make({});
  ASSERT_TRUE(d.apply(Event::set(10.0, preset(Preset::Fibrosis))).ok());
  EXPECT_EQ(d.apply(Event::of(9.0, EventKind::HoldStart)).error(),
            "hold start at 9 s: expected a time at or after the last event (10 s)");
  PatternChange big;
  big.tidal_volume_ml = 2500.0;
  EXPECT_EQ(d.apply(Event::set(11.0, big)).error(),
            "change at 11 s: tidal_volume_ml: expected at most 2077 mL on the fibrosis curve (its volume at 40 "
            "cmH2O less that at 8 cmH2O), got 2500 mL");
  PatternChange fast;
  fast.rate_bpm = 90.0;
  EXPECT_EQ(d.apply(Event::set(11.0, fast)).error(), "change at 11 s: rate_bpm: expected [2, 60] breaths/min, got 90");
  PatternChange vent;
  vent.mode = Mode::Ventilator;
  ASSERT_TRUE(d.apply(Event::set(12.0, vent)).ok());
  EXPECT_EQ(d.apply(Event::sigh(13.0)).error(),
            "sigh at 13 s: sigh: expected spontaneous breathing, got a sigh on the ventilator");
  // A rejected event changes nothing.
  EXPECT_EQ(d.params().preset, Preset::Fibrosis);
  EXPECT_EQ(d.params().mode, Mode::Ventilator);
  EXPECT_DOUBLE_EQ(d.params().tidal_volume_ml, 500.0);

  BreathingParams bad;
  bad.ie_ratio = 0.0;
  EXPECT_EQ(BreathingDriver::create(bad).error(), "ie_ratio: expected [0.1, 4], got 0");
}

TEST(BreathingDriver, AtIsAPureFunctionOfTime) {
  const Scripted s = every_kind_of_change();
  const BreathingSample a = s.driver.at(63.21);
  (void)s.driver.at(150.0);
  (void)s.driver.at(-3.0);
  const BreathingSample b = s.driver.at(63.21);
  EXPECT_EQ(a.v_ml, b.v_ml);
  EXPECT_EQ(a.p_cmh2o, b.p_cmh2o);
}
