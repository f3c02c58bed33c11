/// @file scripted_inputs.h
/// @brief The bench's inputs to the shipped Runtime: a clock that advances 1/60 s a frame whatever the real frame
/// time, a head 450 mm in front of the lungs, a patient turning slowly between upright and supine about the
/// lungs' centre, breathing 0..500 mL every 4 s. Every configuration sees the same frames.
/// @ingroup bench
#pragma once

#include <cstdint>

#include <Eigen/Geometry>

#include "drivers/breath/source/breathing_clock.h"
#include "platform/runtime/pose_source.h"

namespace lungar::platform::bench {

inline constexpr std::int64_t kFrameStepNs = 16'666'667;  // scripted time per frame: 1/60 s
inline constexpr double kHeadDistanceMm = 450.0;          // LOD coverage 3 is hole-free there

/// The lung frame's orientation in the world at scripted time t (s): a turn about x between upright and supine.
Eigen::Quaterniond scripted_turn(double t_s);
/// dV (mL) at scripted time t (s).
double scripted_volume_ml(double t_s);

/// Head and patient poses from the script; `centre_mm` is the lungs' centre in the lung frame.
class ScriptedPoses final : public PoseSource {
 public:
  explicit ScriptedPoses(const Eigen::Vector3d& centre_mm) : centre_(centre_mm) {}
  std::string describe() const override { return "scripted bench poses"; }
  drivers::PoseSample latest(drivers::Role role, std::int64_t now_ns) const override;
  drivers::PoseSample predicted(drivers::Role role, std::int64_t t_ns, std::int64_t) const override {
    return latest(role, t_ns);
  }
  const char* state() const override { return "scripted"; }
  bool finished() const override { return false; }
  SourceCounters counters(double) const override { return {}; }
  void stop() override {}

 private:
  Eigen::Vector3d centre_;
};

class ScriptedBreathing final : public breath::BreathingClock {
 public:
  sim::BreathingSample at(std::int64_t now_ns) const override;
};

}  // namespace lungar::platform::bench
