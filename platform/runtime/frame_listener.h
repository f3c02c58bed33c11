/// @file frame_listener.h
/// @brief What a frame decided, for those who follow it without drawing (a classroom instructor publishing the
/// patient, a recorder): called once per frame after the draw, on the frame loop's thread.
/// @ingroup platform
#pragma once

#include <array>
#include <cstdint>
#include <limits>

#include <Eigen/Geometry>

#include "drivers/pose/pose_sample.h"
#include "sim/breathing/driver.h"

namespace lungar::platform {

struct FrameState {
  std::int64_t now_ns = 0;                  ///< the frame's time (monotonic)
  sim::BreathingSample breath;              ///< step 1
  drivers::PoseSample patient;              ///< the patient pose the frame used (world, mm)
  Eigen::Quaterniond lung_in_world = Eigen::Quaterniond::Identity();  ///< step 2: after the registration
  Eigen::Vector3d lung_origin_mm = Eigen::Vector3d::Zero();           ///< the lung frame's origin in the world
  Eigen::Vector3d gravity_lung = Eigen::Vector3d(0, 0, -1);  ///< g-hat in the lung frame (of lung_in_world)
  /// Step 4: the first two lungs' dV as drawn, in the asset's order (each its posture's share of breath.dv_ml, or its
  /// own when the source measures each lung); NaN for a lung the asset lacks. What a session record keeps of each.
  std::array<double, 2> lung_dv_ml{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
};

class FrameListener {
 public:
  virtual ~FrameListener() = default;
  /// Must not block or allocate: it runs inside the frame loop.
  virtual void on_frame(const FrameState& state) = 0;
};

}  // namespace lungar::platform
