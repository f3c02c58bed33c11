/// @file fastdds_physiology_publisher.cpp
/// @brief The other end of lungar's physiology readers, on the stack the mannequins use: an eProsima Fast DDS
///        publisher (Debian's libfastrtps, types from fastddsgen) of AMM physiology waveforms or OpenICE sample
///        arrays, breathing a known pattern, so that a test reads real wire traffic from another DDS vendor.
///
/// Usage: lungar-test-fastdds-physiology amm|openice DOMAIN SECONDS [bad]
///   amm: Respiratory_LeftLung_Volume, _RightLung_Volume and _LungTotal_Volume (mL) every 20 ms; the left lung
///        takes kLeftShare of each breath. openice: MDC_VOL_AWAY_TIDAL (mL), arrays of 10 samples at 50 Hz.
///   bad: samples that must be dropped, after a 2 s lead-in, in turn: amm, every 25th step an extra sample with a NaN,
///   a negative
///        volume, a wrong unit, or a time a minute back; openice, every 5th array a NaN or a negative volume in
///        place of one of its values, or an extra array in a pressure unit or at 0 Hz.
/// The breath: 1200 mL at 20 a minute, deep enough that each lung's own share stands out from the model's
/// breath a run shows before it follows. Waits up to 10 s for a reader, then publishes for SECONDS; prints one
/// line with what it wrote.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>

#include "ammPubSubTypes.h"
#include "openicePubSubTypes.h"

