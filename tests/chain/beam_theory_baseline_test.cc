// The baseline's section moments against the closed forms of rectangular and
// hollow rectangular sections, on hexahedral and tetrahedral meshes.
#include <softchain/chain/beam_theory_baseline.h>

#include "box_mesh.h"

#include <catch2/catch.hpp>

using namespace softchain::chain;
using softchain::chain::testing::BoxMeshSpec;

namespace
{
  // Joints at (i + 1/2) a with a = 1 cm: section boundaries at multiples of
  // a, which the 5 mm cells of the default box never cut.
  std::vector<double> joint_x(int n, double a)
  {
    std::vector<double> x;
    for (int i = 0; i < n; ++i)
      x.push_back((i + 0.5) * a);
    return x;
  }

  double rectangle(double w, double h) { return w * h * h * h / 12.0; }
} // namespace

TEST_CASE("the section moment of a solid box is w h^3 / 12 about its own centroid")
{
  for (const bool tetrahedra : {false, true})
    {
      BoxMeshSpec spec;
      spec.tetrahedra = tetrahedra;
      const BeamTheoryBaseline baseline(testing::box_mesh(spec), joint_x(9, 0.01));
      // Polynomial integrands integrated exactly by the Gauss rule (header):
      // round-off of sums over ~10^4 quadrature points.
      for (const double I : baseline.second_moments())
        CHECK(I == Approx(rectangle(spec.width, spec.height)).epsilon(1e-12));
      for (const double a : baseline.section_lengths())
        CHECK(a == Approx(0.01).epsilon(1e-14));
    }
}

TEST_CASE("a hollow section subtracts the cavity, and k follows E I / a with 1 : 1 : 4")
{
  BoxMeshSpec spec;
  spec.wall_cells = 1; // walls of 2 mm (y) and 2 mm (z)
  const BeamTheoryBaseline baseline(testing::box_mesh(spec), joint_x(9, 0.01));
  const double             dy = spec.height / spec.ny, dz = spec.width / spec.nz;
  const double             I  = rectangle(spec.width, spec.height) -
                   rectangle(spec.width - 2 * dz, spec.height - 2 * dy);
  CHECK(baseline.second_moments()[4] == Approx(I).epsilon(1e-12));
  const double         E = 2.6e5;
  const JointStiffness k = baseline.stiffness(E);
  CHECK(k.joint(4)[2] == Approx(E * I / 0.01).epsilon(1e-12));
  CHECK(k.joint(4)[1] == k.joint(4)[2]);
  CHECK(k.joint(4)[0] == 4 * k.joint(4)[2]);
}

TEST_CASE("sections cut through cells err by at most the cut cells' share")
{
  // Joints at (i + 1/2) 7 mm: boundaries cut the 5 mm cells. In a prismatic
  // box only the volume counted per section is affected. A cut at fraction t
  // of a cell assigns the Gauss weights of the points below t: that sum
  // differs from t by at most 0.17 (at t = 0.33 or 0.67 of the 4-point
  // rule), so each of the two boundaries errs by at most 0.17 h of length.
  const BoxMeshSpec        spec;
  const double             a = 0.007, h = spec.length / spec.nx;
  const BeamTheoryBaseline baseline(testing::box_mesh(spec), joint_x(12, a));
  double                   largest = 0.0;
  for (std::size_t i = 0; i < 12; ++i)
    {
      const double I = rectangle(spec.width, spec.height);
      CHECK(baseline.second_moments()[i] == Approx(I).epsilon(2 * 0.17 * h / a));
      largest = std::max(largest, std::abs(baseline.second_moments()[i] / I - 1));
    }
  CHECK(largest > 1e-3); // the cuts do matter: the bound is not vacuous
}
