// Knot-energy relaxation (KnotPlot-style): self-repulsion between all vertices plus springs along
// the curve and a little bending stiffness. Every step is limited so that no two non-neighbouring
// segments can meet, so the knot type never changes: a messy unknot relaxes towards a round
// circle, a trefoil towards a symmetric trefoil.
#pragma once
#include <vector>

#include "shape/curve.hpp"

namespace s4d {

// What does not change during a run (MuJoCo's "model").
struct RelaxModel {
  // Defaults tuned on scrambled unknots (closed braids w s1 s2 s3 w^-1): strong bending is what
  // unrolls the last twists into a circle; repulsion alone only spreads the strands.
  double repulsion = 2.0;   // weight of the 1/r^2 vertex repulsion (dimensionless)
  double spring = 2.0;      // weight of the edge-length springs towards rest_length
  double bending = 4.0;     // weight of the discrete Laplacian smoothing
  double step = 0.15;       // gradient step, in units of the rest length
  double max_move = 0.2;    // cap per vertex per step, in units of the rest length
  double safety = 0.3;      // a vertex moves at most safety × (nearest non-neighbour segment gap)
  // Contact: non-neighbouring segments nearer than thickness (× rest length) are pushed apart
  // along their closest points, harder the nearer they are. Without it bending can pull two
  // strands ever closer (the cap shrinks every step but never stops them) until rounding lets
  // one pass through the other.
  double thickness = 0.3;
  double contact = 4.0;     // weight of that push (dimensionless)
  // Per component: first vertex index into the flat arrays, vertex count, rest edge length.
  std::vector<int> first, count;
  std::vector<double> rest_length;
};

// What does (MuJoCo's "data"): buffers sized once, no allocation in a step.
struct RelaxData {
  std::vector<Vec3> x;      // n, positions (flat over components)
  std::vector<Vec3> force;  // n, scratch
  std::vector<int> comp;    // n, component of each vertex
  double min_gap = 0;       // last step's smallest non-neighbour segment distance (lower bound)
  int limited_steps = 0;    // steps shortened by the no-pass-through cap (counted, not thrown)
};

// Builds the model and data of a closed curve (rest lengths = current mean edge lengths).
// Validates like validate_knot_curve.
void relax_setup(const Curve<3>& curve, RelaxModel& model, RelaxData& data);
// One gradient step. Never moves two non-neighbouring segments into contact.
void relax_step(const RelaxModel& model, RelaxData& data);
// A step's first stages alone: every vertex's force (into data.force) and data.min_gap, nothing
// moved. The live relaxation (interact/live_simulation) drives a World by these.
void relax_forces(const RelaxModel& model, RelaxData& data);
// The move relax_step gives vertex i after relax_forces: step × force, within the
// no-pass-through cap (zero when not finite); `limited` is set when the cap shortened it.
Vec3 relax_move(const RelaxModel& model, const RelaxData& data, int i, bool& limited);
// The data's positions as a curve again.
Curve<3> relax_curve(const RelaxModel& model, const RelaxData& data);
// Convenience: `iterations` steps from `curve`.
Curve<3> relax(const Curve<3>& curve, int iterations, const RelaxModel& params = {});

}  // namespace s4d
