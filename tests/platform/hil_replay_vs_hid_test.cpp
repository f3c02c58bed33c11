// Hardware-in-the-loop: a recorded tracker log is fed (a) through the replay source and (b) as reports of an
// emulated hidraw device through real hidapi. For every patient report (one frame each), the patient
// orientation, the force SH and checksums of the deformed positions (the vertex shader's own output, captured by
// transform feedback) must agree between (a) and (b), and with the committed expected output.
//
// Regenerate the expected output (after a deliberate change of the asset, the force model or the log) with
// tests/data/make_hil_data.sh, which reruns this test with LUNGAR_HIL_REGENERATE=1.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <mutex>
#include <sstream>
#include <thread>
#include <vector>

#include "drivers/tracker/tracker_config_toml.h"
#include "drivers/tracker_factory/tracker_factory.h"
#include "drivers/trk/trk_reader.h"
#include "platform/egl/egl_context.h"
#include "platform/runtime/gl_math.h"
#include "platform/runtime/patient_force.h"
#include "render/lung_drawable.h"
#include "render/renderer.h"
#include "sim/asset/asset_io.h"
#include "sim/force/gravity.h"
#include "umockdev_tracker.h"

using namespace lungar;

namespace {

const std::string kData = std::string(LUNGAR_SOURCE_DIR) + "/tests/data/";
const std::string kLog = kData + "upright_to_supine.trk";
const std::string kAsset = kData + "hil_lungs.lungbake";
const std::string kExpected = kData + "upright_to_supine.hil.csv";
constexpr double kTidalMl = 500.0;  // the volume change every frame is drawn at
constexpr int kForceShown = 4;      // force SH values per lung kept in the expected file

/// What one frame computed from one patient report.
struct FrameRecord {
  std::int64_t t_device_ns = 0;
  std::array<double, 4> q{};    ///< patient orientation, w x y z
  std::array<double, 3> g{};    ///< gravity in the lung frame
  std::vector<double> force;    ///< lungs x kForceShown
  double disp_normal_mm = 0;    ///< sum over vertices of (p' - p) . n
  double disp_weighted_mm = 0;  ///< sum over vertices of (p' - p) . (1, 2, 3)
};

struct Collector {
  std::mutex mutex;
  std::vector<drivers::PoseSample> patient;
  std::size_t all = 0;
  drivers::TrackerOptions options() {
    drivers::TrackerOptions o;
    o.on_sample = [this](const drivers::PoseSample& s) {
      std::lock_guard lock(mutex);
      ++all;
      if (s.role == drivers::Role::Patient) patient.push_back(s);
    };
    o.log = [](const std::string&) {};
    return o;
  }
  std::size_t count() {
    std::lock_guard lock(mutex);
    return all;
  }
};

template <typename Pred>
bool eventually(Pred pred, double seconds = 20.0) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (pred()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return pred();
}

class HardwareInTheLoop : public ::testing::Test {
 protected:
  void SetUp() override {
    auto loaded = sim::load_asset(kAsset);
    ASSERT_TRUE(loaded) << loaded.error();
    asset = std::move(*loaded);
    auto log = drivers::load_trk(kLog);
    ASSERT_TRUE(log) << log.error();
    records = log->records.size();
    auto t = drivers::tracker_config_from_toml(log->header.layout_toml, kLog);
    ASSERT_TRUE(t) << t.error();
    trackers = *t;
    auto ctx = platform::EglContext::headless();
    ASSERT_TRUE(ctx) << ctx.error();
    context = ctx.take();
    auto d = render::LungDrawable::create(asset);
    ASSERT_TRUE(d) << d.error();
    drawable.emplace(d.take());
    auto r = render::Renderer::create(*drawable);
    ASSERT_TRUE(r) << r.error();
    renderer.emplace(r.take());
  }

