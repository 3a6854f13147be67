// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The nonsmooth first-order minimizer (internal/Solvers/Lbfgs_minimizer.h): convergence on smooth
// (Rosenbrock) and nonsmooth (|x| + x^2, max of quadratics) problems with known minimizers, the
// line-search conditions of every accepted step, the state API (step, reset), the stopping rules,
// NaN regions, determinism. Counts are printed for the record (`test_optimizer -s` shows them).

#include <CGAL/Surface_design/internal/Solvers/Lbfgs_minimizer.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>
#include <cstring>
#include <functional>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace SD = CGAL::Surface_design;
using SD::internal::Descent_method;
using SD::internal::Lbfgs_iteration_report;
using SD::internal::Lbfgs_minimizer;
using SD::internal::Lbfgs_options;
using SD::internal::Lbfgs_report;
using SD::internal::Lbfgs_step_status;
using SD::internal::Lbfgs_stop_reason;
using Eigen::VectorXd;

namespace {

const double not_a_number = std::numeric_limits<double>::quiet_NaN();

// Chained Rosenbrock: sum_i 100 (x_{i+1} - x_i^2)^2 + (1 - x_i)^2, minimum 0 at (1, ..., 1).
double rosenbrock(const VectorXd& x, VectorXd& g)
{
  double f = 0.;
  for(Eigen::Index i = 0; i + 1 < x.size(); ++i)
  {
    const double a = x[i + 1] - x[i] * x[i], b = 1. - x[i];
    f += 100. * a * a + b * b;
    g[i] += -400. * a * x[i] - 2. * b;
    g[i + 1] += 200. * a;
  }
  return f;
}

VectorXd rosenbrock_start(Eigen::Index n)
{
  VectorXd x(n);
  for(Eigen::Index i = 0; i < n; ++i)
    x[i] = i % 2 == 0 ? -1.2 : 1.; // the classical start (-1.2, 1), repeated
  return x;
}

// sum_i |x_i| + x_i^2: minimum 0 at 0, where every coordinate has a kink. Subgradient sign(0) = 0.
double abs_plus_square(const VectorXd& x, VectorXd& g)
{
  double f = 0.;
  for(Eigen::Index i = 0; i < x.size(); ++i)
  {
    f += std::abs(x[i]) + x[i] * x[i];
    g[i] = (x[i] > 0. ? 1. : x[i] < 0. ? -1. : 0.) + 2. * x[i];
  }
  return f;
}

// f(x) = max_i (x - c_i)' Q_i (x - c_i) + b_i, built so that its minimizer x* and minimum E* are
// known: choose multipliers lambda_i > 0 summing to 1 and gradients a_i at x* with
// sum_i lambda_i a_i = 0, then c_i = x* - Q_i^-1 a_i / 2 and b_i = E* - (x* - c_i)' Q_i (x* - c_i):
// every piece is active at x* with gradient a_i, 0 is in the convex hull of the active gradients,
// and f is strictly convex, so x* is its unique minimizer (the KKT condition is sufficient).
struct Max_of_quadratics
{
  std::vector<Eigen::MatrixXd> q;
  std::vector<VectorXd> c;
  std::vector<double> b;
  VectorXd minimizer;
  double minimum = 0.;

  Max_of_quadratics(const VectorXd& x_star, double e_star, const std::vector<VectorXd>& active_gradients)
    : minimizer(x_star), minimum(e_star)
  {
    const Eigen::Index n = x_star.size();
    for(std::size_t i = 0; i < active_gradients.size(); ++i)
    {
      // a fixed well-conditioned SPD matrix per piece: I + M'M, M with entries sin(...)
      Eigen::MatrixXd m(n, n);
      for(Eigen::Index r = 0; r < n; ++r)
        for(Eigen::Index k = 0; k < n; ++k)
          m(r, k) = std::sin(1.7 * double(r + 1) + 2.3 * double(k + 1) + 0.9 * double(i + 1));
      q.push_back(Eigen::MatrixXd::Identity(n, n) + m.transpose() * m);
      c.push_back(x_star - 0.5 * q.back().ldlt().solve(active_gradients[i]));
      const VectorXd d = x_star - c.back();
      b.push_back(e_star - d.dot(q.back() * d));
    }
  }

