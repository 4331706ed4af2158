// NewtonSolver and LoadPath on a model system whose answers are known in
// closed form: the scalar spring-hardening law
//     R(x) = x + x^3 - f s,
// with the load f scaled by the path parameter s. The model "inverts" (an
// element with J <= 0) where x exceeds a limit, so that the line search's
// halving and the failure classes can be forced.
#include <softchain/fem/load_path.h>
#include <softchain/fem/newton_solver.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

using namespace softchain::fem;

namespace
{
  class HardeningSpring : public NewtonSystem, public LoadPathProblem
  {
  public:
    double f         = 2.0;                                     // load at s = 1
    double x_limit   = std::numeric_limits<double>::infinity(); // x beyond it "inverts"
    bool   singular  = false;                                   // the linear solve fails
    double x = 0, x_converged = 0, s_target = 0, dx = 0, r = 0, k = 1, factor_taken = 1;
    unsigned int assemblies = 0;

    bool assemble(bool) override
    {
      ++assemblies;
      r = x + x * x * x - f * s_target;
      k = 1 + 3 * x * x;
      return x < x_limit;
    }
    double residual_norm() const override { return std::abs(r); }
    bool   residual_converged(double residual, double tolerance) const override
    {
      return residual <= tolerance * std::abs(f * s_target);
    }
    double solution_norm() const override { return std::abs(x); }
    double residual_scale() const override { return std::abs(f * s_target); }
    bool   solve_correction(bool, double) override
    {
      if (singular)
        return false;
      dx = -r / k;
      return true;
    }
    bool   keeps_factorisation() const override { return false; }
    double correction_norm() const override { return std::abs(dx); }
    double correction_slope() const override { return dx * r; }
    void   apply_correction() override
    {
      x += dx;
      factor_taken = 1;
    }
    void scale_correction(double factor) override
    {
      x += (factor - 1) * dx;
      dx *= factor;
      factor_taken *= factor;
    }
    bool energy_line_search() const override { return true; }
    bool backtracks = false;
    bool backtrack_when_stalled() const override { return backtracks; }

    NewtonSystem &begin_step(double s) override
    {
      s_target = s;
      return *this;
    }
    void accept_step(double) override { x_converged = x; }
    void reject_step() override { x = x_converged; }
  };

  SolverParameters solver_parameters()
  {
    SolverParameters prm{};
    prm.residual_tolerance     = 1e-10;
    prm.displacement_tolerance = 1e-10;
    prm.intermediate_tolerance = 1e-3;
    prm.max_newton_iterations  = 12;
    prm.initial_load_step      = 1;
    prm.min_load_step          = 1e-4;
    prm.max_load_step          = 1;
    prm.line_search            = true;
    return prm;
  }

  Parameters path_parameters()
  {
    Parameters prm{};
    prm.solver         = solver_parameters();
    prm.output.verbose = false;
    return prm;
  }
} // namespace

TEST_CASE("Newton converges quadratically to the closed-form root", "[fem][newton]")
{
  // x + x^3 = 2 has the root x = 1.
  HardeningSpring     spring;
  spring.s_target = 1;
  std::ostringstream  log;
  std::vector<double> history;
  NewtonSolver        newton(solver_parameters(), false, log);
  const auto          outcome = newton.solve(spring, true, &history);
  REQUIRE(outcome.converged());
  CHECK(spring.x == Approx(1.0).epsilon(1e-10));
  // Quadratic convergence: once |R| < 0.1, each residual is at most a
  // modest multiple of the square of the last (R''/(2 R'^2) = 6x/(2 16) < 1
  // near x = 1, so a factor of 1 is generous).
  REQUIRE(history.size() >= 3);
  for (std::size_t i = 1; i < history.size(); ++i)
    if (history[i - 1] < 0.1)
      CHECK(history[i] <= history[i - 1] * history[i - 1]);
  CHECK(outcome.iterations == history.size() - 1);
}

namespace
{
  // R(x) = atan(x - 1), root x = 1: the textbook case of full Newton steps
  // that overshoot further each time from |x0 - 1| > 1.39 (Dennis and
  // Schnabel 1996, Ch. 6), as friction's stick and slip make a finger's
  // steps overshoot.
  class ArctanLaw : public HardeningSpring
  {
  public:
    bool assemble(bool) override
    {
      ++assemblies;
      r = std::atan(x - 1);
      k = 1 / (1 + (x - 1) * (x - 1));
      return true;
    }
    bool residual_converged(double residual, double tolerance) const override
    {
      return residual <= tolerance;
    }
    double residual_scale() const override { return 1; }
    // Like friction, no energy: no energy line search.
    bool energy_line_search() const override { return false; }
  };
} // namespace

