// SessionMonitor: the independent checks of a live simulation, run off the UI thread on the
// latest snapshot — true intersections (the proximity finder), the smallest gap, and the
// scenario's verdict — so the panel can say "true intersections: 0" without dropping frames.
#pragma once
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <thread>
#include <vector>

#include "physics/model.hpp"
#include "scenario/scenario.hpp"
#include "scenario/verdict.hpp"
#include "shape/surface.hpp"

namespace s4d {

struct MonitorResult {
  bool valid = false;             // false until the first check finished
  double sim_time = 0;            // s, of the state checked
  int true_intersections = 0;     // cell pairs (sharing no vertex) that truly meet
  double min_gap = 0;             // smallest gap between such pairs within `search` (inf beyond); for
                                  // curves between strands, not segments near along one chain
  std::optional<VerdictResult> verdict;  // the scenario's, when the session has one
  double check_ms = 0;            // wall time of the last round of checks
  std::uint64_t rounds = 0;
};

// A world of curves' cells as the monitor checks them: segments (global vertex indices) and where
// each lies along its chain (physics/model.hpp), so that neighbours along a chain are no "gap".
struct MonitorCurves {
  std::vector<Segment> segments;
  std::vector<ChainPlace> places;  // per segment
  std::vector<Chain> chains;
};

class SessionMonitor {
 public:
  // triangles, curves: the world's cells (global vertex indices; one of them empty); dim: 3 or
  // 4; search: the gap range reported (2 δ); scenario: judged live when given (first/count/initial
  // as VerdictJudge's).
  SessionMonitor(std::vector<Triangle> triangles, MonitorCurves curves, int dim, double search,
                 const Scenario* scenario, std::vector<int> first, std::vector<int> count, std::vector<Vec4> initial);
  ~SessionMonitor();
  SessionMonitor(const SessionMonitor&) = delete;
  SessionMonitor& operator=(const SessionMonitor&) = delete;

  // UI thread: hands over a state (nv × dim values) to check; dropped while a check runs (the
  // next one will be newer). A time that goes back (a reset) restarts the verdict's history.
  void submit(std::span<const double> points, double sim_time);
  MonitorResult latest() const;

 private:
  void run();
  void check_pending();  // checks the state submitted last (the worker, or submit without threads)

  const std::vector<Triangle> triangles_;
  const MonitorCurves curves_;
  const int dim_;
  const double search_;
  std::optional<Scenario> scenario_;
  std::vector<int> first_, count_;
  std::vector<Vec4> initial_;
  std::unique_ptr<VerdictJudge> judge_;  // worker thread only
  double judged_time_ = -1;              // worker thread only
  std::vector<double> points_;           // worker thread only: the state being checked

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::vector<double> pending_;
  double pending_time_ = 0;
  bool has_pending_ = false, busy_ = false, stop_ = false;
  MonitorResult result_;
  std::thread thread_;
};

}  // namespace s4d
