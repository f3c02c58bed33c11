// Tests of drivers/decode: every field type, both endiannesses, component orders and signs, Euler sequences,
// axis remaps (mirrors included), station and fixed-offset sensors, and each way a report is malformed.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "drivers/decode/decoder.h"
#include "drivers/decode/encoder.h"
#include "drivers/tracker/tracker_config.h"

using namespace lungar;
using namespace lungar::drivers;

namespace {

constexpr double kPosTolMm = 0.01;   // i32 at 0.01 mm per unit: half a unit of rounding
constexpr double kRotTolRad = 2e-4;  // Q2.14 quaternion components: ~6e-5 each

/// A hand-built report: bytes placed one by one, so the decoder is checked against the layout as documented.
struct Bytes {
  std::vector<std::uint8_t> b;
  explicit Bytes(std::size_t n) : b(n, 0) {}
  void u8(std::size_t at, std::uint8_t v) { b[at] = v; }
  void u16(std::size_t at, std::uint16_t v, bool big) {
    b[at + (big ? 0 : 1)] = static_cast<std::uint8_t>(v >> 8);
    b[at + (big ? 1 : 0)] = static_cast<std::uint8_t>(v);
  }
  void u32(std::size_t at, std::uint32_t v, bool big) {
    for (int k = 0; k < 4; ++k) b[at + (big ? 3 - k : k)] = static_cast<std::uint8_t>(v >> (8 * k));
  }
  void f32(std::size_t at, float v, bool big) { u32(at, std::bit_cast<std::uint32_t>(v), big); }
};

/// A default-layout report (32 bytes) with its id and the head's station byte set, the rest zero.
Bytes head_report() {
  Bytes r(32);
  r.u8(0, 1);
  r.u8(1, 1);
  return r;
}

ReportLayout layout_of(const TrackerConfig& t) {
  auto r = make_layout(t);
  EXPECT_TRUE(r) << r.error();
  return r ? *r : ReportLayout{};
}

/// Rotation by `angle_rad` about coordinate axis 0, 1 or 2.
Eigen::Quaterniond about(int axis, double angle_rad) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle_rad, Eigen::Vector3d::Unit(axis)));
}

PoseSample pose(Role role, const Eigen::Vector3d& p, const Eigen::Quaterniond& q) {
  PoseSample d;
  d.role = role;
  d.set_position(p);
  d.set_orientation(q.normalized());
  return d;
}

void expect_same_pose(const PoseSample& got, const PoseSample& want, double pos_tol = kPosTolMm,
                      double rot_tol = kRotTolRad) {
  EXPECT_EQ(got.role, want.role);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(got.position_mm[i], want.position_mm[i], pos_tol) << "axis " << i;
  EXPECT_LT(got.orientation().angularDistance(want.orientation()), rot_tol);
}

}  // namespace

TEST(Decode, DefaultLayoutByHand) {
  const TrackerConfig t;  // 32 bytes: id 1, station, u32 time, 3 x i32 0.01 mm, 4 x Q2.14 w,x,y,z
  const ReportLayout l = layout_of(t);
  Bytes r(32);
  r.u8(0, 1);
  r.u8(1, 2);  // patient
  r.u32(2, 123456, false);
  r.u32(6, static_cast<std::uint32_t>(12345), false);     // 123.45 mm
  r.u32(10, static_cast<std::uint32_t>(-2000), false);    // -20 mm
  r.u32(14, static_cast<std::uint32_t>(100000), false);   // 1000 mm
  r.u16(18, 11585, false);                                // w = cos 45 deg in Q2.14
  r.u16(20, 11585, false);                                // x
  const DecodedReport d = decode_report(r.b, l);
  ASSERT_EQ(d.error, DecodeError::None);
  ASSERT_EQ(d.count, 1);
  EXPECT_TRUE(d.has_time);
  EXPECT_EQ(d.device_ticks, 123456u);
  expect_same_pose(d.poses[0], pose(Role::Patient, {123.45, -20, 1000}, about(0, M_PI / 2)));
}

