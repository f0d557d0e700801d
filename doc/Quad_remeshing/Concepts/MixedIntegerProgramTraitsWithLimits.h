/*!
\ingroup PkgQuadRemeshingConcepts
\cgalConcept

A refinement of `MixedIntegerProgramTraits` for solves that must end in bounded time and say
honestly what they found. CGAL's concept has no time limit, reports a time-out or a solver failure
like infeasibility, and cannot be copied (create one object per program, pass it by reference).
`quantize_patch_sides()` creates one default-constructed object per cluster solve and uses it once.
If the model has a static member function `release_thread_resources()` (optional), each of its worker
threads calls it once when it has finished all its solves (the GLPK model frees GLPK's per-thread
environment there).

\cgalRefines{MixedIntegerProgramTraits}

\cgalHasModelsBegin
\cgalHasModels{CGAL::Quad_remeshing::GLPK_mixed_integer_program_traits_with_limits}
\cgalHasModelsEnd
*/
class MixedIntegerProgramTraitsWithLimits
{
public:
  /// Sets the wall-clock limit of `solve()` in seconds; <= 0 means none.
  void set_time_limit(double seconds);
  /// Sets the number of branch-and-bound nodes after which `solve()` stops; 0 means none.
  void set_node_limit(std::size_t nodes);
  /// Sets the relative gap at which the search may stop and report `OPTIMAL`.
  void set_relative_gap(double gap);
  /// Gives a feasible point (one value per variable, in creation order); a limited solve returns
  /// a solution at least as good as it (`FEASIBLE_AT_LIMIT` if nothing better was found in time).
  void set_initial_solution(const std::vector<double>& x);
  /// Solves; returns `true` iff `solution()` holds a solution whose bounds and constraints hold
  /// (checked on the rounded integer values), i.e. iff `status()` is `OPTIMAL` or `FEASIBLE_AT_LIMIT`.
  bool solve();
  /// The outcome of the last `solve()`.
  CGAL::Quad_remeshing::Mip_status status() const;
};
