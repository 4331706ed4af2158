// BaseReaction: the wrench the finger exerts on its clamped base equals the
// resultant of the applied loads (global equilibrium): the internal forces
// cancel over the body, and the follower pressure on the closed cavity has
// no resultant. A dead point load f at the material point X, which moves to
// x, gives F = f and M = (x - O) x f about the base centroid O.
#include "fem_test_tools.h"

#include <softchain/fem/base_reaction.h>

#include <catch2/catch.hpp>

using namespace dealii;
using namespace softchain;
using namespace softchain::fem;

TEST_CASE("the base wrench of a force-controlled solve equals the applied load's wrench",
          "[fem][reaction]")
{
  // Newton to a relative residual of 1e-10: the wrench of the residual left
  // at the free DoFs is then ~sqrt(n) 1e-10 |f_ext| ~ 1e-7 of the load, so
  // 1e-6 bounds the mismatch with a margin; a missing internal force, a
  // wrong sign or moment arm would be of the order of the load itself.
  for (const std::string element : {"Q2", "P2"})
    {
      INFO(element);
      test::SolverFixture f(test::parameters_from_text(
        "base_reaction",
        test::bender_prm(element, 4,
                         "subsection Springs\n  set Generate for bender = false\nend\n"
                         "subsection Solver\n  set Residual tolerance = 1e-10\n"
                         "  set Displacement tolerance = 1e-10\nend\n")));
      const Point<3>     X(0.079, 0.006, 0.009); // in the tip cap
      const Tensor<1, 3> force({0.02, -0.3, 0.1});
      LoadState          load;
      load.pressure    = 5e3;
      load.point_loads = {{X, force}};
      REQUIRE(f.solver->solve(load).converged);

      const BaseReaction base(f.solver->space());
      // The bender's base face is the full rectangle at x = 0.
      CHECK(base.centroid().distance(Point<3>(0, 0.006, 0.009)) < 1e-12);
      const auto           wrench   = base.wrench(f.solver->support_forces());
      const Point<3>       x        = f.solver->deformed_points({X})[0];
      const Tensor<1, 3>   expected = cross_product_3d(x - base.centroid(), force);
      INFO("force " << wrench.force << " moment " << wrench.moment << " expected " << expected);
      CHECK((wrench.force - force).norm() < 1e-6 * force.norm());
      CHECK((wrench.moment - expected).norm() < 1e-6 * expected.norm());
      // The load point moved: the moment arm is the deformed one.
      CHECK(x.distance(X) > 1e-4);
    }
}
