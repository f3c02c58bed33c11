/// @file amm_reader.cpp
/// @brief AMM's waveforms on Fast DDS (amm_reader.h); without Fast DDS in the build, a refusal that says so.
#include "drivers/breath/amm/amm_reader.h"

#if LUNGAR_WITH_FASTDDS
#include <atomic>

#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/subscriber/qos/DataReaderQos.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>

#include "ammPubSubTypes.h"
#include "config/base/clock.h"
#endif

namespace lungar::breath::physiology {

#if LUNGAR_WITH_FASTDDS
namespace {

namespace fdds = eprosima::fastdds::dds;

class FastDdsAmmReader final : public AmmReader, private fdds::DataReaderListener {
 public:
  explicit FastDdsAmmReader(PhysiologyInbox& inbox) : inbox_(inbox) {}
  ~FastDdsAmmReader() override {
    if (!participant_) return;
    participant_->delete_contained_entities();  // the listener is called no more
    fdds::DomainParticipantFactory::get_instance()->delete_participant(participant_);
  }

  Status open(std::uint32_t domain) {
    participant_ = fdds::DomainParticipantFactory::get_instance()->create_participant(
        static_cast<fdds::DomainId_t>(domain), fdds::PARTICIPANT_QOS_DEFAULT);
    if (!participant_) return fail("Fast DDS could not make a participant in domain " + std::to_string(domain));
    fdds::TypeSupport type(new AMM::PhysiologyWaveformPubSubType());
    type.register_type(participant_);
    fdds::Topic* topic = participant_->create_topic(kAmmTopic, type.get_type_name(), fdds::TOPIC_QOS_DEFAULT);
    fdds::Subscriber* sub = participant_->create_subscriber(fdds::SUBSCRIBER_QOS_DEFAULT);
    if (!topic || !sub) return fail(std::string("Fast DDS could not make the topic '") + kAmmTopic + "'");
    fdds::DataReaderQos q = fdds::DATAREADER_QOS_DEFAULT;
    q.reliability().kind = fdds::RELIABLE_RELIABILITY_QOS;
    q.durability().kind = fdds::TRANSIENT_LOCAL_DURABILITY_QOS;
    q.ownership().kind = fdds::EXCLUSIVE_OWNERSHIP_QOS;
    q.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
    q.history().depth = 256;
    if (!sub->create_datareader(topic, q, this)) return fail("Fast DDS could not make the reader");
    return ok();
  }
  int matched() const override { return matched_.load(); }

 private:
  void on_data_available(fdds::DataReader* reader) override {
    AMM::PhysiologyWaveform s;
    fdds::SampleInfo info;
    const auto dropped = [this](Drop why) { inbox_.drop(why); };
    while (reader->take_next_sample(&s, &info) == eprosima::fastrtps::types::ReturnCode_t::RETCODE_OK) {
      if (!info.valid_data) continue;
      const std::optional<Sample> kept = checks_.check(s.name(), s.unit(), s.simulation_time(), s.value(), dropped);
      if (kept) inbox_.push(*kept, monotonic_ns());
    }
  }
  void on_subscription_matched(fdds::DataReader*, const fdds::SubscriptionMatchedStatus& status) override {
    matched_.store(status.current_count);
  }

  PhysiologyInbox& inbox_;
  AmmChecks checks_;  ///< Fast DDS's listener thread only
  std::atomic<int> matched_{0};
  fdds::DomainParticipant* participant_ = nullptr;
};

}  // namespace

Result<std::unique_ptr<AmmReader>> AmmReader::open(std::uint32_t domain, PhysiologyInbox& inbox) {
  auto reader = std::make_unique<FastDdsAmmReader>(inbox);
  if (Status s = reader->open(domain); !s) return Error{s.error()};
  return std::unique_ptr<AmmReader>(std::move(reader));
}
#else
Result<std::unique_ptr<AmmReader>> AmmReader::open(std::uint32_t, PhysiologyInbox&) {
  return fail(
      "this lungar was built without eProsima Fast DDS (AMM's DDS stack; Debian's libfastrtps-dev and "
      "fastddsgen): install them and build again");
}
#endif

}  // namespace lungar::breath::physiology
