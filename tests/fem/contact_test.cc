// Contact with rigid obstacles (ObstacleContact) against what no one here
// wrote:
//  - its tangent against finite differences of its residual, on every
//    obstacle shape and on both branches (points open and pressed). Measured
//    errors 1e-11 to 1e-10; without the normal's turning (the t_N H term)
//    they are 0.22 (sphere) and 0.09 (cylinder). A box presses with its flat
//    faces only (its curvature is outside, where g > 0: checked in
//    tests/geometry/rigid_obstacle_test.cc);
//  - the frictionless patch test: a block pressed by a rigid plane is in
//    homogeneous uniaxial stress, so the contact pressure is uniform and
//    the force is the closed-form neo-Hookean one at the block's stretch;
//  - the augmented Lagrangian: with a soft penalty, Uzawa's updates take
//    the penetration below its tolerance and the force to the one of the
//    prescribed compression;
//  - the friction tangent's solve by GMRES with the LDL^T factors of its
//    symmetric approximation, against Trilinos' KLU;
//  - obstacles from STL files against the analytic ones they mesh, and an
//    obstacle turned along the load path against the same obstacle brought
//    to its final pose by a translation.
#include "../geometry/obstacle_meshes.h"
#include "fem_test_tools.h"

#include <softchain/fem/boundary_ids.h>
#include <softchain/fem/serial_direct_solver.h>
#include <softchain/fem/volume_controlled_inflation.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/numerics/vector_tools.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>

using namespace dealii;
using namespace softchain;
using namespace softchain::fem;

namespace
{
  std::string obstacle(const std::string &name, const std::string &settings)
  {
    return "  subsection " + name + "\n" + settings + "  end\n";
  }

  std::string contact_section(const std::string &obstacles, const std::string &law = "")
  {
    return "subsection Contact\n" + law + obstacles + "end\n";
  }

  // The contact's own tangent error |K_c v - FD_c| / |K_c v| at a deformed
  // state of the demo bender (Q2, 4 cells, [0, 0.08] x [0, 0.012] x
  // [0, 0.018]) whose bottom face y = 0 the obstacle cuts, so that some
  // contact points are pressed and others open (both counted). K_c v and
  // FD_c are the differences between the bender with and without the
  // obstacle, so that the material's larger part does not hide an error.
  double contact_tangent_error(const std::string &contact, unsigned int &pressed, unsigned int &open,
                               unsigned int *stick = nullptr, unsigned int *slip = nullptr)
  {
    const std::string no_springs = "subsection Springs\n  set Generate for bender = false\nend\n";
    test::SolverFixture with(test::parameters_from_text("contact_tangent", test::bender_prm("Q2", 4, no_springs + contact)));
    test::SolverFixture without(test::parameters_from_text("contact_tangent_free", test::bender_prm("Q2", 4, no_springs)));
    const auto u = test::smooth_displacement(*with.solver, 2e-3, 0.05, 1);
    const auto v = test::smooth_displacement(*with.solver, 1.0, 1.0, 2);
    with.solver->set_displacement(u);
    pressed = open = 0;
    for (const auto &p : with.solver->obstacle_contact()->point_states(with.solver->displacement(), 0.0))
      {
        ++(p.pressure > 0 ? pressed : open);
        if (stick && p.status == ObstacleContact::Status::stick)
          ++*stick;
        if (slip && p.status == ObstacleContact::Status::slip)
          ++*slip;
      }
    // Central differences with h = 1e-8 along a v of unit-size entries:
    // truncation ~h^2 and round-off ~1e-16 |R| / h, both below 1e-7 of
    // K_c v here (measured: 1e-8 to 1e-9); no contact point lies within
    // 1e-8 m of its kink (g = 0) for this field.
    auto [Kv, fd]         = test::tangent_and_difference(*with.solver, LoadState(), u, v, 1e-8);
    const auto [Kv0, fd0] = test::tangent_and_difference(*without.solver, LoadState(), u, v, 1e-8);
    Kv -= Kv0;
    fd -= fd0;
    fd -= Kv;
    return fd.l2_norm() / Kv.l2_norm();
  }

