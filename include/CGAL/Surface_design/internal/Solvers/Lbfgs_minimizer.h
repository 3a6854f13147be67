// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A first-order minimizer for nonsmooth, locally Lipschitz energies: L-BFGS with the weak-Wolfe
// bracketing line search of Lewis & Overton (2013), or gradient descent with Armijo backtracking.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_LBFGS_MINIMIZER_H
#define CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_LBFGS_MINIMIZER_H

#include <CGAL/Surface_design/exceptions.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

// References
//  [LO13] A. S. Lewis, M. L. Overton, Nonsmooth optimization via quasi-Newton methods,
//         Math. Program. 141 (2013) 135-163: BFGS with an inexact line search that asks only for
//         the Armijo and the *weak* Wolfe conditions, found by doubling and bisection.
//  [NW06] J. Nocedal, S. J. Wright, Numerical Optimization, 2nd ed., Springer 2006:
//         Algorithm 7.4 (L-BFGS two-loop recursion), eq. (7.20) (initial scaling gamma),
//         Algorithm 3.1 (backtracking line search).
//  [SGC18] O. Stein, E. Grinspun, K. Crane, Developability of triangle meshes, ACM TOG 37(4) 2018,
//         and its reference code, whose optimizer constants are quoted below (research notes, sec. 1).

namespace CGAL {
namespace Surface_design {
namespace internal {

/// How a search direction is chosen.
enum class Descent_method
{
  lbfgs,           ///< limited-memory BFGS [NW06, Alg. 7.4] + weak-Wolfe bracketing search [LO13]
  gradient_descent ///< d = -gradient + Armijo backtracking [NW06, Alg. 3.1]
};

inline const char* to_string(Descent_method m)
{
  switch(m)
  {
    case Descent_method::lbfgs: return "L-BFGS";
    case Descent_method::gradient_descent: return "gradient descent";
  }
  return "unknown method";
}

/// Every constant of the minimizer. The defaults are those of the reference code of [SGC18]
/// unless said otherwise. `Lbfgs_minimizer`'s constructor checks them (see `check()`).
struct Lbfgs_options
{
  Descent_method method = Descent_method::lbfgs;

  /// L-BFGS: number m of secant pairs (s, y) kept. 0 turns L-BFGS into steepest descent with the
  /// weak-Wolfe search. Memory 2 m n doubles, cost O(m n) per direction.
  std::size_t memory = 8;

  /// Armijo (sufficient decrease) constant c1: a step t along d is short enough when
  /// f(x + t d) <= f(x) + c1 t g'd. Both methods. Must satisfy 0 < c1 < 1 (and c1 < c2 for L-BFGS).
  double armijo = 1e-4;

  /// Weak Wolfe (curvature) constant c2 of L-BFGS: a step is long enough when
  /// g(x + t d)'d >= c2 g'd. Never the strong (two-sided) Wolfe condition, which a nonsmooth f
  /// may have no point to satisfy [LO13]. c1 < c2 < 1. 0.9 is the usual quasi-Newton value
  /// [NW06, sec. 3.1]; the reference code of [SGC18] uses 0.99 (longer steps accepted, fewer
  /// trials per search, poorer secant pairs).
  double wolfe = 0.9;

  /// Gradient descent: the Armijo backtracking shrink factor rho (t <- rho t after a rejected
  /// trial), 0 < rho < 1. 0.5 halves the step; the reference code of [SGC18] uses 0.9 (finer
  /// steps, up to 7 times more trials per search).
  double backtracking_factor = 0.5;

  /// At most this many evaluations of f per line search (both methods); a search that has not
  /// found an acceptable step by then has failed. >= 1.
  std::size_t max_line_search_trials = 100;

  /// Trial steps are kept in [min_step, max_step], 0 < min_step <= max_step < inf. A search whose
  /// next trial would be shorter than `min_step` has failed. A step of `max_step` that satisfies
  /// Armijo is accepted even if the curvature condition fails (f may be unbounded below); the
  /// result says so (`curvature_condition == false`).
  double min_step = 1e-12;
  double max_step = 100.;

  /// First trial step of the first line search of a new minimizer. Afterwards each search starts
  /// from t0 = min(2 t_prev, max_step), t_prev the previous accepted step. Steps are measured
  /// in units of the direction d: for steepest descent, of the gradient (the reference code's
  /// mesh units); for L-BFGS with memory, t = 1 is the quasi-Newton step.
  double initial_step = 1e-5;