namespace {

using namespace eprosima::fastdds::dds;

constexpr double kTidalMl = 1200.0, kPeriodS = 3.0, kLeftShare = 0.25;
constexpr double kLeftFrcMl = 1100.0, kRightFrcMl = 1300.0;
/// The first seconds carry no bad sample. The writer matching the reader does not mean the reader has matched the
/// writer: a best-effort reader still discovering it drops what comes first (on a loaded CI machine, the first bad
/// sample was lost and the count of dropped samples came one short).
constexpr double kLeadInS = 2.0;

double breath_ml(double t) { return 0.5 * kTidalMl * (1.0 - std::cos(2.0 * M_PI * t / kPeriodS)); }

DataWriter* make_writer(DomainParticipant* p, TypeSupport type, const char* topic_name, bool exclusive) {
  type.register_type(p);
  Topic* topic = p->create_topic(topic_name, type.get_type_name(), TOPIC_QOS_DEFAULT);
  Publisher* pub = p->create_publisher(PUBLISHER_QOS_DEFAULT);
  DataWriterQos q = DATAWRITER_QOS_DEFAULT;
  q.reliability().kind = RELIABLE_RELIABILITY_QOS;
  q.durability().kind = TRANSIENT_LOCAL_DURABILITY_QOS;
  q.history().kind = KEEP_LAST_HISTORY_QOS;
  q.history().depth = 64;
  if (exclusive) q.ownership().kind = EXCLUSIVE_OWNERSHIP_QOS;
  return topic && pub ? pub->create_datawriter(topic, q) : nullptr;
}

bool wait_for_reader(DataWriter* w) {
  for (int i = 0; i < 1000; ++i) {
    PublicationMatchedStatus s;
    if (w->get_publication_matched_status(s) == eprosima::fastrtps::types::ReturnCode_t::RETCODE_OK &&
        s.current_count > 0)
      return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

struct Counts {
  long good = 0, bad = 0;
};

void write_amm(DataWriter* w, double t, long step, bool bad, Counts& n) {
  AMM::PhysiologyWaveform s;
  s.educational_encounter().id("lungar-test-encounter");
  s.simulation_time(static_cast<int64_t>(std::llround(t * 1000.0)));
  s.timestamp(static_cast<uint64_t>(std::chrono::duration_cast<std::chrono::milliseconds>(
                                        std::chrono::system_clock::now().time_since_epoch()).count()));
  s.unit("mL");
  const double b = breath_ml(t);
  const std::pair<const char*, double> lungs[] = {{"Respiratory_LeftLung_Volume", kLeftFrcMl + kLeftShare * b},
                                                  {"Respiratory_RightLung_Volume", kRightFrcMl + (1 - kLeftShare) * b},
                                                  {"Respiratory_LungTotal_Volume", kLeftFrcMl + kRightFrcMl + b}};
  for (const auto& [name, v] : lungs) {
    s.name(name);
    s.value(v);
    w->write(&s);
    ++n.good;
  }
  if (!bad || step % 25 != 0) return;
  switch ((step / 25) % 4) {
    case 0: s.value(std::nan("")); break;
    case 1: s.value(-5.0); break;
    case 2: s.unit("mmHg"); break;
    default: s.simulation_time(s.simulation_time() - 60'000); break;  // a minute back
  }
  w->write(&s);
  ++n.bad;
}

void write_openice(DataWriter* w, double t_end, long step, bool bad, Counts& n) {
  ice::SampleArray a;
  a.unique_device_identifier("lungar-test-ventilator");
  a.metric_id("MDC_VOL_AWAY_TIDAL");
  a.vendor_metric_id("");
  a.instance_id(0);
  a.unit_id("MDC_DIM_MILLI_L");
  a.frequency(50);
  for (int i = 9; i >= 0; --i) a.values().push_back(static_cast<float>(breath_ml(t_end - i * 0.02)));
  const double sec = std::floor(t_end);
  a.device_time().sec(static_cast<int32_t>(sec));
  a.device_time().nanosec(static_cast<int32_t>(std::llround((t_end - sec) * 1e9)));
  a.presentation_time(a.device_time());
  const int kind = bad && step % 5 == 0 ? static_cast<int>((step / 5) % 4) : -1;
  if (kind == 0) a.values()[3] = std::nanf("");
  if (kind == 1) a.values()[3] = -5.0f;
  w->write(&a);
  ++n.good;
  if (kind < 0) return;
  ++n.bad;
  if (kind < 2) return;
  if (kind == 2) a.unit_id("MDC_DIM_CM_H2O");
  else a.frequency(0);
  w->write(&a);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: %s amm|openice DOMAIN SECONDS [bad]\n", argv[0]);
    return 2;
  }
  const std::string kind = argv[1];
  const int domain = std::atoi(argv[2]);
  const double seconds = std::atof(argv[3]);
  const bool bad = argc > 4 && std::string(argv[4]) == "bad";
  // Fast DDS's default profile: the test's FASTRTPS_DEFAULT_PROFILES_FILE (config/fastdds/loopback-tests.xml).
  DomainParticipant* p = DomainParticipantFactory::get_instance()->create_participant(domain, PARTICIPANT_QOS_DEFAULT);
  if (!p) return std::fprintf(stderr, "fastdds publisher: no participant\n"), 1;
  const bool amm = kind == "amm";
  DataWriter* w = amm ? make_writer(p, TypeSupport(new AMM::PhysiologyWaveformPubSubType()), "Physiology Waveform", true)
                      : make_writer(p, TypeSupport(new ice::SampleArrayPubSubType()), "SampleArray", false);
  if (!w) return std::fprintf(stderr, "fastdds publisher: no writer\n"), 1;
  if (!wait_for_reader(w)) return std::fprintf(stderr, "fastdds publisher: no reader matched in 10 s\n"), 1;
  const double step_s = amm ? 0.02 : 0.2;
  const auto start = std::chrono::steady_clock::now();
  Counts n;
  for (long step = 0; step * step_s <= seconds; ++step) {
    std::this_thread::sleep_until(start + std::chrono::microseconds(std::llround(step * step_s * 1e6)));
    const bool bad_now = bad && step * step_s >= kLeadInS;
    if (amm)
      write_amm(w, step * step_s, step, bad_now, n);
    else
      write_openice(w, 1000.0 + step * step_s, step, bad_now, n);  // the device's clock: not the run's
  }
  std::printf("fastdds publisher: %s on domain %d: %ld samples, %ld bad\n", kind.c_str(), domain, n.good, n.bad);
  std::fflush(stdout);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // reliable: let the last ones be acknowledged
  p->delete_contained_entities();
  DomainParticipantFactory::get_instance()->delete_participant(p);
  return 0;
}