  double operator()(const VectorXd& x, VectorXd& g) const
  {
    double best = -std::numeric_limits<double>::infinity();
    std::size_t arg = 0;
    for(std::size_t i = 0; i < q.size(); ++i)
    {
      const VectorXd d = x - c[i];
      const double v = d.dot(q[i] * d) + b[i];
      if(v > best)
      {
        best = v;
        arg = i;
      }
    }
    g = 2. * q[arg] * (x - c[arg]);
    return best;
  }
};

// two pieces in dimension n: the minimum lies on the ridge where they are equal
Max_of_quadratics ridge_problem(Eigen::Index n)
{
  VectorXd x_star(n), a(n);
  for(Eigen::Index i = 0; i < n; ++i)
  {
    x_star[i] = 0.3 - 0.17 * double(i);
    a[i] = std::cos(0.7 * double(i) + 0.2);
  }
  const double lambda = 0.35;
  return Max_of_quadratics(x_star, 1., {(1. - lambda) * a, -lambda * a});
}

// three pieces in the plane: the minimum is a corner where all three are equal (f grows
// linearly in every direction, like |x|)
Max_of_quadratics corner_problem()
{
  VectorXd x_star(2);
  x_star << 0.4, -0.25;
  std::vector<VectorXd> a;
  for(int i = 0; i < 3; ++i)
  {
    VectorXd v(2);
    const double angle = 0.3 + 2.0943951023931957 * i; // 120 degrees apart: equal multipliers
    v << std::cos(angle), std::sin(angle);
    a.push_back(v);
  }
  return Max_of_quadratics(x_star, 1., a);
}

Lbfgs_options options_for(Descent_method method)
{
  Lbfgs_options o;
  o.method = method;
  return o;
}

void print(const std::string& problem, Descent_method method, const Lbfgs_report& r, double error)
{
  std::cout << "[optimizer] " << problem << ", " << to_string(method) << ": " << r.iterations
            << " iterations, " << r.evaluations << " evaluations, energy " << r.energy << ", |g|/sqrt(n) "
            << r.gradient_norm << ", error " << error << ", stop: " << to_string(r.stop_reason) << '\n';
}

// Records every iteration report and checks the line-search conditions of every accepted step:
// exactly on the reported numbers, and by re-evaluating f at the new point.
template <class F>
struct Step_checker
{
  F f;
  Lbfgs_options options;
  VectorXd previous_x, previous_g;
  double previous_energy = not_a_number;
  std::size_t accepted = 0, failed = 0, without_curvature = 0;

  Step_checker(F objective, const Lbfgs_options& o, const VectorXd& x0) : f(objective), options(o), previous_x(x0)
  {
    previous_g.setZero(x0.size());
    previous_energy = f(x0, previous_g);
  }

  bool operator()(const Lbfgs_iteration_report& it)
  {
    const VectorXd& x = *it.x;
    if(it.line_search_failed)
    {
      ++failed;
      REQUIRE(it.step_length == 0.);
      REQUIRE(std::memcmp(x.data(), previous_x.data(), std::size_t(x.size()) * sizeof(double)) == 0);
      REQUIRE(it.energy == previous_energy);
      return true;
    }
    ++accepted;
    // the reported numbers satisfy the conditions exactly
    REQUIRE(it.energy_before == previous_energy);
    REQUIRE(it.slope_before < 0.);
    REQUIRE(it.energy <= it.energy_before + options.armijo * it.step_length * it.slope_before);
    if(options.method == Descent_method::lbfgs)
    {
      if(it.curvature_condition)
        REQUIRE(it.slope_after >= options.wolfe * it.slope_before);
      else
      {
        ++without_curvature; // only allowed at the largest step
        REQUIRE(it.step_length == options.max_step);
      }
    }
    REQUIRE(it.step_length >= options.min_step);
    REQUIRE(it.step_length <= options.max_step);

    // and they are f's: re-evaluate at the new point; s = x_new - x_old = t d
    VectorXd g = VectorXd::Zero(x.size());
    const double e = f(x, g);
    REQUIRE(e == it.energy);
    REQUIRE(std::memcmp(g.data(), it.gradient->data(), std::size_t(g.size()) * sizeof(double)) == 0);
    // s differs from t d by the rounding of x_new = x_old + t d: allow for it
    const VectorXd s = x - previous_x;
    const double rounding = 1e-14 * (x.norm() + previous_x.norm());
    REQUIRE(std::abs(previous_g.dot(s) - it.step_length * it.slope_before) <=
            1e-10 * std::abs(it.step_length * it.slope_before) + previous_g.norm() * rounding);
    REQUIRE(std::abs(g.dot(s) - it.step_length * it.slope_after) <=
            1e-10 * std::abs(it.step_length * it.slope_after) + g.norm() * rounding);
    REQUIRE(e <= previous_energy + options.armijo * previous_g.dot(s) + previous_g.norm() * rounding);
    if(options.method == Descent_method::lbfgs && it.curvature_condition)
      REQUIRE(g.dot(s) >= options.wolfe * previous_g.dot(s) - (g.norm() + previous_g.norm()) * rounding);

    previous_x = x;
    previous_g = g;
    previous_energy = e;
    return true;
  }
};

template <class F>
Step_checker<F> make_checker(F f, const Lbfgs_options& o, const VectorXd& x0)
{
  return Step_checker<F>(f, o, x0);
}

} // namespace