TEST(Decode, EveryFieldTypeInBothEndiannesses) {
  const FieldType types[] = {FieldType::I16, FieldType::I32, FieldType::F32,
                                     FieldType::Fixed16, FieldType::Fixed32};
  for (bool big : {false, true}) {
    for (FieldType pt : types) {
      for (FieldType ot : types) {
        SCOPED_TRACE(std::string(to_string(pt)) + " / " + to_string(ot) + (big ? " big" : " little"));
        TrackerConfig t;
        t.report.endian = big ? Endian::Big : Endian::Little;
        t.report.position_type = pt;
        // Ranges that hold 1234 mm: i16 in 0.1 mm, Q11.4 in mm, i32 in 0.01 mm, Q23.8 in 0.01 mm, f32 in mm.
        t.report.position_frac_bits = pt == FieldType::Fixed16 ? 4 : pt == FieldType::Fixed32 ? 8 : 0;
        t.report.position_scale = pt == FieldType::I16 ? 0.1
                                  : (pt == FieldType::F32 || pt == FieldType::Fixed16) ? 1.0
                                                                                                      : 0.01;
        t.report.orientation_type = ot;
        t.report.orientation_frac_bits = ot == FieldType::Fixed16 ? 14 : ot == FieldType::Fixed32 ? 30 : 0;
        t.report.orientation_scale =
            ot == FieldType::I16 ? 1.0 / 16384 : ot == FieldType::I32 ? 1.0 / (1 << 30) : 1.0;
        t.report.length = 48;
        t.report.orientation_offset = 12;
        const ReportLayout l = layout_of(t);
        // Hand-encode the raw values of position (100.5, -42.25, 1234.0) mm and a 30-degree turn about z.
        const std::array<double, 3> pos = {100.5, -42.25, 1234.0};
        const Eigen::Quaterniond q = about(2, M_PI / 6);
        const std::array<double, 4> wxyz = {q.w(), q.x(), q.y(), q.z()};
        Bytes r(48);
        r.u8(0, 1);
        r.u8(1, 1);
        auto put = [&](std::size_t at, FieldType type, int frac, double scale, double value) {
          const double raw = std::ldexp(value / scale, frac);
          switch (type) {
            case FieldType::I16:
            case FieldType::Fixed16:
              r.u16(at, static_cast<std::uint16_t>(static_cast<std::int16_t>(std::lround(raw))), big);
              return 2;
            case FieldType::I32:
            case FieldType::Fixed32:
              r.u32(at, static_cast<std::uint32_t>(static_cast<std::int32_t>(std::llround(raw))), big);
              return 4;
            case FieldType::F32: r.f32(at, static_cast<float>(raw), big); return 4;
            case FieldType::None: return 0;
          }
          return 0;
        };
        std::size_t at = 6;
        for (double v : pos) at += put(at, pt, t.report.position_frac_bits, t.report.position_scale, v);
        at = 18;
        for (double v : wxyz) at += put(at, ot, t.report.orientation_frac_bits, t.report.orientation_scale, v);
        const DecodedReport d = decode_report(r.b, l);
        ASSERT_EQ(d.error, DecodeError::None) << to_string(d.error);
        ASSERT_EQ(d.count, 1);
        // Half a unit of the type's resolution, plus rounding: 0.05 mm (i16), 1/32 mm (Q11.4), 0.005 mm (i32).
        const double pos_tol = pt == FieldType::I16 ? 0.0501 : pt == FieldType::Fixed16 ? 0.0313 : 0.005;
        const double rot_tol = ot == FieldType::I16 || ot == FieldType::Fixed16 ? kRotTolRad : 1e-6;
        expect_same_pose(d.poses[0], pose(Role::Head, Eigen::Vector3d(pos.data()), q), pos_tol, rot_tol);
      }
    }
  }
}

