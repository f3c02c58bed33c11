/// @file physiology_feed.h
/// @brief `--breath amm[@DOMAIN]` and `--breath openice[:volume|flow|pressure][@DOMAIN]`: the breath of a
///        mannequin's physiology engine (AMM, its lung volumes, each lung's when it publishes them) or of a
///        ventilator (OpenICE, its tidal volume, its flow integrated to a volume, or its airway pressure as a
///        surrogate scaled to V_T), read over DDS and fed to the breath follower.
///
/// A source's clock is not the run's: each sample is placed at its source time plus the smallest (arrival -
/// source time) seen so far, the least-delayed sample's offset, so that transport jitter moves no sample later
/// than its fastest neighbour and the breath's shape keeps its own timing.
///
/// They are two of the breath sources (drivers/breath/); their readers share the DDS layer with the classroom, so
/// they sit here and plug into make_breath_source() through open_physiology_breath().
/// @ingroup platform
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "config/base/result.h"
#include "drivers/breath/amm/amm_reader.h"
#include "drivers/breath/openice/openice_reader.h"
#include "drivers/breath/physiology/physiology_spec.h"
#include "drivers/breath/source/surrogate_feed.h"

namespace lungar::breath::physiology {

class PhysiologyFeed final : public breath::SurrogateFeed {
 public:
  /// Starts reading; `cyclonedds_xml` configures OpenICE's Cyclone participant (AMM's Fast DDS participant takes
  /// FASTRTPS_DEFAULT_PROFILES_FILE). Times are seconds from `t0_ns` (the run's start, monotonic).
  static Result<std::shared_ptr<PhysiologyFeed>> open(const PhysiologySpec& spec, const std::string& cyclonedds_xml,
                                                      std::int64_t t0_ns);
  void feed(double t_s, breath::Followers& followers) override;
  /// breath_source ("amm", "openice:volume", ...), breath_dds_domain, breath_dds_publishers, breath_dds_samples,
  /// breath_dropped (by reason) and breath_invalid_samples (their sum, and samples lost to a full inbox).
  void add_stats(nlohmann::json& stats) const override;
  bool in_ml() const override { return spec_.quantity != Quantity::pressure_cmh2o; }
  bool per_lung() const override { return spec_.source == BreathSource::Amm; }
  /// "amm on domain 3" and the like, for the log.
  std::string describe() const;

 private:
  PhysiologyFeed(const PhysiologySpec& spec, std::int64_t t0_ns);
  /// One checked sample to its follower, at run time `t_s`.
  void give(const Sample& s, double t_s, breath::Followers& followers);

  PhysiologySpec spec_;
  std::int64_t t0_ns_;
  PhysiologyInbox inbox_;  ///< before the readers: they write into it until they go
  std::unique_ptr<AmmReader> amm_;
  std::unique_ptr<OpenIceReader> openice_;
  // The frame thread.
  std::optional<double> offset_s_;                           ///< run time minus source time: the smallest seen
  std::array<double, kChannels> last_t_{};                   ///< each channel's last fed time, so it never goes back
  bool total_seen_ = false;                                  ///< the source publishes the whole breath itself
  std::array<double, 2> lung_ml_{}, lung_source_t_{-1, -1};  ///< without a total: the two lungs summed
  double flow_volume_ml_ = 0, flow_t_ = std::numeric_limits<double>::quiet_NaN();
  std::uint64_t fed_ = 0;
};

/// `source` (amm..., openice...) opened for make_breath_source() (BreathSourceOptions::open_dds), the log told what
/// it follows; or what is wrong with the spec or the reader.
Result<std::shared_ptr<breath::SurrogateFeed>> open_physiology_breath(
    const std::string& source, const std::string& cyclonedds_xml, std::int64_t t0_ns,
    const std::function<void(const std::string&)>& log);

}  // namespace lungar::breath::physiology
