/// @file demo_asset_test.cpp
/// @brief The demo's asset: the shipped CT label map baked by the lungar-bake executable (a child process: the
///        runtime links no ITK) into the cache once, then loaded from it; keyed by the bake revision; the
///        procedural pair on --procedural or when no bake tool is found; a failed bake is one error and no cache; a
///        bake stopped (Ctrl-C) leaves nothing in the cache.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "platform/app/demo_asset.h"

namespace lungar::platform {
namespace {

namespace fs = std::filesystem;

class DemoAsset : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("lungar_demo_asset_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    options_.cache_dir = (dir_ / "cache").string();
    options_.nodes = 4000;  // small: the shipped map is read whole, the surfaces are coarse
    options_.bands = 4;
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::vector<std::string> cached() const {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(options_.cache_dir, ec)) names.push_back(e.path().filename().string());
    return names;
  }
  fs::path dir_;
  DemoAssetOptions options_;
  std::vector<std::string> log_;
  std::function<void(const std::string&)> log_to_ = [this](const std::string& l) { log_.push_back(l); };
};

TEST_F(DemoAsset, CtLungsAreBakedOnceByTheBakeToolThenLoadedFromTheCache) {
  auto first = load_drawn_asset("", options_, log_to_);
  ASSERT_TRUE(first) << first.error();
  EXPECT_EQ(first->name.rfind("ct-10002K_INSP_STD_BWH_COPD_leftLungRightLung-", 0), 0u) << first->name;
  EXPECT_NE(first->name.find("-b" + std::to_string(sim::kBakeRevision) + ".lungbake"), std::string::npos)
      << "a new bake revision is a new cache entry: " << first->name;
  ASSERT_EQ(first->asset.lungs.size(), 2u);
  EXPECT_EQ(first->asset.lungs[0].name, "right");
  EXPECT_LT(first->asset.lungs[0].centre[0], 0) << "LPS: the right lung at -x";
  EXPECT_GT(first->asset.lungs[1].centre[0], 0);
  EXPECT_NEAR(first->asset.vertex_count(), 4000, 200);
  EXPECT_FALSE(first->asset.has_transfer_rows());
  ASSERT_EQ(cached(), std::vector<std::string>{first->name});
  const auto baked_at = fs::last_write_time(fs::path(options_.cache_dir) / first->name);

  log_.clear();
  auto second = load_drawn_asset("", options_, log_to_);
  ASSERT_TRUE(second) << second.error();
  EXPECT_EQ(second->name, first->name);
  EXPECT_EQ(fs::last_write_time(fs::path(options_.cache_dir) / first->name), baked_at) << "loaded, not baked again";
  for (const std::string& l : log_) EXPECT_EQ(l.find("baking"), std::string::npos) << l;
}

TEST_F(DemoAsset, ProceduralOnRequestAndWhenNoBakeToolIsFound) {
  options_.procedural = true;
  auto p = load_drawn_asset("", options_, log_to_);
  ASSERT_TRUE(p) << p.error();
  EXPECT_EQ(p->name.rfind("procedural-", 0), 0u) << p->name;

  options_.procedural = false;
  options_.bake_tool = (dir_ / "no-such-lungar-bake").string();
  log_.clear();
  auto fallback = load_drawn_asset("", options_, log_to_);
  ASSERT_TRUE(fallback) << fallback.error();
  EXPECT_EQ(fallback->name.rfind("procedural-", 0), 0u);
  ASSERT_FALSE(log_.empty());
  EXPECT_NE(log_.front().find("no lungar-bake found"), std::string::npos) << log_.front();
}

TEST_F(DemoAsset, AFailedBakeIsOneErrorAndCachesNothing) {
  options_.data_dir = (dir_ / "data").string();
  fs::create_directories(dir_ / "data" / "lungs");
  std::ofstream(dir_ / "data" / "lungs" / kDemoLabelMap) << "NRRD0004\ntype: what\n";  // a broken map
  auto r = load_drawn_asset("", options_, log_to_);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().find("demo asset: "), std::string::npos) << r.error();
  EXPECT_NE(r.error().find("lungar-bake: failed"), std::string::npos) << r.error();
  EXPECT_TRUE(cached().empty());
}

TEST_F(DemoAsset, AStoppedBakeEndsAtOnceAndLeavesNothingPartial) {
  // A bake tool that has begun its output and would go on for 30 s, deaf to SIGTERM (a long factorisation): the stop
  // must still end it and remove what it wrote, for the CT lungs and for the procedural pair alike.
  fs::create_directories(dir_);
  const fs::path tool = dir_ / "slow-lungar-bake";
  std::ofstream(tool)
      << "#!/bin/sh\ntrap '' TERM INT\nwhile [ $# -gt 0 ]; do [ \"$1\" = --out ] && out=$2; shift; done\n"
         "echo half > \"$out.partial-abc123\"\nexec sleep 30\n";
  fs::permissions(tool, fs::perms::owner_all);
  options_.bake_tool = tool.string();
  for (const bool procedural : {false, true}) {
    SCOPED_TRACE(procedural ? "procedural" : "CT");
    options_.procedural = procedural;
    std::atomic<bool> stop{false};
    options_.stop = &stop;
    std::thread ctrl_c([&] {  // once the bake has written part of its output
      while (!stop.load()) {
        for (const std::string& name : cached())
          if (name.find(".partial-") != std::string::npos) stop.store(true);
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
      }
    });
    auto r = load_drawn_asset("", options_, log_to_);
    stop.store(true);
    ctrl_c.join();
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().find("stopped before the bake finished; nothing was cached"), std::string::npos) << r.error();
    EXPECT_TRUE(cached().empty()) << cached().front();
  }
}

TEST_F(DemoAsset, AConfiguredAssetIsDrawnAsItIsAndNamed) {
  const std::string path = std::string(LUNGAR_SOURCE_DIR) + "/tests/data/hil_lungs.lungbake";
  auto r = load_drawn_asset(path, options_, log_to_);
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r->name, path);
  EXPECT_TRUE(cached().empty());
}

}  // namespace
}  // namespace lungar::platform
