/// @file stations_test.h
/// @brief Test support: the fixture of a test that runs classroom stations as processes.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "sync_test_support.h"

namespace lungar::testing {

/// What a station process runs: the runtime, the classroom's station settings and the small HIL lungs.
inline const std::string kLungar = std::string(LUNGAR_BINARY_DIR) + "/platform/lungar";
inline const std::string kConfig = std::string(LUNGAR_SOURCE_DIR) + "/config/classroom-station.toml";
inline const std::string kAsset = std::string(LUNGAR_SOURCE_DIR) + "/tests/data/hil_lungs.lungbake";

/// A test of stations run as processes: a folder of its own for their logs and JSON files, and a DDS domain and
/// a classroom (`room_tag` and the process id) of its own, so that tests running at once never meet.
class StationsTest : public ::testing::Test {
 protected:
  explicit StationsTest(std::string room_tag) : room_tag_(std::move(room_tag)) {}
  void SetUp() override {
    dir = test_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    domain = std::to_string(test_domain());
    room = test_classroom(room_tag_);
  }
  /// The JSON file (--report-json, --stats-json) that `station` wrote into dir.
  nlohmann::json json_of(const std::string& station) const {
    std::ifstream in(dir / (station + ".json"));
    return nlohmann::json::parse(in);
  }

  std::filesystem::path dir;
  std::string domain, room;

 private:
  std::string room_tag_;
};

}  // namespace lungar::testing
