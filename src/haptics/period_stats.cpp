// Histogram percentiles for the loop period; exact to the 1 us bin width below 20 ms.
#include "haptics/period_stats.hpp"

#include <algorithm>
#include <cmath>

namespace s4d {

void PeriodStats::add_period(double us) {
  if (!std::isfinite(us) || us < 0) us = 0;
  const int bin = std::min(kBins - 1, static_cast<int>(us));
  ++bins_[bin];
  ++count_;
  sum_ += us;
  max_ = std::max(max_, us);
  if (us > 2000.0) ++over_2ms_;
  recent_[recent_head_] = static_cast<float>(us);
  recent_head_ = (recent_head_ + 1) % kRecent;
}

void PeriodStats::reset() {
  std::fill(bins_.begin(), bins_.end(), 0u);
  count_ = missed_ = over_2ms_ = 0;
  sum_ = max_ = worst_lateness_ = 0;
  recent_.fill(0);
  recent_head_ = 0;
}

// The smallest bin value v such that at least q of the periods are <= v + 1 us; reported at the bin's
// upper edge, clipped to the true maximum, so p100 == max.
double PeriodStats::percentile(double q) const {
  if (count_ == 0) return 0;
  const auto rank = static_cast<std::uint64_t>(std::ceil(q * static_cast<double>(count_)));
  std::uint64_t seen = 0;
  for (int i = 0; i < kBins; ++i) {
    seen += bins_[i];
    if (seen >= std::max<std::uint64_t>(rank, 1)) return std::min(max_, i + 1.0);
  }
  return max_;
}

PeriodSummary PeriodStats::summary() const {
  PeriodSummary s;
  s.ticks = count_;
  s.nominal_us = nominal_us_;
  s.p50_us = percentile(0.5);
  s.p99_us = percentile(0.99);
  s.p999_us = percentile(0.999);
  s.max_us = max_;
  s.mean_us = count_ ? sum_ / static_cast<double>(count_) : 0;
  s.missed = missed_;
  s.over_2ms = over_2ms_;
  s.worst_lateness_us = worst_lateness_;
  return s;
}

int PeriodStats::recent(std::array<float, kRecent>& out) const {
  const int n = static_cast<int>(std::min<std::uint64_t>(count_, kRecent));
  const int start = (recent_head_ - n + kRecent) % kRecent;
  for (int i = 0; i < n; ++i) out[i] = recent_[(start + i) % kRecent];
  return n;
}

}  // namespace s4d
