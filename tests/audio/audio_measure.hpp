// Measurements the audio tests (and the explorer's WAV test) make on PCM: Goertzel power at a
// frequency, the dominant frequency over a grid, peak amplitude.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>

namespace s4d::test {

// Power of `x` at frequency f (Hz) by the Goertzel recurrence, normalised by the length.
inline double goertzel_power(std::span<const float> x, double f, int rate) {
  const double w = 2 * 3.141592653589793 * f / rate, c = 2 * std::cos(w);
  double s1 = 0, s2 = 0;
  for (float v : x) {
    const double s0 = v + c * s1 - s2;
    s2 = s1;
    s1 = s0;
  }
  const double p = s1 * s1 + s2 * s2 - c * s1 * s2;
  return x.empty() ? 0 : p / (double(x.size()) * double(x.size()));
}

// The frequency of largest Goertzel power on lo, lo + step, ..., hi.
inline double dominant_frequency(std::span<const float> x, int rate, double lo = 50, double hi = 4000,
                                 double step = 5) {
  double best_f = lo, best_p = -1;
  for (double f = lo; f <= hi; f += step) {
    const double p = goertzel_power(x, f, rate);
    if (p > best_p) {
      best_p = p;
      best_f = f;
    }
  }
  return best_f;
}

inline double peak(std::span<const float> x) {
  double m = 0;
  for (float v : x) m = std::max(m, double(std::abs(v)));
  return m;
}

// The window [t0, t1) seconds of x.
inline std::span<const float> window(std::span<const float> x, double t0, double t1, int rate) {
  const std::size_t a = std::min(x.size(), std::size_t(std::max(0.0, t0 * rate)));
  const std::size_t b = std::min(x.size(), std::size_t(std::max(0.0, t1 * rate)));
  return x.subspan(a, b > a ? b - a : 0);
}

}  // namespace s4d::test
