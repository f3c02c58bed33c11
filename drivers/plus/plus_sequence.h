/// @file plus_sequence.h
/// @brief PLUS tracked sequence files (`.igs.mha`, `.seq.mha`, `.mhd`): what PlusServer and 3D Slicer save of a
///        tracked session. A MetaImage header (`Key = Value` lines up to `ElementDataFile`) holds, per frame N,
///        `Seq_FrameNNNN_<Tool>To<Frame>Transform` (16 numbers, a row-major 4 x 4, mm),
///        `Seq_FrameNNNN_<Tool>To<Frame>TransformStatus` (OK or INVALID) and `Seq_FrameNNNN_Timestamp` (s). The image
///        data after the header (an ultrasound video, or a 1 x 1 placeholder) is not read.
/// @ingroup drivers
#pragma once

#include <istream>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "config/base/result.h"

namespace lungar::drivers {

struct PlusTransform {
  std::string tool;   ///< "Stylus" of StylusToTracker
  std::string frame;  ///< "Tracker" of StylusToTracker
  bool valid = true;  ///< TransformStatus OK (a missing status reads as OK, as PLUS does)
  Eigen::Matrix4d matrix = Eigen::Matrix4d::Identity();
  std::string name() const { return tool + "To" + frame; }
};

struct PlusFrame {
  double timestamp_s = 0;
  std::vector<PlusTransform> transforms;
  /// The transform of `tool` in this frame, valid or not; nullptr when the frame has none.
  const PlusTransform* find(const std::string& tool) const;
};

struct PlusSequence {
  std::vector<PlusFrame> frames;  ///< in frame-number order
  int invalid_transforms = 0;     ///< TransformStatus INVALID, over all frames
};

/// Reads the header of a tracked sequence; the error is one line naming the file, the line and the field.
Result<PlusSequence> read_plus_sequence(const std::string& path);

/// The same from a stream (`path` names it in errors): what the fuzz target drives.
Result<PlusSequence> parse_plus_sequence(std::istream& in, const std::string& path);

/// Whether `path` names a MetaImage file (.mha, .mhd): what `--tracker replay:` and `--stylus-log` read as PLUS.
bool is_plus_sequence_path(const std::string& path);

}  // namespace lungar::drivers
