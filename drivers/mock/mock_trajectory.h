/// @file mock_trajectory.h
/// @brief Scripted poses for the mock tracker and `lungar-trk synth`: pure functions of time.
/// @ingroup drivers
///
/// World frame: millimetres, +z up. The patient's lung frame is DICOM LPS (+x left, +y posterior, +z superior);
/// identity = standing upright. Supine (on the back) is a -90 degree turn about world x: posterior -> world
/// down, superior -> world +y. The head sensor looks along its own +y with its +z up, so identity looks
/// along world +y.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "drivers/decode/decoder.h"

namespace lungar::drivers {

/// Where the mock puts the patient's lung centre, mm.
inline constexpr std::array<double, 3> kMockPatientCentreMm = {0.0, 0.0, 1000.0};
/// upright_to_supine: hold upright, turn over kTurnS with a raised-cosine ease, then lie supine.
inline constexpr double kMockTurnStartS = 1.0;
inline constexpr double kMockTurnS = 4.0;

/// The mock's trajectories, as messages list them: static (the head in front of an upright patient),
/// upright_to_supine (the patient turns), head_orbit (the head walks round), bedside (the head at the foot of the
/// bed, a little to the patient's right, looking at the diaphragm: front at the top when supine, the view the
/// README's ventilation map is drawn from).
inline constexpr const char* kMockTrajectoriesExpected = "static | upright_to_supine | head_orbit | bedside";

/// "FIELD: expected static | ... | bedside, got "NAME"": the line for a trajectory name that is none of them.
std::string unknown_trajectory(const std::string& field, const std::string& name);

/// The pose of `role` at `t_s` seconds into `trajectory` (kMockTrajectoriesExpected); nullopt for an unknown
/// trajectory name.
std::optional<PoseSample> mock_pose(const std::string& trajectory, Role role, double t_s);

/// The patient's turn angle about world x at `t_s` for upright_to_supine, radians (0 upright, -pi/2 supine).
double upright_to_supine_angle(double t_s);

}  // namespace lungar::drivers