  // The patch test's block: edge `edge`, 2^3 cells with interior vertices
  // moved at random (its faces stay flat), on the symmetry planes x = 0,
  // y = 0, z = 0; the top z = edge free to meet the plane.
  constexpr double edge = 0.01;
  void symmetric_block(Triangulation<3> &mesh)
  {
    GridGenerator::subdivided_hyper_rectangle(mesh, {2, 2, 2}, Point<3>(), Point<3>(edge, edge, edge));
    GridTools::distort_random(0.2, mesh, /*keep_boundary*/ true, /*seed*/ 3);
    for (const auto &face : mesh.active_face_iterators())
      if (face->at_boundary())
        {
          const Point<3> c = face->center();
          face->set_boundary_id(c[0] < 1e-9 ? boundary::fixed_x :
                                c[1] < 1e-9 ? boundary::fixed_y :
                                c[2] < 1e-9 ? boundary::fixed_z :
                                              boundary::other);
        }
  }

  // The log neo-Hookean W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2 in
  // uniaxial stress with axial stretch a: the lateral stretch b solves
  // mu (b^2 - 1) + lambda ln(a b^2) = 0 (zero lateral Cauchy stress), and
  // the axial force on the reference area A0 is
  //     N = (mu (a^2 - 1) + lambda ln J) / J * b^2 A0,   J = a b^2.
  double uniaxial_force(const double E, const double nu, const double a, const double A0)
  {
    const double mu = E / (2 * (1 + nu)), lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
    double       b  = 1;
    for (int k = 0; k < 50; ++k) // Newton on b
      b -= (mu * (b * b - 1) + lambda * std::log(a * b * b)) / (2 * mu * b + 2 * lambda / b);
    const double J = a * b * b;
    return (mu * (a * a - 1) + lambda * std::log(J)) / J * b * b * A0;
  }

  // A block [0, edge]^3 of 2^3 cells clamped at z = 0 (the base).
  void clamped_block(Triangulation<3> &mesh)
  {
    GridGenerator::subdivided_hyper_rectangle(mesh, {2, 2, 2}, Point<3>(), Point<3>(edge, edge, edge));
    for (const auto &face : mesh.active_face_iterators())
      if (face->at_boundary())
        face->set_boundary_id(face->center()[2] < 1e-9 ? boundary::base : boundary::other);
  }

  // The symmetric block pressed by the obstacles of `contact` at the end of
  // their motion (Q2, E = 2.6e5 Pa, nu = 0.3, Newton to 1e-10); returns what
  // `read` takes from the solver there.
  template <typename Read>
  auto pressed_block(const std::string &name, const std::string &contact, Read read)
  {
    Triangulation<3> mesh;
    symmetric_block(mesh);
    test::MeshSolverFixture f(
      test::parameters_from_text(name, test::solid_prm("Q2", "log", 2.6e5, 0.3,
                                                       "subsection Solver\n  set Residual tolerance = 1e-10\n"
                                                       "  set Displacement tolerance = 1e-10\nend\n" +
                                                         contact)),
      mesh);
    LoadState pressed;
    pressed.obstacle_motion = 1;
    REQUIRE(f.solver->solve(pressed).converged);
    return read(*f.solver);
  }

  const std::string pressing_plane =
    obstacle("press", "    set Shape = plane\n    set Position = 0, 0, 0.01\n    set Normal = 0, 0, -1\n"
                      "    set Motion = 0, 0, -0.001\n");
} // namespace

