/// @file display_calibration_test.cpp
/// @brief SPAAM on a known HMD: alignments with aiming noise fit each eye's projection (held-out points and the
///        eye's centre); too few, flat or badly written alignments are refused in one line; and the runtime's eye
///        views built from the fit put a world point on the pixel the 3 x 4 gives.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <random>

#include <Eigen/Geometry>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "platform/app/settings_load.h"
#include "platform/egl/egl_context.h"
#include "platform/output/hmd_views.h"
#include "render/frame_target.h"
#include "render/renderer.h"
#include "platform/registration/display_calibration.h"

namespace lungar::platform {
namespace {

/// A known eye: 900 px focal lengths, the principal point off centre, looking along the sensor's +z with a small
/// tilt, centred at `centre` in the sensor frame (mm).
Eigen::Matrix<double, 3, 4> known_eye(const Eigen::Vector3d& centre, double tilt) {
  Eigen::Matrix3d k;
  k << 900, 0, 630, 0, 905, 372, 0, 0, 1;
  const Eigen::Matrix3d r = (Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(0.5 * tilt, Eigen::Vector3d::UnitX())).toRotationMatrix();
  Eigen::Matrix<double, 3, 4> rt;
  rt << r, -r * centre;
  return k * rt;
}

/// A point the eye sees at depth 300 .. 900 mm, within its viewport.
Eigen::Vector3d visible_point(const Eigen::Matrix<double, 3, 4>& p, std::mt19937& rng) {
  std::uniform_real_distribution<double> depth(300, 900), u(80, 1200), v(60, 660);
  const Eigen::Matrix3d m = p.leftCols<3>();
  const Eigen::Vector3d centre = -m.inverse() * p.col(3);
  const Eigen::Vector3d ray = m.inverse() * Eigen::Vector3d(u(rng), v(rng), 1.0);
  return centre + depth(rng) * ray / ray.z();
}

std::vector<Alignment> aligned(const Eigen::Matrix<double, 3, 4>& p, int n, double noise_px, std::mt19937& rng) {
  std::normal_distribution<double> aim(0.0, noise_px);
  std::vector<Alignment> out;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d x = visible_point(p, rng);
    out.push_back({x, project(p, x) + Eigen::Vector2d(aim(rng), aim(rng))});
  }
  return out;
}

TEST(DisplayCalibration, TwentyFiveNoisyAlignmentsAnEyeReprojectHeldOutPointsAndFindTheEye) {
  std::mt19937 rng(3);
  for (const Eigen::Vector3d& centre : {Eigen::Vector3d(-31.5, -78.0, -72.0), Eigen::Vector3d(31.5, -78.0, -72.0)}) {
    const Eigen::Matrix<double, 3, 4> truth = known_eye(centre, centre.x() < 0 ? 0.04 : -0.03);
    auto fit = calibrate_eye(aligned(truth, 25, 1.5, rng));
    ASSERT_TRUE(fit) << fit.error();
    std::vector<double> held_out;
    for (int i = 0; i < 200; ++i) {
      const Eigen::Vector3d x = visible_point(truth, rng);
      held_out.push_back((project(fit->projection, x) - project(truth, x)).norm());
    }
    std::nth_element(held_out.begin(), held_out.begin() + 100, held_out.end());
    EXPECT_LE(held_out[100], 2.0) << "median reprojection of held-out points, px";
    EXPECT_LT((fit->centre_mm - centre).norm(), 8.0) << fit->centre_mm.transpose();
    EXPECT_GT(fit->rms_px, 0.5) << "the aiming noise shows in the residual";
    EXPECT_LT(fit->rms_px, 2.5);
  }
}

TEST(DisplayCalibration, TooFewOrFlatAlignmentsAreRefused) {
  std::mt19937 rng(4);
  const Eigen::Matrix<double, 3, 4> truth = known_eye(Eigen::Vector3d(-32, -80, -70), 0.0);
  auto five = calibrate_eye(aligned(truth, 5, 0.0, rng));
  ASSERT_FALSE(five);
  EXPECT_NE(five.error().find("at least 6 alignments, got 5"), std::string::npos) << five.error();
  std::vector<Alignment> flat = aligned(truth, 25, 0.0, rng);
  for (Alignment& a : flat) {  // every point moved along its ray to one depth: a plane facing the eye
    const Eigen::Vector3d c(-32, -80, -70);
    a.point_mm = c + (a.point_mm - c) * (600.0 / (a.point_mm.z() - c.z()));
  }
  auto coplanar = calibrate_eye(flat);
  ASSERT_FALSE(coplanar);
  EXPECT_NE(coplanar.error().find("near a plane"), std::string::npos) << coplanar.error();
}

// The refusal says how flat the points are: the smallest spread over the largest. The corners of a 400 x 200 x 4 mm
// box spread 200, 100 and 2 mm about their centre, so 0.01 (over the middle spread it would read 0.02).
TEST(DisplayCalibration, AFlatSetIsRefusedWithItsSpreadRatio) {
  std::vector<Alignment> box;
  for (double x : {-200.0, 200.0})
    for (double y : {-100.0, 100.0})
      for (double z : {598.0, 602.0}) box.push_back({Eigen::Vector3d(x, y, z), Eigen::Vector2d(640 + x, 360 + y)});
  auto flat = calibrate_eye(box);
  ASSERT_FALSE(flat);
  EXPECT_NE(flat.error().find("(spread 0.01 of their largest)"), std::string::npos) << flat.error();
}

// The JSON report gives each eye's focal lengths and principal point as K holds them (a skew in K, so that an
// entry read from the wrong place shows).
TEST(DisplayCalibration, TheJsonReportGivesEachEyesFocalLengthsAndPrincipalPoint) {
  std::array<EyeCalibration, 2> eyes{};
  for (int e = 0; e < 2; ++e) {
    eyes[e].projection.setZero();
    eyes[e].rotation.setIdentity();
    eyes[e].centre_mm.setZero();
    eyes[e].intrinsics << 900.0 + e, 0.5, 630.0 + e, 0.0, 905.0 + e, 372.0 + e, 0.0, 0.0, 1.0;
  }
  const auto path = std::filesystem::temp_directory_path() / "lungar_display_calibration_report.json";
  const Status written = write_display_calibration_json(path.string(), eyes);
  ASSERT_TRUE(written) << written.error();
  std::ifstream in(path);
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["left"]["focal_px"], nlohmann::json({900.0, 905.0}));
  EXPECT_EQ(j["left"]["principal_point_px"], nlohmann::json({630.0, 372.0}));
  EXPECT_EQ(j["right"]["focal_px"], nlohmann::json({901.0, 906.0}));
  EXPECT_EQ(j["right"]["principal_point_px"], nlohmann::json({631.0, 373.0}));
  std::filesystem::remove(path);
}

