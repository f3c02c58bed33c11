// Tests of drivers/igtl's pure decoder: messages packed by libopenigtlink's own classes (TRANSFORM, TDATA,
// QTDATA) come out as the poses they carry, and each way a message is wrong is told apart and carries no pose.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "drivers/igtl/igtl_decoder.h"
#include "drivers/igtl/igtl_messages.h"
#include "drivers/tracker/tracker_config.h"

using namespace lungar;
using namespace lungar::drivers;

namespace {

constexpr double kTol = 1e-6;  // the equality: float matrices decode to what was sent within 1e-6

Eigen::Matrix4d pose_matrix(const Eigen::Vector3d& p_mm, const Eigen::Quaterniond& q) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = q.normalized().toRotationMatrix();
  m.topRightCorner<3, 1>() = p_mm;
  return m;
}

/// What the sender put on the wire: the matrix as float, the rotation's quaternion taken from those floats.
struct Sent {
  Eigen::Vector3d position;
  Eigen::Quaterniond orientation;
};
Sent as_sent(const Eigen::Matrix4d& m) {
  const Eigen::Matrix4d f = m.cast<float>().cast<double>();
  return {f.topRightCorner<3, 1>(), Eigen::Quaterniond(Eigen::Matrix3d(f.topLeftCorner<3, 3>())).normalized()};
}

void expect_pose(const PoseSample& got, Role role, const Sent& want, double scale = 1.0) {
  EXPECT_EQ(got.role, role);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(got.position_mm[i], want.position[i] * scale, kTol * scale) << "axis " << i;
  EXPECT_LT(got.orientation().angularDistance(want.orientation), kTol);
  EXPECT_NEAR(got.orientation().norm(), 1.0, 1e-12);
}

IgtlLayout layout(const TrackerConfig& t = {}) {
  auto l = make_igtl_layout(t.igtl, t);
  EXPECT_TRUE(l) << l.error();
  return l ? *l : IgtlLayout{};
}

const Eigen::Matrix4d kPatient = pose_matrix(
    {12.5, -340.25, 1012.125}, Eigen::Quaterniond(Eigen::AngleAxisd(-1.2, Eigen::Vector3d(1, 0.2, 0).normalized())));
const Eigen::Matrix4d kHead = pose_matrix(
    {-30.0, -700.5, 1300.75}, Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d(0.3, -1, 0.5).normalized())));

/// Rewrites the header's 12-byte type name (the header is not covered by the CRC).
void set_type(std::vector<std::uint8_t>& msg, const char* type) {
  std::memset(msg.data() + 2, 0, 12);
  std::memcpy(msg.data() + 2, type, std::strlen(type));
}

}  // namespace

TEST(IgtlDecode, TransformOfAMappedDeviceIsItsPoseWithItsTimestamp) {
  const auto msg =
      igtl_transform_message("PatientToTracker", kPatient, IgtlTime::from_ns(1'700'000'000'250'000'000ull));
  ASSERT_EQ(msg.size(), kIgtlHeaderBytes + 48);
  const DecodedReport d = decode_igtl_message(msg, layout());
  ASSERT_EQ(d.error, DecodeError::None) << to_string(d.error);
  ASSERT_EQ(d.count, 1);
  expect_pose(d.poses[0], Role::Patient, as_sent(kPatient));
  ASSERT_TRUE(d.has_time);
  EXPECT_EQ(d.time_bits, 64);
  // 2^-32 s fractions: the nanoseconds come back within one fraction step.
  EXPECT_NEAR(static_cast<double>(d.device_ticks), 1'700'000'000'250'000'000.0, 1.0);
  const DecodedReport head = decode_igtl_message(igtl_transform_message("HeadToTracker", kHead, {}), layout());
  ASSERT_EQ(head.count, 1);
  expect_pose(head.poses[0], Role::Head, as_sent(kHead));
  EXPECT_FALSE(head.has_time);  // a zero timestamp: arrival time stands in
}

TEST(IgtlDecode, TdataAndQtdataCarrySeveralToolsEachToItsRole) {
  const std::vector<IgtlTool> tools = {
      {"HeadToTracker", kHead}, {"ProbeToTracker", kHead}, {"PatientToTracker", kPatient}};
  for (bool quaternion : {false, true}) {
    SCOPED_TRACE(quaternion ? "QTDATA" : "TDATA");
    const auto msg = quaternion ? igtl_qtdata_message("Tracker", tools, {}) : igtl_tdata_message("Tracker", tools, {});
    const DecodedReport d = decode_igtl_message(msg, layout());
    ASSERT_EQ(d.error, DecodeError::None) << to_string(d.error);
    ASSERT_EQ(d.count, 2);
    expect_pose(d.poses[0], Role::Head, as_sent(kHead));
    expect_pose(d.poses[1], Role::Patient, as_sent(kPatient));
    EXPECT_EQ(d.ignored, 1);  // the probe feeds no role
    EXPECT_STREQ(d.ignored_name.data(), "ProbeToTracker");
  }
}

TEST(IgtlDecode, ConfiguredNamesScaleAndAxisRemapApply) {
  TrackerConfig t;
  t.igtl.patient = "Reference";
  t.igtl.scale = 1000.0;  // a sender in metres
  t.axis_remap = "x,-z,y";
  t.world_offset_mm = {0, 0, 500};
  const Eigen::Matrix4d metres =
      pose_matrix({0.25, -0.5, 0.125}, Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ())));
  EXPECT_EQ(decode_igtl_message(igtl_transform_message("PatientToTracker", metres, {}), layout(t)).count, 0);
  const DecodedReport d = decode_igtl_message(igtl_transform_message("Reference", metres, {}), layout(t));
  ASSERT_EQ(d.count, 1);
  Eigen::Matrix3d m;
  m << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  const Sent s = as_sent(metres);
  const Eigen::Vector3d want = m * s.position * 1000.0 + Eigen::Vector3d(0, 0, 500);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(d.poses[0].position_mm[i], want[i], 1e-3);
  const Eigen::Matrix3d r = m * s.orientation.toRotationMatrix() * m.transpose();
  EXPECT_LT(d.poses[0].orientation().angularDistance(Eigen::Quaterniond(r)), kTol);
}