TEST(Decode, QuaternionOrderAndSignsFollowTheComponentList) {
  TrackerConfig t;
  t.report.orientation_components = "x,y,z,w";
  t.report.position_components = "-y,x,z";  // the device sends -y first, then x, then z
  const ReportLayout l = layout_of(t);
  Bytes r(32);
  r.u8(0, 1);
  r.u8(1, 1);
  r.u32(6, static_cast<std::uint32_t>(-500), false);  // -y = -5 mm -> y = 5
  r.u32(10, 700, false);                              // x = 7
  r.u32(14, 900, false);                              // z = 9
  const Eigen::Quaterniond q = about(1, 0.3);
  r.u16(18, static_cast<std::uint16_t>(std::lround(q.x() * 16384)), false);  // x first
  r.u16(20, static_cast<std::uint16_t>(std::lround(q.y() * 16384)), false);
  r.u16(22, static_cast<std::uint16_t>(std::lround(q.z() * 16384)), false);
  r.u16(24, static_cast<std::uint16_t>(std::lround(q.w() * 16384)), false);  // w last
  const DecodedReport d = decode_report(r.b, l);
  ASSERT_EQ(d.error, DecodeError::None);
  expect_same_pose(d.poses[0], pose(Role::Head, {7, 5, 9}, q));
}

TEST(Decode, EulerSequencesMatchTheirRotationProducts) {
  const char* sequences[] = {"zyx", "xyz", "yxz", "zxy", "xzy", "yzx"};
  for (const char* seq : sequences) {
    SCOPED_TRACE(seq);
    TrackerConfig t;
    t.report.orientation = OrientationKind::Euler;
    t.report.orientation_components = "z,y,-x";  // angles about z, y, then minus the angle about x
    t.report.orientation_type = FieldType::F32;
    t.report.orientation_frac_bits = 0;
    t.report.euler_sequence = seq;
    const ReportLayout l = layout_of(t);
    const double az = 40, ay = -25, ax = 60;  // degrees
    Bytes r(32);
    r.u8(0, 1);
    r.u8(1, 1);
    r.f32(18, static_cast<float>(az), false);
    r.f32(22, static_cast<float>(ay), false);
    r.f32(26, static_cast<float>(-ax), false);
    const DecodedReport d = decode_report(r.b, l);
    ASSERT_EQ(d.error, DecodeError::None);
    const double rad[3] = {ax * M_PI / 180, ay * M_PI / 180, az * M_PI / 180};
    const int a = seq[0] - 'x', b = seq[1] - 'x', c = seq[2] - 'x';
    const Eigen::Quaterniond want = about(a, rad[a]) * about(b, rad[b]) * about(c, rad[c]);
    expect_same_pose(d.poses[0], pose(Role::Head, {0, 0, 0}, want), kPosTolMm, 1e-6);
  }
}

TEST(Decode, AxisRemapIsAChangeOfBasisEvenForAMirror) {
  for (const char* remap : {"x,-z,y", "-x,y,z", "y,x,z", "z,x,y"}) {
    SCOPED_TRACE(remap);
    TrackerConfig ident;
    TrackerConfig t;
    t.axis_remap = remap;
    t.world_offset_mm = {10, 20, 30};
    const ReportLayout li = layout_of(ident), lr = layout_of(t);
    std::array<std::uint8_t, 32> buf{};
    const PoseSample device = pose(Role::Head, {100, 200, 300}, about(2, 0.5));
    encode_report(li, std::span<const PoseSample>(&device, 1), 0, buf);  // tracker-frame bytes
    const DecodedReport d = decode_report(buf, lr);
    ASSERT_EQ(d.error, DecodeError::None);
    // Expected: p' = M p + offset; R' = M R M^T.
    const auto axes = *parse_signed_axes(remap, "xyz");
    Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
    for (int i = 0; i < 3; ++i) m(i, axes[i].index) = axes[i].sign;
    const Eigen::Matrix3d want = m * device.orientation().toRotationMatrix() * m.transpose();
    const Eigen::Matrix3d got = d.poses[0].orientation().toRotationMatrix();
    const Eigen::Vector3d p = m * device.position() + Eigen::Vector3d(t.world_offset_mm.data());
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(d.poses[0].position_mm[i], p[i], kPosTolMm);
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(got(i, j), want(i, j), 1e-3) << i << "," << j;
    }
  }
}

