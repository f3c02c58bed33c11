/// @file dds.h
/// @brief A thin RAII layer over Cyclone DDS's C API (Debian ships no C++ binding): every entity is deleted by
/// its owner's destructor, every failure is a lungar::Result naming the call and Cyclone's reason.
/// @ingroup platform
///
/// Only what the classroom needs: a domain made from an XML file, a participant, QoS, topics, writers with
/// source timestamps, readers that take into caller-owned storage (no allocation for fixed-size types), read
/// and guard conditions and a waitset. Deleting a participant deletes its children in Cyclone, so children
/// are declared after their parent (C++ destroys in reverse order) and each deletes itself first.
#pragma once

#include <dds/dds.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "config/base/result.h"

namespace lungar::dds {

/// "dds_create_writer: Precondition not met" style text for a Cyclone return code.
std::string describe(const char* call, dds_return_t rc);

/// What Cyclone's DDS Security said about remote participants since the last call (a handshake that failed,
/// a participant its permissions do not allow), each distinct line once per process, oldest first. Cyclone
/// tells this only in its log, at warning level, and repeats it at every handshake attempt.
std::vector<std::string> take_security_complaints();

/// One owned dds_entity_t (participant, topic, reader, writer, condition, waitset, domain).
class Entity {
 public:
  Entity() = default;
  explicit Entity(dds_entity_t handle) : handle_(handle) {}
  ~Entity() { reset(); }
  Entity(Entity&& other) noexcept : handle_(other.handle_) { other.handle_ = 0; }
  Entity& operator=(Entity&& other) noexcept {
    if (this != &other) {
      reset();
      handle_ = other.handle_;
      other.handle_ = 0;
    }
    return *this;
  }
  Entity(const Entity&) = delete;
  Entity& operator=(const Entity&) = delete;

  dds_entity_t get() const { return handle_; }
  explicit operator bool() const { return handle_ > 0; }
  /// Deletes the entity (and, in Cyclone, its children) now.
  void reset();

 private:
  dds_entity_t handle_ = 0;
};

/// Turns a handle-or-negative-code into an owned Entity or an error line naming `call`.
Result<Entity> own(const char* call, dds_entity_t handle);

/// A QoS set, built by chaining; the topic profiles live in classroom_topics.h.
class Qos {
 public:
  Qos() : qos_(dds_create_qos()) {}
  ~Qos() { dds_delete_qos(qos_); }
  Qos(const Qos&) = delete;
  Qos& operator=(const Qos&) = delete;

  Qos& reliable() { return dds_qset_reliability(qos_, DDS_RELIABILITY_RELIABLE, DDS_SECS(1)), *this; }
  Qos& best_effort() { return dds_qset_reliability(qos_, DDS_RELIABILITY_BEST_EFFORT, 0), *this; }
  Qos& volatile_() { return dds_qset_durability(qos_, DDS_DURABILITY_VOLATILE), *this; }
  Qos& transient_local() { return dds_qset_durability(qos_, DDS_DURABILITY_TRANSIENT_LOCAL), *this; }
  Qos& keep_last(int32_t depth) { return dds_qset_history(qos_, DDS_HISTORY_KEEP_LAST, depth), *this; }
  Qos& partition(const std::string& name) { return dds_qset_partition1(qos_, name.c_str()), *this; }
  /// A name/value property (DDS Security reads its plugins and files from these, "dds.sec.*").
  Qos& property(const std::string& name, const std::string& value) {
    return dds_qset_prop(qos_, name.c_str(), value.c_str()), *this;
  }
  const dds_qos_t* get() const { return qos_; }

 private:
  dds_qos_t* qos_;
};

/// A Cyclone domain made from an XML configuration file, and the one participant lungar uses in it.
class Domain {
 public:
  /// Reads and checks `config_path` (a Cyclone XML file) and creates domain `domain_id` from it, and the
  /// participant with `participant_qos` (DDS Security's properties, or none). Cyclone's own complaint about the
  /// file or the participant's security, if any, is part of the error line.
  static Result<Domain> create(std::uint32_t domain_id, const std::string& config_path,
                               const Qos* participant_qos = nullptr);

