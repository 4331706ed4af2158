// A thick-walled cylinder (inner radius A, outer B) in plane strain under an
// internal follower pressure p, against the exact inflation solution of the
// compressible neo-Hookean ("log") solid. The deformation r = f(R) has
// principal stretches l_r = f', l_t = f / R, l_z = 1 and principal nominal
// stresses
//     P_i = dW/dl_i = mu (l_i - 1 / l_i) + lambda ln(J) / l_i,  J = l_r l_t,
// from W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2. Radial equilibrium in
// the reference configuration, Div P = 0 in cylindrical coordinates for the
// diagonal P = diag(P_r, P_t, P_z) (R. W. Ogden, Non-linear Elastic
// Deformations, Dover 1997, Ch. 5, inflation of a compressible tube), is
//     dP_r/dR = (P_t - P_r) / R,
// with P_r(A) = -p f(A) / A (the Cauchy traction -p on the deformed inner
// surface, sigma_r = P_r / l_t) and P_r(B) = 0. No closed form exists for the
// compressible solid, so the test integrates this ODE (RK4, shooting on f(A))
// to ~1e-12 (relative) and compares the FEM radial displacements of a quarter ring
// (symmetry faces u_x = 0, u_y = 0; u_z = 0 on both flat faces).
#include "fem_test_tools.h"

#include <softchain/fem/boundary_ids.h>
#include <softchain/fem/hyperelastic_material.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <catch2/catch.hpp>

#include <array>
#include <cmath>

using namespace dealii;
using namespace softchain;
using namespace softchain::fem;

// Its own namespace, so that the unity batch that compiles this file with
// others holds each file's constants once.
namespace thick_cylinder_test
{

  namespace
  {
    constexpr double H = 0.001; // slice thickness [m]
    constexpr double E = 2.6e5, nu = 0.48;

    // Inner and outer radius [m] and the internal pressure [Pa].
    struct Tube
    {
      double A, B, p;
    };
    constexpr Tube thick{0.005, 0.010, 4e4}; // large strain: inner hoop stretch 1.57
    constexpr Tube thin{0.010, 0.0125, 1e4}; // P10's 2.5 mm wall

    struct Lame
    {
      double mu, lambda;
    };

    double nominal_stress(const Lame &m, const double l, const double J)
    {
      return m.mu * (l - 1 / l) + m.lambda * std::log(J) / l;
    }

    // The radial stretch l_r with P_r(l_r, l_t) = P (P_r grows with l_r).
    double radial_stretch(const Lame &m, const double P, const double l_t)
    {
      double l = 1;
      for (int k = 0; k < 50; ++k)
        {
          const double g  = nominal_stress(m, l, l * l_t) - P;
          const double dg = m.mu * (1 + 1 / (l * l)) + m.lambda * (1 - std::log(l * l_t)) / (l * l);
          l -= g / dg;
          if (std::abs(g) < 1e-14 * m.mu)
            break;
        }
      return l;
    }

    using State = std::array<double, 2>; // (f, P_r) at R, or their derivatives

    State add(const State &y, const double h, const State &k)
    {
      return {{y[0] + h * k[0], y[1] + h * k[1]}};
    }

    // The ODE's right-hand side at R.
    State slope(const Lame &m, const double R, const State &y)
    {
      const double l_t = y[0] / R, l_r = radial_stretch(m, y[1], l_t);
      return {{l_r, (nominal_stress(m, l_t, l_r * l_t) - y[1]) / R}};
    }