TEST(DisplayCalibration, AlignmentFileErrorsNameTheLine) {
  const auto dir = std::filesystem::temp_directory_path() / "lungar_spaam_test";
  std::filesystem::create_directories(dir);
  const std::pair<const char*, const char*> cases[] = {
      {"eye,x,y,z,u,v\n", ":1: header"},
      {"eye,x_mm,y_mm,z_mm,u_px,v_px\nleft,1,2,3,4,5\ncentre,1,2,3,4,5\n", ":3: eye: expected left or right"},
      {"eye,x_mm,y_mm,z_mm,u_px,v_px\nright,1,2,3,4\n", ":2: expected five finite numbers"},
      {"eye,x_mm,y_mm,z_mm,u_px,v_px\nright,1,2,3,4,nan\n", ":2: expected five finite numbers"}};
  for (const auto& [text, why] : cases) {
    const std::string path = (dir / "al.csv").string();
    std::ofstream(path) << text;
    auto r = read_alignments_csv(path);
    ASSERT_FALSE(r) << text;
    EXPECT_NE(r.error().find(path + why), std::string::npos) << r.error();
  }
  std::filesystem::remove_all(dir);
}

/// The pixel (from the eye viewport's top-left corner) where the runtime's view and projection put a world point.
Eigen::Vector2d drawn_pixel(const render::EyeView& eye, const Eigen::Vector3d& world, int width, int height) {
  const glm::vec4 clip = eye.projection * eye.view * glm::vec4(world.x(), world.y(), world.z(), 1.0);
  const double x = clip.x / clip.w, y = clip.y / clip.w;
  return {(x + 1) / 2 * width, height - (y + 1) / 2 * height};
}