  dds_entity_t participant() const { return participant_.get(); }
  std::uint32_t id() const { return id_; }

 private:
  Domain() = default;
  std::uint32_t id_ = 0;
  Entity domain_;       ///< destroyed last
  Entity participant_;  ///< destroyed first
};

/// A topic of the idlc-generated type T; `descriptor` is T's generated T_desc.
template <class T>
class Topic {
 public:
  static Result<Topic> create(dds_entity_t participant, const dds_topic_descriptor_t& descriptor, const char* name) {
    auto e = own("dds_create_topic", dds_create_topic(participant, &descriptor, name, nullptr, nullptr));
    if (!e) return Error{e.error()};
    Topic t;
    t.entity_ = e.take();
    return t;
  }
  dds_entity_t get() const { return entity_.get(); }

 private:
  Entity entity_;
};

/// Cyclone's calls for the writing side of a topic, for Endpoint.
struct WriterCalls {
  static constexpr const char* kCreate = "dds_create_writer";
  static constexpr auto create = &dds_create_writer;
  using MatchedStatus = dds_publication_matched_status_t;
  static constexpr auto get_matched = &dds_get_publication_matched_status;
};
/// Cyclone's calls for the reading side of a topic, for Endpoint.
struct ReaderCalls {
  static constexpr const char* kCreate = "dds_create_reader";
  static constexpr auto create = &dds_create_reader;
  using MatchedStatus = dds_subscription_matched_status_t;
  static constexpr auto get_matched = &dds_get_subscription_matched_status;
};

/// What a writer and a reader of T share (Self is Writer<T> or Reader<T>; Calls names Cyclone's calls for it):
/// being made on a topic with a QoS, and counting the other side's endpoints it matched.
template <class Self, class T, class Calls>
class Endpoint {
 public:
  static Result<Self> create(dds_entity_t participant, const Topic<T>& topic, const Qos& qos) {
    auto e = own(Calls::kCreate, Calls::create(participant, topic.get(), qos.get(), nullptr));
    if (!e) return Error{e.error()};
    Self made;
    made.entity_ = e.take();
    return made;
  }
  /// Endpoints of the other side (readers of a writer, writers of a reader) matched now by DDS discovery, or -1
  /// when Cyclone cannot say.
  int matched() const {
    typename Calls::MatchedStatus s{};
    return Calls::get_matched(entity_.get(), &s) < 0 ? -1 : static_cast<int>(s.current_count);
  }
  dds_entity_t get() const { return entity_.get(); }

 protected:
  Entity entity_;
};

/// A writer of T that stamps each sample with the caller's clock (source timestamp).
template <class T>
class Writer : public Endpoint<Writer<T>, T, WriterCalls> {
 public:
  /// Writes `sample` with source timestamp `source_ns` (ns since the epoch on the station clock).
  Status write(const T& sample, std::int64_t source_ns) const {
    const dds_return_t rc = dds_write_ts(this->entity_.get(), &sample, source_ns);
    if (rc < 0) return fail(describe("dds_write_ts", rc));
    return ok();
  }
};

/// A reader of T that takes samples into caller-owned storage.
template <class T>
class Reader : public Endpoint<Reader<T>, T, ReaderCalls> {
 public:
  static constexpr std::size_t kMaxTake = 16;

