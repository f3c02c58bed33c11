/// @file physiology_spec.cpp
/// @brief Reading a DDS breath source's spec (physiology_spec.h).
#include "drivers/breath/physiology/physiology_spec.h"

#include <cstdlib>

namespace lungar::breath::physiology {

namespace {

/// "expected amm[@DOMAIN] or openice[:volume|flow|pressure][@DOMAIN], DOMAIN a DDS domain id 0 to 232".
std::string spec_help() {
  std::string metrics;
  for (const auto& [q, name] : kQuantityNames.entries) metrics += (metrics.empty() ? "" : "|") + std::string(name);
  return std::string("expected ") + kBreathSourceNames.name(BreathSource::Amm) + "[@DOMAIN] or " +
         kBreathSourceNames.name(BreathSource::OpenIce) + "[:" + metrics +
         "][@DOMAIN], DOMAIN a DDS domain id 0 to 232";
}

}  // namespace

Result<std::optional<PhysiologySpec>> parse_physiology_spec(const std::string& breath) {
  const std::size_t at = breath.find('@');
  const std::string head = breath.substr(0, at);
  const std::size_t colon = head.find(':');
  const std::string source = head.substr(0, colon);
  PhysiologySpec spec;
  const std::optional<BreathSource> named = kBreathSourceNames.parse(source);
  if (named != BreathSource::Amm && named != BreathSource::OpenIce) return std::optional<PhysiologySpec>{};
  spec.source = *named;
  if (colon != std::string::npos) {
    const std::optional<Quantity> q = kQuantityNames.parse(head.substr(colon + 1));
    if (spec.source == BreathSource::Amm || !q) return fail("'" + breath + "': " + spec_help());
    spec.quantity = *q;
  }
  if (at != std::string::npos) {
    const std::string d = breath.substr(at + 1);
    char* end = nullptr;
    const long id = d.empty() ? -1 : std::strtol(d.c_str(), &end, 10);
    if (id < 0 || id > 232 || *end != '\0') return fail("'" + breath + "': DOMAIN: " + spec_help());
    spec.domain = static_cast<std::uint32_t>(id);
  }
  return std::optional<PhysiologySpec>{spec};
}

}  // namespace lungar::breath::physiology
