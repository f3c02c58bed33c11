// The RAII layer over Cyclone DDS's C API, on a real Cyclone domain on loopback: configuration errors as one
// line, samples with their source timestamps, partitions, late joiners, the waitset, entity lifetimes.
#include <gtest/gtest.h>

#include <fstream>

#include "config/base/clock.h"
#include "drivers/classroom/classroom_topics.h"
#include "drivers/dds/dds.h"
#include "sync_test_support.h"

using namespace lungar;
using namespace lungar::platform;
using namespace lungar::classroom;
using lungar::testing::kLoopbackXml;
using lungar::testing::test_domain;

namespace {

using WirePose = lungar_sync_PatientPose;
using State = lungar_sync_BreathingState;

template <class T>
dds::Topic<T> topic(const dds::Domain& d) {
  auto t = dds::Topic<T>::create(d.participant(), classroom::TopicInfo<T>::descriptor(), classroom::TopicInfo<T>::name);
  EXPECT_TRUE(t) << t.error();
  return t.take();
}

template <class T>
void qos_for(dds::Qos& q, const std::string& partition) {
  classroom::classroom_qos<T>(q, partition);
}

/// Takes one sample within `timeout_ns` (the waitset wakes on its arrival).
template <class T>
int take_within(const dds::Reader<T>& r, dds::WaitSet& ws, T& out, dds_sample_info_t& info, std::int64_t timeout_ns) {
  const std::int64_t until = monotonic_ns() + timeout_ns;
  for (;;) {
    int n = r.take(std::span<T>(&out, 1), std::span<dds_sample_info_t>(&info, 1));
    if (n != 0 || monotonic_ns() >= until) return n;
    ws.wait(until - monotonic_ns());
  }
}

/// Topic T on a loopback domain, a writer of it in one partition and a reader in another (or the same), and a
/// waitset that wakes on the reader's data: what a sample needs to go round. The members are in the order they
/// are made, so that each is deleted before what it was made from.
template <class T>
struct RoundTrip {
  static Result<RoundTrip> open(const std::string& writer_partition, const std::string& reader_partition) {
    auto d = dds::Domain::create(test_domain(), kLoopbackXml);
    if (!d) return Error{d.error()};
    const dds_entity_t p = d->participant();
    auto t = dds::Topic<T>::create(p, classroom::TopicInfo<T>::descriptor(), classroom::TopicInfo<T>::name);
    if (!t) return Error{t.error()};
    dds::Qos wq, rq;
    qos_for<T>(wq, writer_partition);
    qos_for<T>(rq, reader_partition);
    auto w = dds::Writer<T>::create(p, *t, wq);
    auto r = dds::Reader<T>::create(p, *t, rq);
    auto ws = dds::WaitSet::create(p);
    if (!w || !r || !ws) return fail(!w ? w.error() : !r ? r.error() : ws.error());
    if (Status a = ws->attach_reader(r->get()); !a) return Error{a.error()};
    return RoundTrip{d.take(), t.take(), w.take(), r.take(), ws.take()};
  }
  /// Takes one sample within `timeout_ns`.
  int take_within(T& out, dds_sample_info_t& info, std::int64_t timeout_ns) {
    return ::take_within(reader, waitset, out, info, timeout_ns);
  }

  dds::Domain domain;
  dds::Topic<T> topic;
  dds::Writer<T> writer;
  dds::Reader<T> reader;
  dds::WaitSet waitset;
};

}  // namespace

TEST(DdsLayer, AMissingOrForeignConfigurationIsOneLineNamingTheFile) {
  auto missing = dds::Domain::create(test_domain(), "/nonexistent/cyclone.xml");
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().find("/nonexistent/cyclone.xml: cannot read"), std::string::npos) << missing.error();
  const std::string path = (lungar::testing::test_dir("dds") / "bad.xml").string();
  std::ofstream(path) << "<NotCyclone/>\n";
  auto foreign = dds::Domain::create(test_domain(), path);
  ASSERT_FALSE(foreign);
  EXPECT_NE(foreign.error().find("expected a Cyclone DDS XML configuration"), std::string::npos);
  std::ofstream(path) << "<CycloneDDS><Domain><General><NoSuchOption>1</NoSuchOption></General></Domain></CycloneDDS>\n";
  auto wrong = dds::Domain::create(test_domain(), path);
  ASSERT_FALSE(wrong);
  EXPECT_NE(wrong.error().find(path + ": Cyclone DDS refused the configuration"), std::string::npos) << wrong.error();
  EXPECT_EQ(wrong.error().find('\n'), std::string::npos);
  auto port = dds::Domain::create(240, kLoopbackXml);
  ASSERT_FALSE(port);
  EXPECT_NE(port.error().find("sync.domain"), std::string::npos);
}

