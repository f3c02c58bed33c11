/// @file landmark_matching.h
/// @brief Which stylus dwell touched which model landmark, in a real session: the stylus rests before and after,
///        pauses on its way, touches a landmark twice. Repeats are merged; the dwells are matched to the model's
///        landmarks in touching order when that fits, else by their shape (the rigid transform that puts the
///        most landmarks on dwells, searched over triples whose distances agree); dwells that fit no landmark are
///        dropped as rests; a landmark with no dwell refuses the set.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "config/base/result.h"
#include "platform/registration/fiducial_registration.h"

namespace lungar::platform {

/// One dwell of the stylus tip: where (patient frame), when it started and how long it lasted.
struct Dwell {
  Eigen::Vector3d position_mm = Eigen::Vector3d::Zero();
  double start_s = 0;
  double duration_s = 0;
};

struct LandmarkRules {
  double merge_mm = 3.0;  ///< dwells closer than this are one landmark touched again
  double match_mm = 5.0;  ///< a landmark further than this from its dwell after the fit is not matched
};

struct LandmarkMatch {
  std::vector<Eigen::Vector3d> tracked;  ///< one per model landmark, in the model's order
  std::vector<double> fre_mm;            ///< each landmark's residual after the fit
  Registration registration;
  bool in_order = true;                  ///< matched in touching order (else by shape)
  int merged = 0;                        ///< repeated touches merged into one
  int dropped = 0;                       ///< dwells that fit no landmark (rests, pauses)
  std::vector<std::string> warnings;     ///< lines for the user
};

/// The dwells of a stylus track: runs that stay within `radius_mm` of their running mean for `dwell_s` or more.
std::vector<Dwell> find_dwells(const std::vector<StylusSample>& samples, double radius_mm = 1.5, double dwell_s = 0.5);

/// Matches `dwells` to `model`; refused (one line naming the landmark) when a landmark has no dwell.
Result<LandmarkMatch> match_landmarks(const std::vector<Eigen::Vector3d>& model, std::vector<Dwell> dwells,
                                      const LandmarkRules& rules = {});

}  // namespace lungar::platform