TEST(Decode, FixedOffsetSensorsShareOneUnnumberedReport) {
  TrackerConfig t;
  t.report.report_id = -1;
  t.report.station_offset = -1;
  t.report.time_offset = 48;
  t.report.time_bits = 16;
  t.report.length = 50;
  t.head = {true, 0, 0, {}};
  t.patient = {true, 0, 24, {}};
  const ReportLayout l = layout_of(t);
  const std::array<PoseSample, 2> poses = {pose(Role::Head, {1, 2, 3}, about(0, 0.1)),
                                            pose(Role::Patient, {-4, -5, 6}, about(1, -0.2))};
  std::array<std::uint8_t, 50> buf{};
  ASSERT_TRUE(encode_report(l, poses, 0xBEEF, buf));
  const DecodedReport d = decode_report(buf, l);
  ASSERT_EQ(d.error, DecodeError::None);
  ASSERT_EQ(d.count, 2);
  EXPECT_EQ(d.device_ticks, 0xBEEFu);
  expect_same_pose(d.poses[0], poses[0]);
  expect_same_pose(d.poses[1], poses[1]);
}

TEST(Decode, EncoderRoundTripsThroughEveryConvention) {
  TrackerConfig t;
  t.report.endian = Endian::Big;
  t.report.orientation = OrientationKind::Euler;
  t.report.orientation_components = "y,-x,z";
  t.report.orientation_type = FieldType::Fixed32;
  t.report.orientation_frac_bits = 16;
  t.report.euler_sequence = "yxz";
  t.axis_remap = "-y,x,z";
  const ReportLayout l = layout_of(t);
  for (double a = -3.0; a <= 3.0; a += 0.37) {
    const PoseSample p = pose(Role::Patient, {a * 100, -a * 50, 1000 + a},
                               about(2, a) * about(0, 0.4 * a) * about(1, 0.3));
    std::array<std::uint8_t, 32> buf{};
    ASSERT_TRUE(encode_report(l, std::span<const PoseSample>(&p, 1), 7, buf));
    const DecodedReport d = decode_report(buf, l);
    ASSERT_EQ(d.error, DecodeError::None);
    expect_same_pose(d.poses[0], p, kPosTolMm, 1e-4);
  }
}

TEST(Decode, MalformedReportsAreRejectedWithTheirReason) {
  const TrackerConfig t;
  const ReportLayout l = layout_of(t);
  std::array<std::uint8_t, 32> good{};
  const PoseSample p = pose(Role::Head, {1, 2, 3}, Eigen::Quaterniond::Identity());
  ASSERT_TRUE(encode_report(l, std::span<const PoseSample>(&p, 1), 0, good));
  ASSERT_EQ(decode_report(good, l).error, DecodeError::None);

  EXPECT_EQ(decode_report(std::span<const std::uint8_t>(good.data(), 31), l).error, DecodeError::WrongLength);
  std::vector<std::uint8_t> longer(good.begin(), good.end());
  longer.push_back(0);  // one byte too many (a log made with another layout)
  EXPECT_EQ(decode_report(longer, l).error, DecodeError::WrongLength);
  EXPECT_EQ(decode_report(std::span<const std::uint8_t>(), l).error, DecodeError::WrongLength);
  auto bad = good;
  bad[0] = 2;
  EXPECT_EQ(decode_report(bad, l).error, DecodeError::UnknownReportId);
  bad = good;
  bad[1] = 3;  // the stylus' station, but the stylus is disabled
  EXPECT_EQ(decode_report(bad, l).error, DecodeError::UnknownStation);
  bad = good;
  bad[18] = 0x00;
  bad[19] = 0x48;  // w = 1.125: norm off by 0.125 > 0.05
  EXPECT_EQ(decode_report(bad, l).error, DecodeError::QuaternionNorm);
  bad = good;
  bad[14] = 0xFF;
  bad[15] = 0xFF;
  bad[16] = 0xFF;
  bad[17] = 0x7F;  // z = 21 km
  EXPECT_EQ(decode_report(bad, l).error, DecodeError::OutsideWorkspace);

  TrackerConfig f = t;
  f.report.position_type = FieldType::F32;
  f.report.position_scale = 1.0;
  const ReportLayout lf = layout_of(f);
  std::array<std::uint8_t, 32> fb{};
  ASSERT_TRUE(encode_report(lf, std::span<const PoseSample>(&p, 1), 0, fb));
  ASSERT_EQ(decode_report(fb, lf).error, DecodeError::None);
  for (float v : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
    const auto u = std::bit_cast<std::uint32_t>(v);
    for (int k = 0; k < 4; ++k) fb[10 + k] = static_cast<std::uint8_t>(u >> (8 * k));
    EXPECT_EQ(decode_report(fb, lf).error, DecodeError::NotFinite);
  }
}