TEST_CASE("the contact tangent matches finite differences on every obstacle shape", "[fem][contact][tangent]")
{
  const std::vector<std::pair<std::string, std::string>> shapes{
    {"plane", "    set Shape = plane\n    set Position = 0, 0.0002, 0\n    set Normal = 0, 1, 0\n"},
    {"sphere", "    set Shape = sphere\n    set Position = 0.06, -0.0085, 0.009\n    set Radius = 0.01\n"},
    {"cylinder", "    set Shape = cylinder\n    set Position = 0.05, -0.0096, 0\n    set Axis = 0, 0, 1\n"
                 "    set Radius = 0.01\n"},
    {"box", "    set Shape = box\n    set Position = 0.07, -0.009, 0.009\n"
            "    set Half sizes = 0.005, 0.01, 0.005\n"},
    // The sphere's place, meshed by 512 triangles: its curvature lives on
    // the edges and vertices.
    {"stl", "    set Shape = stl\n    set File = contact_tangent_sphere.stl\n"
            "    set Position = 0.06, -0.0085, 0.009\n"}};
  geometry::testing::sphere_surface(Eigen::Vector3d::Zero(), 0.01, 3).write("contact_tangent_sphere.stl");
  for (const auto &[shape, settings] : shapes)
    {
      INFO(shape);
      unsigned int pressed = 0, open = 0;
      const double error   = contact_tangent_error(contact_section(obstacle("obstacle", settings)), pressed, open);
      INFO(shape << ": " << pressed << " points pressed, " << open << " open, error " << error);
      CHECK(pressed > 0);
      CHECK(open > 0);
      CHECK(error < 1e-6);
    }
}

TEST_CASE("the friction tangent matches finite differences where points stick and slip",
          "[fem][contact][tangent]")
{
  // The sphere under the bender with Coulomb friction; the anchors are the
  // points at rest, so a point sticks where the displacement's tangential
  // part is below mu times its penetration, and slips elsewhere.
  unsigned int pressed = 0, open = 0, stick = 0, slip = 0;
  const std::string sphere = "    set Shape = sphere\n    set Position = 0.06, -0.0085, 0.009\n"
                             "    set Radius = 0.01\n    set Friction coefficient = 0.5\n";
  const double error = contact_tangent_error(contact_section(obstacle("obstacle", sphere)), pressed, open,
                                             &stick, &slip);
  INFO(stick << " points stick, " << slip << " slip, error " << error);
  CHECK(stick > 0);
  CHECK(slip > 0);
  CHECK(error < 1e-6);
}