  /// First trial step after a reset (`reset()`, a line-search failure, a direction that is not
  /// a descent direction, or an `x` changed between two steps): the reference code restarts
  /// from this small step after remeshing. The doubling phase of the search recovers any larger
  /// scale at the cost of one evaluation per factor 2.
  double reset_step = 1e-8;

  /// L-BFGS, not in the reference code: when the direction comes from the memory, try the
  /// quasi-Newton step t = 1 first (clamped to [min_step, max_step]) instead of
  /// min(2 t_prev, max_step), as BFGS with this line search does in [LO13]. On Rosenbrock it
  /// halves the evaluations per iteration (the doubled step usually fails Armijo and costs one
  /// extra evaluation); see test/test_optimizer.cpp.
  bool unit_first_trial = false;

  // --- Stopping rules of `minimize()` (unused by `step()`) ---

  /// Stop after this many iterations (0: return after the initial evaluation).
  std::size_t max_iterations = 1000;

  /// Stop before starting an iteration once this many evaluations of f were made in the run
  /// (0: no limit). The last line search may overshoot it by up to `max_line_search_trials`.
  std::size_t max_evaluations = 0;

  /// Stop when the root mean square of the gradient, |g| / sqrt(n), is at most this value.
  /// (The reference code of [SGC18] displays |g| / sqrt(|V|) for n = 3 |V| coordinates, which is
  /// sqrt(3) times this norm.) On a nonsmooth energy the gradient need not become small at a
  /// minimizer (a kink); there the line-search failure and the energy stall rules stop the run.
  double gradient_tolerance = 1e-8;

  /// Stop when the energy decreased by at most `energy_tolerance * max(|E_{k-w}|, |E_k|)` over
  /// the last w = `energy_window` iterations (E_k the energy after iteration k). A relative test:
  /// scale free, and with tolerance 0 it stops only when w iterations brought no decrease.
  double energy_tolerance = 1e-10;
  /// The window w of the energy test; 0 disables the test.
  std::size_t energy_window = 10;

  /// Stop after this many consecutive failed iterations, >= 1. An iteration fails when its line
  /// search fails and so does one retry from steepest descent with `reset_step` (the retry is
  /// skipped when the failed search was already exactly that one). With a deterministic f the
  /// next iteration would repeat the failed retry, so 1 is the sensible default; more helps only
  /// an f that changes between evaluations.
  std::size_t max_line_search_failures = 1;