TEST(Decode, DeviceClockUnwrapsAndRejectsBackwardsTime) {
  DeviceClock c;
  EXPECT_EQ(c.advance(65530, 16, 1000.0), 0);
  EXPECT_EQ(c.advance(65535, 16, 1000.0), 5000);
  EXPECT_EQ(c.advance(4, 16, 1000.0), 10000);  // wrapped
  EXPECT_EQ(c.advance(4, 16, 1000.0), 10000);  // equal time is fine (several stations per frame)
  EXPECT_EQ(c.advance(2, 16, 1000.0), -1);     // backwards
  EXPECT_EQ(c.advance(10, 16, 1000.0), 16000);
  DeviceClock w;
  EXPECT_EQ(w.advance(0xFFFFFFF0u, 32, 1.0), 0);
  EXPECT_EQ(w.advance(0x10u, 32, 1.0), 0x20);
  DeviceClock n;  // OpenIGTLink: 64-bit nanoseconds since 1970
  EXPECT_EQ(n.advance(1'700'000'000'000'000'000ull, 64, 1.0), 0);
  EXPECT_EQ(n.advance(1'700'000'000'016'666'667ull, 64, 1.0), 16'666'667);
  EXPECT_EQ(n.advance(1'699'999'999'000'000'000ull, 64, 1.0), -1);  // a second back
  EXPECT_EQ(n.advance(1'700'000'000'033'333'334ull, 64, 1.0), 33'333'334);
}

TEST(Decode, LayoutErrorsNameTheKey) {
  TrackerConfig t;
  t.report.length = 20;
  EXPECT_EQ(make_layout(t).error(), "trackers.head.offset: expected the sensor's fields inside the report");
  t = {};
  t.axis_remap = "x,x,z";
  EXPECT_EQ(make_layout(t).error(), "trackers.axis_remap: expected a signed permutation of x,y,z");
  t = {};
  t.patient.station = t.head.station;  // found by the decode fuzzer: one report would feed two roles
  EXPECT_EQ(make_layout(t).error(), "trackers.patient.station: expected a station different from trackers.head's");
  t.report.station_offset = -1;  // without a station byte the values do not matter
  EXPECT_TRUE(make_layout(t));
  for (int length : {0, 1025}) {
    t = {};
    t.report.length = length;
    EXPECT_EQ(make_layout(t).error(), "trackers.report.length: expected 1 to 1024 bytes") << length;
  }
  t = {};
  t.report.report_id = 0;  // a report id, even 0, takes the first byte: no field may sit on it
  t.report.station_offset = 0;
  EXPECT_EQ(make_layout(t).error(), "trackers.report.station_offset: expected a byte inside the report");
  FieldFormat none;
  none.type = FieldType::None;
  EXPECT_EQ(none.bytes(), 0) << "a position of type none takes no bytes";
}