// The bender of the friction tangent test, its points sticking and slipping
// on the sphere: K is unsymmetric, K - N symmetric (N the part
// ObstacleContact assembles apart), and GMRES preconditioned by the LDL^T
// factors of K - N solves K x = b as KLU's LU does.
TEST_CASE("GMRES with the factors of the symmetric approximation solves the friction tangent",
          "[fem][contact][friction][solver]")
{
  if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
    return; // SerialDirectSolver is the one-rank path
  const std::string   sphere = "    set Shape = sphere\n    set Position = 0.06, -0.0085, 0.009\n"
                               "    set Radius = 0.01\n    set Friction coefficient = 0.5\n";
  const std::string   no_springs = "subsection Springs\n  set Generate for bender = false\nend\n";
  test::SolverFixture f(test::parameters_from_text(
    "friction_gmres", test::bender_prm("Q2", 4, no_springs + contact_section(obstacle("obstacle", sphere)))));
  QuasiStaticSolver &solver = *f.solver;
  solver.set_displacement(test::smooth_displacement(solver, 2e-3, 0.05, 1));
  REQUIRE(solver.assemble(LoadState(), true));
  const TrilinosWrappers::SparseMatrix &K = solver.tangent();
  const TrilinosWrappers::MPI::Vector  &b = solver.negative_residual();

  TrilinosWrappers::SparseMatrix N, contact_tangent;
  N.reinit(K);
  contact_tangent.reinit(K);
  N               = 0;
  contact_tangent = 0;
  TrilinosWrappers::MPI::Vector contact_force(b);
  contact_force = 0;
  solver.obstacle_contact()->assemble(solver.displacement(), 0.0, solver.space().fixed_dofs, &contact_tangent,
                                      contact_force, &N);
  N.compress(VectorOperation::add);
  REQUIRE(N.frobenius_norm() > 0);

  // Without N the unsymmetric K goes to LU; with it, to GMRES.
  TrilinosWrappers::MPI::Vector lu(b), x(b), r(b);
  SerialDirectSolver            direct(K);
  REQUIRE(direct.solve(K, lu, b));
  REQUIRE(direct.last_factors() == SerialDirectSolver::Factors::lu);
  REQUIRE(direct.solve(K, x, b, &N));
  CHECK(direct.last_factors() == SerialDirectSolver::Factors::krylov);
  INFO("GMRES iterations " << direct.krylov_iterations_taken());
  // K - N differs from K on the contact points alone: a few iterations
  // (measured: 9 to this test's 1e-12; 3 to 13 to Newton's 1e-8 on P10).
  CHECK(direct.krylov_iterations_taken() <= 15);

  // Without a caller's relative residual GMRES stops at |b - K x| <=
  // 1e-12 |b| (FGMRES's residual is K's own; Trilinos' product sums in
  // another order, round-off 1e-16 |K| |x|).
  K.vmult(r, x);
  r -= b;
  CHECK(r.l2_norm() <= 1.01e-12 * b.l2_norm());
  // KLU and UMFPACK's LU are backward stable: each differs from the GMRES
  // solution by at most cond(K) times the relative residual 1e-12; the
  // ratio of forward to backward error on the bender's tangents is 1e5 to
  // 1e6 (serial_direct_solver_test.cc), so 1e-5 bounds it with margin.
  TrilinosWrappers::MPI::Vector klu(b);
  SolverControl                 control(1, 0);
  TrilinosWrappers::SolverDirect(control, TrilinosWrappers::SolverDirect::AdditionalData(false, "Amesos_Klu"))
    .solve(K, klu, b);
  for (const auto *other : {&klu, &lu})
    {
      TrilinosWrappers::MPI::Vector difference(x);
      difference -= *other;
      CHECK(difference.l2_norm() <= 1e-5 * other->l2_norm());
    }
  // The simplified Newton correction's second right-hand side reuses the
  // factors and K.
  TrilinosWrappers::MPI::Vector b2(b), x2(b);
  b2 *= -3.0;
  direct.solve_again(x2, b2);
  K.vmult(r, x2);
  r -= b2;
  CHECK(r.l2_norm() <= 1.01e-12 * b2.l2_norm());
}

TEST_CASE("a step that carries open contact points into an obstacle stops where they enter it",
          "[fem][contact]")
{
  // The block's top z = 0.01 lies 0.5 mm below a plane; its four faces are
  // 5 mm squares (h = 5 mm), so a point may enter by 2 % of h, 0.1 mm. A
  // translation by dz along z moves every gap by -dz: the step is admitted
  // up to (0.5 + 0.1) / dz mm, exactly (the plane's gap is linear in x).
  Triangulation<3> mesh;
  symmetric_block(mesh);
  test::MeshSolverFixture f(
    test::parameters_from_text(
      "contact_entry",
      test::solid_prm("Q2", "log", 2.6e5, 0.3,
                      contact_section(obstacle("lid", "    set Shape = plane\n    set Position = 0, 0, 0.0105\n"
                                                      "    set Normal = 0, 0, -1\n")))),
    mesh);
  const FiniteElementSpace     &space = f.solver->space();
  TrilinosWrappers::MPI::Vector owned(space.owned_dofs, space.communicator);
  const auto translated = [&](const double dz) {
    VectorTools::interpolate(*space.mapping, space.dof_handler,
                             Functions::ConstantFunction<3>(std::vector<double>{0, 0, dz}), owned);
    TrilinosWrappers::MPI::Vector ghosted(f.solver->displacement());
    ghosted = owned;
    return ghosted;
  };
  const auto             rest    = translated(0.0);
  const ObstacleContact &contact = *f.solver->obstacle_contact();
  CHECK(contact.entry_fraction(rest, translated(0.001), 0.0, 0.02) == Approx(0.6).epsilon(1e-10));
  CHECK(contact.entry_fraction(rest, translated(0.002), 0.0, 0.02) == Approx(0.3).epsilon(1e-10));
  CHECK(contact.entry_fraction(rest, translated(0.00055), 0.0, 0.02) == 1.0); // within the 0.1 mm
  CHECK(contact.entry_fraction(rest, translated(-0.001), 0.0, 0.02) == 1.0);  // away from it
  // A point already pressed (here: the whole top, 0.2 mm inside) has the
  // penalty in its tangent, and its step is not cut; the side faces' open
  // points then stop it. The highest of them (3-point Gauss rule on the
  // faces) lie at z_q = 5 mm + 5 mm (1 + sqrt(3/5)) / 2, 0.56 mm below the top.
  const auto   inside = translated(0.0007);
  const double z_q    = 0.005 + 0.005 * (1 + std::sqrt(0.6)) / 2;
  const double g0 = 0.0105 - (z_q + 0.0007), g1 = 0.0105 - (z_q + 0.002);
  CHECK(contact.entry_fraction(inside, translated(0.002), 0.0, 0.02) ==
        Approx((g0 + 1e-4) / (g0 - g1)).epsilon(1e-10));
}