  /// Throws `Invalid_parameter` naming the first option out of its range.
  void check() const
  {
    auto fail = [](const char* name, double value, const char* range) {
      std::ostringstream s;
      s << "the optimizer option is " << value << ", expected " << range;
      throw Invalid_parameter(name, s.str());
    };
    if(!(armijo > 0. && armijo < 1.))
      fail("armijo", armijo, "0 < armijo < 1");
    if(method == Descent_method::lbfgs && !(wolfe > armijo && wolfe < 1.))
      fail("wolfe", wolfe, "armijo < wolfe < 1");
    if(!(backtracking_factor > 0. && backtracking_factor < 1.))
      fail("backtracking_factor", backtracking_factor, "0 < backtracking_factor < 1");
    if(max_line_search_trials < 1)
      fail("max_line_search_trials", double(max_line_search_trials), ">= 1");
    if(!(min_step > 0. && std::isfinite(min_step)))
      fail("min_step", min_step, "a finite positive number");
    if(!(max_step >= min_step && std::isfinite(max_step)))
      fail("max_step", max_step, "finite and >= min_step");
    if(!(initial_step > 0. && std::isfinite(initial_step)))
      fail("initial_step", initial_step, "a finite positive number");
    if(!(reset_step > 0. && std::isfinite(reset_step)))
      fail("reset_step", reset_step, "a finite positive number");
    if(!(gradient_tolerance >= 0.))
      fail("gradient_tolerance", gradient_tolerance, ">= 0");
    if(!(energy_tolerance >= 0.))
      fail("energy_tolerance", energy_tolerance, ">= 0");
    if(max_line_search_failures < 1)
      fail("max_line_search_failures", double(max_line_search_failures), ">= 1");
  }
};

/// What one `Lbfgs_minimizer::step()` did.
enum class Lbfgs_step_status
{
  accepted,           ///< x moved to a point that passed the line search
  line_search_failed, ///< no acceptable step: x unchanged, memory cleared, next search from `reset_step`
  stationary,         ///< the gradient at x is exactly zero (or x is empty): nothing to do
  non_finite_point    ///< the energy or the gradient at x itself is NaN or infinite: x unchanged
};

inline const char* to_string(Lbfgs_step_status s)
{
  switch(s)
  {
    case Lbfgs_step_status::accepted: return "accepted";
    case Lbfgs_step_status::line_search_failed: return "line search failed";
    case Lbfgs_step_status::stationary: return "stationary point";
    case Lbfgs_step_status::non_finite_point: return "non-finite energy or gradient";
  }
  return "unknown status";
}

/// Why a line search failed.
enum class Line_search_failure
{
  none,               ///< it did not fail
  max_trials,         ///< `max_line_search_trials` evaluations without an acceptable step
  min_step,           ///< the next trial would be shorter than `min_step`
  interval_collapsed  ///< the bracket [alpha, beta] has no representable midpoint left
};

inline const char* to_string(Line_search_failure r)
{
  switch(r)
  {
    case Line_search_failure::none: return "none";
    case Line_search_failure::max_trials: return "too many trials";
    case Line_search_failure::min_step: return "step below the minimum";
    case Line_search_failure::interval_collapsed: return "bracket collapsed";
  }
  return "unknown failure";
}

/// The outcome of one iteration of `Lbfgs_minimizer::step()`. The line-search conditions of
/// an accepted step can be checked from it: `energy <= energy_before + c1 * step_length *
/// slope_before` (Armijo) and, if `curvature_condition`, `slope_after >= c2 * slope_before`.
struct Lbfgs_step_result
{
  Lbfgs_step_status status = Lbfgs_step_status::stationary;
  Line_search_failure failure = Line_search_failure::none;
  double step_length = 0.;     ///< accepted t (x_new = x + t d); 0 if not accepted
  double first_trial = 0.;     ///< the first trial step of the line search
  std::size_t evaluations = 0; ///< evaluations of f in this step (including one at x if needed)
  double energy_before = std::numeric_limits<double>::quiet_NaN(); ///< f(x) before the step
  double energy = std::numeric_limits<double>::quiet_NaN();        ///< f(x) after the step
  double slope_before = 0.;    ///< g(x)'d, < 0
  double slope_after = 0.;     ///< g(x + t d)'d at the accepted point
  bool curvature_condition = false; ///< the accepted step satisfies weak Wolfe (always for L-BFGS but at `max_step`)
  bool steepest_descent = false;    ///< the direction was d = -g
  /// The optimizer restarted in this step: it found x changed since the last step, or the
  /// L-BFGS direction was not a descent direction (then d = -g), or the line search failed.
  /// The memory was cleared and, except for a non-descent direction, the next search starts from
  /// `reset_step`.
  bool memory_reset = false;
};

/// What `minimize()` passes to its visitor after every iteration.
struct Lbfgs_iteration_report
{
  std::size_t iteration = 0;   ///< 1 for the first iteration of the run
  double energy = 0.;          ///< at the current x (after the iteration)
  double gradient_norm = 0.;   ///< |g| / sqrt(n) at the current x
  double step_length = 0.;     ///< the accepted step (0 if the iteration failed)
  std::size_t evaluations = 0; ///< evaluations of f in the run so far
  bool line_search_failed = false; ///< the iteration failed (search and retry); x unchanged
  bool memory_reset = false;   ///< the optimizer restarted during the iteration (see `Lbfgs_step_result`)
  // The accepted step in detail (as in `Lbfgs_step_result`).
  double energy_before = 0.;
  double slope_before = 0.;
  double slope_after = 0.;
  bool curvature_condition = false;
  /// The current point and its gradient; valid during the visitor call only.
  const Eigen::VectorXd* x = nullptr;
  const Eigen::VectorXd* gradient = nullptr;
};

/// Why `minimize()` stopped.
enum class Lbfgs_stop_reason
{
  empty_problem,        ///< x has no coordinate
  non_finite_start,     ///< the energy or the gradient at the starting point is NaN or infinite
  gradient_tolerance,   ///< |g| / sqrt(n) <= gradient_tolerance (includes a zero gradient)
  line_search_failures, ///< max_line_search_failures consecutive failed iterations (at a kink, or at rounding level)
  energy_stalled,       ///< relative energy decrease over energy_window iterations <= energy_tolerance
  max_iterations,       ///< max_iterations iterations done
  max_evaluations,      ///< max_evaluations evaluations done
  visitor               ///< the visitor returned false
};

inline const char* to_string(Lbfgs_stop_reason r)
{
  switch(r)
  {
    case Lbfgs_stop_reason::empty_problem: return "empty problem";
    case Lbfgs_stop_reason::non_finite_start: return "non-finite energy or gradient at the start";
    case Lbfgs_stop_reason::gradient_tolerance: return "gradient below tolerance";
    case Lbfgs_stop_reason::line_search_failures: return "line search failed";
    case Lbfgs_stop_reason::energy_stalled: return "energy decrease below tolerance";
    case Lbfgs_stop_reason::max_iterations: return "iteration limit";
    case Lbfgs_stop_reason::max_evaluations: return "evaluation limit";
    case Lbfgs_stop_reason::visitor: return "stopped by the visitor";
  }
  return "unknown reason";
}

/// Summary of a `minimize()` run.
struct Lbfgs_report
{
  Lbfgs_stop_reason stop_reason = Lbfgs_stop_reason::max_iterations;
  std::size_t iterations = 0;           ///< iterations done (a retry belongs to its iteration)
  std::size_t evaluations = 0;          ///< evaluations of f in the run
  std::size_t failed_line_searches = 0; ///< line searches that failed (retries included)
  std::size_t resets = 0;               ///< iterations in which the optimizer restarted
  double initial_energy = std::numeric_limits<double>::quiet_NaN();
  double energy = std::numeric_limits<double>::quiet_NaN();        ///< at the final x
  double gradient_norm = std::numeric_limits<double>::quiet_NaN(); ///< |g| / sqrt(n) at the final x
};

/// Minimizes a locally Lipschitz energy f: R^n -> R, smooth almost everywhere (piecewise smooth
/// with kinks, like the developability energies of [SGC18]), from first-order information.
///
/// **Objective.** A callable `double f(const Eigen::VectorXd& x, Eigen::VectorXd& gradient)`
/// returning f(x) and writing a gradient (at a kink: any element of the Clarke subdifferential,
/// e.g. the gradient of one active piece) into `gradient`, which it receives sized n and zeroed.
/// A NaN or infinite energy or gradient at a trial point means "outside the domain": the line
/// search treats it as a step that went too far. It never reaches x.
///
/// **Why this line search.** On a nonsmooth f, strong Wolfe points (|g'd| small) may not exist
/// and smooth interpolation is meaningless; [LO13] show that Armijo plus the *weak* Wolfe
/// condition, searched by doubling and bisection of a bracket, terminates for semi-algebraic f
/// and keeps s'y > 0, so BFGS stays well defined. Iteration by iteration:
///  1. direction d: L-BFGS two-loop recursion [NW06, Alg. 7.4] on the m newest pairs, initial
///     Hessian H0 = gamma I with gamma = s'y / y'y of the newest pair [NW06, eq. (7.20)]; with no
///     pair (or for gradient descent) d = -g. If d is not finite or g'd >= 0: memory cleared,
///     d = -g.
///  2. step t: L-BFGS, the bracketing search of [LO13]: alpha = 0, beta = inf, t = t0;
///     Armijo fails (or f/g non-finite): beta = t; else weak Wolfe fails: alpha = t; else
///     accept. Next t = (alpha + beta) / 2 if beta < inf, else min(2 alpha, max_step).
///     Gradient descent: Armijo backtracking t <- rho t [NW06, Alg. 3.1].
///     t0 = initial_step on the first search, reset_step after a reset, else
///     min(2 t_prev, max_step) (the reference code's rule; or 1 for a quasi-Newton direction
///     with `unit_first_trial`), clamped to [min_step, max_step].
///  3. update: x <- x + t d; the pair s = x_new - x_old, y = g_new - g_old is stored unless
///     s'y <= 0 or s'y, y'y are not finite (then the memory is kept as it was).
/// A failed search leaves x unchanged, clears the memory and restarts the next search from
/// `reset_step` (the reference code's response). On a nonsmooth f this failure is the normal
/// termination signal at a kink [LO13].
///
/// **State.** The minimizer keeps the current point, its energy and gradient, the secant pairs
/// and the last step, so that a driver can interleave remeshing: call `step(f, x)` repeatedly,
/// and `reset()` whenever f or the length of x changes (an x changed between two steps is
/// detected and handled like a reset; a changed f with the same x is not: call `reset()`).
/// `minimize()` loops over `step()` with the stopping rules of `Lbfgs_options`.
///
/// **Limitations.** Weak Wolfe needs the slope along the line to rise to c2 times its initial
/// value: where f is linear along d up to the edge of its domain (NaN beyond), no step
/// qualifies and L-BFGS stops by line-search failure without moving; gradient descent (Armijo
/// only) does move there. On the kinks of f the gradient does not vanish: expect the run to end
/// by line-search failure or energy stall, not by the gradient tolerance.
///
/// **Cost.** Per iteration O(m n) for the direction and the update plus one evaluation of f per
/// line-search trial; memory (2 m + 6) n doubles. Deterministic: the same f, x and options give
/// bitwise identical results.
class Lbfgs_minimizer
{
public:
  using Options = Lbfgs_options;
  using Step_result = Lbfgs_step_result;
  using Iteration_report = Lbfgs_iteration_report;
  using Report = Lbfgs_report;

