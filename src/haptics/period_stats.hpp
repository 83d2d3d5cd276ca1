// PeriodStats: the haptic loop's measurement of its own period (p50/p99/p99.9/max, missed deadlines)
// with a fixed 1 us histogram, so recording a tick costs a few nanoseconds and never allocates.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

namespace s4d {

// A summary cheap to copy into snapshots and print.
struct PeriodSummary {
  std::uint64_t ticks = 0;             // periods measured
  double nominal_us = 1000;            // us, the configured period
  double p50_us = 0, p99_us = 0, p999_us = 0, max_us = 0, mean_us = 0;  // us
  std::uint64_t missed = 0;            // ticks that ended after the next deadline
  std::uint64_t over_2ms = 0;          // periods longer than 2 ms (the hard bound)
  double worst_lateness_us = 0;        // us, latest wake-up after its deadline
};

class PeriodStats {
 public:
  static constexpr int kBins = 20000;  // 1 us bins up to 20 ms; longer periods land in the last bin
  static constexpr int kRecent = 256;  // periods kept for the live plot

  explicit PeriodStats(double nominal_us = 1000) : nominal_us_(nominal_us) { bins_.resize(kBins, 0); }

  void add_period(double us);
  void add_missed() { ++missed_; }
  void add_lateness(double us) {
    if (us > worst_lateness_) worst_lateness_ = us;
  }
  void reset();

  PeriodSummary summary() const;
  // The last kRecent periods (us), oldest first, into `out` (size kRecent); returns how many are valid.
  int recent(std::array<float, kRecent>& out) const;
  double nominal_us() const { return nominal_us_; }

 private:
  double percentile(double q) const;

  double nominal_us_;
  std::vector<std::uint32_t> bins_;  // kBins, count of periods per microsecond
  std::uint64_t count_ = 0, missed_ = 0, over_2ms_ = 0;
  double sum_ = 0, max_ = 0, worst_lateness_ = 0;
  std::array<float, kRecent> recent_{};  // ring of the latest periods (us)
  int recent_head_ = 0;
};

}  // namespace s4d