TEST_CASE("a block pressed by a rigid plane: uniform contact pressure, the closed-form force",
          "[fem][contact][patch]")
{
  const double     E = 2.6e5, nu = 0.3;
  Triangulation<3> mesh;
  symmetric_block(mesh);
  test::MeshSolverFixture f(
    test::parameters_from_text("contact_patch",
                               test::solid_prm("Q2", "log", E, nu,
                                               "subsection Solver\n  set Residual tolerance = 1e-10\n"
                                               "  set Displacement tolerance = 1e-10\nend\n" +
                                                 contact_section(pressing_plane))),
    mesh);
  QuasiStaticSolver &solver = *f.solver;
  LoadState          pressed;
  pressed.obstacle_motion = 1;
  const auto result       = solver.solve(pressed);
  REQUIRE(result.converged);

  const auto   states = solver.obstacle_contact()->point_states(solver.displacement(), 1.0);
  double       low = 1e300, high = 0;
  unsigned int n = 0;
  for (const auto &p : states)
    if (p.pressure > 0)
      {
        low  = std::min(low, p.pressure);
        high = std::max(high, p.pressure);
        ++n;
        CHECK(std::abs(p.reference[2] - edge) < 1e-12); // only the top touches
      }
  // Every top point (2 x 2 faces, 3 x 3 points each) is pressed, all alike:
  // a homogeneous state is exact in the element space, so the spread is
  // Newton's tolerance (1e-10) at most.
  CHECK(n == 36);
  CHECK((high - low) / high < 1e-8);

  // The force the plane receives against the closed form at the stretch the
  // top reached (a little short of the plane's, by the penalty's penetration).
  const double a     = 1 + test::displacement_at(solver, Point<3>(edge, edge, edge))[2] / edge;
  const auto   force = solver.obstacle_contact()->obstacle_wrenches(solver.displacement(), 1.0)[0].force;
  CHECK(a > 0.9);
  CHECK(a < 0.91);
  CHECK(force[2] == Approx(-uniaxial_force(E, nu, a, edge * edge)).epsilon(1e-7));
  CHECK(std::abs(force[0]) < 1e-9 * force[2]);
  CHECK(std::abs(force[1]) < 1e-9 * force[2]);
}