TEST(IgtlDecode, EachWayAMessageIsWrongHasItsReasonAndNoPose) {
  const IgtlLayout l = layout();
  const auto good = igtl_transform_message("PatientToTracker", kPatient, {});
  ASSERT_EQ(decode_igtl_message(good, l).error, DecodeError::None);
  auto expect = [&](const std::vector<std::uint8_t>& msg, DecodeError want, const char* what) {
    const DecodedReport d = decode_igtl_message(msg, l);
    EXPECT_EQ(d.error, want) << what << ": got " << to_string(d.error);
    EXPECT_EQ(d.count, 0) << what;
  };
  expect(igtl_status_message("PatientToTracker", {}), DecodeError::UnknownType, "STATUS message");
  auto bad = good;
  bad.back() ^= 0x01;  // one bit of the translation
  expect(bad, DecodeError::BadCrc, "flipped body bit");
  bad = good;
  bad.pop_back();
  expect(bad, DecodeError::Truncated, "body one byte short");
  expect(std::vector<std::uint8_t>(good.begin(), good.begin() + 40), DecodeError::Truncated, "half a header");
  bad = good;
  bad.push_back(0);
  expect(bad, DecodeError::Truncated, "one byte too many");
  bad = igtl_tdata_message("Tracker", std::vector<IgtlTool>{{"PatientToTracker", kPatient}}, {});
  set_type(bad, "TRANSFORM");  // 70 bytes are no TRANSFORM body
  expect(bad, DecodeError::WrongLength, "TDATA body under a TRANSFORM header");
  bad = good;
  bad[1] = 2;  // header version 2 (OpenIGTLink 3's extended header)
  expect(bad, DecodeError::UnsupportedVersion, "header version 2");
  Eigen::Matrix4d scaled = kPatient;
  scaled.topLeftCorner<3, 3>() *= 1.1;  // a scaling calibration (ImageToProbe), not a pose
  expect(igtl_transform_message("PatientToTracker", scaled, {}), DecodeError::NotRigid, "scaled rotation");
  Eigen::Matrix4d mirror = kPatient;
  mirror.col(0) = -mirror.col(0);  // orthonormal, determinant -1
  expect(igtl_transform_message("PatientToTracker", mirror, {}), DecodeError::NotRigid, "mirror");
  Eigen::Matrix4d nan = kPatient;
  nan(1, 3) = std::numeric_limits<double>::quiet_NaN();
  expect(igtl_transform_message("PatientToTracker", nan, {}), DecodeError::NotFinite, "NaN translation");
  const std::vector<IgtlTool> one_bad = {{"HeadToTracker", kHead}, {"PatientToTracker", scaled}};
  expect(igtl_tdata_message("Tracker", one_bad, {}), DecodeError::NotRigid, "one bad tool spoils the message");
}

TEST(IgtlDecode, RigidityToleranceIsTheConfiguredOne) {
  Eigen::Matrix4d nearly = kPatient;
  nearly.topLeftCorner<3, 3>() *= 1.0004;  // |R^T R - I| ~ 8e-4
  EXPECT_EQ(decode_igtl_message(igtl_transform_message("PatientToTracker", nearly, {}), layout()).error,
            DecodeError::None);
  TrackerConfig t;
  t.igtl.rigid_tolerance = 5e-4;
  EXPECT_EQ(decode_igtl_message(igtl_transform_message("PatientToTracker", nearly, {}), layout(t)).error,
            DecodeError::NotRigid);
}

TEST(IgtlDecode, HeaderInfoSaysWhichBodiesAreWorthReading) {
  const auto good = igtl_transform_message("PatientToTracker", kPatient, {});
  auto info = igtl_header_info(std::span<const std::uint8_t, kIgtlHeaderBytes>(good.data(), kIgtlHeaderBytes));
  EXPECT_TRUE(info.readable);
  EXPECT_EQ(info.body_size, 48u);
  const auto status = igtl_status_message("x", {});
  info = igtl_header_info(std::span<const std::uint8_t, kIgtlHeaderBytes>(status.data(), kIgtlHeaderBytes));
  EXPECT_FALSE(info.readable);
  EXPECT_EQ(info.body_size, status.size() - kIgtlHeaderBytes);  // to be skipped unread
}

TEST(IgtlDecode, LayoutErrorsNameTheKey) {
  TrackerConfig t;
  t.igtl.head = "ThisNameIsLongerThan20";
  EXPECT_EQ(make_igtl_layout(t.igtl, t).error(),
            "trackers.igtl.head: expected at most 20 characters, got \"ThisNameIsLongerThan20\"");
  t = {};
  t.axis_remap = "x,y";
  EXPECT_EQ(make_igtl_layout(t.igtl, t).error(), "trackers.axis_remap: expected a signed permutation of x,y,z");
  for (double scale : {0.0, 1e7}) {  // each end of the range is outside it
    t = {};
    t.igtl.scale = scale;
    EXPECT_EQ(make_igtl_layout(t.igtl, t).error(), "trackers.igtl.scale: expected a positive scale") << scale;
  }
  t = {};
  t.igtl.rigid_tolerance = 0.0;
  EXPECT_EQ(make_igtl_layout(t.igtl, t).error(), "trackers.igtl.rigid_tolerance: expected a positive tolerance");
}
