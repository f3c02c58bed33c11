// Tests of platform/scenario_adapter: shipped scenarios run as the issue describes, the names config accepts are
// the names sim knows, and errors only the driver can see come back naming the scenario file and line.
#include <gtest/gtest.h>

#include <string>

#include "config/scenario_load.h"
#include "platform/app/scenario_adapter.h"
#include "tests/sim/breathing/breathing_measure.h"

using namespace lungar;
using namespace lungar::sim::testing;

namespace {

const std::string kScenarios = std::string(LUNGAR_SOURCE_DIR) + "/config/scenarios";

sim::BreathingScript load(const std::string& file) {
  config::BreathingSettings b;
  b.scenario = kScenarios + "/" + file;
  auto r = platform::load_breathing_script(b);
  EXPECT_TRUE(r) << r.error();
  return std::move(*r);
}

std::string error_of(const std::string& toml) {
  auto loaded = config::load_scenario_from_string(toml, "s.toml");
  EXPECT_TRUE(loaded) << loaded.error();
  auto r = platform::make_breathing_script(*loaded);
  EXPECT_FALSE(r);
  return r.error();
}

}  // namespace

// "normal for 20 s, turn to supine over 5 s, fibrosis from 40 s".
TEST(ScenarioAdapter, TheTeachingScenario) {
  const sim::BreathingScript s = load("teaching.toml");
  EXPECT_DOUBLE_EQ(s.duration_s, 70.0);
  EXPECT_NEAR(sim::tilt_from_upright_deg(s.orientation.at(19.9)), 0.0, 1e-9);
  EXPECT_NEAR(sim::tilt_from_upright_deg(s.orientation.at(22.5)), 45.0, 1e-6);
  EXPECT_LT((sim::gravity_in_lung_frame(s.orientation.at(25.0)) - Eigen::Vector3d(0, 1, 0)).norm(), 1e-9);  // supine
  EXPECT_NEAR(s.driver.at(39.9).v_frc_ml, sim::pv_preset(sim::Preset::Normal).frc_ml(), 1e-9);
  EXPECT_NEAR(s.driver.at(70.0).v_frc_ml, sim::pv_preset(sim::Preset::Fibrosis).frc_ml(), 1e-9);
  // Steady normal breathing before 40 s, steady fibrotic breathing at the end: 500 mL either way.
  for (double v : tidal_volumes(s.driver, 0.0, 5.0, 7, 0.005)) EXPECT_NEAR(v, 500.0, 5.0);
  EXPECT_LT(s.driver.settled_s(), 60.0);
  for (double v : tidal_volumes(s.driver, 60.0, 5.0, 2, 0.005)) EXPECT_NEAR(v, 500.0, 5.0);
}

// Done-when, on the shipped scenarios: no step larger than the largest step of steady breathing.
TEST(ScenarioAdapter, ShippedScenariosNeverStepFasterThanSteadyBreathing) {
  for (const char* file : {"teaching.toml", "clinical-tour.toml"}) {
    const sim::BreathingScript s = load(file);
    auto loaded = config::load_scenario(kScenarios + "/" + file);
    ASSERT_TRUE(loaded) << loaded.error();
    // Every steady pattern the scenario passes through, including its sighs as breaths of their volume.
    std::vector<sim::BreathingParams> steady;
    const double dt = 0.01;
    auto made = platform::to_breathing_params(loaded->start);
    ASSERT_TRUE(made) << made.error();
    const sim::BreathingParams start = *made;
    steady.push_back(start);
    sim::BreathingParams current = start;
    for (const config::ScenarioEvent& e : loaded->events) {
      if (e.preset) current.preset = *sim::preset_from_name(*e.preset);
      if (e.rate_bpm) current.rate_bpm = *e.rate_bpm;
      if (e.ie_ratio) current.ie_ratio = *e.ie_ratio;
      if (e.tidal_volume_ml) current.tidal_volume_ml = *e.tidal_volume_ml;
      if (e.kind == config::ScenarioEventKind::Ventilator) current.mode = sim::Mode::Ventilator;
      if (e.kind == config::ScenarioEventKind::Spontaneous) current.mode = sim::Mode::Spontaneous;
      if (e.peep_cmh2o) current.peep_cmh2o = *e.peep_cmh2o;
      if (e.tau_s) current.ventilator_tau_s = *e.tau_s;
      steady.push_back(current);
      if (e.kind == config::ScenarioEventKind::Sigh) {
        sim::BreathingParams sigh = current;
        sigh.tidal_volume_ml = e.volume_ml.value_or(2.0 * current.tidal_volume_ml);
        steady.push_back(sigh);
      }
    }
    double reference = 0;
    for (const auto& p : steady) reference = std::max(reference, steady_max_step_ml(p, dt));
    const double worst = max_step_ml(trace(s.driver, 0.0, s.duration_s, dt));
    EXPECT_LE(worst, reference) << file;
    EXPECT_GT(worst, 0.5 * reference) << file;  // the trace does breathe
  }
}

