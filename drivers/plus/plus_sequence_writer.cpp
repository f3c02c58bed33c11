/// @file plus_sequence_writer.cpp
/// @brief The MetaImage header and frames of plus_sequence_writer.h, and a .trk log's poses as PLUS frames.
#include "drivers/plus/plus_sequence_writer.h"

#include <array>
#include <cstdio>
#include <set>

#include "config/base/atomic_file.h"
#include "drivers/decode/decoder.h"
#include "drivers/decode/report_layout.h"
#include "drivers/replay/recorded_trackers.h"

namespace lungar::drivers {

namespace {

std::string frame_key(std::size_t n, const std::string& field) {
  char prefix[32];
  std::snprintf(prefix, sizeof prefix, "Seq_Frame%04zu_", n);
  return prefix + field;
}

std::string matrix_text(const Eigen::Matrix4d& m) {
  std::string s;
  char cell[40];
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      std::snprintf(cell, sizeof cell, "%s%.9g", s.empty() ? "" : " ", m(r, c));
      s += cell;
    }
  return s;
}

}  // namespace

const std::string& plus_tool_of(Role role, const PlusConfig& names) {
  switch (role) {
    case Role::Patient:
      return names.patient;
    case Role::Stylus:
      return names.stylus;
    case Role::Head:
      break;
  }
  return names.head;
}

std::string plus_sequence_text(const PlusSequence& seq) {
  // Every tool of the sequence appears in every frame (INVALID where the frame lacks it): Slicer's reader makes one
  // sequence node per transform name and expects it throughout.
  std::set<std::string> names;
  for (const PlusFrame& f : seq.frames)
    for (const PlusTransform& t : f.transforms) names.insert(t.name());
  std::string h =
      "ObjectType = Image\nNDims = 3\nAnatomicalOrientation = RAI\nBinaryData = True\n"
      "BinaryDataByteOrderMSB = False\nCenterOfRotation = 0 0 0\nCompressedData = False\nDimSize = 1 1 " +
      std::to_string(seq.frames.size()) +
      "\nElementNumberOfChannels = 1\nElementSpacing = 1 1 1\nElementType = MET_UCHAR\nKinds = domain domain list\n"
      "Offset = 0 0 0\nTransformMatrix = 1 0 0 0 1 0 0 0 1\nUltrasoundImageOrientation = MF\n"
      "UltrasoundImageType = BRIGHTNESS\n";
  char stamp[40];
  for (std::size_t n = 0; n < seq.frames.size(); ++n) {
    const PlusFrame& f = seq.frames[n];
    h += frame_key(n, "FrameNumber = ") + std::to_string(n) + "\n";
    for (const std::string& name : names) {
      const PlusTransform* t = nullptr;
      for (const PlusTransform& candidate : f.transforms)
        if (candidate.name() == name) t = &candidate;
      const bool ok = t != nullptr && t->valid;
      h += frame_key(n, name + "Transform = ") + matrix_text(t ? t->matrix : Eigen::Matrix4d::Identity()) + "\n";
      h += frame_key(n, name + "TransformStatus = ") + (ok ? "OK" : "INVALID") + "\n";
    }
    std::snprintf(stamp, sizeof stamp, "%.6f", f.timestamp_s);
    h += frame_key(n, "Timestamp = ") + stamp + "\n";
    h += frame_key(n, "ImageStatus = INVALID\n");
  }
  h += "ElementDataFile = LOCAL\n";
  h.append(seq.frames.size(), '\0');  // the 1 x 1 placeholder image of each frame
  return h;
}

Status write_plus_sequence(const std::string& path, const PlusSequence& seq) {
  return write_file_atomically(path, plus_sequence_text(seq));
}

Result<PlusSequence> plus_from_trk(const TrkLog& log, const std::string& path, const TrackerConfig& otherwise,
                                   int& skipped) {
  auto trackers = recorded_trackers(log, path, otherwise);
  if (!trackers) return trackers.with_context("");
  auto layout = make_layout(*trackers);
  if (!layout) return layout.with_context(path + ": report layout: ");
  auto igtl_layout = make_igtl_layout(trackers->igtl, *trackers);
  if (!igtl_layout) return igtl_layout.with_context(path + ": ");
  const RecordDecoder igtl = igtl_record_decoder(*igtl_layout);
  const PlusConfig& names = trackers->plus;
  PlusSequence seq;
  skipped = 0;
  const std::int64_t t0 = log.records.empty() ? 0 : log.records.front().t_arrival_ns;
  struct Latest {
    bool seen = false;
    double t_s = 0;
    Eigen::Matrix4d matrix = Eigen::Matrix4d::Identity();
  };
  std::array<Latest, kRoleCount> latest{};
  constexpr double kFreshS = 0.1;
  for (const TrkRecord& rec : log.records) {
    const DecodedReport r = rec.source == igtl.source ? igtl.decode(rec.report) : decode_report(rec.report, *layout);
    if (r.error != DecodeError::None || r.count == 0) {
      ++skipped;  // a malformed record is never written as a pose
      continue;
    }
    PlusFrame f;
    f.timestamp_s = static_cast<double>(rec.t_arrival_ns - t0) * 1e-9;
    for (int k = 0; k < r.count; ++k) {
      const PoseSample& pose = r.poses[static_cast<std::size_t>(k)];
      Latest& l = latest[static_cast<std::size_t>(pose.role)];
      l = {true, f.timestamp_s, pose.transform().matrix()};
    }
    // Each frame holds every tool's newest pose, as PLUS's tracker buffers give it: OK while it is fresh, INVALID
    // once the tool has been silent for longer than kFreshS (out of view, unplugged).
    for (Role role : kRoles) {
      const Latest& l = latest[static_cast<std::size_t>(role)];
      if (!l.seen) continue;
      PlusTransform t;
      t.tool = plus_tool_of(role, names);
      t.frame = "Tracker";
      t.matrix = l.matrix;
      t.valid = f.timestamp_s - l.t_s <= kFreshS;
      f.transforms.push_back(t);
    }
    seq.frames.push_back(std::move(f));
  }
  if (seq.frames.empty())
    return fail(path + ": expected records with poses, got none (" + std::to_string(skipped) + " did not decode)");
  return seq;
}

}  // namespace lungar::drivers
