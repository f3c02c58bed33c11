/// @file openice_reader.cpp
/// @brief OpenICE's sample arrays on Cyclone DDS (openice_reader.h).
#include "drivers/breath/openice/openice_reader.h"

#include "config/base/clock.h"
#include "lungar/physiology/openice.h"

namespace lungar::breath::physiology {

namespace {
/// How long the reader's thread waits for data before it looks at its stop flag again.
constexpr std::int64_t kWaitNs = 100'000'000;

double seconds_of(const ice_Time_t& t) { return static_cast<double>(t.sec) + 1e-9 * static_cast<double>(t.nanosec); }
}  // namespace

Result<std::unique_ptr<OpenIceReader>> OpenIceReader::open(std::uint32_t domain, const std::string& cyclonedds_xml,
                                                           Quantity followed, PhysiologyInbox& inbox) {
  auto d = dds::Domain::create(domain, cyclonedds_xml);
  if (!d) return Error{d.error()};
  std::unique_ptr<OpenIceReader> r(new OpenIceReader(d.take(), followed, inbox));
  auto topic = dds::Topic<ice_SampleArray>::create(r->domain_.participant(), ice_SampleArray_desc, kOpenIceTopic);
  if (!topic) return Error{topic.error()};
  r->topic_.emplace(topic.take());
  dds::Qos qos;
  qos.best_effort().volatile_().keep_last(64);
  auto reader = dds::Reader<ice_SampleArray>::create(r->domain_.participant(), *r->topic_, qos);
  if (!reader) return Error{reader.error()};
  r->reader_.emplace(reader.take());
  auto waitset = dds::WaitSet::create(r->domain_.participant());
  if (!waitset) return Error{waitset.error()};
  r->waitset_.emplace(waitset.take());
  if (Status s = r->waitset_->attach_reader(r->reader_->get()); !s) return Error{s.error()};
  OpenIceReader* self = r.get();
  r->thread_.start(*r->waitset_, [self] {
    while (!self->thread_.stopping()) {
      self->waitset_->wait(kWaitNs);
      self->take();
    }
  });
  return r;
}

OpenIceReader::~OpenIceReader() { thread_.stop(); }

void OpenIceReader::take() {
  const auto keep = [this](const Sample& s) { inbox_.push(s, monotonic_ns()); };
  const auto dropped = [this](Drop why) { inbox_.drop(why); };
  while (reader_->take_loaned([&](const ice_SampleArray& a, const dds_sample_info_t& info) {
    if (!info.valid_data) return;
    const ice_Time_t& end = a.device_time.sec != 0 || a.device_time.nanosec != 0 ? a.device_time : a.presentation_time;
    checks_.check({a.metric_id, a.unit_id, a.frequency, {a.values._buffer, a.values._length}, seconds_of(end)}, keep,
                  dropped);
  }) > 0) {
  }
}

}  // namespace lungar::breath::physiology