TEST_CASE("Uzawa's updates take a soft penalty's penetration below its tolerance",
          "[fem][contact][augmented]")
{
  // Penalty factor 1: the penalty alone leaves a penetration of t_N / E of
  // the face size, several per cent here (t_N ~ 0.05 E); the tolerance asks
  // for 1e-4. Each update shrinks it by about (E/L) / (E/L + E/h) = 1/3
  // (the block's stiffness per area against the penalty's).
  const double     E = 2.6e5, nu = 0.3;
  Triangulation<3> mesh;
  symmetric_block(mesh);
  test::MeshSolverFixture f(
    test::parameters_from_text(
      "contact_uzawa",
      test::solid_prm("Q2", "log", E, nu,
                      "subsection Solver\n  set Residual tolerance = 1e-10\n"
                      "  set Displacement tolerance = 1e-10\nend\n" +
                        contact_section(pressing_plane, "  set Penalty factor = 1\n"
                                                        "  set Penetration tolerance = 1e-4\n"
                                                        "  set Maximum augmentations = 30\n"))),
    mesh);
  QuasiStaticSolver &solver = *f.solver;
  LoadState          pressed;
  pressed.obstacle_motion = 1;
  REQUIRE(solver.solve(pressed).converged);
  const double penetration = solver.obstacle_contact()->deepest_penetration(solver.displacement(), 1.0);
  CHECK(penetration <= 1e-4);
  // The top at the plane to within that penetration (1e-4 of h = 5e-3 m is
  // 5e-7 m, 5e-5 of the edge): the force of a 10 % compression.
  const double a     = 1 + test::displacement_at(solver, Point<3>(edge, edge, edge))[2] / edge;
  CHECK(a == Approx(0.9).margin(5.1e-5));
  const auto force = solver.obstacle_contact()->obstacle_wrenches(solver.displacement(), 1.0)[0].force;
  CHECK(force[2] == Approx(-uniaxial_force(E, nu, 0.9, edge * edge)).epsilon(1e-3));
}

// A block clamped at its base, pressed by a plane that then drags it along
// x (both along one load path, so the ratio of the two motions is fixed):
// below the friction limit the top sticks and the tangential force stays
// below mu N; far beyond it every pressed point slips and the force is mu N.
TEST_CASE("a pressed block sticks below mu N and slips at mu N", "[fem][contact][friction]")
{
  const double mu = 0.3;
  const auto   drag = [&](const double dx, unsigned int &stick, unsigned int &slip) {
    Triangulation<3> mesh;
    clamped_block(mesh);
    std::ostringstream plane;
    plane << "    set Shape = plane\n    set Position = 0, 0, 0.01\n    set Normal = 0, 0, -1\n"
          << "    set Friction coefficient = " << mu << "\n    set Motion = " << dx << ", 0, -0.001\n";
    test::MeshSolverFixture f(
      test::parameters_from_text("contact_friction",
                                 test::solid_prm("Q2", "log", 2.6e5, 0.3,
                                                 "subsection Solver\n  set Residual tolerance = 1e-9\n"
                                                 "  set Displacement tolerance = 1e-9\nend\n" +
                                                   contact_section(obstacle("press", plane.str())))),
      mesh);
    LoadState dragged;
    dragged.obstacle_motion = 1;
    REQUIRE(f.solver->solve(dragged).converged);
    stick = slip = 0;
    for (const auto &p : f.solver->obstacle_contact()->point_states(f.solver->displacement(), 1.0))
      {
        stick += p.status == ObstacleContact::Status::stick;
        slip += p.status == ObstacleContact::Status::slip;
      }
    return f.solver->obstacle_contact()->obstacle_wrenches(f.solver->displacement(), 1.0)[0].force;
  };
  unsigned int stick = 0, slip = 0;
  SECTION("a small drag: the top sticks")
  {
    // The block's shear stiffness G A / L ~ 1e3 N/m against N ~ 3 N: a drag
    // of 0.1 mm asks for ~0.1 N, a third of mu N.
    const auto force = drag(1e-4, stick, slip);
    INFO("force " << force << ", " << stick << " points stick, " << slip << " slip");
    CHECK(stick > slip);
    CHECK(-force[0] > 0.01 * mu * force[2]);
    CHECK(-force[0] < 0.9 * mu * force[2]);
  }
  SECTION("a large drag: every point slips, the force is mu N")
  {
    // A drag of 5 mm asks for ~5 N, beyond mu N ~ 1 N: the top slides, its
    // points with t_T = mu t_N, so -F_x = mu N (the obstacle receives the
    // drag's reaction, against x) up to the slip directions' spread across
    // x (the block's lateral bulge) and the points whose last increment of
    // slip stayed within the penalty's elastic range mu t_N / epsilon (they
    // count as stuck, at nearly mu t_N). Measured: -F_x / N = 0.2996,
    // within the 1 % bound, with 17 of 32 pressed points slipping.
    const auto force = drag(5e-3, stick, slip);
    INFO("force " << force << ", " << stick << " points stick, " << slip << " slip");
    CHECK(slip > 0);
    CHECK(-force[0] / force[2] == Approx(mu).epsilon(0.01));
  }
}

