// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The reusable core of the benchmark harness: the mesh type every workload receives, the timing
// API a workload reports its phases through (`Run`), the workload table entry, the solver
// dispatch, and the measurement loop that turns repeated runs into per-phase statistics.

#ifndef CGAL_SURFACE_DESIGN_BENCHMARK_HARNESS_H
#define CGAL_SURFACE_DESIGN_BENCHMARK_HARNESS_H

#include <CGAL/Surface_design/nested_dissection_ordering.h>
#include <CGAL/Surface_design/supernodal_cholesky.h>
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

/// Thrown by a workload that does not apply to a mesh (say, a method that needs positive cotangent
/// weights): the harness reports "not applicable (reason)" for that workload, mesh and solver,
/// which is not an error.
class Not_applicable : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// What a workload sees of the harness during one call: it wraps each phase in `phase()`, may
/// add derived phases with `sum_phase()`, and reports its untimed sanity checks through `check()`.
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

  /// Records phase `name` with a time measured elsewhere (say, by the library's own report), in
  /// milliseconds; counted in `total` like a timed phase.
  void record(const std::string& name, double ms) { add_time(name, ms); }

  /// Records phase `name` as the sum of phases already timed in this run (say, "full" = factor +
  /// field + solve): a number to report, not a measurement; it does not count in `total`.
  /// \throws std::logic_error if one of `parts` has not run yet
  void sum_phase(const std::string& name, const std::vector<std::string>& parts)
  {
    double ms = 0.;
    for(const std::string& part : parts)
    {
      const auto it = std::find_if(m_times.begin(), m_times.end(),
                                   [&part](const auto& t) { return t.first == part; });
      if(it == m_times.end())
        throw std::logic_error("sum_phase(\"" + name + "\"): phase \"" + part + "\" has not run");
      ms += it->second;
    }
    m_sums.emplace_back(name, ms);
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
  /// The phases added by `sum_phase()`, in the order they were added.
  const std::vector<std::pair<std::string, double>>& sum_phase_times() const { return m_sums; }
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
  std::vector<std::pair<std::string, double>> m_times, m_sums;
  std::vector<Check> m_checks;
};

/// A workload runs one algorithm once on `mesh` with the named solver, timing its phases via
/// `run.phase()`. It may throw: the harness reports the error and goes on with the next contender
/// (`Not_applicable` is reported as such, not as an error).
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
  /// Another workload of the table that solves the same problem another way (a reference method),
  /// or null. When both ran, every phase of this workload is compared with the phase of the same
  /// name of the reference, on the same mesh with the same solver:
  /// ratio = reference median / this workload's median.
  const char* reference = nullptr;
  /// Long runs (a whole flow of minutes on a large mesh) run only when named by --workload or by
  /// a preset; "all workloads" leaves them out.
  bool on_request_only = false;
};

// --- solvers

/// A sparse solver the harness knows, whether or not this build has it.
struct Solver_info
{
  const char* name;
  const char* description;
  bool available;      ///< compiled into this build
  const char* missing; ///< why not, when it is not
};

/// Every solver the harness knows, in the order of `--solver all` (the first is the baseline).
inline const std::vector<Solver_info>& known_solvers()
{
#if defined(CGAL_SURFACE_DESIGN_HAS_METIS)
  constexpr bool has_metis = true;
#else
  constexpr bool has_metis = false;
#endif
#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
  constexpr bool has_cholmod = true;
#else
  constexpr bool has_cholmod = false;
#endif
  static const std::vector<Solver_info> table{
    {"default", "Default_solver_traits: Eigen SimplicialLDLT + AMD below 20k unknowns, supernodal Cholesky + nested "
                "dissection from 20k on",
     true, ""},
    {"ldlt", "Simplicial_ldlt_solver_traits: Eigen SimplicialLDLT, AMD ordering", true, ""},
    {"ldlt-nd", "Nested_dissection_ldlt_solver_traits: Eigen SimplicialLDLT, the library's nested dissection",
     true, ""},
    {"supernodal", "Supernodal_solver_traits: the library's supernodal Cholesky, nested dissection", true, ""},
    {"ldlt-metis", "Metis_ldlt_solver_traits: Eigen SimplicialLDLT, METIS nested dissection",
     has_metis, "built without METIS: CGAL_SURFACE_DESIGN_HAS_METIS is not defined"},
    {"cholmod", "Cholmod_solver_traits: CHOLMOD supernodal LLT, AMD ordering, on the loaded BLAS", has_cholmod,
     "built without CHOLMOD: CGAL_SURFACE_DESIGN_HAS_CHOLMOD is not defined"},
  };
  return table;
}

/// Names of the solvers of this build, baseline first (comparisons divide by the first).
inline const std::vector<std::string>& compiled_solvers()
{
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for(const Solver_info& s : known_solvers())
      if(s.available)
        n.push_back(s.name);
    return n;
  }();
  return names;
}

/// Carries a solver traits type to a generic lambda: `with_solver_traits(name, [&](auto tag) {
/// using Traits = typename decltype(tag)::type; ... })`.
template <class SolverTraits>
struct Solver_tag
{
  using type = SolverTraits;
};