TEST(ScenarioAdapter, HoldsAndApnoeasEndAfterTheirDuration) {
  const sim::BreathingScript s = load("clinical-tour.toml");
  // hold at 51.6 s for 6 s; apnoea at 72 s for 12 s.
  EXPECT_EQ(s.driver.at(55.0).phase, sim::BreathPhase::Hold);
  EXPECT_NEAR(s.driver.at(52.0).v_ml, s.driver.at(57.5).v_ml, 1e-9);
  EXPECT_NE(s.driver.at(58.0).phase, sim::BreathPhase::Hold);
  EXPECT_EQ(s.driver.at(83.0).phase, sim::BreathPhase::Apnoea);
  EXPECT_NE(s.driver.at(84.5).phase, sim::BreathPhase::Apnoea);
  // On the ventilator (95-125 s) the applied pressure is a square wave: two levels only.
  const double low = s.driver.at(119.9).p_applied_cmh2o;
  const double high = s.driver.at(120.5).p_applied_cmh2o;
  EXPECT_NEAR(low, sim::pv_preset(sim::Preset::Normal).p_frc_cmh2o + 5.0, 1e-9);
  EXPECT_GT(high, low + 1.0);
}

TEST(ScenarioAdapter, EveryNameSimKnowsIsAcceptedByConfig) {
  for (sim::Preset id : sim::kAllPresets) {
    auto r = config::load_scenario_from_string("[start]\npreset = \"" + std::string(sim::to_string(id)) + "\"\n", "s");
    EXPECT_TRUE(r) << r.error();
  }
  for (sim::Pose pose : sim::kAllPoses) {
    auto r = config::load_scenario_from_string("[start]\npose = \"" + std::string(sim::to_string(pose)) + "\"\n", "s");
    ASSERT_TRUE(r) << r.error();
    auto script = platform::make_breathing_script(*r);
    ASSERT_TRUE(script) << script.error();
    EXPECT_TRUE(script->orientation.at(0.0).isApprox(sim::pose_rotation(pose)));
  }
}

TEST(ScenarioAdapter, DriverErrorsNameTheScenarioFileAndLine) {
  EXPECT_EQ(error_of("[start]\npreset = \"fibrosis\"\n\n[[event]]\nat_s = 3\nkind = \"change\"\n"
                     "tidal_volume_ml = 2500\n"),
            "s.toml:5: key 'event[0]': change at 3 s: tidal_volume_ml: expected at most 2077 mL on the fibrosis "
            "curve (its volume at 40 cmH2O less that at 8 cmH2O), got 2500 mL");
  EXPECT_EQ(error_of("[[event]]\nat_s = 3\nkind = \"sigh\"\nvolume_ml = 2900\n[start]\npreset = \"fibrosis\"\n"),
            "s.toml:2: key 'event[0]': sigh at 3 s: sigh volume_ml: expected at most 2077 mL on the fibrosis curve "
            "(its volume at 40 cmH2O less that at 8 cmH2O), got 2900 mL");
}

TEST(ScenarioAdapter, WithoutAScenarioTheConfigBreathingRunsSteadily) {
  config::BreathingSettings b;
  b.preset = "emphysema";
  b.rate_bpm = 15.0;
  b.tidal_volume_ml = 600.0;
  auto r = platform::load_breathing_script(b, 30.0);
  ASSERT_TRUE(r) << r.error();
  EXPECT_DOUBLE_EQ(r->duration_s, 30.0);
  for (double v : tidal_volumes(r->driver, 0.0, 4.0, 10, 0.005)) EXPECT_NEAR(v, 600.0, 6.0);
  EXPECT_NEAR(sim::tilt_from_upright_deg(r->orientation.at(20.0)), 0.0, 1e-12);
  b.scenario = "/nonexistent.toml";
  EXPECT_EQ(platform::load_breathing_script(b).error(),
            "/nonexistent.toml: cannot read the scenario: expected a TOML file, got no such file");
}