  /// \throws Invalid_parameter if an option is out of range (see `Lbfgs_options::check()`).
  explicit Lbfgs_minimizer(const Options& options = Options())
    : m_options(options)
  {
    m_options.check();
    m_next_step = m_options.initial_step;
    m_s.resize(m_options.memory);
    m_y.resize(m_options.memory);
    m_rho.assign(m_options.memory, 0.);
    m_gamma.assign(m_options.memory, 1.);
    m_alpha.assign(m_options.memory, 0.);
  }

  /// One iteration from x: direction, line search, update. `x` is changed (to the accepted
  /// point) only when the returned status is `accepted`. Evaluates f at x first unless x is
  /// the point this minimizer left after its last step.
  /// \throws Invalid_parameter if f writes a gradient whose size is not x.size()
  template <class F>
  Step_result step(F&& f, Eigen::VectorXd& x)
  {
    Step_result r;
    r.memory_reset = ensure_point(f, x, r.evaluations);
    r.energy_before = r.energy = m_energy;
    if(!m_point_finite)
    {
      r.status = Lbfgs_step_status::non_finite_point;
      return r;
    }
    // an exactly zero gradient (also: n = 0) has no descent direction; an underflowing one
    // (|g|^2 == 0) neither
    if(m_gradient.squaredNorm() == 0.)
    {
      r.status = Lbfgs_step_status::stationary;
      return r;
    }

    compute_direction(r);
    r.first_trial = clamp_step(m_options.unit_first_trial && !r.steepest_descent ? 1. : m_next_step);
    if(m_options.method == Descent_method::lbfgs)
      weak_wolfe_search(f, r);
    else
      backtracking_search(f, r);

    if(r.status == Lbfgs_step_status::accepted)
    {
      if(m_options.method == Descent_method::lbfgs)
        store_pair();
      m_x.swap(m_trial_x);
      m_gradient.swap(m_trial_gradient);
      m_energy = r.energy;
      x = m_x;
      m_next_step = (std::min)(2. * r.step_length, m_options.max_step);
    }
    else
    {
      clear_memory();
      m_next_step = m_options.reset_step;
      r.memory_reset = true;
    }
    return r;
  }

