/// @file room_support.h
/// @brief Test support for classroom stations in one process: a station's [sync] on this process's loopback
/// classroom, and small procedural lungs baked once for the suite (what an instructor draws, and checks a change of
/// its lungs against).
#pragma once

#include <memory>
#include <string>

#include "drivers/classroom/sync_settings.h"
#include "sim/bake/bake.h"
#include "sync_test_support.h"

namespace lungar::testing {

/// [sync] for a station of `room` on the loopback domain of this process, named "instructor" or "trainee".
inline classroom::SyncSettings room_sync_settings(classroom::SyncRole role, const std::string& room) {
  classroom::SyncSettings s;
  s.role = role;
  s.classroom = room;
  s.domain = static_cast<int>(test_domain());
  s.cyclonedds_xml = kLoopbackXml;
  s.station = role == classroom::SyncRole::Instructor ? "instructor" : "trainee";
  return s;
}

/// A procedural pair of 3,000 nodes, baked once.
inline std::shared_ptr<const sim::BakedAsset> procedural_lungs() {
  static const auto a = [] {
    sim::BakeOptions options;
    options.threads = 2;
    options.evaluate = false;
    options.transfer_rows = false;
    return std::make_shared<const sim::BakedAsset>(sim::bake_procedural(3000, 7, options, nullptr).take().asset);
  }();
  return a;
}

}  // namespace lungar::testing
