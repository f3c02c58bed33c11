/// @file breath_clarity.h
/// @brief Which of several surrogates breathes most clearly: a session records three markers (lower and upper
///        abdomen, upper chest), and the upper chest of a talking patient moves mostly with the talking. The
///        default source is the one whose excursion holds the largest share of its power at breathing rates.
#pragma once

#include <cstddef>
#include <vector>

#include "sim/breathing/breath_trace.h"

namespace lungar::sim {

/// The breathing band: 6 to 42 breaths a minute.
inline constexpr double kBreathingBandHz[2] = {0.1, 0.7};

/// The share (0..1) of the trace's power, over its first `window_s` and less its mean, that lies in the breathing
/// band, against all of it from 0.02 Hz (a drift slower than 1 a minute counts against it too) to half the
/// sampling rate. Evaluated on the trace resampled at 10 Hz.
double breathing_clarity(const BreathTrace& trace, double window_s = 60.0);

/// The index of the clearest of `traces` (the first on a tie); 0 for an empty list.
std::size_t clearest_breathing(const std::vector<BreathTrace>& traces, std::vector<double>* clarity = nullptr);

}  // namespace lungar::sim
