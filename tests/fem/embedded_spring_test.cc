// One embedded tension-only spring along a block whose tip face is pulled
// (or pushed) along it by a prescribed motion. With nu = 0 the compressible
// neo-Hookean block (lambda = 0: P = mu (F - F^-T)) stretched by lambda =
// 1 + eps between its clamped and its held face deforms homogeneously with
// no lateral contraction -- the lateral stress mu (b_22 - 1) / J vanishes --
// so its base reaction is exactly A mu (lambda - 1/lambda), and every link
// of the spring (one per cell it crosses) is stretched by eps and carries
//     T = EA (eps + sqrt(eps^2 + d^2)) / 2,
// the law of embedded_spring_network.h with smoothing strain d: ~EA eps
// taut, ~EA d/2 at the knee, ~EA d^2 / (4 |eps|) slack. Equal tensions cancel
// at the interior nodes, so the spring adds exactly T to the base reaction.
// Q2 represents the homogeneous field exactly; tolerance 1e-6 relative: the
// Newton tolerance (1e-6 relative residual and update, the links' tensions
// on their law to that) lies below, a missing, doubled or compressive spring
// force, or a tension left off the law, far above.
#include "fem_test_tools.h"

#include <softchain/fem/base_reaction.h>
#include <softchain/fem/cell_conforming_polylines.h>
#include <softchain/fem/embedded_spring_network.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace dealii;
using namespace softchain;
using namespace softchain::fem;

namespace
{
  constexpr double L = 0.1, h = 0.01, E = 2.6e5, nu = 0.0, EA = 50.0, d = 1e-3;

  // The base reaction along x after moving the tip face by delta along x,
  // with or without the spring; `tensions` receives the links' tensions.
  double pull(const double delta, const bool with_spring, std::vector<double> &tensions)
  {
    Triangulation<3> mesh;
    test::cantilever_block(mesh, {20, 3, 3}, L, h);
    const Parameters prm = test::parameters_from_text(
      with_spring ? "spring_block" : "plain_block",
      test::solid_prm("Q2", "log", E, nu,
                      "subsection Springs\n  set Axial rigidity = fabric: 50\n"
                      "  set Tension smoothing strain = 0.001\nend\n"));
    std::vector<SpringPolyline> springs;
    if (with_spring)
      springs.push_back({"fabric", {Point<3>(0, h / 2, h / 2), Point<3>(L, h / 2, h / 2)}, false});
    std::ostringstream log;
    QuasiStaticSolver  solver(prm, mesh, {"solid"}, springs, {}, MPI_COMM_WORLD, log);
    LoadState          target;
    target.tip_motion = TipMotion{Tensor<1, 3>({delta, 0, 0}), Tensor<1, 3>()};
    REQUIRE(solver.solve(target).converged);
    if (with_spring)
      tensions = solver.spring_network()->tensions(solver.displacement());
    return BaseReaction(solver.space()).wrench(solver.support_forces()).force[0];
  }

  // One link from a to b along x inside a single Q2 cell, and the cell's DoF
  // values of a linear field x -> (x - a)_0 / rest * direction, which moves
  // node b by `direction` and node a not at all (Q2 interpolates it exactly).
  struct OneLinkCell
  {
    OneLinkCell(const Point<3> &a, const Point<3> &b)
      : a(a)
      , rest(b[0] - a[0])
    {
      test::cantilever_block(mesh, {1, 1, 1}, L, h);
      space   = std::make_unique<FiniteElementSpace>(mesh, ElementType::Q2, MPI_COMM_WORLD);
      network = std::make_unique<EmbeddedSpringNetwork>(*space, std::vector<SpringPolyline>{{"fabric", {a, b}, false}}, std::vector<FibreSheet>{},
                                                        std::map<std::string, double>{{"fabric", EA}}, d);
    }