    // (f(B), P_r(B)) from f(A) = a (RK4, 2000 steps: error ~h^4 ~ 1e-14).
    State integrate(const Lame &m, const Tube &t, const double a)
    {
      const unsigned int steps = 2000;
      const double       h     = (t.B - t.A) / steps;
      State              y{{a, -t.p * a / t.A}};
      for (unsigned int k = 0; k < steps; ++k)
        {
          const double R  = t.A + k * h;
          const State  k1 = slope(m, R, y);
          const State  k2 = slope(m, R + h / 2, add(y, h / 2, k1));
          const State  k3 = slope(m, R + h / 2, add(y, h / 2, k2));
          const State  k4 = slope(m, R + h, add(y, h, k3));
          for (unsigned int i = 0; i < 2; ++i)
            y[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
        }
      return y;
    }

    // Exact (u_r(A), u_r(B)): the secant method on f(A) for P_r(B) = 0.
    std::array<double, 2> exact_radial_displacements(const Lame &m, const Tube &t)
    {
      double a0 = 1.01 * t.A, a1 = 1.3 * t.A;
      double g0 = integrate(m, t, a0)[1], g1 = integrate(m, t, a1)[1];
      for (int k = 0; k < 50 && std::abs(g1) > 1e-12 * t.p; ++k)
        {
          const double a2 = a1 - g1 * (a1 - a0) / (g1 - g0);
          a0 = a1, g0 = g1, a1 = a2, g1 = integrate(m, t, a1)[1];
        }
      REQUIRE(std::abs(g1) <= 1e-12 * t.p);
      return {{a1 - t.A, integrate(m, t, a1)[0] - t.B}};
    }

    constexpr double quarter = numbers::PI / 2;

    // Boundary id of a face of the (R, Theta, Z) box with centre c: the cavity
    // R = A, the free outer face R = B, the symmetry planes Theta = 0 (y = 0)
    // and Theta = pi/2 (x = 0), the plane-strain faces Z = 0, H.
    types::boundary_id ring_boundary_id(const Tube &t, const Point<3> &c)
    {
      if (std::abs(c[0] - t.A) < 1e-9 * t.A)
        return boundary::cavity;
      if (std::abs(c[0] - t.B) < 1e-9 * t.A)
        return boundary::other;
      if (c[1] < 1e-9)
        return boundary::fixed_y;
      if (std::abs(c[1] - quarter) < 1e-9)
        return boundary::fixed_x;
      return boundary::fixed_z;
    }

    // A quarter ring of n_r x n_t x 1 hexahedra (or these split into
    // tetrahedra), its vertices exactly on the circles.
    void quarter_ring(const Tube &t, const unsigned int n_r, const unsigned int n_t,
                      const bool tetrahedra, Triangulation<3> &mesh)
    {
      Triangulation<3> box; // in (R, Theta, Z)
      GridGenerator::subdivided_hyper_rectangle(box, {n_r, n_t, 1}, Point<3>(t.A, 0, 0),
                                                Point<3>(t.B, quarter, H));
      if (tetrahedra)
        GridGenerator::convert_hypercube_to_simplex_mesh(box, mesh);
      else
        mesh.copy_triangulation(box);
      for (const auto &face : mesh.active_face_iterators())
        if (face->at_boundary())
          face->set_boundary_id(ring_boundary_id(t, face->center()));
      GridTools::transform(
        [](const Point<3> &q) {
          return Point<3>(q[0] * std::cos(q[1]), q[0] * std::sin(q[1]), q[2]);
        },
        mesh);
    }

    // FEM (u_r(A), u_r(B)) on the x axis. `prm_name` names the .prm file, one
    // per test case (safe under ctest -j, which runs the test cases at once).
    std::array<double, 2> fem_radial_displacements(const std::string &prm_name, const Tube &t,
                                                   const std::string &element, const unsigned int n_r,
                                                   const unsigned int n_t)
    {
      Triangulation<3> mesh;
      quarter_ring(t, n_r, n_t, element[0] == 'P', mesh);
      test::MeshSolverFixture f(test::parameters_from_text(prm_name,
                                                           test::solid_prm(element, "log", E, nu)),
                                mesh);
      LoadState load;
      load.pressure = t.p;
      REQUIRE(f.solver->solve(load).converged);
      return {{test::displacement_at(*f.solver, Point<3>(t.A, 0, 0))[0],
               test::displacement_at(*f.solver, Point<3>(t.B, 0, 0))[0]}};
    }
  } // namespace