  /// Forgets everything: the secant pairs and the current point (f is evaluated again by the
  /// next step), and starts the next line search from `reset_step`. Call it after remeshing,
  /// subdivision, or any other change of the energy.
  void reset()
  {
    clear_memory();
    m_has_point = false;
    m_point_finite = false;
    m_energy = std::numeric_limits<double>::quiet_NaN();
    m_gradient.resize(0);
    m_next_step = m_options.reset_step;
  }

  /// Energy at the current point (NaN before the first step and after `reset()`).
  double energy() const { return m_energy; }
  /// Gradient at the current point (empty before the first step and after `reset()`).
  const Eigen::VectorXd& gradient() const { return m_gradient; }
  /// |g| / sqrt(n) at the current point (0 for n = 0; NaN if there is no current point).
  double gradient_norm() const
  {
    if(!m_has_point)
      return std::numeric_limits<double>::quiet_NaN();
    return m_gradient.size() == 0 ? 0. : m_gradient.norm() / std::sqrt(double(m_gradient.size()));
  }
  /// Number of secant pairs currently stored (0 after a reset; always 0 for gradient descent).
  std::size_t memory_size() const { return m_count; }
  /// First trial step of the next line search (before clamping).
  double next_step() const { return m_next_step; }
  /// Evaluations of f since construction.
  std::size_t evaluations() const { return m_evaluations; }
  const Options& options() const { return m_options; }

