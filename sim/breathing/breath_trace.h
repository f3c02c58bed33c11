/// @file breath_trace.h
/// @brief Recorded respiratory surrogates for the breath follower (breath_follower.h): CSV with the header
///        `t_s,value` (a scalar, inhale up: a belt, a spirometer, an RPM amplitude exported) or `t_s,x_mm,y_mm,z_mm`
///        (a chest or abdomen marker), the ExtMarker data set's `Frame;Timestamp;x;y;z` (extmarker_trace.cpp: `;`
///        separated, decimal commas, ms), and Varian RPM's own `.vxp` files (vxp_trace.cpp). A marker is reduced to its
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
  bool flagged = false;  ///< the recorder's own verdict against it (vxp: validflag < 0); the value is still the signal
};

struct BreathTrace {
  std::vector<TraceSample> samples;  ///< time zero is the file's first sample
  bool marker = false;               ///< read from x, y, z (projected on its axis)
  std::string format = "csv";        ///< csv | extmarker | vxp
  /// Samples the recorder flagged (vxp: a negative validflag, RPM's verdict for gating: the breath outside its
  /// expected pattern or baseline). They carry the patient's breathing, so they are kept and marked; a caller that
  /// wants RPM's verdict drops them (without_flagged()).
  int flagged = 0;
  int peaks_marked = 0;              ///< vxp: samples RPM marked P (its own end-inhale peaks), for comparison
  double samples_per_second = 0;     ///< vxp: the header's Samples_per_second
  int skipped = 0;                   ///< extmarker: rows whose timestamp went back (garbled), dropped
  int first_skipped_line = 0;        ///< the first of them, for the summary
  double scale_to_mm = 1;            ///< vxp: the header's Scale_factor, applied: values are in mm
};

/// A marker's main breathing axis: the principal axis of its positions `p` (at times `t`, increasing) over the
/// first `window_s`, signed so that inhalation, the shorter of the two phases in quiet breathing, is its positive
/// direction. A breath's excursion is then axis . (p - p0).
Eigen::Vector3d breathing_axis(const std::vector<double>& t, const std::vector<Eigen::Vector3d>& p, double window_s);

/// A marker's excursion along its breathing axis (over the first kAxisWindowS), times from the first sample.
std::vector<TraceSample> marker_excursion(const std::vector<double>& t, const std::vector<Eigen::Vector3d>& p);
inline constexpr double kAxisWindowS = 30.0;

/// Reads a trace, by its name: `.vxp` is Varian RPM's format; a file whose header is ExtMarker's
/// (`"Frame";"Timestamp";"x";"y";"z"`) that data set's; anything else the CSV. The error is one line naming the file,
/// the line and what was expected (times must increase, and be seconds: see check_sample_times()).
Result<BreathTrace> read_breath_trace(const std::string& path);
/// The CSV from `in` (`path` names it in errors).
Result<BreathTrace> parse_csv_trace(std::istream& in, const std::string& path);
/// The ExtMarker data set's marker file from `in` (Krilavicius et al.): a header naming Frame, Timestamp, x, y, z,
/// then `;`-separated rows with decimal commas, the timestamp in ms; a last all-zero row (as some files end) is
/// skipped, and so are rows whose timestamp goes back (counted in `skipped`; more than 1 % of them is an error).
Result<BreathTrace> parse_extmarker_trace(std::istream& in, const std::string& path);
/// Times that are seconds: a median interval between samples from 1 ms to 2 s (a respiratory surrogate is sampled
/// at 0.5 to 1000 Hz). A trace in ms under a `t_s` header fails here, named, instead of never locking on.
Status check_sample_times(const BreathTrace& trace, const std::string& path);
/// The trace without its flagged samples (RPM's verdict taken: `[breathing] rpm_flagged = "skip"`).
BreathTrace without_flagged(BreathTrace trace);
/// A Varian RPM `.vxp` file from `in`: a `[Header]` of key=value lines (Samples_per_second and Scale_factor
/// positive, Data_layout naming at least amplitude and timestamp), then `[Data]`, one sample a line in the layout's
/// columns (amplitude,phase,timestamp,validflag,ttlin,mark,ttlout in RPM 1.6). The value is the amplitude as
/// in mm (the amplitude times Scale_factor, which converts RPM's unit to mm: 10 for centimetres); times are the
/// timestamps (ms) from the first, in s; a negative validflag marks the sample flagged (kept, counted); marks are
/// P (peak), Z (zero phase) or none.
Result<BreathTrace> parse_vxp_trace(std::istream& in, const std::string& path);

}  // namespace lungar::sim
