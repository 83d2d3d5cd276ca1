// The live panel's engine: the codes of the curve's diagram in the view, and its name from the one
// naming decision (knot_naming.cpp).
#include "knots/knot_info.hpp"

#include <chrono>

#include "core/error.hpp"
#include "core/threads.hpp"

namespace s4d {

KnotInfo knot_info(const Curve<3>& curve, const std::optional<Frame<3>>& view, const KnotInfoOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  NamingOptions o = options;
  o.frame = view.value_or(Frame<3>());
  KnotNaming named = name_knot(curve, o);
  KnotInfo info;
  const KnotDiagram d = diagram_from_curve(curve, o.frame);  // the view's own, for its codes
  const KnotInvariants& v = named.identification.invariants;
  info.view_crossings = d.crossing_count();
  info.simplified_crossings = v.simplified_crossings;
  info.gauss_code = d.gauss_code();
  info.signed_gauss_code = d.signed_gauss_code();
  info.writhe = d.writhe();
  info.components = d.component_count();
  info.linking = d.linking_numbers();
  info.alexander = v.alexander_text();
  info.jones = v.jones_text();
  info.homfly = v.homfly_text();
  info.determinant = v.determinant;
  info.name = named.name();
  info.headline = named.headline();
  info.proven = named.proven();
  info.chirality = named.chirality();
  info.candidates = named.candidates();
  info.decided_by = std::move(named.decided_by);
  info.further_used = std::move(named.further_used);
  info.skipped = std::move(named.skipped);
  info.unavailable = std::move(named.unavailable);
  info.identification = std::move(named.identification);
  info.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return info;
}

// [SECTION] worker

// Without threads (the web page) there is no worker: submit() names the curve in place.
KnotInfoWorker::KnotInfoWorker(KnotInfoOptions options) : options_(options) {
  if constexpr (kHaveThreads) thread_ = std::thread([this] { run(); });
}

KnotInfoWorker::~KnotInfoWorker() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  if (thread_.joinable()) thread_.join();
}

std::uint64_t KnotInfoWorker::submit(Curve<3> curve, std::optional<Frame<3>> view) {
  std::uint64_t n;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    n = ++submitted_;
    pending_.emplace(std::move(curve), view);
    pending_request_ = n;
  }
  if (!thread_.joinable()) {
    auto job = std::move(*pending_);
    pending_.reset();
    work(std::move(job), n);
    return n;
  }
  changed_.notify_all();
  return n;
}

std::shared_ptr<const KnotInfoWorker::Result> KnotInfoWorker::latest() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return latest_;
}

bool KnotInfoWorker::wait_for(std::uint64_t n, int timeout_ms) const {
  std::unique_lock<std::mutex> lock(mutex_);
  return changed_.wait_for(lock, std::chrono::milliseconds(timeout_ms),
                           [&] { return latest_ && latest_->request >= n; });
}

void KnotInfoWorker::run() {
  for (;;) {
    std::pair<Curve<3>, std::optional<Frame<3>>> job;
    std::uint64_t request;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      changed_.wait(lock, [&] { return stop_ || pending_.has_value(); });
      if (stop_) return;
      job = std::move(*pending_);
      pending_.reset();
      request = pending_request_;
    }
    work(std::move(job), request);
  }
}

void KnotInfoWorker::work(std::pair<Curve<3>, std::optional<Frame<3>>> job, std::uint64_t request) {
  auto result = std::make_shared<Result>();
  result->request = request;
  try {
    result->info = knot_info(job.first, job.second, options_);
  } catch (const std::exception& e) {  // an invalid curve mid-edit: said, not thrown
    result->error = e.what();
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    latest_ = std::move(result);
  }
  changed_.notify_all();
}

}  // namespace s4d