TEST(DisplayCalibration, TheRuntimesEyeViewsPutAWorldPointWhereTheProjectionSays) {
  std::mt19937 rng(5);
  const std::array<Eigen::Matrix<double, 3, 4>, 2> truth = {known_eye(Eigen::Vector3d(-32, -80, -70), 0.03),
                                                            known_eye(Eigen::Vector3d(32, -80, -70), -0.02)};
  const auto dir = std::filesystem::temp_directory_path() / "lungar_spaam_views";
  std::filesystem::create_directories(dir);
  std::array<EyeCalibration, 2> eyes;
  for (int e = 0; e < 2; ++e) {
    auto fit = calibrate_eye(aligned(truth[e], 25, 0.0, rng));
    ASSERT_TRUE(fit) << fit.error();
    eyes[e] = *fit;
  }
  const std::string toml = (dir / "display.toml").string();
  ASSERT_TRUE(write_display_calibration_toml(toml, eyes));
  auto settings = load_settings(toml);  // what `--config display.toml` gives the runtime
  ASSERT_TRUE(settings) << settings.error();
  ASSERT_TRUE(settings->hmd.display_calibration.has_value());
  settings->hmd.head_to_eye_mm = {5.0, -60.0, -40.0};  // the calibration must not depend on it
  render::StereoView view(hmd_geometry(settings->hmd));
  // The head sensor somewhere in the room, as the runtime turns it into the head frame (runtime.cpp).
  Eigen::Isometry3d world_from_sensor = Eigen::Isometry3d::Identity();
  world_from_sensor.translate(Eigen::Vector3d(100, 1500, -200));
  world_from_sensor.rotate(Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.3, 1, 0.2).normalized()));
  Eigen::Isometry3d head = world_from_sensor;
  head.translate(Eigen::Vector3d(5.0, -60.0, -40.0));
  head.rotate(Eigen::AngleAxisd(EIGEN_PI / 2, Eigen::Vector3d::UnitX()));
  glm::mat4 head_to_world;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) head_to_world[c][r] = static_cast<float>(head.matrix()(r, c));
  const auto views = view.eyes(head_to_world);
  for (int e = 0; e < 2; ++e) {
    for (int i = 0; i < 20; ++i) {
      const Eigen::Vector3d in_sensor = visible_point(truth[e], rng);
      const Eigen::Vector3d world = world_from_sensor * in_sensor;
      const Eigen::Vector2d want = project(truth[e], in_sensor);
      EXPECT_LT((drawn_pixel(views[e], world, 640, 720) - want).norm(), 0.05) << "eye " << e << " point " << i;
    }
  }
  // One eye alone, or a singular projection, is refused when the settings are read.
  std::ofstream(toml) << "[hmd.display_calibration]\nleft_projection_3x4 = [1,0,0,0, 0,1,0,0, 0,0,1,0]\n";
  auto one = load_settings(toml);
  ASSERT_FALSE(one);
  EXPECT_NE(one.error().find("right_projection_3x4"), std::string::npos) << one.error();
  std::ofstream(toml) << "[hmd.display_calibration]\nleft_projection_3x4 = [1,0,0,0, 0,1,0,0, 0,0,0,1]\n"
                         "right_projection_3x4 = [1,0,0,0, 0,1,0,0, 0,0,1,0]\n";
  auto singular = load_settings(toml);
  ASSERT_FALSE(singular);
  EXPECT_NE(singular.error().find("left_projection_3x4"), std::string::npos) << singular.error();
  std::filesystem::remove_all(dir);
}

