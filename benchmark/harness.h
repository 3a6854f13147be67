// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The reusable core of the benchmark harness: the mesh type every workload receives, the timing
// API a workload reports its phases through (`Run`), the workload table entry, the solver
// dispatch, and the measurement loop that turns repeated runs into per-phase statistics.

#ifndef CGAL_SURFACE_DESIGN_BENCHMARK_HARNESS_H
#define CGAL_SURFACE_DESIGN_BENCHMARK_HARNESS_H

#include <CGAL/Surface_design/solver_traits.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <exception>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace benchmark {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Clock = std::chrono::steady_clock;

/// `printf`-style formatting of one number, so that no stream keeps a changed precision.
inline std::string format_number(const char* format, double value)
{
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

/// Name of the synthetic phase holding the sum of a run's phases (added when a run has several).
inline const std::string total_phase = "total";

/// What a workload sees of the harness during one call: it wraps each phase in `phase()` and
/// reports its untimed sanity checks through `check()`.
class Run
{
public:
  struct Check
  {
    std::string what;
    double value;
    double bound; ///< the check passes when `value < bound` (and `value` is finite)
  };

  explicit Run(bool checks_enabled) : m_checks_enabled(checks_enabled) {}

  /// Times `f()` with `steady_clock` as phase `name`. Calling it twice with the same name in one
  /// run adds the times.
  template <class F>
  void phase(const std::string& name, F&& f)
  {
    const Clock::time_point start = Clock::now();
    std::forward<F>(f)();
    const Clock::time_point stop = Clock::now();
    add_time(name, std::chrono::duration<double, std::milli>(stop - start).count());
  }

  /// True on exactly one call per (workload, mesh, solver): do the (untimed, possibly costly)
  /// sanity checks only then.
  bool checks_enabled() const { return m_checks_enabled; }

  /// Reports a quantity that must stay below `bound` (a residual, an error norm...). The harness
  /// prints it, warns when it fails, and writes it to the JSON file.
  void check(const std::string& what, double value, double bound)
  {
    if(m_checks_enabled)
      m_checks.push_back({what, value, bound});
  }

  /// Phase names and times (ms) in the order the phases first ran.
  const std::vector<std::pair<std::string, double>>& phase_times() const { return m_times; }
  const std::vector<Check>& checks() const { return m_checks; }

private:
  void add_time(const std::string& name, double ms)
  {
    for(auto& t : m_times)
      if(t.first == name)
      {
        t.second += ms;
        return;
      }
    m_times.emplace_back(name, ms);
  }

  bool m_checks_enabled;
  std::vector<std::pair<std::string, double>> m_times;
  std::vector<Check> m_checks;
};

/// A workload runs one algorithm once on `mesh` with the named solver, timing its phases via
/// `run.phase()`. It may throw: the harness reports the error and goes on with the next contender.
using Workload_function = void (*)(const Mesh& mesh, const std::string& solver, Run& run);

/// Whether a workload's time depends on the sparse solver.
enum class Solver_use
{
  compared, ///< run once per selected solver, side by side
  none      ///< run once, with solver name "none"
};

/// One line of the workload table.
struct Workload
{
  const char* name;
  const char* description;
  Workload_function function;
  Solver_use solver_use = Solver_use::compared;
};

// --- solvers

/// Names of the solvers of this build, baseline first (comparisons divide by the first).
inline const std::vector<std::string>& compiled_solvers()
{
#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
  static const std::vector<std::string> names{"ldlt", "cholmod"};
#else
  static const std::vector<std::string> names{"ldlt"};
#endif
  return names;
}

/// Carries a solver traits type to a generic lambda: `with_solver_traits(name, [&](auto tag) {
/// using Traits = typename decltype(tag)::type; ... })`.
template <class SolverTraits>
struct Solver_tag
{
  using type = SolverTraits;
};

/// Calls `f(Solver_tag<Traits>())` with the traits named `solver` ("ldlt": the library's
/// `Default_solver_traits`, "cholmod": `Cholmod_solver_traits`).
/// \throws std::invalid_argument for a name that is not in `compiled_solvers()`.
template <class F>
void with_solver_traits(const std::string& solver, F&& f)
{
  if(solver == "ldlt")
    f(Solver_tag<CGAL::Surface_design::Default_solver_traits>());
#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
  else if(solver == "cholmod")
    f(Solver_tag<CGAL::Surface_design::Cholmod_solver_traits>());
#endif
  else
    throw std::invalid_argument("solver \"" + solver + "\" is not available in this build");
}

// --- statistics and results

struct Statistics
{
  double median_ms = 0., min_ms = 0., max_ms = 0.;
};

/// Median (mean of the two middle values for an even count), minimum and maximum.
/// \pre `ms` is not empty.
inline Statistics statistics(std::vector<double> ms)
{
  std::sort(ms.begin(), ms.end());
  const std::size_t n = ms.size();
  Statistics s;
  s.median_ms = n % 2 == 1 ? ms[n / 2] : 0.5 * (ms[n / 2 - 1] + ms[n / 2]);
  s.min_ms = ms.front();
  s.max_ms = ms.back();
  return s;
}

/// One row of the results: the statistics of one phase over the measured runs.
struct Phase_result
{
  std::string workload, mesh;
  std::size_t vertices = 0, faces = 0;
  std::string solver, phase;
  Statistics time;
  std::size_t runs = 0;
};

/// One sanity check, with the context it was made in.
struct Check_result
{
  std::string workload, mesh, solver, what;
  double value = 0., bound = 0.;

  bool passed() const { return std::isfinite(value) && value < bound; }
};

/// Two contenders of the same (workload, mesh, phase): ratio = baseline median / contender median,
/// so a ratio above 1 means the contender is faster.
struct Comparison
{
  std::string workload, mesh, phase, baseline, contender;
  double baseline_ms = 0., contender_ms = 0., ratio = 0.;
};

struct Timing_settings
{
  int warmup = 1; ///< runs made first and not measured
  int runs = 5;   ///< measured runs
};

struct Measurement
{
  std::vector<Phase_result> results;
  std::vector<Check_result> checks;
  std::size_t failures = 0; ///< contenders that threw
};

/// Runs `workload` on `mesh` with every solver of `solvers` (or once with solver "none" if the
/// workload uses none): `settings.warmup` warm-up calls, then `settings.runs` measured calls per
/// solver. The solvers take turns call by call, so that a slow drift of the machine (frequency,
/// other load) affects every contender alike. Checks are enabled on the first call of each solver.
/// Progress, checks and errors go to `log`.
inline Measurement measure(const Workload& workload, const Mesh& mesh, const std::string& mesh_name,
                           const std::vector<std::string>& solvers,
                           const Timing_settings& settings, std::ostream& log)
{
  struct Contender
  {
    std::string solver;
    bool failed = false;
    std::vector<std::string> phases;              // in order of first appearance
    std::vector<std::vector<double>> samples;     // per phase, one time per measured run
  };
  std::vector<Contender> contenders;
  if(workload.solver_use == Solver_use::none)
    contenders.push_back(Contender{"none", false, {}, {}});
  else
    for(const std::string& s : solvers)
      contenders.push_back(Contender{s, false, {}, {}});

  Measurement m;
  const Clock::time_point start = Clock::now();
  log << workload.name << " on " << mesh_name << ": " << settings.warmup << " warm-up + "
      << settings.runs << " measured runs per solver" << std::endl;
  for(int call = 0; call < settings.warmup + settings.runs; ++call)
    for(Contender& c : contenders)
    {
      if(c.failed)
        continue;
      Run run(call == 0);
      try
      {
        workload.function(mesh, c.solver, run);
      }
      catch(const std::exception& e)
      {
        c.failed = true;
        ++m.failures;
        log << "  ERROR: " << workload.name << " on " << mesh_name << " with " << c.solver
            << " failed: " << e.what() << std::endl;
        continue;
      }
      for(const Run::Check& k : run.checks())
      {
        Check_result r{workload.name, mesh_name, c.solver, k.what, k.value, k.bound};
        log << (r.passed() ? "  check " : "  WARNING: check failed: ") << c.solver << ": "
            << k.what << " = " << format_number("%.3g", k.value) << (r.passed() ? " < " : " >= ")
            << format_number("%.3g", k.bound) << std::endl;
        m.checks.push_back(std::move(r));
      }
      if(call < settings.warmup)
        continue;
      std::vector<std::pair<std::string, double>> times = run.phase_times();
      if(times.size() > 1)
      {
        double total = 0.;
        for(const auto& t : times)
          total += t.second;
        times.emplace_back(total_phase, total);
      }
      for(const auto& t : times)
      {
        const auto it = std::find(c.phases.begin(), c.phases.end(), t.first);
        const std::size_t p = std::size_t(it - c.phases.begin());
        if(it == c.phases.end())
        {
          c.phases.push_back(t.first);
          c.samples.emplace_back();
        }
        c.samples[p].push_back(t.second);
      }
    }

  for(const Contender& c : contenders)
  {
    if(c.failed)
      continue;
    for(std::size_t p = 0; p < c.phases.size(); ++p)
      m.results.push_back(Phase_result{workload.name, mesh_name, num_vertices(mesh),
                                       num_faces(mesh), c.solver, c.phases[p],
                                       statistics(c.samples[p]), c.samples[p].size()});
  }
  log << "  done in "
      << format_number("%.1f", std::chrono::duration<double>(Clock::now() - start).count())
      << " s" << std::endl;
  return m;
}

/// Pairs every contender with the baseline (the first solver that ran) of the same workload, mesh
/// and phase.
inline std::vector<Comparison> compare_contenders(const std::vector<Phase_result>& results)
{
  std::vector<Comparison> comparisons;
  for(std::size_t i = 0; i < results.size(); ++i)
  {
    const Phase_result& contender = results[i];
    // the baseline is the first result of this workload and mesh; compare only other solvers
    const Phase_result* baseline_row = nullptr;
    for(std::size_t j = 0; j < i && !baseline_row; ++j)
      if(results[j].workload == contender.workload && results[j].mesh == contender.mesh)
        baseline_row = &results[j];
    if(!baseline_row || baseline_row->solver == contender.solver)
      continue;
    for(std::size_t j = 0; j < i; ++j)
    {
      const Phase_result& b = results[j];
      if(b.workload == contender.workload && b.mesh == contender.mesh &&
         b.solver == baseline_row->solver && b.phase == contender.phase)
      {
        const double ratio = contender.time.median_ms > 0.
                               ? b.time.median_ms / contender.time.median_ms
                               : std::nan("");
        comparisons.push_back(Comparison{contender.workload, contender.mesh, contender.phase,
                                         b.solver, contender.solver, b.time.median_ms,
                                         contender.time.median_ms, ratio});
      }
    }
  }
  return comparisons;
}

} // namespace benchmark

#endif // CGAL_SURFACE_DESIGN_BENCHMARK_HARNESS_H