// Contact works under every load control: the demo bender inflated by
// volume against a plane below it (pressure control: the tests above).
TEST_CASE("contact under volume control", "[fem][contact]")
{
  const std::string table = contact_section(
    obstacle("table", "    set Shape = plane\n    set Position = 0, -0.004, 0\n    set Normal = 0, 1, 0\n"
                      "    set Friction coefficient = 0.5\n"));
  test::SolverFixture f(test::parameters_from_text("contact_controls", test::bender_prm("Q2", 8, table)));
  QuasiStaticSolver &solver = *f.solver;
  {
    VolumeControlledInflation inflation(solver, f.prm);
    const auto                result = inflation.solve(1.3 * inflation.volume());
    REQUIRE(result.converged);
    const auto force = solver.obstacle_contact()->obstacle_wrenches(solver.displacement(), 0.0)[0].force;
    INFO("pressure " << inflation.pressure() << " Pa, table force " << force);
    CHECK(force[1] < -0.01); // pressed down
    CHECK(std::abs(force[0]) <= 0.5 * std::abs(force[1]) * (1 + 1e-9)); // within the friction cone
  }
}

TEST_CASE("contact under a prescribed tip motion", "[fem][contact]")
{
  // The tip moved 8 mm down, its face held parallel: the middle of the
  // bender comes down onto a sphere whose top is 2 mm below it.
  const std::string ball = contact_section(
    obstacle("ball", "    set Shape = sphere\n    set Position = 0.04, -0.012, 0.009\n    set Radius = 0.01\n"
                     "    set Friction coefficient = 0.5\n"));
  test::SolverFixture f(test::parameters_from_text("contact_tip_motion", test::bender_prm("Q2", 8, ball)));
  LoadState           moved;
  moved.tip_motion = TipMotion{Tensor<1, 3>({0, -0.008, 0}), Tensor<1, 3>(), false};
  REQUIRE(f.solver->solve(moved).converged);
  const auto force = f.solver->obstacle_contact()->obstacle_wrenches(f.solver->displacement(), 0.0)[0].force;
  INFO("ball force " << force);
  CHECK(force[1] < -0.1);
}

