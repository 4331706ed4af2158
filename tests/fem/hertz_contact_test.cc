// Hertz's contact (Johnson, Contact Mechanics, 1985, Sec. 4.2): a rigid
// sphere of radius R pressed a depth delta into an elastic half-space of
// Young's modulus E and Poisson's ratio nu takes the force
//     F = 4/3 E* sqrt(R) delta^(3/2),   E* = E / (1 - nu^2),
// over a contact radius a = sqrt(R delta). The FEM's half-space is a
// quarter block (symmetry planes x = 0 and y = 0) of edge 150 a, clamped at
// its bottom, its cells graded geometrically (ratio 1.8) from h at the
// contact to the far boundary; the neo-Hookean solid is nearly linear at
// the strains here (delta / R = 0.001, a / R = 0.03). Uzawa's updates keep
// the penetration below 1e-4 of h, so that the penalty does not soften the
// indentation. Measured (Q2, 27,783 DoFs): F / F_Hertz = 1.0218 at
// h = a / 2 and 1.0117 at h = 0.35 a, an error falling as h^1.75; with a
// block of 20 a and delta / R = 0.004 it was 1.049 (the finite block and
// the finite strain stiffen it), with 60 a 1.024.
#include "fem_test_tools.h"

#include <softchain/fem/boundary_ids.h>

#include <deal.II/grid/grid_generator.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

using namespace dealii;
using namespace softchain;
using namespace softchain::fem;

namespace
{
  constexpr double R = 0.01, delta = 1e-5, E = 2.6e5, nu = 0.3;

  // Steps from h growing by `ratio` until they cover `length` (the last
  // one cut to fit).
  std::vector<double> graded_steps(const double h, const double ratio, const double length)
  {
    std::vector<double> steps;
    double              covered = 0, step = h;
    while (covered + step < length * (1 - 1e-9))
      {
        steps.push_back(step);
        covered += step;
        step *= ratio;
      }
    steps.push_back(length - covered);
    return steps;
  }

  // The quarter block [0, L]^2 x [0, L], the sphere's pole at (0, 0, L).
  void quarter_block(Triangulation<3> &mesh, const double h, const double ratio, const double L)
  {
    const auto          across = graded_steps(h, ratio, L);
    std::vector<double> down(across.rbegin(), across.rend()); // fine at the top
    GridGenerator::subdivided_hyper_rectangle(mesh, {across, across, down}, Point<3>(), Point<3>(L, L, L));
    for (const auto &face : mesh.active_face_iterators())
      if (face->at_boundary())
        {
          const Point<3> c = face->center();
          face->set_boundary_id(c[0] < 1e-12 ? boundary::fixed_x :
                                c[1] < 1e-12 ? boundary::fixed_y :
                                c[2] < 1e-12 ? boundary::base :
                                               boundary::other);
        }
  }

  // The force on the whole sphere (four quarters) over Hertz's.
  double hertz_ratio(const double h_over_a, const double ratio, const double L_over_a, unsigned int &dofs)
  {
    const double     a = std::sqrt(R * delta), L = L_over_a * a;
    Triangulation<3> mesh;
    quarter_block(mesh, h_over_a * a, ratio, L);
    std::ostringstream contact;
    contact << std::setprecision(17) << "subsection Contact\n  set Penetration tolerance = 1e-4\n"
            << "  set Maximum augmentations = 30\n  subsection ball\n    set Shape = sphere\n"
            << "    set Position = 0, 0, " << L + R << "\n    set Radius = " << R
            << "\n    set Motion = 0, 0, " << -delta << "\n  end\nend\n"
            << "subsection Solver\n  set Initial load step = 0.5\nend\n";
    test::MeshSolverFixture f(
      test::parameters_from_text("hertz", test::solid_prm("Q2", "log", E, nu, contact.str())), mesh);
    dofs = f.solver->space().dof_handler.n_dofs();
    LoadState pressed;
    pressed.obstacle_motion = 1;
    REQUIRE(f.solver->solve(pressed).converged);
    const double force = 4 * f.solver->obstacle_contact()->obstacle_wrenches(f.solver->displacement(), 1.0)[0].force[2];
    const double hertz = 4.0 / 3.0 * E / (1 - nu * nu) * std::sqrt(R) * std::pow(delta, 1.5);
    return force / hertz;
  }
} // namespace

TEST_CASE("a sphere pressed into a block takes Hertz's force", "[fem][contact][hertz]")
{
  unsigned int coarse_dofs = 0, fine_dofs = 0;
  const double coarse = hertz_ratio(0.5, 1.8, 150, coarse_dofs);
  const double fine   = hertz_ratio(0.35, 1.8, 150, fine_dofs);
  INFO("F / F_Hertz: " << coarse << " (" << coarse_dofs << " DoFs), " << fine << " (" << fine_dofs << " DoFs)");
  CHECK(std::abs(fine - 1) < 0.02);
  CHECK(std::abs(fine - 1) < std::abs(coarse - 1));
}
