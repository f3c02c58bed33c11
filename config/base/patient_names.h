/// @file patient_names.h
/// @brief The names a user gives the patient's postures and breathing presets, spelled once. The settings and the
///        scenarios (config/) check what a file says against them; sim/breathing/ gives each its model (a pose's
///        rotation, orientation.h; a preset's pressure-volume curve, pv_curve.h). They sit in the base both depend
///        on because config/ does not depend on sim/.
/// @ingroup base
#pragma once

#include "config/base/enum_names.h"

namespace lungar {

/// A named posture of the patient (sim/breathing/orientation.h has each one's rotation).
enum class Pose { Upright, Supine, Prone, LeftLateral, RightLateral };
inline constexpr EnumNames<Pose, 5> kPoseNames{{{{Pose::Upright, "upright"},
                                                 {Pose::Supine, "supine"},
                                                 {Pose::Prone, "prone"},
                                                 {Pose::LeftLateral, "left_lateral"},
                                                 {Pose::RightLateral, "right_lateral"}}}};

/// A breathing preset: the lung's pressure-volume curve (sim/breathing/pv_curve.h has each one's, with its sources).
enum class Preset { Normal, Emphysema, Fibrosis };
inline constexpr EnumNames<Preset, 3> kPresetNames{
    {{{Preset::Normal, "normal"}, {Preset::Emphysema, "emphysema"}, {Preset::Fibrosis, "fibrosis"}}}};

}  // namespace lungar