    Vector<double> field(const Tensor<1, 3> &direction) const
    {
      const auto     cell = space->dof_handler.begin_active();
      const auto    &fe   = *space->fe;
      Vector<double> v(fe.n_dofs_per_cell());
      for (unsigned int i = 0; i < v.size(); ++i)
        {
          const Point<3> x = space->mapping->transform_unit_to_real_cell(cell, fe.get_unit_support_points()[i]);
          v[i] = (x[0] - a[0]) / rest * direction[fe.system_to_component_index(i).first];
        }
      return v;
    }

    // -f_int and K of the cell's link at the DoF values u; returns
    // assemble_cell()'s bound.
    double assemble(const Vector<double> &u, FullMatrix<double> *K, Vector<double> &rhs) const
    {
      return network->assemble_cell(space->dof_handler.begin_active()->active_cell_index(), u, K, rhs);
    }

    Triangulation<3>                       mesh;
    std::unique_ptr<FiniteElementSpace>    space;
    std::unique_ptr<EmbeddedSpringNetwork> network;
    Point<3>                               a;
    double                                 rest;
  };
} // namespace

TEST_CASE("an embedded spring pulled along its length adds its tension law to the reaction",
          "[fem][springs]")
{
  for (const double eps : {1e-2, 0.5 * d, -1e-2}) // taut, at the knee, slack
    {
      const double delta = eps * L;
      const double T     = EA * (eps + std::sqrt(eps * eps + d * d)) / 2;
      const double lambda = 1 + eps, block = h * h * E / 2 * (lambda - 1 / lambda);
      std::vector<double> tensions, unused;
      const double        with = pull(delta, true, tensions), without = pull(delta, false, unused);
      INFO("strain " << eps << ": reaction with " << with << " N, without " << without
                     << " N (block " << block << " N), spring law " << T << " N");
      CHECK(std::abs(without - block) <= 1e-6 * std::abs(block));
      // One link per cell the spring crosses (20), each with the law's tension.
      REQUIRE(tensions.size() == 20);
      for (const double t : tensions)
        CHECK(std::abs(t - T) <= 1e-6 * T + 1e-15);
      // The base holds the block's reaction plus the spring's tension (the
      // finger pulls its base toward the tip, +x, when stretched).
      CHECK(std::abs((with - without) - T) <= 1e-6 * std::max(T, std::abs(block)));
    }
}

// Each link is assembled with the one cell it lies in (the solver splits the
// polylines at cell faces first); a link across cells is an input error that
// names it, not a force silently evaluated in one cell's polynomials.
TEST_CASE("a spring link that crosses a cell face is refused, naming the link", "[fem][springs]")
{
  Triangulation<3> mesh;
  test::cantilever_block(mesh, {20, 3, 3}, L, h);
  const FiniteElementSpace space(mesh, ElementType::Q2, MPI_COMM_WORLD);
  const SpringPolyline     across{"fabric", {Point<3>(0, h / 2, h / 2), Point<3>(L, h / 2, h / 2)}, false};
  CHECK_THROWS_WITH(EmbeddedSpringNetwork(space, {across}, {}, {{"fabric", EA}}, d),
                    Catch::Contains("spring link 0 of network 'fabric'") &&
                      Catch::Contains("does not lie in one cell"));
  // The same polyline split at the faces (20 links) is accepted.
  const auto within = cell_conforming_polylines({across}, mesh, *space.mapping);
  CHECK(EmbeddedSpringNetwork(space, within, {}, {{"fabric", EA}}, d).all_links().size() == 20);
}