/// One point of a one-vertex "lung", drawn through a calibrated eye and read back: the lit pixels' centre lies
/// within a pixel of where the eye's 3 x 4 puts the point (llvmpipe, a real GLES 3 context).
TEST(DisplayCalibration, APointDrawnThroughACalibratedEyeLandsOnItsPixel) {
  auto context = EglContext::headless();
  ASSERT_TRUE(context) << context.error();
  std::mt19937 rng(6);
  const Eigen::Matrix<double, 3, 4> truth = known_eye(Eigen::Vector3d(-32, -80, -70), 0.03);
  auto fit = calibrate_eye(aligned(truth, 25, 0.0, rng));
  ASSERT_TRUE(fit) << fit.error();
  HmdSettings hmd;
  std::array<double, 12> p{};
  for (int i = 0; i < 12; ++i) p[static_cast<std::size_t>(i)] = fit->projection(i / 4, i % 4);
  hmd.display_calibration = std::array<std::array<double, 12>, 2>{p, p};
  hmd.head_to_eye_mm = {0.0, 0.0, 0.0};
  const auto views = render::StereoView(hmd_geometry(hmd)).eyes(glm::rotate(glm::mat4(1.f), glm::half_pi<float>(),
                                                                            glm::vec3(1.f, 0.f, 0.f)));
  // World = the head sensor's frame (the sensor at the origin): the point, facing the eye.
  const Eigen::Vector3d x(-60.0, -60.0, 500.0);
  sim::BakedAsset a;
  a.bands = 1;
  a.positions = {static_cast<float>(x.x()), static_cast<float>(x.y()), static_cast<float>(x.z())};
  const Eigen::Vector3d to_eye = (fit->centre_mm - x).normalized();
  a.normals = {static_cast<float>(to_eye.x()), static_cast<float>(to_eye.y()), static_cast<float>(to_eye.z())};
  a.directions = a.normals;
  a.areas = {1.f};
  a.lung_of_vertex = {0};
  a.sh_coeffs = {0.f};
  a.linear_coeffs = {0.f, 0.f, 0.f, 0.f};
  sim::BakedLung lung;
  lung.vertex_count = 1;
  a.lungs = {lung};
  auto drawable = render::LungDrawable::create(a);
  ASSERT_TRUE(drawable) << drawable.error();
  auto renderer = render::Renderer::create(*drawable);
  ASSERT_TRUE(renderer) << renderer.error();
  auto target = render::FrameTarget::create(2 * hmd.eye_width_px, hmd.eye_height_px);
  ASSERT_TRUE(target) << target.error();
  const std::vector<float> force(1, 0.f);
  const render::LungFrame frame_lung{force, 0.f, {1.f, 1.f, 1.f}};
  render::FrameInputs in;
  in.lungs = std::span(&frame_lung, 1);
  in.eyes = std::span(views.data(), 1);  // the left eye, in the left half of the target
  in.level_of_detail = false;
  in.ambient = 1.f;
  target->bind();
  ASSERT_TRUE(renderer->draw(*drawable, in));
  std::vector<std::uint8_t> rgba;
  render::read_pixels_top_down(0, 0, target->width(), target->height(), rgba);
  double su = 0, sv = 0, lit = 0;
  for (int v = 0; v < target->height(); ++v)
    for (int u = 0; u < target->width(); ++u)
      if (rgba[4 * (static_cast<std::size_t>(v) * target->width() + u)] > 128) {
        su += u + 0.5;  // the pixel's centre, from the top-left corner
        sv += v + 0.5;
        ++lit;
      }
  ASSERT_GT(lit, 0) << "the point was not drawn";
  const Eigen::Vector2d want = project(truth, x);
  EXPECT_LT((Eigen::Vector2d(su / lit, sv / lit) - want).norm(), 1.0) << "drawn at " << su / lit << ", " << sv / lit
                                                                        << "; the 3x4 says " << want.transpose();
}

}  // namespace
}  // namespace lungar::platform