// The patch test's block pressed by a box 1 mm into its top, once as
// BoxObstacle and once as the box's STL surface (12 triangles; the
// diagonals of its bottom face cross the top's quadrature points on x = y,
// where the closest feature is an edge between coplanar triangles). Both
// give the same distance and normal up to round-off (the normal of the
// mesh is (x - q) / |x - q| of a penetration ~1e-5 m, ~1e-12 off), so they
// agree to the Newton tolerance 1e-10. Measured: the force to 1.4e-13 and
// the top corner's displacement to 2.9e-11 (bound 1e-9).
TEST_CASE("a block pressed by the STL surface of a box: the box's answer", "[fem][contact][stl]")
{
  // The STL's box about its origin, which Position places.
  geometry::testing::box_surface(Eigen::Vector3d::Zero(), Eigen::Vector3d(0.02, 0.02, 0.02)).write("contact_stl_box.stl");
  const std::string place = "    set Position = 0.005, 0.005, 0.03\n    set Motion = 0, 0, -0.001\n";
  const auto        press = [&](const std::string &name, const std::string &shape) {
    return pressed_block(name, contact_section(obstacle("crate", shape + place)), [](const QuasiStaticSolver &solver) {
      return std::make_pair(solver.obstacle_contact()->obstacle_wrenches(solver.displacement(), 1.0)[0].force,
                            test::displacement_at(solver, Point<3>(edge, edge, edge)));
    });
  };
  const auto [box_force, box_u] = press("contact_box", "    set Shape = box\n    set Half sizes = 0.02, 0.02, 0.02\n");
  const auto [stl_force, stl_u] = press("contact_stl", "    set Shape = stl\n    set File = contact_stl_box.stl\n");
  INFO("box " << box_force << ", stl " << stl_force << "; top corner " << box_u << ", " << stl_u
               << "; relative differences " << (stl_force - box_force).norm() / box_force.norm() << ", "
               << (stl_u - box_u).norm() / box_u.norm());
  CHECK(box_force[2] > 0.1); // pushed up by the block
  CHECK((stl_force - box_force).norm() < 1e-9 * box_force.norm());
  CHECK((stl_u - box_u).norm() < 1e-9 * box_u.norm());
}

// A plane turned by 0.05 rad about x while it comes down 1.5 mm onto the
// block, against the same plane brought to that final pose along its
// normal without turning. Frictionless contact has no history, so both
// paths end at the same equilibrium, up to the Newton tolerances (1e-10 on
// the residual and the displacement): the bound 1e-8 on the force and the
// moment leaves the two paths' different last load steps two orders of
// room. Measured: 9.1e-15 and 9.0e-15 (the last Newton steps converge
// quadratically far below the tolerance).
TEST_CASE("a plane turned along the load path ends where the plane placed at its final pose does",
          "[fem][contact][motion]")
{
  const double          angle = 0.05;
  const Eigen::Vector3d n(0, std::sin(angle), -std::cos(angle)); // the final normal, R (0, 0, -1)
  const Eigen::Vector3d point(0, 0, 0.009);                      // the pivot at the end
  const auto press = [&](const std::string &name, const std::string &plane) {
    return pressed_block(name, contact_section(obstacle("press", plane)), [](const QuasiStaticSolver &solver) {
      return solver.obstacle_contact()->obstacle_wrenches(solver.displacement(), 1.0)[0];
    });
  };
  const auto turned = press("contact_turned_plane",
                            "    set Shape = plane\n    set Position = 0, 0, 0.0105\n    set Normal = 0, 0, -1\n"
                            "    set Motion = 0, 0, -0.0015\n    set Motion rotation = 0.05, 0, 0\n");
  // At rest 2 mm back along the final normal, clear of the block's top.
  std::ostringstream placed;
  placed.precision(17);
  const Eigen::Vector3d start = point - 0.002 * n, motion = 0.002 * n;
  placed << "    set Shape = plane\n    set Position = " << start[0] << ", " << start[1] << ", " << start[2]
         << "\n    set Normal = " << n[0] << ", " << n[1] << ", " << n[2] << "\n    set Motion = " << motion[0]
         << ", " << motion[1] << ", " << motion[2] << "\n";
  const auto final_pose = press("contact_placed_plane", placed.str());
  INFO("turned " << turned.force << ", placed " << final_pose.force << "; relative differences "
                  << (turned.force - final_pose.force).norm() / final_pose.force.norm() << ", "
                  << (turned.moment - final_pose.moment).norm() / final_pose.moment.norm());
  CHECK(turned.force[2] > 0.1);
  CHECK(turned.force[1] / turned.force[2] == Approx(-std::tan(angle)).epsilon(1e-9)); // along the normal
  CHECK((turned.force - final_pose.force).norm() < 1e-8 * final_pose.force.norm());
  CHECK((turned.moment - final_pose.moment).norm() < 1e-8 * final_pose.moment.norm());
}