// The hole the issue found: with "w,-x,-y,-z" the device sends the conjugate, and the decoder must undo each
// sign. Each component is negated alone, and components come in other orders, in hand-built bytes; the
// quaternion has no zero component, so a decoder that drops any one sign (or all), or reads in the wrong
// order, decodes another rotation.
TEST(Decode, EachQuaternionComponentSignAndOrderIsUndone) {
  const Eigen::Quaterniond q = Eigen::Quaterniond(0.7, 0.3, -0.5, 0.4).normalized();
  const double wxyz[4] = {q.w(), q.x(), q.y(), q.z()};
  for (const char* list : {"-w,x,y,z", "w,-x,y,z", "w,x,-y,z", "w,x,y,-z", "w,-x,-y,-z", "x,y,z,w", "z,w,y,x",
                           "y,-x,w,z"}) {
    SCOPED_TRACE(list);
    TrackerConfig t;
    t.report.orientation_components = list;
    const ReportLayout l = layout_of(t);
    Bytes r = head_report();
    const auto axes = *parse_signed_axes(list, "wxyz");
    for (int k = 0; k < 4; ++k) {  // what such a device puts on the wire: each component times its sign
      r.u16(18 + 2 * k, static_cast<std::uint16_t>(std::lround(axes[k].sign * wxyz[axes[k].index] * 16384)), false);
    }
    const DecodedReport d = decode_report(r.b, l);
    ASSERT_EQ(d.error, DecodeError::None);
    expect_same_pose(d.poses[0], pose(Role::Head, {0, 0, 0}, q));
  }
}

TEST(Decode, EachPositionComponentSignAndOrderIsUndone) {
  const double xyz[3] = {123.0, -456.0, 789.0};
  for (const char* list : {"-x,y,z", "x,-y,z", "x,y,-z", "z,x,y", "y,-z,x"}) {
    SCOPED_TRACE(list);
    TrackerConfig t;
    t.report.position_components = list;
    const ReportLayout l = layout_of(t);
    Bytes r = head_report();
    r.u16(18, 16384, false);  // identity quaternion
    const auto axes = *parse_signed_axes(list, "xyz");
    for (int k = 0; k < 3; ++k) {
      r.u32(6 + 4 * k, static_cast<std::uint32_t>(std::lround(axes[k].sign * xyz[axes[k].index] * 100)), false);
    }
    const DecodedReport d = decode_report(r.b, l);
    ASSERT_EQ(d.error, DecodeError::None);
    expect_same_pose(d.poses[0], pose(Role::Head, {xyz[0], xyz[1], xyz[2]}, Eigen::Quaterniond::Identity()));
  }
}

