/// @file physiology_feed.cpp
/// @brief A mannequin's or a ventilator's breath over DDS to the follower (physiology_feed.h).
#include "drivers/breath/physiology/physiology_feed.h"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "config/base/clock.h"

namespace lungar::breath::physiology {

PhysiologyFeed::PhysiologyFeed(const PhysiologySpec& spec, std::int64_t t0_ns)
    : spec_(spec), t0_ns_(t0_ns), inbox_(kBreathSourceNames.name(spec.source)) {}

Result<std::shared_ptr<PhysiologyFeed>> PhysiologyFeed::open(const PhysiologySpec& spec,
                                                             const std::string& cyclonedds_xml, std::int64_t t0_ns) {
  std::shared_ptr<PhysiologyFeed> f(new PhysiologyFeed(spec, t0_ns));
  // A reader's error is told under the source's name: "amm: Fast DDS could not ...".
  const std::string who = breath_source_prefix(spec.source) + " ";
  if (spec.source == BreathSource::Amm) {
    auto r = AmmReader::open(spec.domain, f->inbox_);
    if (!r) return r.with_context(who);
    f->amm_ = r.take();
  } else {
    auto r = OpenIceReader::open(spec.domain, cyclonedds_xml, spec.quantity, f->inbox_);
    if (!r) return r.with_context(who);
    f->openice_ = r.take();
  }
  return f;
}

std::string PhysiologyFeed::describe() const {
  const std::string d = " on DDS domain " + std::to_string(spec_.domain);
  if (spec_.source == BreathSource::Amm)
    return "the mannequin's lung volumes (AMM, topic '" + std::string(kAmmTopic) + "')" + d;
  return std::string("the ventilator's ") + openice_metric(spec_.quantity) + " (OpenICE)" + d;
}

void PhysiologyFeed::feed(double t_s, breath::Followers& followers) {
  (void)t_s;  // every sample in the inbox came before now
  inbox_.drain([&](const PhysiologyInbox::Item& item) {
    const double arrival = seconds_between(t0_ns_, item.arrival_ns);
    const double offset = arrival - item.sample.t_s;
    if (!offset_s_ || offset < *offset_s_) offset_s_ = offset;
    give(item.sample, item.sample.t_s + *offset_s_, followers);
  });
}

void PhysiologyFeed::give(const Sample& s, double t_s, breath::Followers& followers) {
  const auto c = static_cast<std::size_t>(s.channel);
  t_s = std::max(t_s, last_t_[c]);  // a smaller offset found later must not move a channel back in time
  last_t_[c] = t_s;
  ++fed_;
  if (s.channel != Channel::breath) {
    const std::size_t l = s.channel == Channel::left_lung ? 0 : 1;
    followers.lungs[l].add(t_s, s.value);
    lung_ml_[l] = s.value;
    lung_source_t_[l] = s.t_s;
    // No total published: the two lungs' volumes at one simulation time are the breath's.
    if (!total_seen_ && lung_source_t_[0] == lung_source_t_[1]) followers.breath.add(t_s, lung_ml_[0] + lung_ml_[1]);
    return;
  }
  total_seen_ = true;
  if (s.quantity != Quantity::flow_ml_per_s) return followers.breath.add(t_s, s.value);
  // Flow integrated to a volume; its drift is the follower's end-exhale level to remove.
  if (!std::isnan(flow_t_)) flow_volume_ml_ += s.value * (t_s - flow_t_);
  flow_t_ = t_s;
  followers.breath.add(t_s, flow_volume_ml_);
}

void PhysiologyFeed::add_stats(nlohmann::json& stats) const {
  stats["breath_source"] = spec_.source == BreathSource::Amm
                               ? std::string(kBreathSourceNames.name(spec_.source))
                               : breath_source_prefix(spec_.source) + kQuantityNames.name(spec_.quantity);
  stats["breath_dds_domain"] = spec_.domain;
  stats["breath_dds_publishers"] = amm_ ? amm_->matched() : openice_->matched();
  stats["breath_dds_samples"] = fed_;
  nlohmann::json dropped = nlohmann::json::object();
  std::uint64_t invalid = inbox_.overflowed();
  for (const auto& [why, name] : kDropNames.entries) {
    dropped[name] = inbox_.dropped(why);
    invalid += inbox_.dropped(why);
  }
  stats["breath_dropped"] = dropped;
  stats["breath_invalid_samples"] = invalid;
}

Result<std::shared_ptr<breath::SurrogateFeed>> open_physiology_breath(
    const std::string& source, const std::string& cyclonedds_xml, std::int64_t t0_ns,
    const std::function<void(const std::string&)>& log) {
  auto spec = parse_physiology_spec(source);
  if (!spec) return Error{spec.error()};
  if (!*spec) return fail("'" + source + "': not a breath source over DDS");  // breath_kind() said it was
  auto dds = PhysiologyFeed::open(**spec, cyclonedds_xml, t0_ns);
  if (!dds) return Error{dds.error()};
  log("breathing: following " + (*dds)->describe() + ", the model until its first breaths");
  return std::shared_ptr<breath::SurrogateFeed>(dds.take());
}

}  // namespace lungar::breath::physiology