  /// Iterates `step()` from x until a stopping rule of the options holds, and leaves the best
  /// (last accepted) point in x. After each iteration `visitor(const Iteration_report&)` is
  /// called; returning false stops the run.
  ///
  /// An iteration whose line search fails is retried once from steepest descent (the failed
  /// search cleared the memory; the retry starts from `reset_step`), unless the failed search
  /// was exactly that search. The iteration fails when the retry fails too.
  ///
  /// Stopping rules, tested in this order:
  ///  - before the first iteration: `empty_problem` (n = 0), `non_finite_start`,
  ///    `gradient_tolerance`;
  ///  - after each iteration: `visitor`, `gradient_tolerance`, `line_search_failures`,
  ///    `energy_stalled`;
  ///  - before each iteration: `max_iterations`, `max_evaluations`.
  /// The minimizer keeps its state afterwards: another `minimize()` or `step()` continues.
  ///
  /// \throws Invalid_parameter if f writes a gradient whose size is not x.size()
  template <class F, class Visitor>
  Report minimize(F&& f, Eigen::VectorXd& x, Visitor&& visitor)
  {
    Report rep;
    const std::size_t evaluations_at_start = m_evaluations;
    std::size_t count = 0;
    const bool restarted = ensure_point(f, x, count);
    auto finish = [&](Lbfgs_stop_reason reason) {
      rep.stop_reason = reason;
      rep.evaluations = m_evaluations - evaluations_at_start;
      rep.energy = m_energy;
      rep.gradient_norm = gradient_norm();
      return rep;
    };
    rep.initial_energy = m_energy;
    if(restarted)
      ++rep.resets;
    if(x.size() == 0)
      return finish(Lbfgs_stop_reason::empty_problem);
    if(!m_point_finite)
      return finish(Lbfgs_stop_reason::non_finite_start);
    if(gradient_norm() <= m_options.gradient_tolerance)
      return finish(Lbfgs_stop_reason::gradient_tolerance);

    // energies of the last (window + 1) iterations, E_k at k % (window + 1)
    const std::size_t w = m_options.energy_window;
    std::vector<double> recent(w + 1, m_energy);
    std::size_t consecutive_failures = 0;
    while(true)
    {
      if(rep.iterations >= m_options.max_iterations)
        return finish(Lbfgs_stop_reason::max_iterations);
      if(m_options.max_evaluations > 0 && m_evaluations - evaluations_at_start >= m_options.max_evaluations)
        return finish(Lbfgs_stop_reason::max_evaluations);

      Step_result s = step(f, x);
      bool reset_in_iteration = s.memory_reset;
      if(s.status == Lbfgs_step_status::line_search_failed)
      {
        ++rep.failed_line_searches;
        const bool same_search = s.steepest_descent && s.first_trial == clamp_step(m_options.reset_step);
        if(!same_search)
        {
          const std::size_t evaluations_before = s.evaluations;
          s = step(f, x);
          s.evaluations += evaluations_before;
          if(s.status == Lbfgs_step_status::line_search_failed)
            ++rep.failed_line_searches;
        }
      }
      ++rep.iterations;
      if(reset_in_iteration)
        ++rep.resets;
      if(s.status == Lbfgs_step_status::non_finite_point) // x was changed by someone else
        return finish(Lbfgs_stop_reason::non_finite_start);
      const bool failed = s.status == Lbfgs_step_status::line_search_failed;
      consecutive_failures = failed ? consecutive_failures + 1 : 0;
      recent[rep.iterations % (w + 1)] = m_energy;

      Iteration_report it;
      it.iteration = rep.iterations;
      it.energy = m_energy;
      it.gradient_norm = gradient_norm();
      it.step_length = s.step_length;
      it.evaluations = m_evaluations - evaluations_at_start;
      it.line_search_failed = failed;
      it.memory_reset = reset_in_iteration;
      it.energy_before = s.energy_before;
      it.slope_before = s.slope_before;
      it.slope_after = s.slope_after;
      it.curvature_condition = s.curvature_condition;
      it.x = &x;
      it.gradient = &m_gradient;
      if(!visitor(static_cast<const Iteration_report&>(it)))
        return finish(Lbfgs_stop_reason::visitor);

      if(it.gradient_norm <= m_options.gradient_tolerance)
        return finish(Lbfgs_stop_reason::gradient_tolerance);
      if(consecutive_failures >= m_options.max_line_search_failures)
        return finish(Lbfgs_stop_reason::line_search_failures);
      if(w > 0 && rep.iterations >= w)
      {
        const double before = recent[(rep.iterations - w) % (w + 1)];
        const double now = m_energy;
        if(before - now <= m_options.energy_tolerance * (std::max)(std::abs(before), std::abs(now)))
          return finish(Lbfgs_stop_reason::energy_stalled);
      }
    }
  }

  /// `minimize()` without a visitor.
  template <class F>
  Report minimize(F&& f, Eigen::VectorXd& x)
  {
    return minimize(std::forward<F>(f), x, [](const Iteration_report&) { return true; });
  }

private:
  double clamp_step(double t) const { return (std::min)((std::max)(t, m_options.min_step), m_options.max_step); }

