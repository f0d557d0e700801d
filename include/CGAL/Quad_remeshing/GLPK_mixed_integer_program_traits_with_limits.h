// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_QUAD_REMESHING_GLPK_MIXED_INTEGER_PROGRAM_TRAITS_WITH_LIMITS_H
#define CGAL_QUAD_REMESHING_GLPK_MIXED_INTEGER_PROGRAM_TRAITS_WITH_LIMITS_H

#include <CGAL/Mixed_integer_program_traits.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#if defined(CGAL_USE_GLPK) || defined(DOXYGEN_RUNNING)
#include <glpk.h>
#endif

namespace CGAL {
namespace Quad_remeshing {

/// \ingroup PkgQuadRemeshingRef
/// The outcome of a limited mixed-integer solve, as reported by a model of
/// `MixedIntegerProgramTraitsWithLimits` (CGAL's traits only say "solved or not").
enum class Mip_status {
  OPTIMAL,           ///< proven optimal within the relative gap
  FEASIBLE_AT_LIMIT, ///< the time or node limit was reached; the best feasible solution found is returned
  INFEASIBLE,        ///< no feasible solution exists (proven by the solver)
  NO_SOLUTION,       ///< a limit was reached before any feasible solution was found
  ERROR              ///< the solver failed, or its solution violates the constraints
};

/// \ingroup PkgQuadRemeshingRef
/// Returns a short lower-case name of `s` (`"optimal"`, `"feasible_at_limit"`, ...).
inline const char* to_string(Mip_status s)
{
  switch(s) {
    case Mip_status::OPTIMAL: return "optimal";
    case Mip_status::FEASIBLE_AT_LIMIT: return "feasible_at_limit";
    case Mip_status::INFEASIBLE: return "infeasible";
    case Mip_status::NO_SOLUTION: return "no_solution";
    default: return "error";
  }
}

#if defined(CGAL_USE_GLPK) || defined(DOXYGEN_RUNNING)

/// \ingroup PkgQuadRemeshingRef
/// A model of `MixedIntegerProgramTraitsWithLimits` over GLPK.
///
/// Unlike `CGAL::GLPK_mixed_integer_program_traits`, it honours a time limit and a relative gap, keeps
/// the incumbent when a limit stops the search, tells infeasibility apart from a limit or a failure,
/// and verifies the bounds and constraint residuals of any solution it returns. Rows are sent to GLPK
/// in variable-index order so that the solve is deterministic (the base class stores coefficients in
/// hash maps keyed by pointers). A node limit bounds the search without making the result depend on
/// the speed or load of the machine, as a time limit does. Open nodes are selected by GLPK's best
/// projection heuristic.
///
/// @tparam FT a floating-point number type (`double`)
template <typename FT = double>
class GLPK_mixed_integer_program_traits_with_limits
  : public CGAL::Mixed_integer_program_traits<FT>
{
public:
  /// \cond SKIP_IN_MANUAL
  typedef CGAL::Mixed_integer_program_traits<FT> Base_class;
  typedef typename Base_class::Variable Variable;
  typedef typename Base_class::Linear_constraint Linear_constraint;
  typedef typename Base_class::Linear_objective Linear_objective;
  /// \endcond

  /// Sets the wall-clock limit of `solve()` in seconds; a value <= 0 or infinite means no limit.
  void set_time_limit(double seconds) { time_limit_ = seconds; }
  /// Sets the number of branch-and-bound nodes after which `solve()` stops; 0 means no limit.
  void set_node_limit(std::size_t nodes) { node_limit_ = nodes; }
  /// Sets the relative MIP gap at which the search stops and the solution counts as optimal.
  void set_relative_gap(double gap) { relative_gap_ = gap; }
  /// Sets the absolute tolerance used to check the residuals of a returned solution.
  void set_feasibility_tolerance(double tol) { tolerance_ = tol; }
  /// Gives a feasible starting point (one value per variable, in creation order) offered to the
  /// search as its first incumbent, so that a time limit still ends with a solution at least as good.
  void set_initial_solution(const std::vector<double>& x) { initial_ = x; }
  /// The status of the last `solve()`.
  Mip_status status() const { return status_; }
  /// The number of branch-and-bound nodes the last `solve()` created.
  std::size_t nodes() const { return nodes_; }
  /// The largest bound or constraint violation of the returned solution.
  double max_residual() const { return max_residual_; }
  /// Frees GLPK's environment of the calling thread (`glp_free_env()`). A worker thread calls it once
  /// it has finished all its solves; never while a program of that thread is being solved.
  static void release_thread_resources() { glp_free_env(); }

  /// Solves the program; returns `true` if a feasible solution (optimal or at a limit) is available
  /// through `solution()`.
  virtual bool solve()
  {
    Base_class::error_message_.clear();
    Base_class::result_.clear();
    status_ = Mip_status::ERROR;
    max_residual_ = 0;
    nodes_ = 0;

    glp_prob* lp = glp_create_prob();
    if(lp == nullptr) { Base_class::error_message_ = "failed creating GLPK program"; return false; }
    const int nv = static_cast<int>(Base_class::variables_.size());
    const int nc = static_cast<int>(Base_class::constraints_.size());
    bool has_integer = false;
    if(nv > 0) glp_add_cols(lp, nv);
    for(int i = 0; i < nv; ++i) {
      const Variable* v = Base_class::variables_[i];
      if(v->variable_type() == Variable::CONTINUOUS) glp_set_col_kind(lp, i + 1, GLP_CV);
      else { glp_set_col_kind(lp, i + 1, v->variable_type() == Variable::BINARY ? GLP_BV : GLP_IV); has_integer = true; }
      FT lb, ub; v->get_bounds(lb, ub);
      if(v->variable_type() != Variable::BINARY) glp_set_col_bnds(lp, i + 1, bound_type(lb, ub), lb, ub);
    }
    if(nc > 0) glp_add_rows(lp, nc);
    std::vector<std::pair<int, double> > row;
    std::vector<int> idx; std::vector<double> val;
    for(int r = 0; r < nc; ++r) {
      const Linear_constraint* c = Base_class::constraints_[r];
      sorted_row(c, row);
      idx.assign(1, 0); val.assign(1, 0.);
      for(const auto& e : row) { idx.push_back(e.first + 1); val.push_back(e.second); }
      glp_set_mat_row(lp, r + 1, static_cast<int>(row.size()), idx.data(), val.data());
      FT lb, ub; c->get_bounds(lb, ub);
      glp_set_row_bnds(lp, r + 1, bound_type(lb, ub), lb, ub);
    }
    if(Base_class::objective_ != nullptr) {
      sorted_row(Base_class::objective_, row);
      for(const auto& e : row) glp_set_obj_coef(lp, e.first + 1, e.second);
      glp_set_obj_coef(lp, 0, Base_class::objective_->offset());
      glp_set_obj_dir(lp, Base_class::objective_->sense() == Linear_objective::MINIMIZE ? GLP_MIN : GLP_MAX);
    }

    int rc = 0;
    bool have = false;
    if(!has_integer) {
      glp_smcp p; glp_init_smcp(&p);
      p.msg_lev = GLP_MSG_OFF;
      p.tm_lim = time_limit_ms();
      rc = glp_simplex(lp, &p);
      const int st = glp_get_status(lp);
      if(st == GLP_OPT) { status_ = Mip_status::OPTIMAL; have = true; }
      else if(st == GLP_NOFEAS) status_ = Mip_status::INFEASIBLE;
      else if(rc == GLP_ETMLIM) status_ = Mip_status::NO_SOLUTION;
      if(have) read(lp, false);
    } else {
      glp_iocp p; glp_init_iocp(&p);
      p.msg_lev = GLP_MSG_OFF;
      p.presolve = GLP_ON;
      const auto start = std::chrono::steady_clock::now();
      bool offer = false;
      if(initial_.size() == std::size_t(nv)) {
        // The heuristic callback works on the problem GLPK sees: the presolver (which changes it)
        // is replaced by an explicit root LP solve.
        glp_smcp sp; glp_init_smcp(&sp);
        sp.msg_lev = GLP_MSG_OFF;
        sp.tm_lim = time_limit_ms();
        // Dual simplex: with every objective coefficient >= 0 (a minimised sum of penalties) the
        // starting basis is dual feasible; on the quantization programs the root LP takes about 30 %
        // less time than with the primal simplex.
        sp.meth = GLP_DUALP;
        if(glp_simplex(lp, &sp) == 0 && glp_get_status(lp) == GLP_OPT) {
          p.presolve = GLP_OFF;
          offer = true;
        }
      }
      heuristic_offered_ = !offer;
      p.cb_func = &GLPK_mixed_integer_program_traits_with_limits::callback; // counts nodes, applies the node limit
      p.cb_info = this;
      const double spent = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      p.tm_lim = time_limit_ms(spent);
      p.mip_gap = relative_gap_;
      // Best projection: with an incumbent from the start and a weak bound, it reaches good solutions
      // in far fewer nodes than the default best local bound (measured on the quantization programs).
      p.bt_tech = GLP_BT_BPH;
      rc = glp_intopt(lp, &p);
      const int st = glp_mip_status(lp);
      // GLPK reports "no primal feasible LP relaxation" as an error code, not as a status.
      if(rc == GLP_ENOPFS || st == GLP_NOFEAS) status_ = Mip_status::INFEASIBLE;
      else if(st == GLP_OPT || (st == GLP_FEAS && (rc == 0 || rc == GLP_EMIPGAP)))
      { status_ = Mip_status::OPTIMAL; have = true; }
      else if(st == GLP_FEAS) { status_ = Mip_status::FEASIBLE_AT_LIMIT; have = true; }
      else if(rc == GLP_ETMLIM || rc == GLP_ESTOP) status_ = Mip_status::NO_SOLUTION;
      if(have) read(lp, true);
    }
    // A limit hit before GLPK reached its heuristic stage: the given starting point is still the best
    // known feasible solution (its residuals are checked below like any other).
    if(!have && has_integer && initial_.size() == std::size_t(nv) &&
       (status_ == Mip_status::NO_SOLUTION || status_ == Mip_status::ERROR)) {
      Base_class::result_.resize(nv);
      for(int i = 0; i < nv; ++i) {
        Variable* v = Base_class::variables_[i];
        const FT x = (v->variable_type() == Variable::CONTINUOUS) ? FT(initial_[i]) : std::round(FT(initial_[i]));
        v->set_solution_value(x);
        Base_class::result_[i] = x;
      }
      status_ = Mip_status::FEASIBLE_AT_LIMIT;
      have = true;
    }
    if(!have && Base_class::error_message_.empty())
      Base_class::error_message_ = std::string("GLPK: ") + to_string(status_) + " (code " + std::to_string(rc) + ")";
    glp_delete_prob(lp);

    if(have && !check_residuals()) {
      status_ = Mip_status::ERROR;
      Base_class::error_message_ = "GLPK returned a solution violating the constraints by " + std::to_string(max_residual_);
      Base_class::result_.clear();
      have = false;
    }
    return have;
  }

private:
  static int bound_type(FT lb, FT ub)
  {
    const FT inf = Variable::infinity();
    if(lb <= -inf && ub >= inf) return GLP_FR;
    if(ub >= inf) return GLP_LO;
    if(lb <= -inf) return GLP_UP;
    return lb == ub ? GLP_FX : GLP_DB;
  }

  template <typename Expr>
  static void sorted_row(const Expr* e, std::vector<std::pair<int, double> >& row)
  {
    row.clear();
    for(const auto& kv : e->coefficients()) if(kv.second != 0) row.emplace_back(kv.first->index(), kv.second);
    std::sort(row.begin(), row.end());
  }

  int time_limit_ms(double spent = 0) const
  {
    if(!(time_limit_ > 0) || time_limit_ * 1000. >= double((std::numeric_limits<int>::max)())) return INT_MAX;
    return (std::max)(1, static_cast<int>((time_limit_ - spent) * 1000.));
  }

  static void callback(glp_tree* tree, void* info)
  {
    auto* self = static_cast<GLPK_mixed_integer_program_traits_with_limits*>(info);
    int active = 0, current = 0, total = 0;
    glp_ios_tree_size(tree, &active, &current, &total);
    self->nodes_ = std::size_t(total);
    if(self->node_limit_ > 0 && std::size_t(total) > self->node_limit_) { glp_ios_terminate(tree); return; }
    if(glp_ios_reason(tree) != GLP_IHEUR || self->heuristic_offered_) return;
    self->heuristic_offered_ = true;
    std::vector<double> x(self->initial_.size() + 1, 0.); // GLPK arrays are 1-based
    std::copy(self->initial_.begin(), self->initial_.end(), x.begin() + 1);
    glp_ios_heur_sol(tree, x.data()); // rejected by GLPK if infeasible or not better
  }

  void read(glp_prob* lp, bool mip)
  {
    const int nv = static_cast<int>(Base_class::variables_.size());
    Base_class::result_.resize(nv);
    for(int i = 0; i < nv; ++i) {
      Variable* v = Base_class::variables_[i];
      FT x = mip ? glp_mip_col_val(lp, i + 1) : glp_get_col_prim(lp, i + 1);
      if(v->variable_type() != Variable::CONTINUOUS) x = std::round(x);
      v->set_solution_value(x);
      Base_class::result_[i] = x;
    }
  }

  // The rounded integer values are checked, not GLPK's own: a solution the caller cannot trust
  // must not be reported as feasible.
  bool check_residuals()
  {
    const FT inf = Variable::infinity();
    for(const Variable* v : Base_class::variables_) {
      FT lb, ub; v->get_bounds(lb, ub);
      if(v->variable_type() == Variable::BINARY) { lb = 0; ub = 1; }
      const FT x = Base_class::result_[v->index()];
      if(lb > -inf) max_residual_ = (std::max)(max_residual_, double(lb - x));
      if(ub < inf) max_residual_ = (std::max)(max_residual_, double(x - ub));
    }
    std::vector<std::pair<int, double> > row;
    for(const Linear_constraint* c : Base_class::constraints_) {
      FT lb, ub; c->get_bounds(lb, ub);
      FT s = 0;
      sorted_row(c, row); // summed in variable order, not in the address order of the hash map
      for(const auto& e : row) s += e.second * Base_class::result_[e.first];
      if(lb > -inf) max_residual_ = (std::max)(max_residual_, double(lb - s));
      if(ub < inf) max_residual_ = (std::max)(max_residual_, double(s - ub));
    }
    return max_residual_ <= tolerance_;
  }

  std::vector<double> initial_;
  bool heuristic_offered_ = false;
  double time_limit_ = 0;
  std::size_t node_limit_ = 0;
  std::size_t nodes_ = 0;
  double relative_gap_ = 1e-6;
  double tolerance_ = 1e-6;
  Mip_status status_ = Mip_status::ERROR;
  double max_residual_ = 0;
};

#endif // CGAL_USE_GLPK

} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_GLPK_MIXED_INTEGER_PROGRAM_TRAITS_WITH_LIMITS_H