  /// The frame loop's step 2 and the shader's deformation for one patient pose (platform/runtime's own code).
  FrameRecord frame(const drivers::PoseSample& p) {
    FrameRecord f;
    f.t_device_ns = p.t_device_ns;
    f.q = p.orientation_wxyz;
    const Eigen::Quaterniond lung_q(
        platform::lung_to_world(platform::pose_isometry(p), Eigen::Isometry3d::Identity()).rotation());
    const Eigen::Vector3d g = sim::gravity_in_lung_frame(lung_q);
    f.g = {g.x(), g.y(), g.z()};
    const std::uint32_t c = asset.coefficients();
    std::vector<float> force(asset.lungs.size() * c);
    platform::patient_force_sh(asset, sim::PatientState::of(asset), sim::ForceMode::Exact, lung_q, force);
    std::vector<render::LungFrame> lungs(asset.lungs.size());
    for (std::size_t l = 0; l < lungs.size(); ++l) {
      lungs[l].force = std::span<const float>(force.data() + l * c, c);
      lungs[l].volume_change_ml = static_cast<float>(kTidalMl * asset.lungs[l].volume_share);
      for (int k = 0; k < kForceShown; ++k) f.force.push_back(force[l * c + static_cast<std::size_t>(k)]);
    }
    std::vector<float> xyz;
    const auto captured = renderer->capture_deformed(*drawable, lungs, xyz);
    EXPECT_TRUE(captured) << captured.error();
    for (std::size_t i = 0; i < asset.vertex_count() && 3 * i + 2 < xyz.size(); ++i) {
      double d[3];
      for (int a = 0; a < 3; ++a) d[a] = static_cast<double>(xyz[3 * i + a]) - asset.positions[3 * i + a];
      f.disp_normal_mm +=
          d[0] * asset.normals[3 * i] + d[1] * asset.normals[3 * i + 1] + d[2] * asset.normals[3 * i + 2];
      f.disp_weighted_mm += d[0] + 2 * d[1] + 3 * d[2];
    }
    return f;
  }

  std::vector<FrameRecord> frames(const std::vector<drivers::PoseSample>& patient) {
    std::vector<FrameRecord> out;
    for (const auto& p : patient) out.push_back(frame(p));
    return out;
  }

  sim::BakedAsset asset;
  std::size_t records = 0;
  drivers::TrackerConfig trackers;
  std::unique_ptr<platform::EglContext> context;
  std::optional<render::LungDrawable> drawable;
  std::optional<render::Renderer> renderer;
};

std::string to_csv(const std::vector<FrameRecord>& frames) {
  std::ostringstream o;
  o << "frame,t_device_ns,qw,qx,qy,qz,gx,gy,gz,force...,disp_normal_mm,disp_weighted_mm\n";
  char buf[64];
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const auto& f = frames[k];
    o << k << ',' << f.t_device_ns;
    for (double v : f.q) o << ',' << (std::snprintf(buf, sizeof buf, "%.9f", v), buf);
    for (double v : f.g) o << ',' << (std::snprintf(buf, sizeof buf, "%.9f", v), buf);
    for (double v : f.force) o << ',' << (std::snprintf(buf, sizeof buf, "%.9g", v), buf);
    o << ',' << (std::snprintf(buf, sizeof buf, "%.9g", f.disp_normal_mm), buf);
    o << ',' << (std::snprintf(buf, sizeof buf, "%.9g", f.disp_weighted_mm), buf) << '\n';
  }
  return o.str();
}

std::vector<std::vector<double>> read_csv(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::vector<double>> rows;
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream s(line);
    std::string cell;
    while (std::getline(s, cell, ',')) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

// Stated tolerances. Orientation and gravity come from the same bytes through the same decoder: identical between
// (a) and (b), and equal to the expected file to its printed precision. Force SH and the shader's output are
// float32: between (a) and (b) identical inputs give identical outputs; against the committed file, which another
// machine's rounding may have made, 1e-4 relative to the largest value of the frame.
constexpr double kPrintedTol = 2e-9;
constexpr double kRelTol = 1e-4;

void expect_close(const FrameRecord& a, const FrameRecord& b, double abs_q, double rel) {
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(a.q[k], b.q[k], abs_q) << "q" << k;
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(a.g[k], b.g[k], abs_q) << "g" << k;
  double scale = 0;
  for (double v : b.force) scale = std::max(scale, std::abs(v));
  ASSERT_EQ(a.force.size(), b.force.size());
  for (std::size_t k = 0; k < a.force.size(); ++k) EXPECT_NEAR(a.force[k], b.force[k], rel * scale) << "force " << k;
  EXPECT_NEAR(a.disp_normal_mm, b.disp_normal_mm, rel * std::abs(b.disp_normal_mm) + 1e-9);
  EXPECT_NEAR(a.disp_weighted_mm, b.disp_weighted_mm, rel * std::abs(b.disp_weighted_mm) + 1e-9);
}

}  // namespace

