// Tests of sim/breathing/pv_curve: the presets give the physiological figures their comments claim.
#include <gtest/gtest.h>

#include "sim/breathing/pv_curve.h"

using namespace lungar::sim;

TEST(PvCurve, InverseUndoesTheSigmoid) {
  for (Preset id : kAllPresets) {
    const PvCurve& c = pv_preset(id).curve;
    for (double p = -5.0; p <= 40.0; p += 0.5) {
      EXPECT_NEAR(c.pressure_cmh2o(c.volume_ml(p)), p, 1e-6) << to_string(id) << " at " << p;
    }
  }
}

TEST(PvCurve, ComplianceIsTheSlopeOfTheCurve) {
  for (Preset id : kAllPresets) {
    const PvCurve& c = pv_preset(id).curve;
    for (double p = 0.0; p <= 30.0; p += 2.5) {
      const double h = 1e-4;
      const double numeric = (c.volume_ml(p + h) - c.volume_ml(p - h)) / (2 * h);
      EXPECT_NEAR(c.compliance_ml_per_cmh2o(p), numeric, 1e-4 * numeric) << to_string(id) << " at " << p;
    }
  }
}

// West, Respiratory Physiology: FRC about 2.5 L at +5 cmH2O, TLC about 6 L, compliance about 200 mL/cmH2O.
TEST(PvPresets, NormalAdultFigures) {
  const PvPreset& n = pv_preset(Preset::Normal);
  EXPECT_NEAR(n.frc_ml(), 2500.0, 50.0);
  EXPECT_NEAR(n.curve.volume_ml(30.0), 6000.0, 100.0);
  EXPECT_NEAR(n.curve.compliance_ml_per_cmh2o(n.p_frc_cmh2o), 200.0, 20.0);
  // Quiet breathing is on the steep part: compliance at FRC within 20 % of the curve's maximum (at c).
  EXPECT_GT(n.curve.compliance_ml_per_cmh2o(n.p_frc_cmh2o), 0.8 * n.curve.compliance_ml_per_cmh2o(n.curve.c_cmh2o));
}

TEST(PvPresets, EmphysemaIsMoreCompliantAndLarger) {
  const PvPreset& n = pv_preset(Preset::Normal);
  const PvPreset& e = pv_preset(Preset::Emphysema);
  EXPECT_GT(e.frc_ml(), n.frc_ml() + 1000.0);
  EXPECT_GT(e.curve.volume_ml(kMaxTranspulmonaryCmH2O), n.curve.volume_ml(kMaxTranspulmonaryCmH2O) + 1000.0);
  EXPECT_GT(e.curve.compliance_ml_per_cmh2o(e.p_frc_cmh2o), 2.0 * n.curve.compliance_ml_per_cmh2o(n.p_frc_cmh2o));
  for (double p = 0.0; p <= 30.0; p += 1.0) EXPECT_GT(e.curve.volume_ml(p), n.curve.volume_ml(p)) << p;
}

TEST(PvPresets, FibrosisIsStiffSmallAndRightShifted) {
  const PvPreset& n = pv_preset(Preset::Normal);
  const PvPreset& f = pv_preset(Preset::Fibrosis);
  EXPECT_LT(f.frc_ml(), n.frc_ml() - 500.0);
  EXPECT_LT(f.curve.volume_ml(kMaxTranspulmonaryCmH2O), 0.7 * n.curve.volume_ml(kMaxTranspulmonaryCmH2O));
  EXPECT_LT(f.curve.compliance_ml_per_cmh2o(f.p_frc_cmh2o), 0.5 * n.curve.compliance_ml_per_cmh2o(n.p_frc_cmh2o));
  EXPECT_GT(f.curve.c_cmh2o, n.curve.c_cmh2o);      // inflection to the right
  EXPECT_GT(f.p_frc_cmh2o, n.p_frc_cmh2o);          // more recoil at FRC
  for (double p = 0.0; p <= 40.0; p += 1.0) EXPECT_LT(f.curve.volume_ml(p), n.curve.volume_ml(p)) << p;
}

TEST(PvPresets, NamesRoundTripAndUnknownNamesAreRejected) {
  for (Preset id : kAllPresets) EXPECT_EQ(preset_from_name(to_string(id)), id);
  EXPECT_FALSE(preset_from_name("asthma"));
  EXPECT_FALSE(preset_from_name("Normal"));
}

TEST(PvPresets, EveryPresetCanBreatheTheDefaultAndTheSighVolume) {
  for (Preset id : kAllPresets) {
    const PvPreset& p = pv_preset(id);
    EXPECT_GT(max_tidal_volume_ml(p, p.p_frc_cmh2o), 1000.0) << to_string(id);
  }
}