  /// Takes up to min(samples.size(), kMaxTake) samples; returns how many (0: none), or a negative Cyclone code.
  /// For fixed-size T (no sequences or unbounded strings) Cyclone fills `samples` in place without allocating.
  int take(std::span<T> samples, std::span<dds_sample_info_t> infos) const {
    std::array<void*, kMaxTake> buffers{};
    const std::size_t n = std::min({samples.size(), infos.size(), kMaxTake});
    for (std::size_t i = 0; i < n; ++i) buffers[i] = &samples[i];
    return dds_take(this->entity_.get(), buffers.data(), infos.data(), n, static_cast<uint32_t>(n));
  }
  /// Takes every available sample, N at a time into storage on the stack (no allocation for fixed-size T):
  /// calls `batch()` before each batch (what its samples share, such as the time they were taken) and then
  /// `on(sample, info)` for each of its samples, valid data or not. Returns how many it took.
  template <std::size_t N, class Batch, class On>
  int take_each(Batch&& batch, On&& on) const {
    static_assert(N <= kMaxTake);
    std::array<T, N> samples{};
    std::array<dds_sample_info_t, N> infos{};
    int total = 0;
    for (int n; (n = take(samples, infos)) > 0; total += n) {
      batch();
      for (int i = 0; i < n; ++i) on(samples[i], infos[i]);
    }
    return total;
  }
  template <std::size_t N, class On>
  int take_each(On&& on) const {
    return take_each<N>([] {}, on);
  }
  /// Takes every available sample as a loan and calls `on(sample, info)` for each (for types with sequences,
  /// whose storage Cyclone owns); returns how many, or a negative Cyclone code.
  template <class F>
  int take_loaned(F&& on) const {
    std::array<void*, kMaxTake> buffers{};
    std::array<dds_sample_info_t, kMaxTake> infos{};
    const int n = dds_take(this->entity_.get(), buffers.data(), infos.data(), kMaxTake, kMaxTake);
    for (int i = 0; i < n; ++i) on(*static_cast<const T*>(buffers[i]), infos[i]);
    if (n > 0) dds_return_loan(this->entity_.get(), buffers.data(), n);
    return n;
  }
};

/// One entity of kind E (Topic, Writer or Reader) for each type in T..., made together and found by type: a
/// station's topics, its writers or its readers. Each is empty until open() has made it.
template <template <class> class E, class... T>
class EntitySet {
 public:
  /// Makes each entity in the order of T...: `make(std::type_identity<U>{})` returns a Result<E<U>>, which is
  /// kept, and then `then(E<U>&)` returns a Status. Stops at the first error and returns it.
  template <class Make, class Then>
  Status open(Make&& make, Then&& then) {
    Status status;
    ((status = open_one<T>(make, then)) && ...);
    return status;
  }
  template <class Make>
  Status open(Make&& make) {
    return open(make, [](const auto&) { return ok(); });
  }
  template <class U>
  E<U>& get() {
    return *std::get<std::optional<E<U>>>(entities_);
  }
  template <class U>
  const E<U>& get() const {
    return *std::get<std::optional<E<U>>>(entities_);
  }

 private:
  template <class U, class Make, class Then>
  Status open_one(Make& make, Then& then) {
    Result<E<U>> made = make(std::type_identity<U>{});
    if (!made) return Error{made.error()};
    std::optional<E<U>>& slot = std::get<std::optional<E<U>>>(entities_);
    slot.emplace(made.take());
    return then(*slot);
  }

  std::tuple<std::optional<E<T>>...> entities_;
};

/// A waitset woken by data on readers (read conditions) or by a guard condition the caller triggers.
class WaitSet {
 public:
  static Result<WaitSet> create(dds_entity_t participant);
  /// Wakes the waitset when `reader` has unread data.
  Status attach_reader(dds_entity_t reader);
  /// Wakes the waitset when a reader matches or unmatches `writer` (reading the status clears it).
  Status attach_publication_matched(dds_entity_t writer);
  /// Wakes the waitset from another thread (no allocation): see trigger().
  dds_entity_t guard() const { return guard_.get(); }
  /// Triggers the guard condition; safe from any thread.
  void trigger() const { dds_set_guardcondition(guard_.get(), true); }
  /// Waits at most `timeout_ns`; clears the guard. Returns false on a Cyclone error.
  bool wait(std::int64_t timeout_ns);

 private:
  Entity waitset_;  ///< destroyed last: conditions detach from it first
  Entity guard_;
  std::array<Entity, 16> conditions_;
  std::size_t condition_count_ = 0;
};

}  // namespace lungar::dds