TEST_CASE("Rosenbrock in 2 and 10 dimensions: L-BFGS reaches (1, ..., 1) to 1e-6, gradient "
          "descent too with far more evaluations", "[optimizer]")
{
  for(const Eigen::Index n : {Eigen::Index(2), Eigen::Index(10)})
  {
    const std::string name = "Rosenbrock n = " + std::to_string(n);
    // L-BFGS with the default options (reference rule for the first trial), then with t = 1 first
    VectorXd x = rosenbrock_start(n);
    Lbfgs_options lbfgs = options_for(Descent_method::lbfgs);
    auto checker = make_checker(rosenbrock, lbfgs, x);
    const Lbfgs_report r = SD::internal::minimize(rosenbrock, x, lbfgs, std::ref(checker));
    print(name, Descent_method::lbfgs, r, (x.array() - 1.).abs().maxCoeff());
    REQUIRE(r.stop_reason == Lbfgs_stop_reason::gradient_tolerance);
    REQUIRE((x.array() - 1.).abs().maxCoeff() < 1e-6);
    REQUIRE(r.energy < 1e-12);
    REQUIRE(r.iterations < 200);
    REQUIRE(checker.accepted == r.iterations);
    REQUIRE(checker.without_curvature == 0);

    VectorXd xu = rosenbrock_start(n);
    Lbfgs_options unit = lbfgs;
    unit.unit_first_trial = true;
    auto unit_checker = make_checker(rosenbrock, unit, xu);
    const Lbfgs_report ru = SD::internal::minimize(rosenbrock, xu, unit, std::ref(unit_checker));
    print(name + " (unit first trial)", Descent_method::lbfgs, ru, (xu.array() - 1.).abs().maxCoeff());
    REQUIRE(ru.stop_reason == Lbfgs_stop_reason::gradient_tolerance);
    REQUIRE((xu.array() - 1.).abs().maxCoeff() < 1e-6);
    REQUIRE(ru.evaluations < r.evaluations);

    // gradient descent with Armijo backtracking: about 2 10^4 iterations here (measured 18348 and
    // 24162), so its documented budget is 10^5 iterations
    VectorXd y = rosenbrock_start(n);
    Lbfgs_options gd = options_for(Descent_method::gradient_descent);
    gd.max_iterations = 100000;
    const Lbfgs_report rg = SD::internal::minimize(rosenbrock, y, gd);
    print(name, Descent_method::gradient_descent, rg, (y.array() - 1.).abs().maxCoeff());
    REQUIRE(rg.stop_reason == Lbfgs_stop_reason::gradient_tolerance);
    REQUIRE((y.array() - 1.).abs().maxCoeff() < 1e-6);
    // measured ratios: about 300 (n = 2) and 240 (n = 10)
    REQUIRE(rg.evaluations >= 50 * r.evaluations);
  }
}

TEST_CASE("|x| + x^2 (1D and summed over coordinates): the kink at 0 is reached or the line search "
          "fails there", "[optimizer]")
{
  std::vector<VectorXd> starts;
  starts.push_back((VectorXd(1) << 1.).finished());
  starts.push_back((VectorXd(1) << -0.7).finished());
  starts.push_back((VectorXd(5) << 1., -2., 0.5, 3., -0.25).finished());
  for(const Descent_method method : {Descent_method::lbfgs, Descent_method::gradient_descent})
    for(const VectorXd& x0 : starts)
    {
      VectorXd x = x0;
      const Lbfgs_options o = options_for(method);
      auto checker = make_checker(abs_plus_square, o, x);
      std::size_t first_below = 0; // first iteration with |x|_inf < 1e-8
      const Lbfgs_report r = SD::internal::minimize(abs_plus_square, x, o, [&](const Lbfgs_iteration_report& it) {
        if(first_below == 0 && it.x->cwiseAbs().maxCoeff() < 1e-8)
          first_below = it.iteration;
        return checker(it);
      });
      const double error = x.cwiseAbs().maxCoeff();
      print("|x| + x^2 n = " + std::to_string(x.size()) + " from " + std::to_string(x0[0]) +
              " (|x| < 1e-8 at iteration " + std::to_string(first_below) + ")",
            method, r, error);
      const bool at_kink = error < 1e-8;
      const bool failed_at_kink = r.stop_reason == Lbfgs_stop_reason::line_search_failures && r.energy <= 1e-10;
      REQUIRE((at_kink || failed_at_kink));
      REQUIRE(r.energy >= 0.);
      REQUIRE(r.energy <= r.initial_energy);
    }
}