  // Evaluates f at y into (energy, gradient); true if both are finite.
  template <class F>
  bool evaluate(F& f, const Eigen::VectorXd& y, double& energy, Eigen::VectorXd& gradient)
  {
    gradient.setZero(y.size());
    ++m_evaluations;
    energy = f(static_cast<const Eigen::VectorXd&>(y), gradient);
    if(gradient.size() != y.size())
    {
      std::ostringstream s;
      s << "the objective wrote a gradient of size " << gradient.size() << " for " << y.size()
        << " unknowns";
      throw Invalid_parameter("objective", s.str());
    }
    return std::isfinite(energy) && gradient.allFinite();
  }

  // Makes (m_x, m_energy, m_gradient) describe x, evaluating f if x is not the current point.
  // Returns true if this restarted the optimizer (an earlier point existed and x differs).
  template <class F>
  bool ensure_point(F& f, const Eigen::VectorXd& x, std::size_t& evaluations)
  {
    // bitwise comparison: NaN coordinates never match, and are then evaluated (non-finite)
    if(m_has_point && m_x.size() == x.size() && (m_x.array() == x.array()).all())
      return false;
    const bool restart = m_has_point;
    if(restart)
      reset();
    m_x = x;
    ++evaluations;
    m_point_finite = evaluate(f, m_x, m_energy, m_gradient);
    m_has_point = true;
    return restart;
  }

  // Step 1: the search direction into m_direction, and its slope g'd into r.
  void compute_direction(Step_result& r)
  {
    const bool quasi_newton = m_options.method == Descent_method::lbfgs && m_count > 0;
    if(quasi_newton)
    {
      two_loop_recursion();
      r.slope_before = m_gradient.dot(m_direction);
      // rounding, or pairs from a nonsmooth f, can make -H g point uphill
      if(m_direction.allFinite() && r.slope_before < 0.)
        return;
      clear_memory();
      r.memory_reset = true;
    }
    m_direction = -m_gradient;
    r.slope_before = -m_gradient.squaredNorm();
    r.steepest_descent = true;
  }

  // [NW06, Alg. 7.4]: d = -H g, H the L-BFGS inverse Hessian of the stored pairs with
  // H0 = gamma I, gamma = s'y / y'y of the newest pair [NW06, eq. (7.20)].
  void two_loop_recursion()
  {
    const std::size_t m = m_s.size();
    m_direction = m_gradient;
    for(std::size_t k = m_count; k-- > 0;) // newest to oldest
    {
      const std::size_t i = (m_first + k) % m;
      m_alpha[i] = m_rho[i] * m_s[i].dot(m_direction);
      m_direction.noalias() -= m_alpha[i] * m_y[i];
    }
    const std::size_t newest = (m_first + m_count - 1) % m;
    m_direction *= m_gamma[newest];
    for(std::size_t k = 0; k < m_count; ++k) // oldest to newest
    {
      const std::size_t i = (m_first + k) % m;
      const double beta = m_rho[i] * m_y[i].dot(m_direction);
      m_direction.noalias() += (m_alpha[i] - beta) * m_s[i];
    }
    m_direction = -m_direction;
  }

  // Step 2 for L-BFGS: the weak-Wolfe bracketing search of [LO13]. On acceptance the trial
  // point and its gradient are in m_trial_x, m_trial_gradient.
  template <class F>
  void weak_wolfe_search(F& f, Step_result& r)
  {
    const double c1 = m_options.armijo, c2 = m_options.wolfe;
    const double f0 = m_energy, slope0 = r.slope_before;
    double alpha = 0., beta = std::numeric_limits<double>::infinity();
    double t = r.first_trial;
    for(std::size_t trial = 0; trial < m_options.max_line_search_trials; ++trial)
    {
      m_trial_x = m_x;
      m_trial_x.noalias() += t * m_direction;
      double ft;
      ++r.evaluations;
      const bool finite = evaluate(f, m_trial_x, ft, m_trial_gradient);
      if(!finite || !(ft <= f0 + c1 * t * slope0))
        beta = t; // too far: no sufficient decrease, or outside the domain
      else
      {
        const double slope = m_trial_gradient.dot(m_direction);
        const bool wolfe = slope >= c2 * slope0;
        if(wolfe || t >= m_options.max_step)
        {
          accept(r, t, ft, slope, wolfe);
          return;
        }
        alpha = t; // too short: f still falls steeply
      }
      if(beta < std::numeric_limits<double>::infinity())
      {
        const double mid = 0.5 * (alpha + beta);
        if(mid < m_options.min_step)
        {
          r.failure = Line_search_failure::min_step;
          break;
        }
        if(!(mid > alpha && mid < beta))
        {
          r.failure = Line_search_failure::interval_collapsed;
          break;
        }
        t = mid;
      }
      else
        t = (std::min)(2. * alpha, m_options.max_step);
    }
    if(r.failure == Line_search_failure::none)
      r.failure = Line_search_failure::max_trials;
    r.status = Lbfgs_step_status::line_search_failed;
  }