// A taut link's tangent against the closed forms of a string under tension
// T: stretching it along itself stiffens it by dT/dl = (EA/L) dt/deps (the
// material term; dt/deps = (1 + eps / sqrt(eps^2 + d^2)) / 2, 0.9975 here);
// moving one end across it changes the force
// across by T/l per unit displacement (the geometric term, a tensioned
// string's lateral stiffness). Each is the quadratic form v^T K v of the
// link's cell matrix for a linear field v that moves node b by a unit vector
// and node a not at all (Q2 interpolates it exactly), and the link's
// internal force does the work f . v = T along it. The link lies inside one
// Q2 cell, stretched by a uniform strain eps = 10 d (taut), its tension and
// gap on the law.
TEST_CASE("a taut link's tangent is EA/L along it and T/l across it", "[fem][springs]")
{
  if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
    return;
  OneLinkCell  link({0.25 * L, 0.4 * h, 0.5 * h}, {0.75 * L, 0.4 * h, 0.5 * h});
  const double rest = link.rest, eps = 0.01;
  REQUIRE(link.network->all_links().size() == 1);
  link.network->restore_link_states({link.network->law().state_at(eps)});

  const Vector<double> u = link.field(Tensor<1, 3>({eps * rest, 0, 0})); // b moves by eps rest along the link
  FullMatrix<double>   K(u.size(), u.size());
  Vector<double>       rhs(u.size());
  link.assemble(u, &K, rhs);

  const double T = EA * (eps + std::hypot(eps, d)) / 2, l = rest * (1 + eps);
  const double slope = (1 + eps / std::hypot(eps, d)) / 2;
  const auto   along = link.field(Tensor<1, 3>({1, 0, 0})), across = link.field(Tensor<1, 3>({0, 1, 0}));
  // Sums of ~1e3 products of entries up to EA/L: round-off ~1e-12 relative.
  CHECK(-(rhs * along) == Approx(T).epsilon(1e-10));
  CHECK(K.matrix_norm_square(along) == Approx(EA * slope / rest).epsilon(1e-10));
  CHECK(K.matrix_norm_square(across) == Approx(T / l).epsilon(1e-10));
  CHECK(std::abs(K.matrix_scalar_product(along, across)) <= 1e-10 * EA / rest);
}

// Off its law (a Newton iterate: the link's tension t and gap g are unknowns
// of their own), a link is assembled with the tension its local equations
// predict, T_eff = EA (t + (t (eps - t) + d^2/4) / (t + g)), the axial
// stiffness EA t / ((t + g) L) and the geometric term EA t / l: its own
// equations condensed (TensionOnlyLaw). Here a taut link carries half the
// law's tension and a gap 100 times the law's.
TEST_CASE("a link off its law is assembled with its condensed tension and stiffness",
          "[fem][springs]")
{
  if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
    return;
  OneLinkCell  link({0.25 * L, 0.5 * h, 0.4 * h}, {0.75 * L, 0.5 * h, 0.4 * h});
  const double rest = link.rest, eps = 0.01;
  const auto   on_law = link.network->law().state_at(eps);
  const double t = on_law.tension / 2, g = 100 * on_law.gap;
  link.network->restore_link_states({{t, g}});

  const Vector<double> u = link.field(Tensor<1, 3>({eps * rest, 0, 0}));
  FullMatrix<double>   K(u.size(), u.size());
  Vector<double>       rhs(u.size());
  const double         bound = link.assemble(u, &K, rhs);

  const double T_eff = EA * (t + (t * (eps - t) + d * d / 4) / (t + g)), l = rest * (1 + eps);
  const double T_law = EA * (eps + std::hypot(eps, d)) / 2;
  const auto   along = link.field(Tensor<1, 3>({1, 0, 0})), across = link.field(Tensor<1, 3>({0, 1, 0}));
  INFO("T_eff " << T_eff << " N, law " << T_law << " N");
  REQUIRE(std::abs(T_eff - T_law) > 0.1 * T_law); // the state is far off the law
  CHECK(-(rhs * along) == Approx(T_eff).epsilon(1e-10));
  CHECK(K.matrix_norm_square(along) == Approx(EA * t / (t + g) / rest).epsilon(1e-10));
  CHECK(K.matrix_norm_square(across) == Approx(EA * t / l).epsilon(1e-10));
  // The returned bound on |R_law - R| is exact for a single link: the
  // residual with the link on its law differs by that much.
  link.network->restore_link_states({on_law});
  Vector<double> rhs_law(u.size());
  link.assemble(u, nullptr, rhs_law);
  CHECK(-(rhs_law * along) == Approx(T_law).epsilon(1e-10));
  rhs_law -= rhs;
  CHECK(bound == Approx(rhs_law.l2_norm()).epsilon(1e-10));
}
