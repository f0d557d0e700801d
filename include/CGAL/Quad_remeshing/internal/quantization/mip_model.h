// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_QUAD_REMESHING_INTERNAL_QUANTIZATION_MIP_MODEL_H
#define CGAL_QUAD_REMESHING_INTERNAL_QUANTIZATION_MIP_MODEL_H

#include <CGAL/Quad_remeshing/internal/quantization/problem_helpers.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

struct Quantization_weights
{
  double isometry = 1, regularity_quads = 99, regularity_others = 91, alignment = 9;
  double under_subdivision = 4; // factor of the isometry term of an arc with fewer edges than its target
};

// The isometry term of an arc of `x` edges whose target is `t`, before the isometry weight: the squared
// deviation, `w.under_subdivision` times larger below the target. Too few edges stretch the quads across
// the arc and cut corners off the surface; too many only make them smaller. Convex in `x` for a factor >= 1.
inline double isometry_cost(double x, double t, const Quantization_weights& w)
{
  const double d = x - t;
  return d < 0 ? w.under_subdivision * d * d : d * d;
}

struct Cluster_result
{
  std::size_t variables = 0, constraints = 0;
  int status = -1; // a Mip_status value, or -1 when no solver ran
  bool solved = false;
};

// The integer window [lo, hi] of an arc around its target. Inside it the convex squared deviation is
// represented exactly at integers by the secants through consecutive integers; the window is wide
// enough (at least 3 on each side) for parity and regularity moves. An arc's minimum raises the low
// end and, if it passes the high end, moves the high end as far above the minimum.
inline void arc_window(const Side_quantization_problem::Arc& arc, int& lo, int& hi)
{
  const double t = arc.target;
  const int r = (std::max)(3, static_cast<int>(std::ceil(0.5 * t)));
  lo = (std::max)(1, static_cast<int>(std::floor(t)) - r);
  hi = static_cast<int>(std::ceil(t)) + r;
  lo = (std::max)(lo, arc.minimum);
  hi = (std::max)(hi, lo + r);
}

