/// @file marker_feed.cpp
/// @brief A live marker's positions, in the patient's frame, along its own breathing axis (marker_feed.h).
#include "drivers/breath/marker/marker_feed.h"

#include <nlohmann/json.hpp>

#include "config/base/clock.h"
#include "sim/breathing/breath_trace.h"

namespace lungar::breath {

namespace {
/// The window's samples are kept in storage reserved up front: a marker at up to this rate fills it.
constexpr double kMaxMarkerRateHz = 1000.0;
}  // namespace

MarkerFeed::MarkerFeed(drivers::Role role, std::int64_t t0_ns) : role_(role), t0_ns_(t0_ns) {
  const auto n = static_cast<std::size_t>(kMarkerAxisWindowS * kMaxMarkerRateHz);
  window_t_.reserve(n);
  window_p_.reserve(n);
}

void MarkerFeed::push(const drivers::PoseSample& s) {
  if (s.role == drivers::Role::Patient) {
    patient_ = s;
    patient_seen_ = true;
    return;
  }
  if (s.role != role_ || !s.valid()) return;
  Eigen::Vector3d p = s.position();
  if (patient_seen_) p = patient_.transform().inverse() * p;  // in the patient's frame: turning is not breathing
  ring_.push({seconds_between(t0_ns_, s.t_arrival_ns), p});
}

void MarkerFeed::feed(double t_s, Followers& followers) {
  (void)t_s;  // every sample in the ring was taken before now
  sim::BreathFollower& follower = followers.breath;
  ring_.drain([&](const Sample& s) {
    ++samples_;
    if (axis_found_) {
      follower.add(s.t_s, axis_.dot(s.p_mm - origin_));
      return;
    }
    if (window_t_.size() == window_t_.capacity() || (!window_t_.empty() && !(s.t_s > window_t_.back()))) return;
    window_t_.push_back(s.t_s);
    window_p_.push_back(s.p_mm);
    if (s.t_s - window_t_.front() < kMarkerAxisWindowS) return;
    // The window is full: the axis from it, then its samples to the follower as if they had just come.
    axis_ = sim::breathing_axis(window_t_, window_p_, kMarkerAxisWindowS);
    origin_ = window_p_.front();
    axis_found_ = true;
    for (std::size_t i = 0; i < window_t_.size(); ++i) follower.add(window_t_[i], axis_.dot(window_p_[i] - origin_));
  });
}

void MarkerFeed::add_stats(nlohmann::json& stats) const {
  stats["breath_source"] = breath_source_prefix(BreathSource::Marker) + drivers::to_string(role_);
  stats["breath_marker_samples"] = samples_;
  stats["breath_marker_axis"] =
      axis_found_ ? std::vector<double>{axis_.x(), axis_.y(), axis_.z()} : std::vector<double>{};
  stats["breath_invalid_samples"] = ring_.dropped();
}

Result<std::shared_ptr<MarkerFeed>> open_marker_feed(const std::string& source, std::int64_t t0_ns) {
  const std::string role_text = source.substr(breath_source_prefix(BreathSource::Marker).size());
  const std::optional<drivers::Role> role = drivers::role_from_string(role_text);
  if (!role || *role == drivers::Role::Patient) {
    return fail(breath_source_prefix(BreathSource::Marker) +
                "ROLE: expected the tracker role carrying the chest marker, stylus or head (the patient's "
                "pose is the frame it is read in), got '" +
                role_text + "'");
  }
  return std::make_shared<MarkerFeed>(*role, t0_ns);
}

std::string marker_following(const std::string& source) {
  return "breathing: following the " + source.substr(breath_source_prefix(BreathSource::Marker).size()) +
         " marker live (its breathing axis from its first " + std::to_string(static_cast<int>(kMarkerAxisWindowS)) +
         " s), the model until then";
}

}  // namespace lungar::breath
