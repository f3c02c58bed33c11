/// @file plus_replay.cpp
/// @brief PLUS frames -> OpenIGTLink TRANSFORM records (plus_replay.h).
#include "drivers/plus/plus_replay.h"

#include <cmath>
#include <cstring>

#include "drivers/igtl/igtl_messages.h"

namespace lungar::drivers {

std::optional<Role> plus_tool_role(const std::string& tool, const PlusConfig& names) {
  const PlusConfig plus_own;
  if (tool == names.patient) return Role::Patient;
  if (tool == names.stylus || (names.stylus == plus_own.stylus && tool == "StylusTip")) return Role::Stylus;
  if (tool == names.head || (names.head == plus_own.head && tool == "Head")) return Role::Head;
  return std::nullopt;
}

Result<PlusReplay> plus_replay(const PlusSequence& seq, const TrackerConfig& settings, const std::string& path) {
  // The names the roles arrive under: the first transform of each role's tool in the sequence.
  TrackerConfig named = settings;
  named.igtl.head = named.igtl.patient = named.igtl.stylus = "";
  bool relative_to_reference = false;
  std::string roles;
  for (const PlusFrame& f : seq.frames) {
    for (const PlusTransform& t : f.transforms) {
      const std::optional<Role> role = plus_tool_role(t.tool, settings.plus);
      if (!role) continue;
      std::string* slot = *role == Role::Head      ? &named.igtl.head
                          : *role == Role::Patient ? &named.igtl.patient
                                                   : &named.igtl.stylus;
      if (!slot->empty()) continue;
      if (t.name().size() > 20)
        return fail(path + ": transform " + t.name() + ": expected a name of at most 20 characters");
      *slot = t.name();
      relative_to_reference = relative_to_reference || t.frame == "Reference";
      roles += (roles.empty() ? "" : ", ") + t.tool + " -> " + to_string(*role);
    }
  }
  if (roles.empty()) {
    return fail(path + ": expected transforms of " + settings.plus.patient + " (patient), " + settings.plus.stylus +
                " (stylus) or " + settings.plus.head + " (head) tools, got none of them ([trackers.plus] names them)");
  }
  const bool synthesise_patient = relative_to_reference && named.igtl.patient.empty();
  if (synthesise_patient) named.igtl.patient = "ReferenceToReference";
  auto layout = make_igtl_layout(named.igtl, named);
  if (!layout) return layout.with_context(path + ": ");
  PlusReplay out;
  out.layout = *layout;
  out.frames = static_cast<int>(seq.frames.size());
  // All messages first, then the records' spans into the finished buffer.
  std::vector<std::pair<std::size_t, std::int64_t>> at;  // offset, arrival
  std::vector<std::size_t> sizes;
  const double t0 = seq.frames.empty() ? 0.0 : seq.frames.front().timestamp_s;
  for (const PlusFrame& f : seq.frames) {
    const std::int64_t arrival = 1'000'000'000 + std::llround((f.timestamp_s - t0) * 1e9);
    const IgtlTime time =
        IgtlTime::from_ns(static_cast<std::uint64_t>(std::llround(std::max(0.0, f.timestamp_s) * 1e9)));
    const auto add = [&](const std::string& name, const Eigen::Matrix4d& m) {
      const std::vector<std::uint8_t> message = igtl_transform_message(name, m, time);
      at.push_back({out.log.bytes.size(), arrival});
      sizes.push_back(message.size());
      out.log.bytes.insert(out.log.bytes.end(), message.begin(), message.end());
    };
    if (synthesise_patient) add(named.igtl.patient, Eigen::Matrix4d::Identity());
    for (const PlusTransform& t : f.transforms) {
      const std::optional<Role> role = plus_tool_role(t.tool, settings.plus);
      if (!role) continue;
      const std::string& name = *role == Role::Head      ? named.igtl.head
                                : *role == Role::Patient ? named.igtl.patient
                                                         : named.igtl.stylus;
      if (t.name() != name) continue;  // another frame of reference for the same tool: not mixed in
      if (!t.valid) {
        ++out.invalid_skipped;
        continue;
      }
      add(name, t.matrix);
    }
  }
  for (std::size_t i = 0; i < at.size(); ++i) {
    out.log.records.push_back({TrkSource::Igtl, at[i].second, std::span(out.log.bytes.data() + at[i].first, sizes[i])});
  }
  out.log.header.description = "source=plus\nfile=" + path;
  out.describe = std::to_string(out.frames) + " frames; " + roles +
                 (synthesise_patient ? " (tools relative to the Reference: the patient at identity)" : "") + "; " +
                 std::to_string(out.invalid_skipped) + " invalid transforms skipped";
  return out;
}

}  // namespace lungar::drivers