  // Step 2 for gradient descent: Armijo backtracking [NW06, Alg. 3.1], t <- rho t.
  template <class F>
  void backtracking_search(F& f, Step_result& r)
  {
    const double c1 = m_options.armijo, c2 = m_options.wolfe;
    const double f0 = m_energy, slope0 = r.slope_before;
    double t = r.first_trial;
    for(std::size_t trial = 0; trial < m_options.max_line_search_trials; ++trial)
    {
      m_trial_x = m_x;
      m_trial_x.noalias() += t * m_direction;
      double ft;
      ++r.evaluations;
      const bool finite = evaluate(f, m_trial_x, ft, m_trial_gradient);
      if(finite && ft <= f0 + c1 * t * slope0)
      {
        const double slope = m_trial_gradient.dot(m_direction);
        accept(r, t, ft, slope, slope >= c2 * slope0);
        return;
      }
      t *= m_options.backtracking_factor;
      if(t < m_options.min_step)
      {
        r.failure = Line_search_failure::min_step;
        r.status = Lbfgs_step_status::line_search_failed;
        return;
      }
    }
    r.failure = Line_search_failure::max_trials;
    r.status = Lbfgs_step_status::line_search_failed;
  }

  static void accept(Step_result& r, double t, double ft, double slope, bool wolfe)
  {
    r.status = Lbfgs_step_status::accepted;
    r.step_length = t;
    r.energy = ft;
    r.slope_after = slope;
    r.curvature_condition = wolfe;
  }

  // Step 3: stores the pair of the accepted step (trial point vs. current point), dropping the
  // oldest when the memory is full; skips pairs with s'y <= 0 or non-finite products.
  void store_pair()
  {
    const std::size_t m = m_s.size();
    if(m == 0)
      return;
    m_new_s = m_trial_x - m_x;
    m_new_y = m_trial_gradient - m_gradient;
    const double sy = m_new_s.dot(m_new_y);
    const double yy = m_new_y.squaredNorm();
    if(!(sy > 0.) || !std::isfinite(sy) || !(yy > 0.) || !std::isfinite(yy))
      return;
    std::size_t i;
    if(m_count < m)
      i = (m_first + m_count++) % m;
    else
    {
      i = m_first;
      m_first = (m_first + 1) % m;
    }
    m_s[i].swap(m_new_s);
    m_y[i].swap(m_new_y);
    m_rho[i] = 1. / sy;
    m_gamma[i] = sy / yy;
  }

  void clear_memory()
  {
    m_count = 0;
    m_first = 0;
  }

  Options m_options;
  // current point
  bool m_has_point = false;
  bool m_point_finite = false;
  Eigen::VectorXd m_x, m_gradient;
  double m_energy = std::numeric_limits<double>::quiet_NaN();
  double m_next_step = 0.;
  std::size_t m_evaluations = 0;
  // secant pairs: a ring of m slots, the oldest at m_first
  std::vector<Eigen::VectorXd> m_s, m_y;
  std::vector<double> m_rho, m_gamma, m_alpha;
  std::size_t m_first = 0, m_count = 0;
  // work vectors, reused
  Eigen::VectorXd m_direction, m_trial_x, m_trial_gradient, m_new_s, m_new_y;
};

/// One call: minimizes f from x (updated in place) with the given options; see
/// `Lbfgs_minimizer::minimize()` for the stopping rules and the visitor.
/// \throws Invalid_parameter if an option is out of range, or if f writes a gradient of the
/// wrong size
template <class F, class Visitor>
Lbfgs_report minimize(F&& f, Eigen::VectorXd& x, const Lbfgs_options& options, Visitor&& visitor)
{
  Lbfgs_minimizer minimizer(options);
  return minimizer.minimize(std::forward<F>(f), x, std::forward<Visitor>(visitor));
}

template <class F>
Lbfgs_report minimize(F&& f, Eigen::VectorXd& x, const Lbfgs_options& options = Lbfgs_options())
{
  Lbfgs_minimizer minimizer(options);
  return minimizer.minimize(std::forward<F>(f), x);
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_LBFGS_MINIMIZER_H
