// The live panel's engine: identification in the given view, the panel's texts, and the further
// invariants (covers, Reidemeister search, solid-torus recognition) where candidates remain.
// Sections: [SECTION] texts, [SECTION] further invariants, [SECTION] worker
#include "knots/knot_info.hpp"

#include <algorithm>
#include <chrono>
#include <set>

#include "core/error.hpp"
#include "knots/knot_table.hpp"
#include "knots/link_table.hpp"
#include "knots/regina_link.hpp"

namespace s4d {

namespace {

// [SECTION] texts

std::string factor_label(const KnotFactor& f) {
  std::string s = f.text();
  if (f.entry && !f.entry->rolfsen_name.empty() && !f.entry->dt_name.empty())
    s += " (DT " + f.entry->dt_name + ")";
  return s;
}

std::string name_of(const KnotIdentification& id) {
  if (id.candidates.size() == 1)
    return id.candidates[0].size() == 1 ? factor_label(id.candidates[0][0])
                                        : factorisation_text(id.candidates[0]);
  std::string s = "one of:";
  for (std::size_t i = 0; i < id.candidates.size(); ++i)
    s += (i ? ", " : " ") + factorisation_text(id.candidates[i]);
  return s;
}

std::string chirality_sentence(const KnotFactor& f) {
  const std::string n = f.entry->display_name();
  const std::string table =
      !f.entry->rolfsen_name.empty() ? "the Rolfsen table's (Knot Atlas) diagram" : "the census diagram";
  switch (f.chirality) {
    case Chirality::kAsTable:
      return n + " as drawn in " + table + ", not its mirror image";
    case Chirality::kMirror:
      return "the mirror image of " + n + " as drawn in " + table;
    case Chirality::kAmphichiral:
      return n + " is amphichiral: the same knot as its mirror image (proven)";
    case Chirality::kUnknown:
      return "unknown: HOMFLY-PT cannot tell " + n +
             " from its mirror image, and no proof either way is known here";
  }
  return {};
}

std::string link_chirality_sentence(const LinkCandidate& l) {
  const std::string n = l.entry->name;
  switch (l.chirality) {
    case Chirality::kAsTable: return n + " as drawn in KnotInfo's link table, not its mirror image";
    case Chirality::kMirror: return "the mirror image of " + n + " as drawn in KnotInfo's link table";
    default:
      return "unknown: HOMFLY-PT (in every orientation) cannot tell " + n + " from its mirror image";
  }
}

std::string chirality_text(const KnotIdentification& id) {
  if (id.kind == KnotKind::kUnknot) return id.proven ? "the unknot is amphichiral" : "";
  if (id.kind == KnotKind::kLink)
    return id.link_candidates.size() == 1 && id.link_candidates[0].entry
               ? link_chirality_sentence(id.link_candidates[0])
               : "";
  if (id.kind == KnotKind::kLink || id.candidates.size() != 1) return "";
  const auto& f = id.candidates[0];
  if (f.size() == 1) return chirality_sentence(f[0]);
  std::string s;
  for (const auto& k : f) s += (s.empty() ? "" : "; ") + chirality_sentence(k);
  return s;
}

// [SECTION] further invariants

template <int k>
void covers_of_index(const regina::GroupPresentation& g, std::vector<std::string>& out) {
  g.enumerateCovers<k>([&](regina::GroupPresentation&& sub) { out.push_back(sub.abelianisation().str()); });
}

regina::Link table_link(const KnotFactor& f) {
  regina::Link l = regina::Link::fromKnotSig(f.entry->sig);
  if (f.chirality == Chirality::kMirror) l.reflect();
  return l;
}

}  // namespace

std::string cover_signature(const KnotDiagram& diagram, int max_index) {
  if (max_index > 7) throw Error("covers of index above 7 are too slow to count here");
  const regina::GroupPresentation g = to_regina_link(diagram).group(true);
  std::string sig;
  for (int k = 2; k <= max_index; ++k) {
    std::vector<std::string> homology;
    switch (k) {
      case 2:
        covers_of_index<2>(g, homology);
        break;
      case 3:
        covers_of_index<3>(g, homology);
        break;
      case 4:
        covers_of_index<4>(g, homology);
        break;
      case 5:
        covers_of_index<5>(g, homology);
        break;
      case 6:
        covers_of_index<6>(g, homology);
        break;
      case 7:
        covers_of_index<7>(g, homology);
        break;
    }
    std::sort(homology.begin(), homology.end());
    sig += std::to_string(k) + ":";
    for (const auto& h : homology) sig += " " + h + ",";
    sig += "; ";
  }
  return sig;
}

namespace {

// Links the HOMFLY-PT polynomial, the components and the linking numbers leave together (mostly
// mutants): covers of the link group tell most apart (index 2 to 5 decide 75 of the table's 77
// such groups). Regina's Reidemeister search takes knots only.
void refine_link(KnotIdentification& id, const KnotInfoOptions& options, std::vector<std::string>& used,
                 std::vector<std::string>& decided) {
  const auto table = std::count_if(id.link_candidates.begin(), id.link_candidates.end(),
                                   [](const LinkCandidate& c) { return c.entry != nullptr; });
  if (table < 2 || options.max_cover_index < 2) return;
  const std::string covers = "covers of the link group of index 2 to " + std::to_string(options.max_cover_index);
  const std::string mine = cover_signature(id.diagram, options.max_cover_index);
  used.push_back(covers + ", with their homology (Regina)");
  std::vector<LinkCandidate> kept;
  for (const LinkCandidate& c : id.link_candidates)
    if (!c.entry || cover_signature(link_diagram(*c.entry), options.max_cover_index) == mine) kept.push_back(c);
  if (kept.size() == id.link_candidates.size() || kept.empty()) return;
  decided.push_back(covers + " rule out " + std::to_string(id.link_candidates.size() - kept.size()) +
                    " candidate(s)");
  id.link_candidates = std::move(kept);
  const KnotIndex& index = options.index ? *options.index : KnotIndex::shipped();
  settle_link(id, index, LinkTable::shipped());
}

}  // namespace

void refine_identification(KnotIdentification& id, const KnotInfoOptions& options,
                           std::vector<std::string>& used, std::vector<std::string>& decided) {
  const KnotIndex& index = options.index ? *options.index : KnotIndex::shipped();
  if (id.kind == KnotKind::kLink) return refine_link(id, options, used, decided);
  if (id.diagram.component_count() != 1) return;
  if (id.kind == KnotKind::kUnknot && !id.proven) {
    used.push_back("unknot recognition of the complement (Regina: is it a solid torus?)");
    if (is_unknot(id.diagram, true)) {
      id.proven = true;
      id.name = "unknot";
      decided.push_back("the complement is a solid torus (Regina's unknot recognition)");
    } else {
      id.kind = KnotKind::kUnknown;
      id.name =
          "a knot with trivial HOMFLY-PT polynomial that is not the unknot (its complement is not a solid "
          "torus)";
      id.proven = true;
      decided.push_back("the complement is not a solid torus (Regina's unknot recognition)");
    }
    return;
  }
  if (id.candidates.size() < 2) return;
  const auto prime_with_diagram = [](const KnotFactorisation& f) {
    return f.size() == 1 && !f[0].entry->sig.empty();
  };

  // Covers: the number and homology of index-k covers are invariants of the knot group.
  if (options.max_cover_index >= 2) {
    const std::string mine = cover_signature(id.diagram, options.max_cover_index);
    used.push_back("covers of the knot group of index 2 to " + std::to_string(options.max_cover_index) +
                   ", with their homology (Regina)");
    std::vector<KnotFactorisation> kept;
    for (const auto& f : id.candidates) {
      if (!prime_with_diagram(f) ||
          cover_signature(diagram_from_regina(table_link(f[0])), options.max_cover_index) == mine)
        kept.push_back(f);
    }
    if (kept.size() < id.candidates.size() && !kept.empty()) {
      decided.push_back("covers of the knot group of index 2 to " + std::to_string(options.max_cover_index) +
                        " rule out " + std::to_string(id.candidates.size() - kept.size()) + " candidate(s)");
      id.candidates = std::move(kept);
    }
  }

  // Reidemeister search: reaching a candidate's table diagram proves the knot is that one.
  if (id.candidates.size() > 1 && options.rewrite_height >= 0) {
    std::vector<std::pair<std::string, std::size_t>> targets;
    for (std::size_t i = 0; i < id.candidates.size(); ++i)
      if (prime_with_diagram(id.candidates[i]))
        targets.emplace_back(table_link(id.candidates[i][0]).knotSig(), i);
    regina::Link link = to_regina_link(id.diagram);
    link.intelligentSimplify();
    used.push_back("a Reidemeister search (Regina's rewrite, up to " +
                   std::to_string(options.rewrite_height) +
                   " extra crossing(s)) towards the candidates' table diagrams");
    std::optional<std::size_t> hit;
    auto match = [&](const std::string& sig) {
      for (const auto& [t, i] : targets)
        if (t == sig) {
          hit = i;
          return true;
        }
      return false;
    };
    if (!match(link.knotSig()) && options.rewrite_height > 0)
      link.rewrite(options.rewrite_height, 1, nullptr,
                   [&](const std::string& sig, const regina::Link&) { return match(sig); });
    if (hit) {
      decided.push_back("Reidemeister moves turn the diagram into the table's diagram of " +
                        factorisation_text(id.candidates[*hit]));
      id.candidates = {id.candidates[*hit]};
    }
  }
  id.proven = id.candidates.size() == 1 && id.invariants.simplified_crossings <= index.max_crossings();
  id.kind = id.candidates[0].size() == 1 ? KnotKind::kPrime : KnotKind::kComposite;
  id.name = name_of(id);
}

KnotInfo knot_info(const Curve<3>& curve, const std::optional<Frame<3>>& view,
                   const KnotInfoOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  const KnotIndex& index = options.index ? *options.index : KnotIndex::shipped();
  IdentifyOptions o;
  o.frame = view.value_or(Frame<3>());
  o.choose_view = false;
  o.index = &index;
  KnotInfo info;
  info.identification = identify_knot(curve, o);
  KnotIdentification& id = info.identification;
  const KnotDiagram& d = id.diagram;
  const KnotInvariants& v = id.invariants;

  info.view_crossings = d.crossing_count();
  info.simplified_crossings = v.simplified_crossings;
  info.gauss_code = d.gauss_code();
  info.signed_gauss_code = d.signed_gauss_code();
  info.writhe = d.writhe();
  info.components = d.component_count();
  info.linking = v.linking;
  info.alexander = v.alexander_text();
  info.jones = v.jones_text();
  info.homfly = v.homfly_text();
  info.determinant = v.determinant;

  // What the identification itself rests on.
  if (id.kind == KnotKind::kUnknot && id.proven && v.simplified_crossings == 0) {
    info.decided_by.push_back("Reidemeister simplification to a diagram without crossings (Regina)");
  } else if (id.kind == KnotKind::kUnknot && id.proven) {
    info.decided_by.push_back("the complement is a solid torus (Regina's unknot recognition)");
  } else if ((id.kind == KnotKind::kPrime || id.kind == KnotKind::kComposite) && id.candidates.size() == 1) {
    info.decided_by.push_back("the HOMFLY-PT polynomial, matched against every prime knot of the census to " +
                              std::to_string(index.max_crossings()) + " crossings" +
                              (id.kind == KnotKind::kComposite ? " and their products" : ""));
    if (id.proven)
      info.decided_by.push_back("a simplified diagram of " + std::to_string(v.simplified_crossings) +
                                " crossings, so the census holds every knot it could be");
  } else if (id.kind == KnotKind::kLink && !id.link_candidates.empty()) {
    const LinkTable& links = LinkTable::shipped();
    info.decided_by.push_back(
        "the HOMFLY-PT polynomial in every orientation, the components' knot types and linking numbers, matched "
        "against Thistlethwaite's link table to " + std::to_string(links.max_crossings()) + " crossings");
    if (id.proven)
      info.decided_by.push_back("a connected simplified diagram of " + std::to_string(v.simplified_crossings) +
                                " crossings, and no split or composite link with the same HOMFLY-PT, so the "
                                "table holds every link it could be");
  }
  if (options.refine && (id.candidates.size() > 1 || id.link_candidates.size() > 1 ||
                         (id.kind == KnotKind::kUnknot && !id.proven))) {
    const bool was_proven = id.proven;
    refine_identification(id, options, info.further_used, info.decided_by);
    if (id.kind == KnotKind::kLink && id.proven && !was_proven)
      info.decided_by.push_back("then one table link left, a connected simplified diagram of " +
                                std::to_string(v.simplified_crossings) +
                                " crossings, and no split or composite link with the same HOMFLY-PT");
  }

  info.name = id.name;
  info.proven = id.proven;
  info.chirality = chirality_text(id);
  if (id.kind == KnotKind::kUnknot) info.candidates = {"unknot"};
  for (const auto& f : id.candidates) info.candidates.push_back(factorisation_text(f));
  for (const auto& l : id.link_candidates) info.candidates.push_back(l.text());
  info.milliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return info;
}

// [SECTION] worker

KnotInfoWorker::KnotInfoWorker(KnotInfoOptions options) : options_(options) {
  thread_ = std::thread([this] { run(); });
}

KnotInfoWorker::~KnotInfoWorker() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

std::uint64_t KnotInfoWorker::submit(Curve<3> curve, std::optional<Frame<3>> view) {
  std::uint64_t n;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    n = ++submitted_;
    pending_.emplace(std::move(curve), view);
    pending_request_ = n;
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
}

}  // namespace s4d
