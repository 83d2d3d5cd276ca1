// The monitor's worker: latest-only hand-over under a mutex (the UI never waits for a check).
#include "interact/session/session_monitor.hpp"

#include <chrono>
#include <limits>

#include "core/threads.hpp"
#include "proximity/mesh_proximity.hpp"
#include "proximity/self_proximity.hpp"
#include "proximity/smallest_within.hpp"
#include "scenario/script_driver.hpp"

namespace s4d {

namespace {

template <int D>
std::vector<Vec<D>> unpack(const std::vector<double>& p) {
  std::vector<Vec<D>> x(p.size() / D);
  for (std::size_t i = 0; i < x.size(); ++i)
    for (int k = 0; k < D; ++k) x[i][k] = p[i * D + k];
  return x;
}

// `near(a, b)`: a pair that is no gap (neighbours along a chain).
template <int D, std::size_t K, class Near>
void check(const std::vector<std::array<int, K>>& given, const std::vector<double>& points, double search,
           Near near, MonitorResult& r) {
  constexpr int k = static_cast<int>(K);
  const std::vector<Vec<D>> x = unpack<D>(points);
  std::vector<Cell<k>> cells(given.begin(), given.end());
  Vec<D> lo = x.empty() ? Vec<D>::Zero() : x[0], hi = lo;
  for (const Vec<D>& p : x) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  r.true_intersections = static_cast<int>(intersecting_pairs<D, k>(x, cells, 1e-9 * (hi - lo).norm()).size());
  SelfProximity<D, k> prox(std::move(cells));
  std::vector<ProximityPair<D>> pairs;
  r.min_gap = smallest_within(search, [&](double within) {
    prox.pairs_within(x, within, pairs);
    double d = std::numeric_limits<double>::infinity();
    for (const auto& p : pairs)
      if (!near(p.a, p.b)) d = std::min(d, p.closest.distance);
    return d;
  });
}

}  // namespace

SessionMonitor::SessionMonitor(std::vector<Triangle> triangles, MonitorCurves curves, int dim, double search,
                               const Scenario* scenario, std::vector<int> first, std::vector<int> count,
                               std::vector<Vec4> initial)
    : triangles_(std::move(triangles)),
      curves_(std::move(curves)),
      dim_(dim),
      search_(search),
      first_(std::move(first)),
      count_(std::move(count)),
      initial_(std::move(initial)) {
  if (scenario) scenario_ = *scenario;
  if constexpr (kHaveThreads) thread_ = std::thread([this] { run(); });
}

SessionMonitor::~SessionMonitor() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_one();
  if (thread_.joinable()) thread_.join();
}

void SessionMonitor::submit(std::span<const double> points, double sim_time) {
  {
    std::lock_guard lock(mutex_);
    if (busy_ || has_pending_) return;
    pending_.assign(points.begin(), points.end());
    pending_time_ = sim_time;
    has_pending_ = true;
  }
  if (!thread_.joinable()) {  // no threads (the web page): the check runs now, on the caller's
    check_pending();
    return;
  }
  wake_.notify_one();
}

MonitorResult SessionMonitor::latest() const {
  std::lock_guard lock(mutex_);
  return result_;
}

void SessionMonitor::run() {
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || has_pending_; });
      if (stop_) return;
    }
    check_pending();
  }
}

void SessionMonitor::check_pending() {
  {
    double t = 0;
    {
      std::lock_guard lock(mutex_);
      points_.swap(pending_);
      t = pending_time_;
      has_pending_ = false;
      busy_ = true;
    }
    const std::vector<double>& points = points_;
    const auto t0 = std::chrono::steady_clock::now();
    MonitorResult r;
    r.valid = true;
    r.sim_time = t;
    try {
      const auto along_chain = [this](int a, int b) { return chain_near(curves_.places, curves_.chains, a, b); };
      const auto never = [](int, int) { return false; };
      if (!curves_.segments.empty()) {
        if (dim_ == 3) check<3>(curves_.segments, points, search_, along_chain, r);
        else check<4>(curves_.segments, points, search_, along_chain, r);
      } else {
        if (dim_ == 3) check<3>(triangles_, points, search_, never, r);
        else check<4>(triangles_, points, search_, never, r);
      }
      if (scenario_) {
        std::vector<Vec4> x(points.size() / static_cast<std::size_t>(dim_), Vec4::Zero());
        for (std::size_t i = 0; i < x.size(); ++i)
          for (int k = 0; k < dim_; ++k) x[i][k] = points[i * static_cast<std::size_t>(dim_) + static_cast<std::size_t>(k)];
        if (!judge_ || t < judged_time_) {  // first look, or the run was reset
          std::vector<std::uint8_t> tool(initial_.size(), 0);
          std::vector<Vec<4>> init4(initial_.begin(), initial_.end());
          for (const ScriptAction& a : scenario_->script)
            for (int v : selected_vertices<4>(*scenario_, first_, count_, init4, a.select))
              tool[static_cast<std::size_t>(v)] = 1;
          judge_ = std::make_unique<VerdictJudge>(*scenario_, first_, count_, initial_, tool);
          judged_time_ = 0;
        }
        judge_->observe(judged_time_, t, x);
        judged_time_ = t;
        r.verdict = judge_->judge(x);
      }
    } catch (const std::exception& e) {
      VerdictResult v;
      v.detail = std::string("the check failed: ") + e.what();
      r.verdict = v;
    }
    r.check_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    std::lock_guard lock(mutex_);
    r.rounds = result_.rounds + 1;
    result_ = r;
    busy_ = false;
  }
}

}  // namespace s4d
