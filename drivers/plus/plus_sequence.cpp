/// @file plus_sequence.cpp
/// @brief The MetaImage header of a PLUS tracked sequence, read line by line up to ElementDataFile.
#include "drivers/plus/plus_sequence.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

namespace lungar::drivers {
namespace {

constexpr long kMaxFrames = 10'000'000;  // a day at 100 Hz: anything larger is a corrupt number, not a session

std::string trim(const std::string& s) {
  const std::size_t a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

/// "StylusToTracker" -> ("Stylus", "Tracker"): split at the first "To" after the first letter that starts a word.
bool split_transform_name(const std::string& name, std::string& tool, std::string& frame) {
  for (std::size_t i = 1; i + 2 < name.size(); ++i) {
    if (name.compare(i, 2, "To") == 0 && std::isupper(static_cast<unsigned char>(name[i + 2]))) {
      tool = name.substr(0, i);
      frame = name.substr(i + 2);
      return true;
    }
  }
  return false;
}

bool parse_numbers(const std::string& text, double* out, int n) {
  std::istringstream in(text);
  for (int i = 0; i < n; ++i) {
    if (!(in >> out[i]) || !std::isfinite(out[i])) return false;
  }
  std::string extra;
  return !(in >> extra);
}

}  // namespace

const PlusTransform* PlusFrame::find(const std::string& tool) const {
  for (const PlusTransform& t : transforms)
    if (t.tool == tool) return &t;
  return nullptr;
}

bool is_plus_sequence_path(const std::string& path) { return ends_with(path, ".mha") || ends_with(path, ".mhd"); }

Result<PlusSequence> read_plus_sequence(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(path + ": cannot open: expected a PLUS tracked sequence (.igs.mha, .seq.mha, .mhd)");
  return parse_plus_sequence(in, path);
}

Result<PlusSequence> parse_plus_sequence(std::istream& in, const std::string& path) {
  struct Pending {
    PlusFrame frame;
    bool has_time = false;
    std::map<std::string, bool> status;  ///< transform name -> OK
  };
  std::map<long, Pending> frames;
  std::string line;
  bool data_file = false, any_key = false;
  for (int line_no = 1; !data_file && std::getline(in, line); ++line_no) {
    const auto at = [&](const std::string& why) { return fail(path + ":" + std::to_string(line_no) + ": " + why); };
    if (trim(line).empty()) continue;
    const std::size_t eq = line.find('=');
    if (eq == std::string::npos) return at("expected 'Key = Value' (a MetaImage header line), got '" + trim(line) + "'");
    const std::string key = trim(line.substr(0, eq)), value = trim(line.substr(eq + 1));
    any_key = true;
    if (key == "ElementDataFile") data_file = true;
    if (key == "ObjectType" && value != "Image") return at("ObjectType: expected Image, got '" + value + "'");
    if (key.rfind("Seq_Frame", 0) != 0) continue;
    const std::size_t underscore = key.find('_', 9);
    char* end = nullptr;
    const long number = std::strtol(key.c_str() + 9, &end, 10);
    if (underscore == std::string::npos || end != key.c_str() + underscore || number < 0 || number >= kMaxFrames)
      return at(key + ": expected Seq_FrameNNNN_<field> with a frame number below 10000000");
    const std::string field = key.substr(underscore + 1);
    Pending& f = frames[number];
    if (field == "Timestamp") {
      if (!parse_numbers(value, &f.frame.timestamp_s, 1)) return at(key + ": expected a finite time in seconds");
      f.has_time = true;
    } else if (ends_with(field, "TransformStatus")) {
      if (value != "OK" && value != "INVALID") return at(key + ": expected OK or INVALID, got '" + value + "'");
      f.status[field.substr(0, field.size() - 15)] = value == "OK";
    } else if (ends_with(field, "Transform")) {
      PlusTransform t;
      if (!split_transform_name(field.substr(0, field.size() - 9), t.tool, t.frame))
        return at(key + ": expected a transform named <Tool>To<Frame>");
      double m[16];
      if (!parse_numbers(value, m, 16)) return at(key + ": expected 16 finite numbers (a row-major 4x4, mm)");
      for (int i = 0; i < 16; ++i) t.matrix(i / 4, i % 4) = m[i];
      f.frame.transforms.push_back(t);
    }
  }
  if (!any_key) return fail(path + ": expected a MetaImage header ('Key = Value' lines), got none");
  if (!data_file) return fail(path + ": ElementDataFile: expected the header to end with it, the file is cut short");
  PlusSequence out;
  for (auto& [number, f] : frames) {
    if (!f.has_time) return fail(path + ": Seq_Frame" + std::to_string(number) + "_Timestamp: expected one, got none");
    for (PlusTransform& t : f.frame.transforms) {
      const auto s = f.status.find(t.name());
      t.valid = s == f.status.end() || s->second;
      out.invalid_transforms += t.valid ? 0 : 1;
    }
    out.frames.push_back(std::move(f.frame));
  }
  return out;
}

}  // namespace lungar::drivers