TEST_F(HardwareInTheLoop, ReplayAndEmulatedHidGiveTheSameFramesAsTheCommittedOutput) {
  if (!lungar::testing::UmockdevTracker::available()) GTEST_SKIP() << "not under umockdev-wrapper";

  // (a) replay, as fast as possible
  drivers::TrackerConfig rs = trackers;
  rs.source = drivers::TrackerSource::Replay;
  rs.replay_file = kLog;
  rs.replay_realtime = false;
  Collector via_replay;
  auto replay = drivers::make_tracker(rs, via_replay.options());
  ASSERT_TRUE(replay) << replay.error();
  ASSERT_TRUE(eventually([&] { return (*replay)->finished(); }));
  (*replay)->stop();

  // (b) the same reports written to an emulated hidraw device, read by real hidapi
  lungar::testing::UmockdevTracker device;
  lungar::testing::UmockdevTrackerSpec spec;
  spec.report_id = trackers.report.report_id;
  spec.length = trackers.report.length;
  ASSERT_TRUE(device.plug(spec)) << device.error();
  drivers::TrackerConfig hs = trackers;
  hs.source = drivers::TrackerSource::Hid;
  hs.hid.vendor_id = spec.vendor_id;
  hs.hid.product_id = spec.product_id;
  Collector via_hid;
  auto hid = drivers::make_tracker(hs, via_hid.options());
  ASSERT_TRUE(hid) << hid.error();
  ASSERT_TRUE(eventually([&] { return (*hid)->stats().opens >= 1; }));
  auto log = drivers::load_trk(kLog);
  ASSERT_TRUE(log);
  std::size_t written = 0;
  for (const auto& rec : log->records) {
    // The emulated node is a pseudo-terminal with a 4 KiB buffer: keep at most 64 reports in flight.
    ASSERT_TRUE(eventually([&] { return written < via_hid.count() + 64; }));
    ASSERT_TRUE(device.write(rec.report));
    ++written;
  }
  ASSERT_TRUE(eventually([&] { return via_hid.count() >= records; })) << via_hid.count() << " of " << records;
  (*hid)->stop();
  EXPECT_EQ((*hid)->stats().malformed, 0u);

  ASSERT_GT(via_replay.patient.size(), 100u);
  ASSERT_EQ(via_replay.patient.size(), via_hid.patient.size());
  const auto a = frames(via_replay.patient);
  const auto b = frames(via_hid.patient);
  for (std::size_t k = 0; k < a.size(); ++k) {
    SCOPED_TRACE("frame " + std::to_string(k));
    EXPECT_EQ(a[k].t_device_ns, b[k].t_device_ns);
    expect_close(a[k], b[k], 0.0, 0.0);  // same inputs, same code: identical
  }

  // The turn happened: upright at the start (gravity inferior, -z), supine at the end (gravity posterior, +y).
  EXPECT_NEAR(a.front().g[2], -1.0, 1e-6);
  EXPECT_NEAR(a.back().g[1], 1.0, 1e-6);
  EXPECT_NE(a.front().disp_weighted_mm, a.back().disp_weighted_mm);

  if (std::getenv("LUNGAR_HIL_REGENERATE")) {
    std::ofstream(kExpected) << to_csv(a);
    GTEST_SKIP() << "wrote " << kExpected;
  }
  const auto expected = read_csv(kExpected);
  ASSERT_EQ(expected.size(), a.size()) << kExpected << " (regenerate with tests/data/make_hil_data.sh)";
  for (std::size_t k = 0; k < a.size(); ++k) {
    SCOPED_TRACE("frame " + std::to_string(k));
    const auto& row = expected[k];
    ASSERT_EQ(row.size(), 2 + 4 + 3 + a[k].force.size() + 2);
    FrameRecord e;
    e.t_device_ns = static_cast<std::int64_t>(row[1]);
    for (int i = 0; i < 4; ++i) e.q[i] = row[2 + i];
    for (int i = 0; i < 3; ++i) e.g[i] = row[6 + i];
    e.force.assign(row.begin() + 9, row.end() - 2);
    e.disp_normal_mm = row[row.size() - 2];
    e.disp_weighted_mm = row.back();
    EXPECT_EQ(a[k].t_device_ns, e.t_device_ns);
    expect_close(a[k], e, kPrintedTol, kRelTol);
  }
}
