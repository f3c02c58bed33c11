/// @file ventilation_ramp.h
/// @brief The ventilation map's colour ramp, from no sweep (0) to full scale (1): dark violet, blue, teal, green,
///        yellow (viridis-like: it grows lighter all the way, so it reads in grey and for the colour-blind). The
///        vertex shader (render/shaders/deform.vert, ventilation_ramp) holds the same stops; the legend and the
///        tests read them here.
#pragma once

#include <algorithm>
#include <array>

namespace lungar::render {

inline constexpr std::array<std::array<float, 3>, 5> kVentilationStops{{{0.27f, 0.00f, 0.33f},
                                                                        {0.23f, 0.32f, 0.55f},
                                                                        {0.13f, 0.57f, 0.55f},
                                                                        {0.37f, 0.79f, 0.38f},
                                                                        {0.99f, 0.91f, 0.14f}}};

/// The ramp's colour at s (clamped to 0..1), piecewise linear between the stops at 0, 1/4, 1/2, 3/4 and 1.
inline std::array<float, 3> ventilation_colour(float s) {
  s = std::clamp(s, 0.f, 1.f);
  const int k = std::min(3, static_cast<int>(s * 4.f));
  const float t = s * 4.f - static_cast<float>(k);
  std::array<float, 3> c{};
  for (int i = 0; i < 3; ++i) c[i] = kVentilationStops[k][i] + t * (kVentilationStops[k + 1][i] - kVentilationStops[k][i]);
  return c;
}

}  // namespace lungar::render