TEST_CASE("a stalled Newton backtracks on |R| where the system asks for it", "[fem][newton]")
{
  std::ostringstream log;
  NewtonSolver       newton(solver_parameters(), false, log);
  ArctanLaw          law;
  law.s_target = 1;
  law.x        = 2.5;
  SECTION("full steps diverge")
  {
    CHECK_FALSE(newton.solve(law, true).converged());
  }
  SECTION("steps shortened once two iterations have not halved |R| converge")
  {
    law.backtracks     = true;
    const auto outcome = newton.solve(law, true);
    REQUIRE(outcome.converged());
    CHECK(law.x == Approx(1.0).epsilon(1e-10));
  }
}

TEST_CASE("Newton halves a step that inverts an element and classifies its failures",
          "[fem][newton]")
{
  std::ostringstream log;
  NewtonSolver       newton(solver_parameters(), false, log);

  SECTION("a step past the limit is halved until admissible")
  {
    // From 0 the first Newton step of x + x^3 = 2 is dx = 2; past x = 1.5
    // it inverts and is halved to 1 (the root), within the limit.
    HardeningSpring spring;
    spring.s_target = 1;
    spring.x_limit  = 1.5;
    const auto outcome = newton.solve(spring, true);
    REQUIRE(outcome.converged());
    CHECK(spring.x == Approx(1.0).epsilon(1e-10));
  }
  SECTION("an inverted start is reported as inverted")
  {
    HardeningSpring spring;
    spring.s_target = 1;
    spring.x        = 2;
    spring.x_limit  = 1.5;
    CHECK(newton.solve(spring, true).status == NewtonSolver::Status::inverted);
  }
  SECTION("a failed linear solve is reported as such")
  {
    HardeningSpring spring;
    spring.s_target = 1;
    spring.singular = true;
    CHECK(newton.solve(spring, true).status == NewtonSolver::Status::linear_failure);
  }
  SECTION("too few iterations: not converged, after exactly the maximum")
  {
    SolverParameters prm      = solver_parameters();
    prm.max_newton_iterations = 2;
    NewtonSolver    short_newton(prm, false, log);
    HardeningSpring spring;
    spring.s_target    = 1;
    spring.f           = 1e6; // root near 100: far more than two steps away
    const auto outcome = short_newton.solve(spring, true);
    CHECK(outcome.status == NewtonSolver::Status::not_converged);
    CHECK(outcome.iterations == 2);
  }
}

TEST_CASE("a load path reaches its target, or stops in bounded attempts with a named cause",
          "[fem][newton][stepping]")
{
  std::ostringstream log;
  SECTION("the target, along converged steps")
  {
    HardeningSpring spring;
    const auto      result = LoadPath(path_parameters(), 0.25, "load factor", log).follow(spring);
    REQUIRE(result.finished());
    CHECK(result.reached == 1.0);
    CHECK(spring.x == Approx(1.0).epsilon(1e-10));
    CHECK(result.attempts == result.load_steps);
  }
  SECTION("a cut step below the minimum stops the path")
  {
    // No state beyond x = 0.5 is admissible: the path converges up to
    // about s = (0.5 + 0.125) / 2 = 0.3125 (its intermediate steps to a
    // residual of 1e-3 of the load) and its cut steps then shrink below the
    // minimum.
    HardeningSpring spring;
    spring.x_limit    = 0.5;
    const auto result = LoadPath(path_parameters(), 0.25, "load factor", log).follow(spring);
    CHECK(result.stop == LoadPath::Stop::step_too_small);
    CHECK(result.last_failure == NewtonSolver::Status::inverted);
    CHECK(result.reached > 0.3);
    CHECK(result.reached < 0.3125 * (1 + 1e-2));
    CHECK(spring.x < 0.5);
    CHECK(spring.x == spring.x_converged); // back at the last converged state
  }
  SECTION("the attempts are bounded even where the minimum step would allow more")
  {
    Parameters prm                    = path_parameters();
    prm.solver.min_load_step          = 1e-300;
    prm.solver.max_load_step_attempts = 50;
    HardeningSpring spring;
    spring.x_limit    = 0.5;
    const auto result = LoadPath(prm, 0.25, "load factor", log).follow(spring);
    CHECK(result.stop == LoadPath::Stop::too_many_attempts);
    CHECK(result.attempts == 50);
  }
}