TEST_CASE("Max of quadratics: L-BFGS finds the minimum on the ridge and at a corner to 1e-6", "[optimizer]")
{
  struct Case
  {
    std::string name;
    Max_of_quadratics f;
    VectorXd start;
  };
  std::vector<Case> problems;
  problems.push_back({"ridge of 2 quadratics n = 2", ridge_problem(2), (VectorXd(2) << 2., 1.5).finished()});
  problems.push_back({"ridge of 2 quadratics n = 6", ridge_problem(6), VectorXd::Constant(6, 1.)});
  problems.push_back({"corner of 3 quadratics n = 2", corner_problem(), (VectorXd(2) << -1., 2.).finished()});
  for(const Case& c : problems)
  {
    // the construction: every piece active at x*, value E*
    for(std::size_t i = 0; i < c.f.q.size(); ++i)
    {
      const VectorXd d = c.f.minimizer - c.f.c[i];
      REQUIRE(d.dot(c.f.q[i] * d) + c.f.b[i] == Approx(c.f.minimum).epsilon(1e-14));
    }
    VectorXd x = c.start;
    const Lbfgs_options o = options_for(Descent_method::lbfgs);
    auto checker = make_checker(std::cref(c.f), o, x);
    const Lbfgs_report r = SD::internal::minimize(std::cref(c.f), x, o, std::ref(checker));
    const double error = (x - c.f.minimizer).cwiseAbs().maxCoeff();
    print(c.name, Descent_method::lbfgs, r, error);
    REQUIRE(error < 1e-6);
    REQUIRE(r.energy - c.f.minimum < 1e-10);
    REQUIRE(r.energy >= c.f.minimum - 1e-14);
  }
}

TEST_CASE("step(): every accepted step satisfies Armijo and weak Wolfe, x changes only on acceptance",
          "[optimizer]")
{
  const Max_of_quadratics f = ridge_problem(6);
  for(const Descent_method method : {Descent_method::lbfgs, Descent_method::gradient_descent})
  {
    Lbfgs_options o = options_for(method);
    Lbfgs_minimizer minimizer(o);
    VectorXd x = VectorXd::Constant(6, 1.);
    std::size_t accepted = 0, failures = 0;
    for(int k = 0; k < 300; ++k)
    {
      const VectorXd before = x;
      VectorXd g0 = VectorXd::Zero(6);
      const double e0 = f(before, g0);
      const auto r = minimizer.step(f, x);
      REQUIRE(r.energy_before == e0);
      if(r.status != Lbfgs_step_status::accepted)
      {
        REQUIRE(r.status == Lbfgs_step_status::line_search_failed);
        REQUIRE(std::memcmp(x.data(), before.data(), 6 * sizeof(double)) == 0);
        REQUIRE(minimizer.memory_size() == 0);
        REQUIRE(minimizer.next_step() == o.reset_step);
        ++failures;
        continue;
      }
      ++accepted;
      VectorXd g1 = VectorXd::Zero(6);
      const double e1 = f(x, g1);
      REQUIRE(e1 == r.energy);
      REQUIRE(e1 == minimizer.energy());
      const VectorXd s = x - before;
      REQUIRE(r.energy <= r.energy_before + o.armijo * r.step_length * r.slope_before);
      REQUIRE(e1 <= e0 + o.armijo * g0.dot(s) + 1e-13);
      if(method == Descent_method::lbfgs)
      {
        REQUIRE(r.curvature_condition);
        REQUIRE(r.slope_after >= o.wolfe * r.slope_before);
        REQUIRE(g1.dot(s) >= o.wolfe * g0.dot(s) - 1e-13);
      }
      if(minimizer.gradient_norm() < 1e-12)
        break;
    }
    std::cout << "[optimizer] step() on the 6D ridge, " << to_string(method) << ": " << accepted
              << " accepted steps, " << failures << " failed line searches, "
              << minimizer.evaluations() << " evaluations, error "
              << (x - f.minimizer).cwiseAbs().maxCoeff() << '\n';
    REQUIRE(accepted > 0);
  }
}

