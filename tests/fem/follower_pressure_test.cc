// The follower pressure on a closed cavity: its forces sum to zero at any
// state, since the deformed area vectors cof(F) N dA of a closed surface sum
// to zero (divergence theorem with the Piola identity Div cof(F) = 0). On the
// conforming discrete surface this holds exactly, and Gauss quadrature of
// degree + 1 points integrates the polynomial area vectors exactly, so the
// resultant vanishes to round-off relative to p times the cavity area. The
// enclosed volume at rest is the bender's analytic cavity volume.
#include "fem_test_tools.h"

#include <softchain/fem/built_in_bender.h>

#include <catch2/catch.hpp>

using namespace dealii;
using namespace softchain;
using namespace softchain::fem;

namespace
{
  // Cavity wall area of the bender's box-shaped cavity.
  double cavity_area(const Parameters &prm)
  {
    const auto  &m = prm.mesh;
    const double a = m.bender_length - 2 * m.bender_wall, b = m.bender_width - 2 * m.bender_wall,
                 c = m.bender_height - 2 * m.bender_wall;
    return 2 * (a * b + b * c + c * a);
  }
} // namespace

TEST_CASE("follower pressure on a closed cavity has zero resultant", "[fem][pressure]")
{
  const double p = 5e4;
  for (const std::string element : {"Q1", "Q2", "P2"})
    {
      INFO(element);
      const std::string no_springs = "subsection Springs\n  set Generate for bender = false\nend\n";
      test::SolverFixture f(
        test::parameters_from_text("pressure_resultant", test::bender_prm(element, 4, no_springs)));
      const auto &pressure = f.solver->pressure_load();
      // Each of the ~1e3 face-point terms is exact to ~1e-16 of p A: 1e-12
      // leaves a margin of ~1e1 over accumulated round-off and is far below
      // the ~1e-3 p A that an open surface or a wrong cofactor would leave.
      const double scale = p * cavity_area(f.prm);
      const auto   rest  = f.solver->displacement();
      CHECK(pressure.resultant(rest, p).norm() <= 1e-12 * scale);
      // Every cavity face is planar at rest, so the discrete volume is exact.
      CHECK(pressure.cavity_volume(rest) ==
            Approx(BuiltInBender(f.prm).cavity_volume()).epsilon(1e-12));

      f.solver->set_displacement(test::smooth_displacement(*f.solver, 2e-3, 0.05, 3));
      const auto &deformed = f.solver->displacement();
      INFO("deformed resultant " << pressure.resultant(deformed, p) << " N, p A = " << scale);
      CHECK(pressure.resultant(deformed, p).norm() <= 1e-12 * scale);
      // Sanity of the deformed state: the volume changed by more than round-off.
      CHECK(std::abs(pressure.cavity_volume(deformed) / BuiltInBender(f.prm).cavity_volume() - 1) >
            1e-3);
    }
}
