// ContinuationPredictor on model paths u(s) in R^3 whose form is known: the
// secant is exact on a straight path, the parabola on a quadratic one, and
// the order follows which of the two would have predicted the last state;
// a scalar carried along (volume control's pressure) is extrapolated alike,
// here the path's first component.
#include <softchain/fem/continuation_predictor.h>

#include <deal.II/base/index_set.h>

#include <catch2/catch.hpp>

#include <functional>

using namespace dealii;
using namespace softchain::fem;

namespace
{
  using Path = std::function<double(double s, unsigned int i)>;

  TrilinosWrappers::MPI::Vector state(const Path &u, const double s)
  {
    TrilinosWrappers::MPI::Vector v(complete_index_set(3), MPI_COMM_SELF);
    for (unsigned int i = 0; i < 3; ++i)
      v[i] = u(s, i);
    return v;
  }

  // The predictor after the path's converged states at `s` (s[0] = 0: its start).
  ContinuationPredictor along(const Path &u, const std::vector<double> &s)
  {
    ContinuationPredictor predictor(state(u, s[0]), u(s[0], 0));
    for (std::size_t k = 1; k < s.size(); ++k)
      predictor.converged(s[k], state(u, s[k]), u(s[k], 0));
    return predictor;
  }

  // |prediction - u(s)|; the scalar's prediction is checked against the
  // vector's first component (the same weights).
  double error(const ContinuationPredictor &predictor, const Path &u, const double s)
  {
    TrilinosWrappers::MPI::Vector v(complete_index_set(3), MPI_COMM_SELF);
    double                        scalar = 0;
    REQUIRE(predictor.predict(s, v, &scalar));
    CHECK(scalar == Approx(v[0]).epsilon(1e-14)); // the same sum, to round-off
    v -= state(u, s);
    return v.l2_norm();
  }

  const Path quadratic = [](double s, unsigned int i) { return 1.0 + i + (2.0 - i) * s + (3.0 + i) * s * s; };
} // namespace

TEST_CASE("the predictor has nothing to extrapolate from before a step has converged",
          "[fem][stepping]")
{
  const ContinuationPredictor   predictor(state(quadratic, 0.0));
  TrilinosWrappers::MPI::Vector v = state(quadratic, 0.7);
  CHECK_FALSE(predictor.predict(0.25, v));
  CHECK(v[1] == quadratic(0.7, 1));
}

TEST_CASE("the secant is exact on a straight path, the parabola on a quadratic one",
          "[fem][stepping]")
{
  const Path straight = [](double s, unsigned int i) { return 0.5 * i - (1.0 + i) * s; };
  // Round-off: a few ulps of |u| ~ 10, with weights of order 10.
  const ContinuationPredictor line = along(straight, {0.0, 0.125, 0.3});
  CHECK(line.order() == 1);
  CHECK(error(line, straight, 0.6) < 1e-13);

  // Steps of a real path: grown by 1.5, one retried shorter.
  const ContinuationPredictor curve = along(quadratic, {0.0, 0.125, 0.3125, 0.359, 0.43});
  CHECK(curve.order() == 2);
  CHECK(error(curve, quadratic, 0.54) < 1e-13);
  // The secant through the last two misses by |c| (s - s0)(s - s1), c = (3, 4, 5).
  const ContinuationPredictor secant = along(quadratic, {0.0, 0.359, 0.43});
  CHECK(secant.order() == 1);
  CHECK(error(secant, quadratic, 0.54) == Approx(std::sqrt(50.0) * 0.11 * 0.181).epsilon(1e-12));
}

TEST_CASE("the order stays 1 where the parabola would have predicted the last state worse",
          "[fem][stepping]")
{
  // A path that stops moving after s = 0.1 (as after a snap): through
  // (0, 0), (0.1, 1), (0.2, 1) the parabola puts u(0.3) at 0, the secant at 1.
  const Path flattens = [](double s, unsigned int) { return s < 0.05 ? 0.0 : 1.0; };
  const ContinuationPredictor predictor = along(flattens, {0.0, 0.1, 0.2, 0.3});
  CHECK(predictor.order() == 1);
  CHECK(error(predictor, flattens, 0.4) < 1e-14); // weights 2 and -1, to round-off
}