TEST_CASE("The visitor can stop the run", "[optimizer]")
{
  VectorXd x = rosenbrock_start(10);
  std::vector<std::size_t> seen;
  std::size_t evaluations_reported = 0;
  const Lbfgs_report r = SD::internal::minimize(rosenbrock, x, Lbfgs_options(), [&](const Lbfgs_iteration_report& it) {
    seen.push_back(it.iteration);
    REQUIRE(it.evaluations > evaluations_reported);
    evaluations_reported = it.evaluations;
    REQUIRE(it.gradient_norm == Approx(it.gradient->norm() / std::sqrt(10.)));
    return it.iteration < 5;
  });
  REQUIRE(r.stop_reason == Lbfgs_stop_reason::visitor);
  REQUIRE(r.iterations == 5);
  REQUIRE(seen == std::vector<std::size_t>{1, 2, 3, 4, 5});
  REQUIRE(r.evaluations == evaluations_reported);
  VectorXd g = VectorXd::Zero(10);
  REQUIRE(rosenbrock(x, g) == r.energy); // x is the point of the last iteration
}

TEST_CASE("reset() clears the memory: the next direction is -gradient, from the reset step", "[optimizer]")
{
  Lbfgs_minimizer minimizer;
  VectorXd x = rosenbrock_start(10);
  for(int k = 0; k < 12; ++k)
    REQUIRE(minimizer.step(rosenbrock, x).status == Lbfgs_step_status::accepted);
  REQUIRE(minimizer.memory_size() == 8); // full memory (m = 8)
  // with memory the direction is not the steepest one
  {
    Lbfgs_minimizer copy = minimizer;
    VectorXd y = x;
    REQUIRE_FALSE(copy.step(rosenbrock, y).steepest_descent);
  }

  minimizer.reset();
  REQUIRE(minimizer.memory_size() == 0);
  REQUIRE(std::isnan(minimizer.energy()));
  REQUIRE(minimizer.gradient().size() == 0);
  const std::size_t evaluations = minimizer.evaluations();
  const VectorXd before = x;
  VectorXd g = VectorXd::Zero(10);
  rosenbrock(before, g);
  const auto r = minimizer.step(rosenbrock, x);
  REQUIRE(r.status == Lbfgs_step_status::accepted);
  REQUIRE(r.steepest_descent);
  REQUIRE(r.first_trial == Lbfgs_options().reset_step);
  REQUIRE(minimizer.evaluations() == evaluations + r.evaluations); // f re-evaluated at x: counted
  // x_new = x - t g, bit for bit
  VectorXd expected = before;
  expected.noalias() += r.step_length * (-g);
  REQUIRE(std::memcmp(expected.data(), x.data(), 10 * sizeof(double)) == 0);
  REQUIRE(r.slope_before == -g.squaredNorm());
  REQUIRE(minimizer.memory_size() == 1);

  // a point changed behind the minimizer's back is detected: memory cleared, f evaluated
  x[0] += 1e-3;
  const auto moved = minimizer.step(rosenbrock, x);
  REQUIRE(moved.memory_reset);
  REQUIRE(moved.steepest_descent);
  REQUIRE(moved.first_trial == Lbfgs_options().reset_step);
}

