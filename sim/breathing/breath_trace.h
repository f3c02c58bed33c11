/// @file breath_trace.h
/// @brief Recorded respiratory surrogates for the breath follower (breath_follower.h): CSV with the header
///        `t_s,value` (a scalar, inhale up: a belt, a spirometer, an RPM amplitude exported) or `t_s,x_mm,y_mm,z_mm`
///        (a chest or abdomen marker), and Varian RPM's own `.vxp` files (vxp_trace.cpp). A marker is reduced to its
///        excursion along its main breathing axis: the principal axis of its positions over the first 30 s, signed
///        so that inhalation, the shorter of the two phases in quiet breathing, goes up.
#pragma once

#include <istream>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "config/base/result.h"

namespace lungar::sim {

struct TraceSample {
  double t_s = 0;
  double value = 0;
};

struct BreathTrace {
  std::vector<TraceSample> samples;  ///< time zero is the file's first sample
  bool marker = false;               ///< read from x, y, z (projected on its axis)
  std::string format = "csv";        ///< csv | vxp
  int invalid = 0;                   ///< samples the recorder flagged as not tracked (vxp: validflag < 0), skipped
  int peaks_marked = 0;              ///< vxp: samples RPM marked P (its own end-inhale peaks), for comparison
  double samples_per_second = 0;     ///< vxp: the header's Samples_per_second
};

/// A marker's main breathing axis: the principal axis of its positions `p` (at times `t`, increasing) over the
/// first `window_s`, signed so that inhalation, the shorter of the two phases in quiet breathing, is its positive
/// direction. A breath's excursion is then axis . (p - p0).
Eigen::Vector3d breathing_axis(const std::vector<double>& t, const std::vector<Eigen::Vector3d>& p, double window_s);

/// Reads a trace, by its name: `.vxp` is Varian RPM's format, anything else the CSV. The error is one line naming
/// the file, the line and what was expected (times must increase).
Result<BreathTrace> read_breath_trace(const std::string& path);
/// The CSV from `in` (`path` names it in errors).
Result<BreathTrace> parse_csv_trace(std::istream& in, const std::string& path);
/// A Varian RPM `.vxp` file from `in`: a `[Header]` of key=value lines (Samples_per_second and Scale_factor
/// positive, Data_layout naming at least amplitude and timestamp), then `[Data]`, one sample a line in the layout's
/// columns (amplitude,phase,timestamp,validflag,ttlin,mark,ttlout in RPM 1.6). The value is the amplitude as
/// written (RPM's centimetres; Scale_factor is checked, not applied: the follower scales each breath to V_T
/// itself); times are the timestamps (ms) from the first; a negative validflag skips the sample (counted);
/// marks are P (peak), Z (zero phase) or none.
Result<BreathTrace> parse_vxp_trace(std::istream& in, const std::string& path);

}  // namespace lungar::sim