// The device time is read by hand too: its width (16 or 32 bits, the neighbouring bytes set so that a wrong
// width shows) and its byte order, and it is ticked in the layout's unit.
TEST(Decode, DeviceTimeWidthByteOrderAndTickAreTheLayouts) {
  for (bool big : {false, true}) {
    for (int bits : {16, 32}) {
      SCOPED_TRACE(std::to_string(bits) + (big ? " big" : " little"));
      TrackerConfig t;
      t.report.endian = big ? Endian::Big : Endian::Little;
      t.report.time_bits = bits;
      t.report.time_tick_us = 250.0;
      const ReportLayout l = layout_of(t);
      Bytes r = head_report();
      r.u32(2, 0x12345678u, big);  // a 16-bit time is the first two bytes of this
      r.u16(18, 16384, big);       // identity quaternion
      const DecodedReport d = decode_report(r.b, l);
      ASSERT_EQ(d.error, DecodeError::None);
      const std::uint64_t want = bits == 32 ? 0x12345678u : (big ? 0x1234u : 0x5678u);
      EXPECT_EQ(d.device_ticks, want);
      EXPECT_EQ(d.time_bits, bits);
      EXPECT_DOUBLE_EQ(d.time_tick_ns, 250'000.0);
    }
  }
}

TEST(Decode, EqualRotationsComeOutWithOneSign) {
  // q and -q are the same rotation; a device may send either. Both decode to the same numbers (w >= 0), so
  // that equal poses compare equal (replay against live, the HIL test).
  const TrackerConfig t;
  const ReportLayout l = layout_of(t);
  const Eigen::Quaterniond q = about(0, 2.5);  // w = cos(1.25) > 0
  Bytes plus(32), minus(32);
  for (Bytes* r : {&plus, &minus}) {
    r->u8(0, 1);
    r->u8(1, 1);
  }
  const double wxyz[4] = {q.w(), q.x(), q.y(), q.z()};
  for (int k = 0; k < 4; ++k) {
    plus.u16(18 + 2 * k, static_cast<std::uint16_t>(std::lround(wxyz[k] * 16384)), false);
    minus.u16(18 + 2 * k, static_cast<std::uint16_t>(std::lround(-wxyz[k] * 16384)), false);
  }
  const DecodedReport a = decode_report(plus.b, l), b = decode_report(minus.b, l);
  ASSERT_EQ(a.error, DecodeError::None);
  ASSERT_EQ(b.error, DecodeError::None);
  EXPECT_GE(b.poses[0].orientation_wxyz[0], 0.0);
  EXPECT_EQ(a.poses[0].orientation_wxyz, b.poses[0].orientation_wxyz);
}

TEST(Decode, WorkspaceBoundsBothWays) {
  TrackerConfig t;
  t.workspace_min_mm = {-100, -100, 500};
  t.workspace_max_mm = {100, 100, 1500};
  const ReportLayout l = layout_of(t);
  // The last two: the bounds themselves are inside.
  for (const auto& [p, inside] : std::vector<std::pair<Eigen::Vector3d, bool>>{{{0, 0, 1000}, true},
                                                                               {{0, 0, 499}, false},
                                                                               {{0, 0, 1501}, false},
                                                                               {{-101, 0, 1000}, false},
                                                                               {{0, 101, 1000}, false},
                                                                               {{-100, -100, 500}, true},
                                                                               {{100, 100, 1500}, true}}) {
    SCOPED_TRACE(p.transpose());
    Bytes r = head_report();
    for (int k = 0; k < 3; ++k) r.u32(6 + 4 * k, static_cast<std::uint32_t>(std::lround(p[k] * 100)), false);
    r.u16(18, 16384, false);
    EXPECT_EQ(decode_report(r.b, l).error, inside ? DecodeError::None : DecodeError::OutsideWorkspace);
  }
}

// An orientation-only sensor (an HMD's IMU): no position bytes at all; each role takes its fixed position, in
// the tracker's axes, through the same axis remap and world offset as a measured one.
TEST(Decode, PositionNoneTakesEachRolesFixedPositionThroughTheRemap) {
  TrackerConfig t;
  t.report.report_id = -1;
  t.report.length = 16;
  t.report.station_offset = -1;
  t.report.time_offset = -1;
  t.report.position_type = FieldType::None;
  t.report.position_offset = 0;
  t.report.orientation_offset = 0;
  t.head = {true, 0, 0, {10.0, 20.0, 1300.0}};
  t.patient = {true, 0, 8, {0.0, -5.0, 1000.0}};
  t.axis_remap = "x,-z,y";
  t.world_offset_mm = {1, 2, 3};
  const ReportLayout l = layout_of(t);
  const Eigen::Quaterniond qh = about(2, 0.7), qp = about(1, -0.4);
  Bytes r(16);
  const double h[4] = {qh.w(), qh.x(), qh.y(), qh.z()}, p[4] = {qp.w(), qp.x(), qp.y(), qp.z()};
  for (int k = 0; k < 4; ++k) {
    r.u16(2 * k, static_cast<std::uint16_t>(std::lround(h[k] * 16384)), false);
    r.u16(8 + 2 * k, static_cast<std::uint16_t>(std::lround(p[k] * 16384)), false);
  }
  const DecodedReport d = decode_report(r.b, l);
  ASSERT_EQ(d.error, DecodeError::None);
  ASSERT_EQ(d.count, 2);
  Eigen::Matrix3d m;
  m << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  const Eigen::Vector3d offset(1, 2, 3);
  const Eigen::Quaterniond r_proper(m);
  expect_same_pose(d.poses[0],
                   pose(Role::Head, m * Eigen::Vector3d(10, 20, 1300) + offset, r_proper * qh * r_proper.conjugate()));
  const Eigen::Quaterniond qp_world = r_proper * qp * r_proper.conjugate();
  expect_same_pose(d.poses[1], pose(Role::Patient, m * Eigen::Vector3d(0, -5, 1000) + offset, qp_world));
  // The encoder writes no position for such a layout, and what it writes decodes to the same poses.
  std::array<std::uint8_t, 16> buf{};
  ASSERT_TRUE(encode_report(l, std::span<const PoseSample>(d.poses.data(), 2), 0, buf));
  const DecodedReport again = decode_report(buf, l);
  ASSERT_EQ(again.error, DecodeError::None);
  expect_same_pose(again.poses[0], d.poses[0]);
  expect_same_pose(again.poses[1], d.poses[1]);
}

TEST(Decode, EncodedEulerAnglesAreTaitBryanAsDevicesSendThem) {
  // Devices send yaw and roll in [-180, 180] and the middle angle in [-90, 90]; the encoder (mock, synth) too.
  TrackerConfig t;
  t.report.orientation = OrientationKind::Euler;
  t.report.orientation_components = "z,y,x";
  t.report.orientation_type = FieldType::F32;
  t.report.orientation_frac_bits = 0;
  const ReportLayout l = layout_of(t);
  for (double a = -3.0; a <= 3.0; a += 0.5) {
    const PoseSample p = pose(Role::Head, {0, 0, 0}, about(2, a) * about(1, 0.9 * std::sin(a) * 1.5) * about(0, -a));
    std::array<std::uint8_t, 32> buf{};
    ASSERT_TRUE(encode_report(l, std::span<const PoseSample>(&p, 1), 0, buf));
    float deg[3];
    std::memcpy(deg, buf.data() + 18, sizeof deg);
    EXPECT_LE(std::abs(deg[0]), 180.0f + 1e-3f);
    EXPECT_LE(std::abs(deg[1]), 90.0f + 1e-3f);
    EXPECT_LE(std::abs(deg[2]), 180.0f + 1e-3f);
    expect_same_pose(decode_report(buf, l).poses[0], p, kPosTolMm, 1e-5);
  }
}

TEST(Decode, FieldOffsetsInsideTheSensorBlockAreTheLayouts) {
  TrackerConfig t;
  t.report.length = 48;
  t.report.position_offset = 14;  // position after the orientation, inside the sensor's block
  t.report.orientation_offset = 2;
  t.head = {true, 1, 10, {}};
  t.patient.enabled = false;
  const ReportLayout l = layout_of(t);
  const Eigen::Quaterniond q = about(2, -0.8);
  const double wxyz[4] = {q.w(), q.x(), q.y(), q.z()};
  Bytes r(48);
  r.u8(0, 1);
  r.u8(1, 1);
  for (int k = 0; k < 4; ++k) r.u16(12 + 2 * k, static_cast<std::uint16_t>(std::lround(wxyz[k] * 16384)), false);
  r.u32(24, static_cast<std::uint32_t>(-12345), false);
  r.u32(28, 6789, false);
  r.u32(32, 100000, false);
  const DecodedReport d = decode_report(r.b, l);
  ASSERT_EQ(d.error, DecodeError::None);
  expect_same_pose(d.poses[0], pose(Role::Head, {-123.45, 67.89, 1000.0}, q));
}