TEST(DdsLayer, ASampleArrivesWithItsSourceTimestamp) {
  auto room = RoundTrip<WirePose>::open("room", "room");
  ASSERT_TRUE(room) << room.error();
  WirePose sent{};
  sent.seq = 42;
  sent.orientation_wxyz.w = 1.0;
  const std::int64_t stamp = 1'234'567'890'123'456'789;
  ASSERT_TRUE(room->writer.write(sent, stamp));
  WirePose got{};
  dds_sample_info_t info{};
  ASSERT_EQ(room->take_within(got, info, 2'000'000'000), 1);
  EXPECT_EQ(got.seq, 42u);
  EXPECT_EQ(info.source_timestamp, stamp);
  EXPECT_EQ(room->writer.matched(), 1);
  EXPECT_EQ(room->reader.matched(), 1);
}

TEST(DdsLayer, PartitionsKeepClassroomsApart) {
  auto rooms = RoundTrip<WirePose>::open("room-a", "room-b");
  ASSERT_TRUE(rooms) << rooms.error();
  ASSERT_TRUE(rooms->writer.write(WirePose{}, 1));
  WirePose got{};
  dds_sample_info_t info{};
  EXPECT_EQ(rooms->take_within(got, info, 300'000'000), 0);
  EXPECT_EQ(rooms->reader.matched(), 0);
}

TEST(DdsLayer, ALateReaderOfDurableStateGetsTheLatestSampleOnly) {
  auto d = dds::Domain::create(test_domain(), kLoopbackXml);
  ASSERT_TRUE(d) << d.error();
  auto t = topic<State>(*d);
  dds::Qos q;
  qos_for<State>(q, "room");
  auto w = dds::Writer<State>::create(d->participant(), t, q);
  ASSERT_TRUE(w);
  State s{};
  for (std::uint32_t rev = 1; rev <= 3; ++rev) {
    s.revision = rev;
    ASSERT_TRUE(w->write(s, rev));
  }
  auto r = dds::Reader<State>::create(d->participant(), t, q);  // joins after the writes
  auto ws = dds::WaitSet::create(d->participant());
  ASSERT_TRUE(r && ws);
  ASSERT_TRUE(ws->attach_reader(r->get()));
  State got{};
  dds_sample_info_t info{};
  ASSERT_EQ(take_within(*r, *ws, got, info, 2'000'000'000), 1);
  EXPECT_EQ(got.revision, 3u);  // keep-last 1
  EXPECT_EQ(take_within(*r, *ws, got, info, 100'000'000), 0);
}

TEST(DdsLayer, TheGuardConditionWakesTheWaitset) {
  auto d = dds::Domain::create(test_domain(), kLoopbackXml);
  ASSERT_TRUE(d) << d.error();
  auto ws = dds::WaitSet::create(d->participant());
  ASSERT_TRUE(ws);
  ws->trigger();
  const std::int64_t t0 = monotonic_ns();
  ASSERT_TRUE(ws->wait(10'000'000'000));  // returns at once: triggered
  EXPECT_LT(monotonic_ns() - t0, 5'000'000'000);
  bool triggered = true;
  ASSERT_EQ(dds_read_guardcondition(ws->guard(), &triggered), 0);
  EXPECT_FALSE(triggered);  // wait() clears it
}

TEST(DdsLayer, EntitiesAreDeletedByTheirOwners) {
  auto d = dds::Domain::create(test_domain(), kLoopbackXml);
  ASSERT_TRUE(d) << d.error();
  dds_entity_t handle = 0;
  {
    auto t = topic<WirePose>(*d);
    dds::Qos q;
    auto w = dds::Writer<WirePose>::create(d->participant(), t, q);
    ASSERT_TRUE(w);
    handle = w->get();
    EXPECT_EQ(dds_get_participant(handle), d->participant());
  }
  EXPECT_LT(dds_get_participant(handle), 0);  // gone with its owner
  dds::Entity moved_from(dds_create_guardcondition(d->participant()));
  const dds_entity_t g = moved_from.get();
  dds::Entity moved_to(std::move(moved_from));
  EXPECT_EQ(moved_to.get(), g);
  EXPECT_FALSE(moved_from);
  moved_to.reset();
  EXPECT_LT(dds_get_parent(g), 0);
}
