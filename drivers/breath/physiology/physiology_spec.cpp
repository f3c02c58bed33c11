/// @file physiology_spec.cpp
/// @brief Reading a DDS breath source's spec (physiology_spec.h).
#include "drivers/breath/physiology/physiology_spec.h"

#include <cstdlib>

namespace lungar::breath::physiology {

namespace {

constexpr const char* kSpecHelp =
    "expected amm[@DOMAIN] or openice[:volume|flow|pressure][@DOMAIN], DOMAIN a DDS domain id 0 to 232";

}  // namespace

Result<std::optional<PhysiologySpec>> parse_physiology_spec(const std::string& breath) {
  const std::size_t at = breath.find('@');
  const std::string head = breath.substr(0, at);
  const std::size_t colon = head.find(':');
  const std::string source = head.substr(0, colon);
  PhysiologySpec spec;
  if (source == "amm")
    spec.source = PhysiologySpec::Source::Amm;
  else if (source == "openice")
    spec.source = PhysiologySpec::Source::OpenIce;
  else
    return std::optional<PhysiologySpec>{};
  if (colon != std::string::npos) {
    const std::optional<Quantity> q = kQuantityNames.parse(head.substr(colon + 1));
    if (spec.source == PhysiologySpec::Source::Amm || !q) return fail("'" + breath + "': " + kSpecHelp);
    spec.quantity = *q;
  }
  if (at != std::string::npos) {
    const std::string d = breath.substr(at + 1);
    char* end = nullptr;
    const long id = d.empty() ? -1 : std::strtol(d.c_str(), &end, 10);
    if (id < 0 || id > 232 || *end != '\0') return fail("'" + breath + "': DOMAIN: " + kSpecHelp);
    spec.domain = static_cast<std::uint32_t>(id);
  }
  return std::optional<PhysiologySpec>{spec};
}

}  // namespace lungar::breath::physiology