/// Calls `f(Solver_tag<Traits>())` with the traits named `solver` ("default": the library's
/// `Default_solver_traits`, "ldlt": `Simplicial_ldlt_solver_traits`, "ldlt-nd": `Nested_dissection_ldlt_solver_traits`, "supernodal": `Supernodal_solver_traits`, "ldlt-metis": `Metis_ldlt_solver_traits`, "cholmod":
/// `Cholmod_solver_traits`).
/// \throws std::invalid_argument for a name that is not in `compiled_solvers()`.
template <class F>
void with_solver_traits(const std::string& solver, F&& f)
{
  if(solver == "default")
    f(Solver_tag<CGAL::Surface_design::Default_solver_traits>());
  else if(solver == "ldlt")
    f(Solver_tag<CGAL::Surface_design::Simplicial_ldlt_solver_traits>());
  else if(solver == "ldlt-nd")
    f(Solver_tag<CGAL::Surface_design::Nested_dissection_ldlt_solver_traits>());
  else if(solver == "supernodal")
    f(Solver_tag<CGAL::Surface_design::Supernodal_solver_traits>());
#if defined(CGAL_SURFACE_DESIGN_HAS_METIS)
  else if(solver == "ldlt-metis")
    f(Solver_tag<CGAL::Surface_design::Metis_ldlt_solver_traits>());
#endif
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

/// A workload that did not apply to a mesh with a solver (it threw `Not_applicable`).
struct Not_applicable_result
{
  std::string workload, mesh, solver, reason;
};

/// Two contenders of the same mesh and phase: ratio = baseline median / contender median, so a
/// ratio above 1 means the contender is faster. A contender is a (workload, solver) pair:
/// - kind `solver`: the same workload with two solvers, the baseline being the first solver;
/// - kind `reference`: a workload and its reference workload (`Workload::reference`, the
///   baseline) with the same solver.
struct Comparison
{
  enum class Kind { solver, reference };

  Kind kind = Kind::solver;
  std::string mesh, phase;
  std::string baseline_workload, baseline_solver, contender_workload, contender_solver;
  double baseline_ms = 0., contender_ms = 0., ratio = 0.;

  const char* kind_name() const { return kind == Kind::solver ? "solver" : "reference"; }
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
  std::vector<Not_applicable_result> not_applicable;
  std::size_t failures = 0; ///< contenders that threw (other than `Not_applicable`)
};

/// Runs `workload` on `mesh` with every solver of `solvers` (or once with solver "none" if the
/// workload uses none): `settings.warmup` warm-up calls, then `settings.runs` measured calls per
/// solver. The solvers take turns call by call, so that a slow drift of the machine (frequency,
/// other load) affects every contender alike. Checks are enabled on the first call of each solver.
/// A contender that throws is dropped (its earlier samples too). Progress, checks and errors go
/// to `log`.
inline Measurement measure(const Workload& workload, const Mesh& mesh, const std::string& mesh_name,
                           const std::vector<std::string>& solvers,
                           const Timing_settings& settings, std::ostream& log)
{
  struct Contender
  {
    std::string solver;
    bool failed = false; // threw: an error, or not applicable
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
      catch(const Not_applicable& e)
      {
        c.failed = true;
        m.not_applicable.push_back(Not_applicable_result{workload.name, mesh_name, c.solver, e.what()});
        log << "  not applicable with " << c.solver << ": " << e.what() << std::endl;
        continue;
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
      // timed phases, then the sums the workload reported, then the total of the timed phases
      std::vector<std::pair<std::string, double>> times = run.phase_times();
      const std::size_t timed = times.size();
      times.insert(times.end(), run.sum_phase_times().begin(), run.sum_phase_times().end());
      if(timed > 1)
      {
        double total = 0.;
        for(std::size_t i = 0; i < timed; ++i)
          total += times[i].second;
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

namespace harness_detail {

inline Comparison make_comparison(Comparison::Kind kind, const Phase_result& baseline,
                                  const Phase_result& contender)
{
  const double ratio = contender.time.median_ms > 0.
                         ? baseline.time.median_ms / contender.time.median_ms
                         : std::nan("");
  return Comparison{kind,
                    contender.mesh,
                    contender.phase,
                    baseline.workload,
                    baseline.solver,
                    contender.workload,
                    contender.solver,
                    baseline.time.median_ms,
                    contender.time.median_ms,
                    ratio};
}

} // namespace harness_detail

/// Solver comparisons: pairs every contender with the baseline (the first solver that ran) of the
/// same workload, mesh and phase.
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
        comparisons.push_back(
          harness_detail::make_comparison(Comparison::Kind::solver, b, contender));
    }
  }
  return comparisons;
}

/// Reference comparisons: pairs every result of a workload that names a reference in `table`
/// with the result of the reference workload of the same mesh, solver and phase, if it ran.
/// Ordered like the workload's results (by mesh, solver, phase).
inline std::vector<Comparison> compare_with_references(const std::vector<Phase_result>& results,
                                                       const std::vector<Workload>& table)
{
  std::vector<Comparison> comparisons;
  for(const Phase_result& contender : results)
  {
    const auto w = std::find_if(table.begin(), table.end(), [&contender](const Workload& x) {
      return contender.workload == x.name;
    });
    if(w == table.end() || !w->reference)
      continue;
    const std::string reference = w->reference;
    const auto b = std::find_if(results.begin(), results.end(), [&](const Phase_result& r) {
      return r.workload == reference && r.mesh == contender.mesh &&
             r.solver == contender.solver && r.phase == contender.phase;
    });
    if(b != results.end())
      comparisons.push_back(
        harness_detail::make_comparison(Comparison::Kind::reference, *b, contender));
  }
  return comparisons;
}

} // namespace benchmark

#endif // CGAL_SURFACE_DESIGN_BENCHMARK_HARNESS_H
