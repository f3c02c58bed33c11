/// @file breath_factory.cpp
/// @brief Choosing a breath source by its name and building its clock (breath_factory.h).
#include "drivers/breath/breath_factory/breath_factory.h"

#include "drivers/breath/physiology/physiology_feed.h"

#include "drivers/breath/model/script_breathing.h"
#include "drivers/breath/source/followed_breathing.h"

namespace lungar::breath {

BreathKind breath_kind(const std::string& source) {
  // A name comes before its argument (':') and a DDS source's domain ('@'); a path that happens to start with a
  // name ("model.csv", "amm_run.csv") is still a trace.
  const std::size_t end = source.find_first_of(":@");
  switch (source.empty() ? BreathSource::Model
                         : kBreathSourceNames.parse(source.substr(0, end)).value_or(BreathSource::Trace)) {
    case BreathSource::Model:
      return end == std::string::npos ? BreathKind::Model : BreathKind::Trace;
    case BreathSource::Marker:
      return end != std::string::npos && source[end] == ':' ? BreathKind::Marker : BreathKind::Trace;
    case BreathSource::Amm:
    case BreathSource::OpenIce:
      return BreathKind::Dds;
    case BreathSource::Trace:
      break;
  }
  return BreathKind::Trace;
}

std::function<void(const drivers::PoseSample&)> ChosenBreath::tracker_tap() const {
  if (!marker) return {};
  return [feed = marker](const drivers::PoseSample& sample) { feed->push(sample); };
}

Result<ChosenBreath> choose_breath_source(const std::string& source, std::int64_t t0_ns) {
  ChosenBreath chosen{source, breath_kind(source), nullptr};
  if (chosen.kind == BreathKind::Marker) {
    auto feed = open_marker_feed(source, t0_ns);
    if (!feed) return Error{feed.error()};
    chosen.marker = feed.take();
  }
  return chosen;
}

namespace {

/// The surrogate a followed source gives its samples through.
Result<std::shared_ptr<SurrogateFeed>> open_feed(const ChosenBreath& chosen, const BreathSourceOptions& options,
                                                 std::int64_t t0_ns) {
  switch (chosen.kind) {
    case BreathKind::Marker:
      options.log(marker_following(chosen.source));
      return std::shared_ptr<SurrogateFeed>(chosen.marker);
    case BreathKind::Dds:
      if (options.open_dds) return options.open_dds(chosen.source);
      return physiology::open_physiology_breath(chosen.source, options.cyclonedds_xml, t0_ns, options.log);
    case BreathKind::Trace: {
      auto trace = open_trace_feed(chosen.source, options.trace, options.log);
      if (!trace) return Error{trace.error()};
      return std::shared_ptr<SurrogateFeed>(trace.take());
    }
    case BreathKind::Model:
      break;
  }
  return fail("'" + chosen.source + "': not a followed breath source");
}

}  // namespace

Result<std::unique_ptr<BreathingClock>> make_breath_source(const ChosenBreath& chosen,
                                                           const BreathSourceOptions& options, std::int64_t t0_ns) {
  if (!chosen.followed()) {
    return std::unique_ptr<BreathingClock>(std::make_unique<ScriptBreathing>(options.script, t0_ns));
  }
  auto feed = open_feed(chosen, options, t0_ns);
  if (!feed) return Error{feed.error()};
  return std::unique_ptr<BreathingClock>(std::make_unique<FollowedBreathing>(feed.take(), options.script, t0_ns));
}

}  // namespace lungar::breath