  // The cells have straight edges (trilinear or affine mapping), so the cavity
  // is a polygon whose chords sag by R (1 - cos(dTheta / 2)) ~ R dTheta^2 / 8:
  // an O(h^2) geometry error that dominates the O(h^3) interpolation error of
  // Q2 and P2. The test checks that rate (> 1.8 per halving; measured 2.2 for
  // Q2, 2.1-2.3 for P2) and that the Richardson extrapolation
  // u_4 + (u_4 - u_2) / 3 of the rate-2 error agrees with the exact solution to
  // 5e-4 (measured 1.3e-4 to 4e-4 for Q2, 6e-5 for P2): both fail for an error
  // in the material, the follower pressure or the symmetry constraints.
  TEST_CASE("thick cylinder under internal pressure matches the exact inflation", "[fem][cylinder]")
  {
    const ElasticConstants c(E, nu);
    const auto             exact = exact_radial_displacements({c.mu, c.lambda}, thick);
    for (const std::string element : {"Q2", "P2"})
      {
        std::vector<std::array<double, 2>> fem;
        std::vector<double>                error;
        for (const unsigned int n : {1u, 2u, 4u})
          {
            fem.push_back(fem_radial_displacements("thick_cylinder", thick, element, 2 * n, 4 * n));
            error.push_back(std::max(std::abs(fem.back()[0] / exact[0] - 1),
                                     std::abs(fem.back()[1] / exact[1] - 1)));
            WARN("thick cylinder, " << element << " on " << 2 * n << " x " << 4 * n
                                    << " hexahedra: u_r(A) = " << fem.back()[0] << " m (exact "
                                    << exact[0] << "), u_r(B) = " << fem.back()[1] << " m (exact "
                                    << exact[1] << "), relative error " << error.back());
          }
        INFO(element);
        for (const unsigned int k : {0u, 1u})
          CHECK(std::log2(error[k] / error[k + 1]) > 1.8);
        for (const unsigned int i : {0u, 1u})
          {
            const double extrapolated = fem[2][i] + (fem[2][i] - fem[1][i]) / 3;
            INFO((i == 0 ? "inner" : "outer") << " radius: extrapolated " << extrapolated);
            CHECK(std::abs(extrapolated / exact[i] - 1) < 5e-4);
          }
      }
  }

  // Through a thin wall (P10's 2.5 mm at 10 mm radius) the radial resolution
  // alone: 1, 2 and 4 Q2 elements across the wall on one fine angular mesh.
  // The straight chords' geometry error (see above) then stays the same on
  // the three meshes and cancels in their differences, so the observed order
  // log2(|u_1 - u_2| / |u_2 - u_4|) is the element's own rate through the
  // wall. Q2's nodal values converge at twice its degree for such a smooth
  // radial field (superconvergence at the element vertices; the L2 rate is
  // 3): measured 3.95 at the inner and 4.04 at the outer radius. The bound 3.5
  // fails for an element that converges only at Q2's L2 rate or slower. One
  // element across the wall is already within 2.1e-4 of four (the bound 1e-3):
  // through a wall, Q2's error is small next to the geometry's (1.5e-4 here,
  // the chords' sag with 48 cells per quarter) and the mesh's along the finger.
  TEST_CASE("Q2 converges at its rate through a thin wall", "[fem][cylinder][convergence]")
  {
    const ElasticConstants c(E, nu);
    const auto             exact = exact_radial_displacements({c.mu, c.lambda}, thin);
    std::vector<std::array<double, 2>> fem;
    for (const unsigned int n : {1u, 2u, 4u})
      fem.push_back(fem_radial_displacements("thin_wall", thin, "Q2", n, 48));
    for (const unsigned int i : {0u, 1u})
      {
        const double order = std::log2(std::abs(fem[0][i] - fem[1][i]) / std::abs(fem[1][i] - fem[2][i]));
        WARN("thin wall, " << (i == 0 ? "inner" : "outer") << " radius: u_r = " << fem[0][i] << ", "
                           << fem[1][i] << ", " << fem[2][i] << " m with 1, 2, 4 elements (exact "
                           << exact[i] << "), observed order " << order);
        CHECK(order > 3.5);
        CHECK(std::abs(fem[0][i] - fem[2][i]) <= 1e-3 * std::abs(fem[2][i]));
      }
  }
} // namespace thick_cylinder_test