TEST_CASE("NaN regions: trial points with a NaN or infinite energy or gradient are too far, never "
          "accepted", "[optimizer]")
{
  // sum (x_i - 2)^2 inside the box |x_i| <= 2.5; outside, by `outside`: a NaN energy, an infinite
  // energy, or a finite energy with a NaN gradient. A first trial step of 10 lands there (at 40)
  // from the start at 0.
  for(const int outside : {0, 1, 2})
    for(const Descent_method method : {Descent_method::lbfgs, Descent_method::gradient_descent})
    {
      std::size_t bad_evaluations = 0;
      auto boxed = [&](const VectorXd& x, VectorXd& g) {
        g = 2. * (x.array() - 2.).matrix();
        const double e = (x.array() - 2.).square().sum();
        if(x.cwiseAbs().maxCoeff() <= 2.5)
          return e;
        ++bad_evaluations;
        if(outside == 2)
          g[0] = not_a_number;
        return outside == 0 ? not_a_number : outside == 1 ? std::numeric_limits<double>::infinity() : e;
      };
      Lbfgs_options o = options_for(method);
      o.initial_step = 10.;
      VectorXd x = VectorXd::Zero(4);
      const Lbfgs_report r = SD::internal::minimize(boxed, x, o, [](const Lbfgs_iteration_report& it) {
        REQUIRE(it.x->allFinite());
        REQUIRE(it.x->cwiseAbs().maxCoeff() <= 2.5);
        REQUIRE(std::isfinite(it.energy));
        REQUIRE(it.gradient->allFinite());
        return true;
      });
      print(std::string("quadratic in a box, outside ") + (outside == 0 ? "NaN" : outside == 1 ? "inf" : "NaN gradient"),
            method, r, (x.array() - 2.).abs().maxCoeff());
      REQUIRE(bad_evaluations > 0);
      REQUIRE(x.allFinite());
      REQUIRE((x.array() - 2.).abs().maxCoeff() < 1e-6);
    }
}

TEST_CASE("A linear energy cut by a NaN cliff: gradient descent approaches the cliff, L-BFGS (no "
          "weak-Wolfe point on such a line) stops by line-search failure without moving",
          "[optimizer]")
{
  // -sum x_i for x_i <= 1, NaN beyond. Along any descent line f is linear up to the cliff: the
  // slope never rises to c2 times the initial slope, so no step satisfies weak Wolfe.
  auto cliff = [](const VectorXd& x, VectorXd& g) {
    g.setConstant(-1.);
    return x.maxCoeff() > 1. ? not_a_number : -x.sum();
  };
  for(const Descent_method method : {Descent_method::lbfgs, Descent_method::gradient_descent})
  {
    VectorXd y = VectorXd::Zero(3);
    const Lbfgs_report r = SD::internal::minimize(cliff, y, options_for(method), [](const Lbfgs_iteration_report& it) {
      REQUIRE(it.x->maxCoeff() <= 1.);
      return true;
    });
    print("linear energy cut by a NaN cliff", method, r, 1. - y.minCoeff());
    REQUIRE(r.stop_reason == Lbfgs_stop_reason::line_search_failures);
    REQUIRE(y.allFinite());
    REQUIRE(y.maxCoeff() <= 1.);
    if(method == Descent_method::gradient_descent)
      REQUIRE(y.minCoeff() > 1. - 1e-6); // pushed against the cliff
    else
      REQUIRE(y == VectorXd::Zero(3));
  }
}

TEST_CASE("Deterministic: two runs are identical bit for bit", "[optimizer]")
{
  const Max_of_quadratics f = ridge_problem(6);
  for(const Descent_method method : {Descent_method::lbfgs, Descent_method::gradient_descent})
  {
    std::vector<double> energies[2];
    VectorXd x[2];
    Lbfgs_report r[2];
    for(int run = 0; run < 2; ++run)
    {
      x[run] = VectorXd::Constant(6, 1.);
      Lbfgs_options o = options_for(method);
      o.max_iterations = 300;
      r[run] = SD::internal::minimize(std::cref(f), x[run], o, [&](const Lbfgs_iteration_report& it) {
        energies[run].push_back(it.energy);
        energies[run].push_back(it.step_length);
        return true;
      });
    }
    REQUIRE(r[0].iterations == r[1].iterations);
    REQUIRE(r[0].evaluations == r[1].evaluations);
    REQUIRE(r[0].stop_reason == r[1].stop_reason);
    REQUIRE(energies[0].size() == energies[1].size());
    REQUIRE(std::memcmp(energies[0].data(), energies[1].data(), energies[0].size() * sizeof(double)) == 0);
    REQUIRE(std::memcmp(x[0].data(), x[1].data(), 6 * sizeof(double)) == 0);
  }
}