// Builds and solves the program of one cluster (its patches; arcs not in the cluster are fixed in
// v.fixed) and writes the values of its free arcs into s. `pairs` are the alignment terms of the
// program (both patches in the cluster). The traits object is used once.
template <typename MIP>
Cluster_result solve_cluster(const Quantization_view& v, const std::vector<std::size_t>& patches,
                             const std::vector<Alignment_pair>& pairs,
                             const Quantization_weights& w, double time_limit, std::size_t node_limit,
                             double gap, std::vector<int>& s, MIP& mip)
{
  typedef typename MIP::Variable Variable;
  typedef typename MIP::Linear_constraint Constraint;
  typedef typename MIP::Linear_objective Objective;
  const Side_quantization_problem& pb = *v.problem;
  Cluster_result res;
  mip.set_time_limit(time_limit);
  mip.set_node_limit(node_limit);
  mip.set_relative_gap(gap);
  Objective* obj = mip.create_objective(Objective::MINIMIZE);
  // The incoming s (the fallback's values) as a starting point: every auxiliary variable takes its
  // smallest feasible value. Offered only if every arc lies in its window.
  std::vector<double> x0;
  bool x0_valid = true;
  auto start = [&](Variable* x, double value) {
    if(x0.size() <= std::size_t(x->index())) x0.resize(std::size_t(x->index()) + 1, 0.);
    x0[std::size_t(x->index())] = value;
  };
  auto e_of = [&](std::size_t p, std::size_t i) { return double(side_count(v, p, i, s)); };

  // Arcs in ascending id order: deterministic variable numbering.
  std::map<std::size_t, Variable*> var;
  for(std::size_t p : patches)
    for(std::size_t a : v.patch_arcs[p])
      if(v.fixed[a] == 0) var.emplace(a, nullptr);
  for(auto& kv : var) {
    const double t = pb.arcs[kv.first].target;
    int lo, hi; arc_window(pb.arcs[kv.first], lo, hi);
    kv.second = mip.create_variable(Variable::INTEGER, lo, hi);
    Variable* epi = mip.create_variable(Variable::CONTINUOUS, 0, Variable::infinity());
    const int s0 = s[kv.first];
    if(s0 < lo || s0 > hi) x0_valid = false;
    start(kv.second, s0);
    start(epi, isometry_cost(s0, t, w));
    obj->add_coefficient(epi, w.isometry);
    for(int j = lo; j < hi; ++j) {
      // epi >= f(j) + m (s - j), m = f(j+1) - f(j), f = isometry_cost(., t, w) (convex: its chords bound it)
      const double fj = isometry_cost(j, t, w), m = isometry_cost(j + 1, t, w) - fj;
      Constraint* c = mip.create_constraint(fj - m * j, Variable::infinity());
      c->add_coefficient(epi, 1.);
      c->add_coefficient(kv.second, -m);
    }
  }
  // e_i = sum of arcs of side i: a linear form (variable part + constant part).
  auto add_side = [&](Constraint* c, std::size_t p, std::size_t i, double sign, double& constant) {
    for(std::size_t a : pb.patches[p][i]) {
      if(v.fixed[a] > 0) constant += sign * v.fixed[a];
      else c->add_coefficient(var[a], sign); // accumulates
    }
  };
  for(std::size_t p : patches) {
    const std::size_t n = pb.patches[p].size();
    // Parity: perimeter = 2 k, k >= 2.
    {
      Variable* k = mip.create_variable(Variable::INTEGER, 2, Variable::infinity());
      Constraint* c = mip.create_constraint(0, 0);
      double constant = 0;
      for(std::size_t i = 0; i < n; ++i) add_side(c, p, i, 1., constant);
      c->add_coefficient(k, -2.);
      c->set_bounds(-constant, -constant);
      start(k, 0.5 * double(perimeter(v, p, s)));
    }
    if(n == 4) {
      for(std::size_t i = 0; i < 2; ++i) {
        // d >= |e_i - e_{i+2}| through two rows
        Variable* d = mip.create_variable(Variable::CONTINUOUS, 0, Variable::infinity());
        obj->add_coefficient(d, w.regularity_quads);
        start(d, std::abs(e_of(p, i) - e_of(p, i + 2)));
        for(double sign : {1., -1.}) {
          Constraint* c = mip.create_constraint(0, Variable::infinity());
          double constant = 0;
          c->add_coefficient(d, 1.);
          add_side(c, p, i, -sign, constant);
          add_side(c, p, i + 2, sign, constant);
          c->set_bounds(-constant, Variable::infinity());
        }
      }
    } else {
      // Tarini's inequalities  sum r_j e_j + slack >= 2, slack weighted per patch (1/n).
      for(const auto& r : tarini_rows(n)) {
        Variable* sl = mip.create_variable(Variable::CONTINUOUS, 0, Variable::infinity());
        obj->add_coefficient(sl, w.regularity_others / double(n));
        Constraint* c = mip.create_constraint(2, Variable::infinity());
        double constant = 0, lhs = 0;
        for(std::size_t i = 0; i < n; ++i) if(r[i] != 0) { add_side(c, p, i, double(r[i]), constant); lhs += r[i] * e_of(p, i); }
        start(sl, (std::max)(0., 2. - lhs));
        c->add_coefficient(sl, 1.);
        c->set_bounds(2. - constant, Variable::infinity());
      }
      if(n == 6) {
        // Soft hexagon parity: e0 + e2 + e4 = 2 h + odd, odd in {0, 1} penalised.
        Variable* h = mip.create_variable(Variable::INTEGER, 0, Variable::infinity());
        Variable* odd = mip.create_variable(Variable::BINARY, 0, 1);
        obj->add_coefficient(odd, w.regularity_others / double(n));
        Constraint* c = mip.create_constraint(0, 0);
        double constant = 0;
        for(std::size_t i : {0, 2, 4}) add_side(c, p, i, 1., constant);
        c->add_coefficient(h, -2.);
        c->add_coefficient(odd, -1.);
        const long sum = long(e_of(p, 0) + e_of(p, 2) + e_of(p, 4));
        start(h, double(sum / 2));
        start(odd, double(sum % 2));
        c->set_bounds(-constant, -constant);
      }
    }
  }
  // Alignment: d >= |up_p - down_q| and d' >= |down_p - up_q|, each weighted w.alignment / 2.
  auto add_form = [&](Constraint* c, std::size_t p, const std::vector<int>& r, double sign, double& constant) {
    for(std::size_t k = 0; k < r.size(); ++k) if(r[k] != 0) add_side(c, p, k, sign * r[k], constant);
  };
  if(w.alignment > 0)
    for(const Alignment_pair& ap : pairs) {
      std::vector<int> up_p, down_p, up_q, down_q;
      sub_side_rows(pb.patches[ap.p].size(), ap.i, up_p, down_p);
      sub_side_rows(pb.patches[ap.q].size(), ap.j, up_q, down_q);
      const std::vector<int>* forms[2][2] = {{&up_p, &down_q}, {&down_p, &up_q}};
      for(const auto& f : forms) {
        Variable* d = mip.create_variable(Variable::CONTINUOUS, 0, Variable::infinity());
        obj->add_coefficient(d, 0.5 * w.alignment);
        start(d, std::abs(double(dot_sides(v, ap.p, *f[0], s) - dot_sides(v, ap.q, *f[1], s))));
        for(double sign : {1., -1.}) {
          // d - sign (form_p - form_q) >= 0
          Constraint* c = mip.create_constraint(0, Variable::infinity());
          double constant = 0;
          c->add_coefficient(d, 1.);
          add_form(c, ap.p, *f[0], -sign, constant);
          add_form(c, ap.q, *f[1], sign, constant);
          c->set_bounds(-constant, Variable::infinity());
        }
      }
    }
  res.variables = mip.number_of_variables();
  res.constraints = mip.number_of_constraints();
  if(x0_valid) { x0.resize(mip.number_of_variables(), 0.); mip.set_initial_solution(x0); }
  res.solved = mip.solve();
  res.status = static_cast<int>(mip.status());
  if(res.solved)
    for(const auto& kv : var) s[kv.first] = static_cast<int>(std::lround(kv.second->solution_value()));
  return res;
}

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif
