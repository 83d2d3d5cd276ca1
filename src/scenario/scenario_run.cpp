// Executes a scenario (see scenario_run.hpp): world from objects, scripted tool, frames, checks.
#include "scenario_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numeric>
#include <sstream>

#include "core/error.hpp"
#include "core/plane.hpp"
#include "io/off.hpp"
#include "io/scene.hpp"
#include "physics/world.hpp"
#include "proximity/mesh_proximity.hpp"
#include "render/renderer.hpp"
#include "scenario_verdicts.hpp"

namespace s4d::scenario {
namespace {

using Json = nlohmann::json;

Surface<4> build_object(const ObjectSpec& o, int dim) {
  const Shape shape = generate(o.generator.name, o.generator.params);
  Surface<4> s;
  if (const auto* s3 = std::get_if<Surface<3>>(&shape))
    s = lift_to_4d(*s3);
  else if (const auto* s4 = std::get_if<Surface<4>>(&shape))
    s = *s4;
  else
    throw Error(o.name + ": generator '" + o.generator.name + "' makes a curve, not a surface");
  if (!o.matrix.empty()) {
    Eigen::Matrix4d m;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) m(r, c) = o.matrix[4 * r + c];
    for (Vec4& p : s.vertices) p = m * p;
    if (m.determinant() < 0 && o.mirror.size() % 2 == 0)
      for (Triangle& t : s.triangles) std::swap(t[1], t[2]);
  }
  for (Vec4& p : s.vertices) {
    p *= o.scale;
    for (int a : o.mirror) p[a] = -p[a];
  }
  if (o.w_by_row != 0) {
    if (!s.grid) throw Error(o.name + ": w_by_row needs a grid surface");
    for (int i = 0; i < s.grid->rows; ++i)
      for (int j = 0; j < s.grid->cols; ++j)
        s.vertices[s.grid->index(i, j)][3] +=
            o.w_by_row * (static_cast<double>(i) / (s.grid->rows - 1) - 0.5);
  }
  for (Vec4& p : s.vertices)
    for (std::size_t k = 0; k < o.offset.size(); ++k) p[k] += o.offset[k];
  if (dim == 3)
    for (const Vec4& p : s.vertices)
      if (p[3] != 0) throw Error(o.name + ": this object is not in R^3 (w != 0)");
  // Mirroring an odd number of axes flips orientation; keep triangles counter-clockwise.
  if (o.mirror.size() % 2 == 1)
    for (Triangle& t : s.triangles) std::swap(t[1], t[2]);
  return s;
}

template <int D>
Vec<D> head(const std::vector<double>& v) {
  Vec<D> r = Vec<D>::Zero();
  for (int k = 0; k < D && k < static_cast<int>(v.size()); ++k) r[k] = v[k];
  return r;
}

template <int D>
Surface<D> to_dim(const Surface<4>& s) {
  Surface<D> r;
  r.triangles = s.triangles;
  r.grid = s.grid;
  for (const Vec4& p : s.vertices) r.vertices.push_back(p.head<D>());
  return r;
}

template <int D>
PhysicsParams<D> to_dim(const PhysicsParams<4>& p) {
  PhysicsParams<D> q;
  q.time_step = p.time_step;
  q.thickness = p.thickness;
  q.gravity = p.gravity.head<D>();
  q.mass = p.mass;
  q.stiffness = p.stiffness;
  q.shear_scale = p.shear_scale;
  q.bending_scale = p.bending_scale;
  q.beta = p.beta;
  q.damping = p.damping;
  q.spring_damping = p.spring_damping;
  q.friction = p.friction;
  q.integrator = p.integrator;
  q.collisions = p.collisions;
  q.max_step_motion = p.max_step_motion;
  return q;
}

struct ActiveTool {
  const Action* action = nullptr;
  std::vector<int> vertices;
  std::vector<Vec4> start;  // positions when the tool engaged
  bool engaged = false;
};

std::string fmt(double x, int prec = 3) {
  char b[64];
  std::snprintf(b, sizeof b, "%.*g", prec, x);
  return b;
}

template <int D>
RunResult run(const ScenarioSpec& spec, const RunOptions& opt) {
  // [SECTION] Build
  std::vector<Surface<4>> objects;
  std::vector<int> first;
  ModelBuilder<D> builder(to_dim<D>(spec.physics));
  for (const ObjectSpec& o : spec.objects) {
    objects.push_back(build_object(o, D));
    first.push_back(builder.add_body(to_dim<D>(objects.back()), o.mass));
  }
  World<D> world(builder.build());
  const Model<D>& model = world.model();
  auto object_index = [&](const std::string& name) {
    for (std::size_t i = 0; i < spec.objects.size(); ++i)
      if (spec.objects[i].name == name) return static_cast<int>(i);
    throw Error("no object named '" + name + "'");
  };
  auto pos4 = [&](int v) {
    Vec4 p = Vec4::Zero();
    p.head<D>() = world.positions()[v];
    return p;
  };
  auto select = [&](const Selection& s) {
    const int o = object_index(s.object);
    const int n = static_cast<int>(objects[o].vertices.size());
    std::vector<int> v(n);
    std::iota(v.begin(), v.end(), first[o]);
    if (!s.indices.empty()) {
      v.clear();
      for (int i : s.indices) {
        const int local = i < 0 ? n + i : i;
        if (local < 0 || local >= n)
          throw Error(s.object + ": vertex " + std::to_string(i) + " out of range (it has " +
                      std::to_string(n) + ")");
        v.push_back(first[o] + local);
      }
    } else if (!s.all) {
      std::stable_sort(v.begin(), v.end(), [&](int a, int b) {
        return s.max_side ? pos4(a)[s.axis] > pos4(b)[s.axis] : pos4(a)[s.axis] < pos4(b)[s.axis];
      });
      v.resize(std::min(n, s.count));
    }
    return v;
  };
  std::vector<ActiveTool> tools;
  for (const Action& a : spec.script) tools.push_back({&a, select(a.select), {}, false});
  std::vector<Vec4> initial;
  for (int v = 0; v < model.nv; ++v) initial.push_back(pos4(v));

  // [SECTION] Frames and checks
  const int frames = opt.frames > 0 ? opt.frames : spec.frames;
  std::filesystem::create_directories(opt.out_dir);
  std::vector<Cell<3>> cells(model.triangles.begin(), model.triangles.end());
  Vec4 lo = initial[0], hi = initial[0];
  for (const Vec4& p : initial) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double touch = 1e-9 * (hi - lo).norm();
  Json frame_log = Json::array();
  std::vector<ShadowCheck> shadow_log;  // shadow-clean: one per saved frame
  auto current_surface = [&](int o) {
    Surface<4> s = objects[o];
    for (std::size_t i = 0; i < s.vertices.size(); ++i) s.vertices[i] = pos4(first[o] + static_cast<int>(i));
    return s;
  };
  int total_intersections = 0;
  double min_gap = std::numeric_limits<double>::infinity();
  bool png = opt.png;
  std::string png_error;
  auto save_frame = [&](int k) {
    std::vector<Vec<D>> x(world.positions().begin(), world.positions().end());
    const int bad = static_cast<int>(intersecting_pairs<D, 3>(x, cells, touch).size());
    const double gap = world.min_separation(2 * model.contact_thickness);
    total_intersections += bad;
    min_gap = std::min(min_gap, gap);
    Json f{{"frame", k}, {"time", world.data().time}, {"intersections", bad},
           {"min_gap", std::isfinite(gap) ? Json(gap) : Json(nullptr)}};
    if (spec.verdict.kind == "shadow-clean") {
      const ShadowCheck sc =
          check_shadow(current_surface(object_index(spec.verdict.object)), spec.verdict.view);
      f["shadow_length"] = sc.total_length;
      f["shadow_curves"] = sc.curves;
      shadow_log.push_back(sc);
    }
    if (png) {
      Scene scene;
      // Show the shadow the verdict judges, when it names a view.
      if (!spec.verdict.view.empty()) apply_rotations(scene.frame, parse_rotation_list(spec.verdict.view, 4));
      for (std::size_t o = 0; o < objects.size(); ++o) {
        SceneObject so;
        so.name = spec.objects[o].name;
        so.shape = current_surface(static_cast<int>(o));
        scene.objects.push_back(std::move(so));
      }
      char name[32];
      std::snprintf(name, sizeof name, "frame_%03d.png", k);
      try {
        write_png(render_offscreen(scene, opt.png_width, opt.png_height), opt.out_dir / name);
        f["png"] = name;
      } catch (const Error& e) {
        png = false;  // no OpenGL here: keep simulating, say so in the metrics
        png_error = e.what();
      }
    }
    frame_log.push_back(f);
  };

  // [SECTION] Simulate
  const double dt = model.params.time_step;
  const long steps = std::lround(spec.duration / dt);
  // A "lifted" verdict may measure rises from a later state than the start (reference_time, s):
  // the hanging state once the bodies have settled on each other, just before the lift.
  const auto ref_it = spec.verdict.numbers.find("reference_time");
  const double reference_time = ref_it == spec.verdict.numbers.end() ? 0.0 : ref_it->second;
  std::vector<Vec4> reference = initial;
  const auto wall0 = std::chrono::steady_clock::now();
  save_frame(0);
  int next_frame = 1;
  for (long s = 1; s <= steps; ++s) {
    const double t = s * dt;
    for (ActiveTool& tool : tools) {
      const Action& a = *tool.action;
      if (t < a.from) continue;
      if (!tool.engaged) {
        tool.engaged = true;
        for (int v : tool.vertices) tool.start.push_back(pos4(v));
        if (a.kind != "pull")
          for (int v : tool.vertices) world.pin(v);
      }
      const double u = a.to > a.from ? std::clamp((t - a.from) / (a.to - a.from), 0.0, 1.0) : 1.0;
      const double ramp = u * u * (3 - 2 * u);  // smooth start and stop, as a hand would move
      const Vec<D> by = head<D>(a.by);
      for (std::size_t i = 0; i < tool.vertices.size(); ++i) {
        const int v = tool.vertices[i];
        const Vec<D> target = tool.start[i].head<D>() + (a.kind == "hold" ? 0.0 : ramp) * by;
        if (a.kind == "pull") {
          // Virtual coupling: spring to the target, critically damped, force-limited.
          const double c = 2 * std::sqrt(a.stiffness * model.mass[v]);
          Vec<D> f = a.stiffness * (target - world.positions()[v]) - c * world.velocities()[v];
          if (f.norm() > a.max_force) f *= a.max_force / f.norm();
          world.set_external_force(v, f);
        } else {
          world.set_target(v, target);
        }
      }
    }
    world.step();
    if (reference_time > 0 && t - dt < reference_time && t >= reference_time)
      for (int v = 0; v < model.nv; ++v) reference[v] = pos4(v);
    if (s * frames >= next_frame * steps) save_frame(next_frame++);
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();

  // [SECTION] Verdict
  std::vector<Vec4> x;
  for (int v = 0; v < model.nv; ++v) x.push_back(pos4(v));
  const Verdict& vd = spec.verdict;
  const int vo = object_index(vd.object);
  const int v0 = first[vo], v1 = v0 + static_cast<int>(objects[vo].vertices.size());
  auto num = [&](const std::string& k, double def) {
    const auto it = vd.numbers.find(k);
    return it == vd.numbers.end() ? def : it->second;
  };
  Json verdict{{"kind", vd.kind}};
  bool ok = true;
  std::string detail;
  if (vd.kind == "untied" || vd.kind == "knotted") {
    if (!objects[vo].grid) throw Error(vd.object + ": a knot verdict needs a grid ribbon");
    const Grid& g = *objects[vo].grid;
    std::vector<Vec4> xs(x.begin() + v0, x.begin() + v1), x0(initial.begin() + v0, initial.begin() + v1);
    auto centre4 = [&](const std::vector<Vec4>& p) {
      std::vector<Vec4> c;
      for (int i = 0; i < g.rows; ++i) {
        Vec4 s = Vec4::Zero();
        for (int j = 0; j < g.cols; ++j) s += p[g.index(i, j)];
        c.push_back(s / g.cols);
      }
      return c;
    };
    const std::vector<Vec4> c0 = centre4(x0), c1 = centre4(xs);
    double length = 0;
    for (std::size_t i = 1; i < c0.size(); ++i) length += (c0[i] - c0[i - 1]).norm();
    const double ends = (c1.back() - c1.front()).norm() / length;
    const Vec3 via = vd.close_via.empty() ? Vec3(0, 0, -1) : head<3>(vd.close_via);
    const Vec3 along = (c1.back() - c1.front()).head<3>();
    const KnotCheck k0 = check_knot(ribbon_centre_line(x0, g), via, along);
    const KnotCheck k1 = check_knot(ribbon_centre_line(xs, g), via, along);
    verdict["end_distance_over_length"] = ends;
    verdict["initial"] = {{"min_crossings", k0.min_crossings}, {"determinant", k0.determinant}};
    verdict["final"] = {{"min_crossings", k1.min_crossings}, {"max_crossings", k1.max_crossings},
                        {"open_crossings", k1.open_crossings}, {"determinant", k1.determinant},
                        {"simplified_crossings", k1.simplified_crossings}, {"knot_error", k1.error}};
    if (vd.kind == "untied") {
      const double need = num("end_fraction", 0.9);
      ok = ends >= need && k1.open_crossings <= num("max_open_crossings", 0) && k1.error.empty() &&
           k1.determinant == 1 && k1.simplified_crossings == 0;
      detail = "ends " + fmt(ends) + " of the length apart (need >= " + fmt(need) + "), shadow centre line " +
               std::to_string(k1.open_crossings) + " crossings in the worst transverse view, closed: " +
               (k1.simplified_crossings == 0 ? "unknot" : "det " + std::to_string(k1.determinant));
    } else {
      const int need = static_cast<int>(num("min_crossings", 3));
      ok = k1.min_crossings >= need && k1.error.empty() && k0.error.empty() &&
           k1.determinant == k0.determinant && k1.fingerprint == k0.fingerprint && k0.determinant == 3;
      detail = "closed centre line has >= " + std::to_string(k1.min_crossings) +
               " crossings in every view (need " + std::to_string(need) + "), det " +
               std::to_string(k1.determinant) + " (start " + std::to_string(k0.determinant) +
               "), knot type " + (k1.fingerprint == k0.fingerprint ? "unchanged" : "CHANGED") + ", ends " +
               fmt(ends) + " of length";
    }
  } else if (vd.kind == "slides-off") {
    const int axis = static_cast<int>(num("axis", 1));
    double top = -1e300, support = 1e300;
    for (int v = 0; v < model.nv; ++v) {
      if (v >= v0 && v < v1)
        top = std::max(top, x[v][axis]);
      else
        support = std::min(support, x[v][axis]);
    }
    verdict["object_top"] = top;
    verdict["support_bottom"] = support;
    ok = top < support - num("margin", 0);
    detail = vd.object + " top at " + fmt(top) + ", below the support's lowest point " + fmt(support) +
             (ok ? " (slid off)" : " (still held)");
  } else if (vd.kind == "lifted") {
    const int axis = static_cast<int>(num("axis", 1));
    int nc = 0;
    std::vector<Triangle> local;
    for (int t = model.body_first_triangle[vo]; t < model.body_first_triangle[vo + 1]; ++t)
      local.push_back({model.triangles[t][0] - v0, model.triangles[t][1] - v0, model.triangles[t][2] - v0});
    const std::vector<int> comp = vertex_components(v1 - v0, local, &nc);
    std::vector<double> rise(nc, 0.0), cnt(nc, 0.0);
    for (int v = v0; v < v1; ++v) {
      rise[comp[v - v0]] += x[v][axis] - reference[v][axis];
      cnt[comp[v - v0]] += 1;
    }
    double worst = 1e300;
    for (int c = 0; c < nc; ++c) worst = std::min(worst, rise[c] / cnt[c]);
    verdict["components"] = nc;
    verdict["min_rise"] = worst;
    verdict["rise_per_component"] = rise;
    verdict["reference_time"] = reference_time;
    for (int c = 0; c < nc; ++c) verdict["rise_per_component"][c] = rise[c] / cnt[c];
    const double need = num("min_rise", 0);
    ok = worst >= need;
    detail = std::to_string(nc) + " components, the lowest rose " + fmt(worst) + " (need >= " + fmt(need) +
             ")" + (reference_time > 0 ? " since t = " + fmt(reference_time) + " s" : "");
  } else if (vd.kind == "shadow-clean") {
    // The shadow's self-intersection curves at the start (they must exist, or the scenario proves
    // nothing) and at the end (their total length must have gone to max_final_length, 0 = none).
    const ShadowCheck s0 = shadow_log.front(), s1 = check_shadow(current_surface(vo), vd.view);
    Json lengths = Json::array();
    for (const ShadowCheck& c : shadow_log) lengths.push_back(c.total_length);
    verdict["view"] = vd.view;
    verdict["initial_length"] = s0.total_length;
    verdict["initial_curves"] = s0.curves;
    verdict["final_length"] = s1.total_length;
    verdict["final_curves"] = s1.curves;
    verdict["final_true_curves"] = s1.true_curves;
    verdict["final_coplanar_pairs"] = s1.coplanar_pairs;
    verdict["length_per_frame"] = lengths;
    const double need0 = num("min_initial_length", 0), max1 = num("max_final_length", 0);
    ok = s0.total_length >= need0 && s0.total_length > 0 && s1.total_length <= max1 && s1.true_curves == 0 &&
         s1.coplanar_pairs == 0;
    detail = "shadow self-intersection length " + fmt(s0.total_length) + " in " + std::to_string(s0.curves) +
             " curves at the start (need >= " + fmt(need0) + "), " + fmt(s1.total_length) + " in " +
             std::to_string(s1.curves) + " curves at the end (need <= " + fmt(max1) + ")" +
             (s1.coplanar_pairs > 0
                  ? ", " + std::to_string(s1.coplanar_pairs) + " coplanar pairs (view not generic)"
                  : "");
  } else {  // deforms: how far the body moved, not the vertices the tool carried
    std::vector<std::uint8_t> tool(model.nv, 0);
    for (const ActiveTool& t : tools)
      for (int v : t.vertices) tool[v] = 1;
    double moved = 0;
    for (int v = v0; v < v1; ++v)
      if (!tool[v]) moved = std::max(moved, (x[v] - initial[v]).norm());
    verdict["max_displacement"] = moved;
    const double need = num("min_displacement", 0);
    ok = moved >= need;
    detail = "largest displacement of a vertex the tool does not hold " + fmt(moved) +
             " (need >= " + fmt(need) + ")";
  }
  const bool embedded = total_intersections == 0 && min_gap > 0;
  ok = ok && embedded;

  // [SECTION] Outputs
  for (std::size_t o = 0; o < objects.size(); ++o) {
    Surface<D> s = to_dim<D>(objects[o]);
    for (std::size_t i = 0; i < s.vertices.size(); ++i) s.vertices[i] = world.positions()[first[o] + i];
    write_off<D>(s, opt.out_dir / ("final_" + spec.objects[o].name + (D == 4 ? ".4off" : ".off")));
  }
  const PhysicsWarnings& w = world.data().warnings;
  Json metrics{{"scenario", spec.name}, {"dim", D}, {"pass", ok}, {"vertices", model.nv},
               {"triangles", model.triangles.size()}, {"springs", model.springs.size()},
               {"steps", steps}, {"time_step", dt}, {"wall_seconds", wall},
               {"ms_per_step", 1e3 * wall / std::max<long>(1, steps)},
               {"contact_thickness", model.contact_thickness}, {"hard_thickness", model.hard_thickness},
               {"integrator", integrator_name(model.params.integrator)},
               {"true_intersections", total_intersections},
               {"min_gap", std::isfinite(min_gap) ? Json(min_gap) : Json(nullptr)},
               {"warnings", {{"rollbacks", w.rollbacks}, {"speed_clamps", w.speed_clamps},
                             {"ccd_freezes", w.ccd_freezes}, {"global_freezes", w.global_freezes}}},
               {"verdict", verdict}, {"frames", frame_log}};
  if (!png_error.empty()) metrics["png_error"] = png_error;
  std::ofstream(opt.out_dir / "metrics.json") << metrics.dump(2) << "\n";

  RunResult r;
  r.pass = ok;
  r.line = std::string(ok ? "PASS " : "FAIL ") + spec.name + ": " + detail + "; " +
           std::to_string(total_intersections) + " true intersections in " +
           std::to_string(frame_log.size()) + " frames (min gap " + fmt(min_gap) + ", hard layer " +
           fmt(model.hard_thickness) + "); " + std::to_string(model.nv) + " vertices, " +
           std::to_string(steps) + " steps, " + fmt(1e3 * wall / std::max<long>(1, steps)) + " ms/step, " +
           std::to_string(w.rollbacks) + " rollbacks, " + std::to_string(w.global_freezes) +
           " global freezes";
  return r;
}

}  // namespace

RunResult run_scenario(const ScenarioSpec& spec, const RunOptions& options) {
  return spec.dim == 3 ? run<3>(spec, options) : run<4>(spec, options);
}

}  // namespace s4d::scenario
