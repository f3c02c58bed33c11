/// @file spaam_session.cpp
/// @brief The crosshair's positions, confirm and undo (spaam_session.h).
#include "platform/registration/spaam_session.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace lungar::platform {

namespace {

/// A step through the `side` x `side` cells (row-major) that visits each once (coprime with their count) and
/// moves at least two columns and one row at a time, where the grid is big enough to allow it.
int visiting_step(int side) {
  const int n = side * side;
  for (int s = (n + 2) / 3; s < n; ++s) {
    const int column = s % side;
    if (std::gcd(s, n) == 1 && column > 1 && column < side - 1) return s;
  }
  return 1;
}

const char* eye_name(int eye) { return eye == 0 ? "LEFT" : "RIGHT"; }

/// Why a pose cannot be used, or empty. The tracker reports no pose of a sensor its settings leave out.
std::string unusable(const drivers::PoseSample& pose, const char* what, drivers::Role role) {
  if (!pose.valid()) {
    return std::string(what) + " pose: none from the tracker yet (is [trackers." + drivers::to_string(role) +
           "] enabled?)";
  }
  if (pose.stale()) return std::string(what) + " pose: stale (out of the tracker's view?)";
  return {};
}

}  // namespace

std::vector<Eigen::Vector2d> spaam_positions(int width_px, int height_px, int side) {
  std::vector<Eigen::Vector2d> cells;
  for (int row = 0; row < side; ++row) {
    for (int column = 0; column < side; ++column) {
      const double fu = side > 1 ? 0.1 + 0.8 * column / (side - 1) : 0.5;
      const double fv = side > 1 ? 0.1 + 0.8 * row / (side - 1) : 0.5;
      cells.emplace_back(std::floor(fu * width_px) + 0.5, std::floor(fv * height_px) + 0.5);
    }
  }
  const int n = static_cast<int>(cells.size()), step = visiting_step(side);
  std::vector<Eigen::Vector2d> ordered;
  for (int k = 0; k < n; ++k) ordered.push_back(cells[static_cast<std::size_t>((n / 2 + k * step) % n)]);
  return ordered;
}

SpaamSession::SpaamSession(int eye_width_px, int eye_height_px, const SpaamPoint& point, int side)
    : positions_(spaam_positions(eye_width_px, eye_height_px, side)), point_(point) {}

SpaamTarget SpaamSession::target() const {
  const int eye = alignments_[0].size() < positions_.size() ? 0 : 1;
  const int count = static_cast<int>(positions_.size());
  const int index = std::min(static_cast<int>(alignments_[static_cast<std::size_t>(eye)].size()), count - 1);
  return {eye, index, count, positions_[static_cast<std::size_t>(index)]};
}

Status SpaamSession::confirm(const drivers::PoseSample& head, const drivers::PoseSample& point_sensor) {
  if (done()) return fail("every position of both eyes is aligned already");
  const char* what = point_.role == drivers::Role::Stylus ? "stylus" : "patient tracker";
  if (std::string why = unusable(head, "head", drivers::Role::Head); !why.empty()) return fail(why + "; not recorded");
  if (std::string why = unusable(point_sensor, what, point_.role); !why.empty()) return fail(why + "; not recorded");
  const Eigen::Vector3d world = point_sensor.transform() * point_.offset_mm;
  const SpaamTarget t = target();
  alignments_[static_cast<std::size_t>(t.eye)].push_back({head.transform().inverse() * world, t.pixel});
  return ok();
}

bool SpaamSession::undo() {
  for (int eye = 1; eye >= 0; --eye) {
    auto& eye_alignments = alignments_[static_cast<std::size_t>(eye)];
    if (eye_alignments.empty()) continue;
    eye_alignments.pop_back();
    return true;
  }
  return false;
}

std::array<std::string, 3> SpaamSession::prompt() const {
  const SpaamTarget t = target();
  const std::string point = point_.role == drivers::Role::Stylus ? "THE STYLUS TIP" : "THE FIDUCIAL";
  return {std::string(eye_name(t.eye)) + " EYE " + std::to_string(t.index + 1) + "/" + std::to_string(t.count) +
              " (CLOSE THE " + eye_name(1 - t.eye) + " EYE)",
          "LINE THE CROSSHAIR UP WITH " + point + ", 0.3-0.9 M AWAY: SPACE OR ENTER",
          "BACKSPACE: UNDO THE LAST    ESC: ABORT, NOTHING WRITTEN"};
}

}  // namespace lungar::platform