TEST_CASE("Stopping rules and degenerate inputs", "[optimizer]")
{
  SECTION("empty problem")
  {
    VectorXd x;
    std::size_t calls = 0;
    const Lbfgs_report r = SD::internal::minimize(
      [&](const VectorXd& y, VectorXd& g) {
        ++calls;
        REQUIRE(y.size() == 0);
        REQUIRE(g.size() == 0);
        return 3.;
      },
      x);
    REQUIRE(r.stop_reason == Lbfgs_stop_reason::empty_problem);
    REQUIRE(r.energy == 3.);
    REQUIRE(r.gradient_norm == 0.);
    REQUIRE(r.iterations == 0);
    REQUIRE(calls == 1);
    Lbfgs_minimizer m;
    REQUIRE(m.step([](const VectorXd&, VectorXd&) { return 1.; }, x).status == Lbfgs_step_status::stationary);
  }
  SECTION("non-finite start: x untouched")
  {
    VectorXd x = VectorXd::Constant(3, 5.);
    const Lbfgs_report r = SD::internal::minimize([](const VectorXd&, VectorXd&) { return not_a_number; }, x);
    REQUIRE(r.stop_reason == Lbfgs_stop_reason::non_finite_start);
    REQUIRE(r.iterations == 0);
    REQUIRE(x == VectorXd::Constant(3, 5.));
  }
  SECTION("a stationary start stops by the gradient rule at once")
  {
    VectorXd x = VectorXd::Ones(4);
    const Lbfgs_report r = SD::internal::minimize(rosenbrock, x);
    REQUIRE(r.stop_reason == Lbfgs_stop_reason::gradient_tolerance);
    REQUIRE(r.iterations == 0);
    REQUIRE(r.evaluations == 1);
  }
  SECTION("iteration and evaluation limits")
  {
    Lbfgs_options o;
    o.max_iterations = 7;
    VectorXd x = rosenbrock_start(2);
    Lbfgs_report r = SD::internal::minimize(rosenbrock, x, o);
    REQUIRE(r.stop_reason == Lbfgs_stop_reason::max_iterations);
    REQUIRE(r.iterations == 7);
    o.max_iterations = 0;
    x = rosenbrock_start(2);
    r = SD::internal::minimize(rosenbrock, x, o);
    REQUIRE(r.stop_reason == Lbfgs_stop_reason::max_iterations);
    REQUIRE(r.iterations == 0);
    REQUIRE(x == rosenbrock_start(2));
    o.max_iterations = 1000;
    o.max_evaluations = 40;
    x = rosenbrock_start(2);
    r = SD::internal::minimize(rosenbrock, x, o);
    REQUIRE(r.stop_reason == Lbfgs_stop_reason::max_evaluations);
    REQUIRE(r.evaluations >= 40);
    REQUIRE(r.evaluations < 40 + o.max_line_search_trials);
  }
  SECTION("relative energy stall over a window")
  {
    Lbfgs_options o;
    o.energy_tolerance = 1e-2;
    o.energy_window = 3;
    VectorXd x = rosenbrock_start(10);
    std::vector<double> e;
    const Lbfgs_report r = SD::internal::minimize(rosenbrock, x, o, [&](const Lbfgs_iteration_report& it) {
      e.push_back(it.energy);
      return true;
    });
    REQUIRE(r.stop_reason == Lbfgs_stop_reason::energy_stalled);
    const std::size_t k = e.size();
    REQUIRE(k >= 4);
    REQUIRE(e[k - 4] - e[k - 1] <= 1e-2 * std::abs(e[k - 4]));
    for(std::size_t j = 3; j + 1 < k; ++j) // it did not hold earlier
      REQUIRE(e[j - 3] - e[j] > 1e-2 * std::abs(e[j - 3]));
  }
  SECTION("a wrong gradient makes the line search fail: x unchanged, failure counted")
  {
    // f = |x|^2 but the gradient has the wrong sign: -g points uphill, no step satisfies Armijo
    VectorXd x = VectorXd::Constant(2, 1.);
    auto liar = [](const VectorXd& y, VectorXd& g) {
      g = -2. * y;
      return y.squaredNorm();
    };
    for(const Descent_method method : {Descent_method::lbfgs, Descent_method::gradient_descent})
    {
      std::vector<bool> failed;
      const Lbfgs_report r = SD::internal::minimize(liar, x, options_for(method), [&](const Lbfgs_iteration_report& it) {
        failed.push_back(it.line_search_failed);
        REQUIRE(it.memory_reset);
        return true;
      });
      REQUIRE(r.stop_reason == Lbfgs_stop_reason::line_search_failures);
      REQUIRE(failed == std::vector<bool>{true});
      REQUIRE(x == VectorXd::Constant(2, 1.));
    }
  }
  SECTION("a failed L-BFGS search is retried from steepest descent within the same iteration")
  {
    // an ill-conditioned quadratic; at iteration 6 every trial point off the steepest-descent
    // ray is made NaN: the L-BFGS search fails, the retry along -g succeeds
    const VectorXd diag = (VectorXd(4) << 1., 4., 9., 30.).finished();
    bool armed = false;
    VectorXd ray_origin, ray_direction;
    auto f = [&](const VectorXd& y, VectorXd& g) {
      if(armed)
      {
        const VectorXd s = y - ray_origin;
        if(s.norm() > 0. && s.dot(ray_direction) < (1. - 1e-9) * s.norm() * ray_direction.norm())
          return not_a_number;
      }
      g = diag.cwiseProduct(y);
      return 0.5 * y.dot(g);
    };
    std::vector<Lbfgs_iteration_report> reports;
    VectorXd x = VectorXd::Ones(4);
    Lbfgs_options o;
    o.max_iterations = 8;
    o.gradient_tolerance = 0.;
    o.energy_window = 0;
    const Lbfgs_report r = SD::internal::minimize(f, x, o, [&](const Lbfgs_iteration_report& it) {
      reports.push_back(it);
      armed = it.iteration == 5;
      ray_origin = *it.x;
      ray_direction = -*it.gradient;
      return true;
    });
    REQUIRE(reports.size() == 8);
    REQUIRE(r.failed_line_searches == 1);
    for(const auto& it : reports)
    {
      REQUIRE_FALSE(it.line_search_failed);
      REQUIRE(it.memory_reset == (it.iteration == 6));
    }
    REQUIRE(reports[5].step_length > 0.);
    REQUIRE(reports[5].energy < reports[4].energy);
  }
  SECTION("invalid options and a gradient of the wrong size throw Invalid_parameter")
  {
    Lbfgs_options o;
    o.wolfe = 1e-5; // below armijo
    REQUIRE_THROWS_AS(Lbfgs_minimizer(o), SD::Invalid_parameter);
    o = Lbfgs_options();
    o.min_step = 0.;
    REQUIRE_THROWS_AS(Lbfgs_minimizer(o), SD::Invalid_parameter);
    o = Lbfgs_options();
    o.max_step = std::numeric_limits<double>::infinity();
    REQUIRE_THROWS_AS(Lbfgs_minimizer(o), SD::Invalid_parameter);
    o = Lbfgs_options();
    o.backtracking_factor = 1.;
    REQUIRE_THROWS_AS(Lbfgs_minimizer(o), SD::Invalid_parameter);
    o = Lbfgs_options();
    o.gradient_tolerance = not_a_number;
    REQUIRE_THROWS_AS(Lbfgs_minimizer(o), SD::Invalid_parameter);
    o = Lbfgs_options();
    o.wolfe = 0.99; // the reference code's value is valid
    REQUIRE_NOTHROW(Lbfgs_minimizer(o));
    VectorXd x = VectorXd::Ones(3);
    REQUIRE_THROWS_AS(SD::internal::minimize(
                        [](const VectorXd&, VectorXd& g) {
                          g.resize(2);
                          return 0.;
                        },
                        x),
                      SD::Invalid_parameter);
  }
  SECTION("memory 0 and the reference's c2 = 0.99 and rho = 0.9 still converge")
  {
    Lbfgs_options o;
    o.memory = 0;
    o.max_iterations = 100000;
    VectorXd x = rosenbrock_start(2);
    Lbfgs_report r = SD::internal::minimize(rosenbrock, x, o);
    print("Rosenbrock n = 2 (memory 0)", o.method, r, (x.array() - 1.).abs().maxCoeff());
    REQUIRE((x.array() - 1.).abs().maxCoeff() < 1e-6);
    o = Lbfgs_options();
    o.wolfe = 0.99;
    x = rosenbrock_start(10);
    r = SD::internal::minimize(rosenbrock, x, o);
    print("Rosenbrock n = 10 (c2 = 0.99)", o.method, r, (x.array() - 1.).abs().maxCoeff());
    REQUIRE((x.array() - 1.).abs().maxCoeff() < 1e-6);
    o = options_for(Descent_method::gradient_descent);
    o.backtracking_factor = 0.9;
    o.max_iterations = 100000;
    x = rosenbrock_start(2);
    r = SD::internal::minimize(rosenbrock, x, o);
    print("Rosenbrock n = 2 (rho = 0.9)", o.method, r, (x.array() - 1.).abs().maxCoeff());
    REQUIRE((x.array() - 1.).abs().maxCoeff() < 1e-6);
  }
}
