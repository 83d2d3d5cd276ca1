// The live information panel's engine (issue 26, point 6): for a curve as seen in a view, the
// crossings, codes, invariants and name with chirality, the candidates where the invariants
// cannot decide, whether the name is proven and what decided it; further exact invariants from
// Regina (covers of the knot group, Reidemeister search, unknot recognition) where candidates
// remain. KnotInfoWorker runs it off the UI thread, newest request first.
#pragma once
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "core/frame.hpp"
#include "knots/knot_identify.hpp"
#include "knots/knot_naming.hpp"
#include "shape/curve.hpp"

namespace s4d {

// The naming's options (fast, cover indices, tables); the view is knot_info's argument.
using KnotInfoOptions = NamingOptions;

struct KnotInfo {
  // In the view
  int view_crossings = 0;         // crossings of the curve's diagram in the view
  int simplified_crossings = 0;   // after Regina's simplification (>= the crossing number)
  std::string gauss_code;         // classical ("1, -2, 3, -1, 2, -3"; components by " | ")
  std::string signed_gauss_code;  // the panel's form ("1+a, 2+b, ...")
  int writhe = 0;                 // of the diagram in the view
  int components = 0;
  std::vector<std::vector<int>> linking;  // components × components (links)
  // Invariants, as the panel shows them
  std::string alexander, jones, homfly;  // in t (or t^(1/2)); HOMFLY-PT in a and z
  std::int64_t determinant = 0;
  // The name
  std::string name;                       // "3_1 (DT 3a_1) mirror", "11n_34", "unknot", a link's line
  std::string headline;                   // the name as shown: with "[not proven]", "[fast: ... skipped]"
  std::string chirality;                  // a sentence: which of the knot and its mirror this is
  std::vector<std::string> candidates;    // every answer still possible (one when decided)
  bool proven = false;                    // no other answer is possible
  std::vector<std::string> decided_by;    // the invariants and proofs that decided it, in order
  std::vector<std::string> further_used;  // the further invariants tried (decisive or not)
  std::vector<std::string> skipped;       // fast: the further invariants left out
  std::vector<std::string> unavailable;   // further invariants due that the engine lacks (no Regina)
  KnotIdentification identification;      // everything, for callers that want more
  double milliseconds = 0;                // time taken
};

// The curve as seen through `view` (nullopt: its own xy, i.e. the identity Frame<3>): its codes in
// that view, and its name from name_knot (knot_naming.hpp), starting from that view. Throws
// s4d::Error for an invalid curve (open, too short, touching itself; see diagram_from_curve).
// Fast, a 500-point, <= 12-crossing curve takes well under 5 ms; with the refinements, when
// candidates remain, up to about a second: call it off the UI thread (KnotInfoWorker).
KnotInfo knot_info(const Curve<3>& curve, const std::optional<Frame<3>>& view = std::nullopt,
                   const KnotInfoOptions& options = {});

// Cover signature of a knot diagram's group: per index 2..max_index, the sorted homology groups
// of its connected covers of that index ("2: Z + Z_3; 3: ..."). Equal for the same knot (and its
// mirror); exact (Regina), and slow beyond index 6.
std::string cover_signature(const KnotDiagram& diagram, int max_index);

// Runs knot_info on its own thread. submit() replaces any request not yet started and returns at
// once; latest() returns the newest finished result without waiting for one under way.
class KnotInfoWorker {
 public:
  struct Result {
    std::uint64_t request = 0;     // submit()'s number for it
    std::optional<KnotInfo> info;  // absent when the curve was refused
    std::string error;             // why it was refused ("" when info is set)
  };

  explicit KnotInfoWorker(KnotInfoOptions options = {});
  ~KnotInfoWorker();  // finishes the computation under way, then stops
  KnotInfoWorker(const KnotInfoWorker&) = delete;
  KnotInfoWorker& operator=(const KnotInfoWorker&) = delete;

  std::uint64_t submit(Curve<3> curve, std::optional<Frame<3>> view = std::nullopt);
  std::shared_ptr<const Result> latest() const;
  // Blocks until the result of request `n` (or a later one) is in, or `timeout_ms` passes.
  bool wait_for(std::uint64_t n, int timeout_ms) const;

 private:
  void run();
  void work(std::pair<Curve<3>, std::optional<Frame<3>>> job, std::uint64_t request);

  KnotInfoOptions options_;
  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  std::optional<std::pair<Curve<3>, std::optional<Frame<3>>>> pending_;
  std::uint64_t pending_request_ = 0, submitted_ = 0;
  std::shared_ptr<const Result> latest_;
  bool stop_ = false;
  std::thread thread_;
};

}  // namespace s4d
