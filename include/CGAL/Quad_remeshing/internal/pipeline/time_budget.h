// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_QUAD_REMESHING_INTERNAL_PIPELINE_TIME_BUDGET_H
#define CGAL_QUAD_REMESHING_INTERNAL_PIPELINE_TIME_BUDGET_H

#include <CGAL/Quad_remeshing/Report.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

/*
  The time budget of a whole run (`quad_remesh()` and the command-line program): a limit in seconds
  counted from the construction, or none (0). The stages whose work can stop early get a share of the
  time left when they start: the layout rounds (fewer candidate paths), the quantization solves (the best
  solution found, or the solver-free fallback) and the smoothing iterations. The others (repair, feature
  detection, remeshing, cross field, quadrangulation) always run to their end, so a limit shorter than
  those stages is exceeded; `report()` says whether the limit was met and which stages gave something up.
*/
class Time_budget
{
public:
  explicit Time_budget(double seconds = 0.)
    : limit_(seconds > 0. && std::isfinite(seconds) ? seconds : 0.), start_(std::chrono::steady_clock::now())
  {}

  bool limited() const { return limit_ > 0.; }
  double elapsed() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
  double left() const
  {
    return limited() ? (std::max)(0., limit_ - elapsed()) : std::numeric_limits<double>::infinity();
  }

  // The seconds a stage that can stop early may take: `share` of the time left, at least a millisecond
  // (a stage limit of 0 means "no limit" to the stages). 0 when the run has no limit.
  double stage_limit(double share) const
  {
    if(!limited()) return 0.;
    return (std::max)(1e-3, share * left());
  }

  // Records that `stage` stopped early, and what it gave up (a short phrase).
  void degraded(const std::string& stage, const std::string& what) { degraded_.emplace_back(stage, what); }

  // Records what the stage whose report is `r` gave up to its time limit, read from the figures it
  // reports: `stopped_in_round` (layout), clusters whose status starts with "fallback" (quantize: no time
  // left for their solve, or a solve that a limit stopped before any solution),
  // `stopped_early` with `iterations` (smooth).
  void record(const std::string& stage, const Report& r)
  {
    if(const Report* round = r.find("stopped_in_round"))
      degraded(stage, "stopped in round " + round->string() + ", later rounds skipped");
    if(const Report* status = r.find("status")) {
      std::size_t n = 0;
      for(const Report& x : status->elements()) n += x.kind() == Report::STRING && x.string().rfind("fallback", 0) == 0;
      if(n > 0)
        degraded(stage, std::to_string(n) + " of " + std::to_string(status->size()) +
                          " clusters kept the solver-free fallback");
    }
    const Report* stopped = r.find("stopped_early");
    const Report* iterations = r.find("iterations");
    if(stopped && stopped->boolean() && iterations)
      degraded(stage, "stopped after " + std::to_string(long(iterations->number())) + " iterations");
  }
  bool any_degraded() const { return !degraded_.empty(); }

  // {"seconds": limit, "elapsed", "met", "degraded": [{"stage", "what"}]}; {"seconds": 0} without a limit
  Report report() const
  {
    Report r = Report::object();
    r["seconds"] = limit_;
    if(!limited()) return r;
    const double e = elapsed();
    r["elapsed"] = e;
    r["met"] = e <= limit_;
    Report d = Report::array();
    for(const auto& x : degraded_) {
      Report o = Report::object();
      o["stage"] = x.first;
      o["what"] = x.second;
      d.push_back(o);
    }
    r["degraded"] = d;
    return r;
  }

  // "layout (...), quantize (...)", or "" when nothing was degraded
  std::string summary() const
  {
    std::string s;
    for(const auto& x : degraded_) s += (s.empty() ? "" : ", ") + x.first + " (" + x.second + ")";
    return s;
  }

private:
  double limit_;
  std::chrono::steady_clock::time_point start_;
  std::vector<std::pair<std::string, std::string> > degraded_;
};

// The shares of the time left that the stages which can stop early get when they start: the layout about
// half (the quantization and the smoothing still to come), the quantization most of what is left then,
// the smoothing most of the rest (the assembly before it and the output after it are short).
constexpr double layout_time_share = 0.5;
constexpr double quantize_time_share = 0.7;
constexpr double smooth_time_share = 0.8;

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_INTERNAL_PIPELINE_TIME_BUDGET_H
