// ChainContact inside ChainEquilibrium: a single joint bent onto a table
// against the closed form of the penalty model and its exact-constraint
// limit; the contact's energy gradient and consistent tangent (plane and
// cylinder, the curvature term included) against central differences; the
// Newton step against the exact tangent's; contact with the tip held
// (TipConstrainedEquilibrium); the collision surface's interpolation, outer
// surface and errors.
#include <softchain/chain/chain_equilibrium.h>
#include <softchain/chain/finger_collision_surface.h>
#include <softchain/chain/tip_constrained_equilibrium.h>

#include "box_mesh.h"
#include "central_differences.h"
#include "contact_fixtures.h"
#include "uniform_finger.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace softchain::chain;
using namespace softchain::chain::testing;

namespace
{
  // The palm finger pressed at 30 kPa on a table 12 mm below the joint line.
  const ChainLoad on_table{3e4, {}, {plane(-0.012)}};

  // (sum of (x - c_1) x f over the touches)_z at `solver`'s last pose.
  double contact_moment_about_joint_1(const ChainEquilibrium &solver)
  {
    double moment = 0.0;
    for (const auto &t : solver.contact().touches())
      moment += (t.position - solver.pose().joint_positions[0]).cross(t.force).z();
    return moment;
  }

  // Three joints along a box of `spec` at x = 0, `second` and `third`, no
  // pressure torque.
  ChainModel box_chain(const testing::BoxMeshSpec &spec, const double second, const double third)
  {
    return ChainModel("box",
                      KinematicChain({{0.0, 0.0, 0.0}, {second, 0.0, 0.0}, {third, 0.0, 0.0}},
                                     Eigen::Vector3d(spec.length, 0.0, 0.0)),
                      JointStiffness(std::vector<Eigen::Vector3d>(3, Eigen::Vector3d(0.3, 0.2, 0.1))),
                      PressureActuation(Eigen::VectorXd::Zero(9)));
  }
} // namespace

TEST_CASE("a joint bent onto a table: the penalty model's closed form and the exact contact's limit")
{
  const double a = 0.1, l = a / 2, k = 0.1, tau = -0.08, h = 0.02, k_c = 1e5;
  ChainModel   model = uniform_finger(1, a, {1.0, 1.0, k}, {0.0, 0.0, tau});
  model.set_collision_surface(CollisionSurface({0}, {{0.0, {Eigen::Vector3d(l, 0, 0)}}}, 1));
  EquilibriumSettings settings;
  settings.contact_stiffness = k_c;
  ChainEquilibrium solver(model, settings);
  const Equilibrium e = solver.solve(ChainLoad{1.0, {}, {plane(-h)}});
  REQUIRE(e.converged);

  // k phi - tau + k_c l cos(phi) (l sin(phi) + h) = 0 by bisection between
  // the free angle tau / k (negative) and the angle that reaches the table.
  const auto f = [&](double phi) { return k * phi - tau + k_c * l * std::cos(phi) * (l * std::sin(phi) + h); };
  double     low = tau / k, high = -std::asin(h / l);
  for (int i = 0; i < 200; ++i)
    (f(0.5 * (low + high)) < 0 ? low : high) = 0.5 * (low + high);
  const double phi = 0.5 * (low + high);
  CHECK(e.angles[2] == Approx(phi).epsilon(1e-9));
  const double force = -k_c * (l * std::sin(phi) + h);
  const auto   wrench = solver.contact().obstacle_wrenches();
  REQUIRE(wrench.size() == 1);
  CHECK(wrench[0].force[1] == Approx(-force).epsilon(1e-8)); // the table is pushed down
  CHECK(std::abs(wrench[0].force[0]) < 1e-12);

  // The exact (rigid) contact: the tip on the table, F = (k phi* - tau) /
  // (l cos phi*). The penalty is a spring k_c in series with the joint's
  // stiffness at the tip, k / (l cos phi)^2: the force errs by about their
  // ratio.
  const double phi_exact = -std::asin(h / l);
  const double exact     = (k * phi_exact - tau) / (l * std::cos(phi_exact));
  const double ratio     = k / std::pow(l * std::cos(phi_exact), 2) / k_c;
  CHECK(std::abs(force - exact) / exact < 2 * ratio);
  CHECK(std::abs(force - exact) / exact > 0.1 * ratio); // the penalty is felt, and measured
}

TEST_CASE("a joint bent onto a table through a compliant skin: the closed form of the penalty in "
          "series with the skin")
{
  // The point x = R(phi) (l e_x + s e_y) touches the plane y = -h with gap
  // g = l sin(phi) + s cos(phi) + h. The skin's equilibrium s / c = -k_c g
  // cos(phi) gives s and g in closed form; the joint's, k phi - tau + k_c g
  // x_x = 0 with x_x = l cos(phi) - s sin(phi), is solved by bisection.
  const double a = 0.1, l = a / 2, k = 0.1, tau = -0.08, h = 0.02, k_c = 1e5, c = 2e-3;
  ChainModel   model = uniform_finger(1, a, {1.0, 1.0, k}, {0.0, 0.0, tau});
  model.set_collision_surface(CollisionSurface({0}, {{0.0, {Eigen::Vector3d(l, 0, 0)}}}, 1));
  model.set_skin_compliance(PiecewiseLinear({0.0}, {c}));
  EquilibriumSettings settings;
  settings.contact_stiffness = k_c;
  ChainEquilibrium  solver(model, settings);
  const Equilibrium e = solver.solve(ChainLoad{1.0, {}, {plane(-h)}});
  REQUIRE(e.converged);

  const auto gap = [&](double phi) {
    return (l * std::sin(phi) + h) / (1.0 + k_c * c * std::pow(std::cos(phi), 2));
  };
  const auto shift = [&](double phi) { return -k_c * c * std::cos(phi) * gap(phi); };
  const auto f     = [&](double phi) {
    return k * phi - tau + k_c * gap(phi) * (l * std::cos(phi) - shift(phi) * std::sin(phi));
  };
  double low = tau / k, high = 0.0;
  for (int i = 0; i < 200; ++i)
    (f(0.5 * (low + high)) < 0 ? low : high) = 0.5 * (low + high);
  const double phi = 0.5 * (low + high);
  CHECK(e.angles[2] == Approx(phi).epsilon(1e-9));
  const auto wrench = solver.contact().obstacle_wrenches();
  REQUIRE(wrench.size() == 1);
  CHECK(wrench[0].force[1] == Approx(k_c * gap(phi)).epsilon(1e-8));
  // The skin gives inwards (s > 0, along +y of the link) by c times the
  // force along d, 1.4 mm here, far more than the penetration (~1 um): the
  // skin, not the penalty, sets the contact's compliance.
  std::vector<ChainContact::Skin> skins;
  solver.contact().skins(solver.pose(), skins);
  REQUIRE(skins.size() == 1);
  CHECK(skins[0].shift == Approx(shift(phi)).epsilon(1e-8));
  CHECK(skins[0].shift > 100.0 * -gap(phi));
}

TEST_CASE("contact on a plane and a cylinder: residual = energy gradient, tangent = central differences")
{
  const int n = 4;
  const double a = 0.02;
  // Rigid sections, and compliant ones whose give (k_s = 100 N/m per link)
  // is of the penetrations' size, on a surface whose points at z < 0 do not
  // give.
  for (const double skin : {0.0, 0.01})
  for (const auto &obstacles : {std::vector{plane(-0.012)},
                                std::vector{cylinder({0.05, -0.016, 0.0}, 0.008)}})
    {
      INFO("skin compliance " << skin << " m/N, " << obstacles.front().shape);
      ChainModel model = uniform_finger(n, a, {0.3, 0.2, 0.1}, {0.0, 0.0, -2e-6});
      model.set_collision_surface(palm_points(n, a, 3, 0.004, 0.006, skin > 0.0));
      if (skin > 0.0)
        model.set_skin_compliance(PiecewiseLinear({0.0}, {skin}));
      // Near the equilibrium, where the contact forces are those of the
      // problem (far from it the penalty's are huge), turned out of plane;
      // a soft penalty, so that the penetrations (~1 mm) dwarf the
      // perturbation and the differences' steps.
      EquilibriumSettings soft;
      soft.contact_stiffness = 100.0;
      ChainEquilibrium  solver(model, soft);
      const Equilibrium e = solver.solve(ChainLoad{1e4, {}, obstacles});
      REQUIRE(e.converged);
      Eigen::VectorXd q = e.angles;
      for (int i = 0; i < 3 * n; ++i)
        q[i] += 2e-3 * std::sin(1.0 + i);
      solver.residual(q);
      const auto &touches = solver.contact().touches();
      REQUIRE(touches.size() >= 2);
      // No point within reach of the differences' step of the kink at g = 0.
      for (const auto &t : touches)
        REQUIRE(-t.gap > 1e-5);
      const Eigen::VectorXd r = solver.residual(q);
      const Eigen::VectorXd g = testing::energy_gradient(solver, q, 1e-6);
      // Central differences err by h^2 |U'''| / 6 + eps |U| / h, ~1e-9 here.
      CHECK((r - g).lpNorm<Eigen::Infinity>() < 1e-7 * r.lpNorm<Eigen::Infinity>());
      const Eigen::MatrixXd H = solver.tangent(q);
      const Eigen::MatrixXd D = testing::central_differences(solver, q, 1e-7);
      CHECK((H - D).lpNorm<Eigen::Infinity>() < 1e-6 * H.lpNorm<Eigen::Infinity>());
      // Each skin balances its touches' force along d: s_b = c f_b . d_b.
      std::vector<ChainContact::Skin> skins;
      solver.contact().skins(solver.pose(), skins);
      CHECK(skins.size() == (skin > 0.0 ? std::size_t(n) : 0));
      std::vector<Eigen::Vector3d> offsets;
      model.collision_surface()->offsets_at(1e4, offsets);
      for (const auto &s : skins)
        {
          double along = 0.0;
          for (const auto &t : touches)
            if (t.link == s.link && solver.contact().gives(t))
              along += t.force.dot(s.direction);
          CHECK(s.shift == Approx(skin * along).margin(1e-12));
          CHECK((along > 0.0) == (s.shift > 0.0));
        }
      // A point moves with its link's skin only where the surface gives.
      for (const auto &t : touches)
        {
          const Eigen::Vector3d carried = solver.pose().joint_positions[t.link] +
                                          solver.pose().link_rotations[t.link] * offsets[t.point];
          const double shift = skin > 0.0 && offsets[t.point].z() > 0 ? skins[t.link].shift : 0.0;
          CHECK((t.position - carried - shift * solver.pose().link_rotations[t.link].col(1)).norm() < 1e-15);
        }
      // Without the curvature rows the cylinder's tangent would be off by
      // about f / R per touching point: checked to be seen.
      if (obstacles.front().shape == "cylinder")
        {
          std::vector<ChainContact::LinkRow> rows;
          solver.contact().tangent_rows(solver.pose(), rows);
          CHECK(rows.size() > touches.size());
        }
      // The solver's step, its rows gathered per link, is the Newton step of
      // the exact tangent (both capped at 1.5 rad per angle).
      const Eigen::VectorXd step  = solver.newton_step(q);
      Eigen::VectorXd       dense = -H.llt().solve(r);
      dense *= std::min(1.0, 1.5 / dense.lpNorm<Eigen::Infinity>());
      CHECK((step - dense).lpNorm<Eigen::Infinity>() < 1e-9 * dense.lpNorm<Eigen::Infinity>());
    }
}

TEST_CASE("the quick test for a penetrating point agrees with the touches an update finds, with and "
          "without sections that give")
{
  const int n = 4;
  for (const double skin : {0.0, 0.01})
    for (const auto &obstacles : {std::vector{plane(-0.012)}, std::vector{cylinder({0.05, -0.016, 0.0}, 0.008)}})
      {
        INFO("skin compliance " << skin << " m/N, " << obstacles.front().shape);
        ChainModel model = uniform_finger(n, 0.02, {0.3, 0.2, 0.1}, {0.0, 0.0, -2e-6});
        model.set_collision_surface(palm_points(n, 0.02, 3, 0.004, 0.006, skin > 0.0));
        if (skin > 0.0)
          model.set_skin_compliance(PiecewiseLinear({0.0}, {skin}));
        ChainEquilibrium  solver(model);
        const Equilibrium e = solver.solve(ChainLoad{1e4, {}, obstacles});
        REQUIRE(e.converged);
        int touching = 0;
        for (int step = 0; step <= 12; ++step)
          {
            solver.residual(0.1 * step * e.angles);
            const bool touches = !solver.contact().touches().empty();
            CHECK(solver.contact().penetrates(solver.pose()) == touches);
            touching += touches;
          }
        // Both answers occur along the way.
        CHECK(touching > 0);
        CHECK(touching < 13);
      }
}

TEST_CASE("a finger pressed on a table converges, pushes only where it penetrates, and the table "
          "takes the joints' torque")
{
  const ChainModel  model = finger_with_palm();
  const ChainLoad  &load  = on_table;
  ChainEquilibrium  solver(model);
  const Equilibrium e = solver.solve(load);
  REQUIRE(e.converged);
  CHECK(e.iterations < 20);
  const auto &touches = solver.contact().touches();
  REQUIRE(!touches.empty());
  for (const auto &t : touches)
    CHECK(t.force.y() > 0.0);
  // Every other surface point stands above the table.
  std::vector<Eigen::Vector3d> offsets;
  model.collision_surface()->offsets_at(load.pressure, offsets);
  for (int k = 0; k < model.collision_surface()->n_points(); ++k)
    {
      const int             b = model.collision_surface()->links()[k];
      const Eigen::Vector3d x = solver.pose().joint_positions[b] + solver.pose().link_rotations[b] * offsets[k];
      const bool touching = std::any_of(touches.begin(), touches.end(), [&](const auto &t) { return t.point == k; });
      CHECK(touching == (x.y() < -0.012));
    }
  // Joint 1's moment balance: k phi_1 = J_p p + (moment of the contact forces about c_1)_z.
  CHECK(0.05 * e.angles[2] == Approx(-1e-7 * 3e4 + contact_moment_about_joint_1(solver)).epsilon(1e-8));
  // The penetration the penalty leaves: |f| / k_c per point.
  CHECK(solver.contact().max_penetration() == Approx(touches.front().force.norm() / 1e5).epsilon(1.0));
}

TEST_CASE("a finger on a table with its tip held: where it rests anyway no tip force and the same "
          "contact, lifted, joint 1 balances the table's and the holder's moments")
{
  const int         n     = 6;
  const ChainModel  model = finger_with_palm();
  const ChainLoad  &load  = on_table;
  ChainEquilibrium  free(model);
  const Equilibrium e = free.solve(load);
  REQUIRE(e.converged);
  const Eigen::Vector3d tip   = free.pose().tip_position;
  const double          table = free.contact().obstacle_wrenches()[0].force[1];
  REQUIRE(table < -1e-3); // the table is pushed down

  // The tip-held solver with the contact in its residual and tangent, from a
  // start turned 0.02 rad off the answer.
  TipConstrainedEquilibrium held(model);
  Eigen::VectorXd           start = e.angles;
  start[3 * (n - 1) + 2] += 0.02;
  const ConstrainedEquilibrium c = held.solve(load, tip, start);
  REQUIRE(c.converged);
  // Tolerance: the equilibrium tolerance 1e-10 relative, on forces of ~0.1 N
  // and angles of ~0.1 rad.
  CHECK(c.contact_force.norm() < 1e-8);
  CHECK((c.angles - e.angles).lpNorm<Eigen::Infinity>() < 1e-8);

  // The tip lifted 1 mm: it pulls up, the table carries less, and joint 1
  // balances the pressure against the table's and the tip's moments,
  // k phi_1 = J_p p + (sum (x - c_1) x f)_z.
  const ConstrainedEquilibrium lifted = held.solve(load, tip + Eigen::Vector3d(0, 0.001, 0), e.angles);
  REQUIRE(lifted.converged);
  CHECK(lifted.contact_force.y() > 0.0); // the holder pulls the tip up
  ChainEquilibrium check(model);
  check.set_load(held.with_contact(load, lifted.contact_force));
  check.residual(lifted.angles);
  const double moment = (check.pose().tip_position - check.pose().joint_positions[0]).cross(lifted.contact_force).z() +
                        contact_moment_about_joint_1(check);
  CHECK(0.05 * lifted.angles[2] == Approx(-1e-7 * 3e4 + moment).epsilon(1e-8));
  CHECK(-check.contact().obstacle_wrenches()[0].force[1] < -table);
}

TEST_CASE("the collision surface: offsets linear in pressure, held beyond, outer surface nodes, errors")
{
  const CollisionSurface surface({0, 1}, {{0.0, {{0, 0, 0}, {1, 0, 0}}}, {1e4, {{0, 2, 0}, {1, 4, 0}}}}, 2);
  std::vector<Eigen::Vector3d> offsets;
  surface.offsets_at(2.5e3, offsets);
  CHECK(offsets[0].y() == Approx(0.5));
  CHECK(offsets[1].y() == Approx(1.0));
  surface.offsets_at(3e4, offsets);
  CHECK(offsets[1].y() == Approx(4.0));
  CHECK(surface.link_begin() == std::vector<int>{0, 1, 2});
  REQUIRE(surface.clusters().size() == 2);
  // The one-point cluster of link 1 moves by 4 along y from 0 to 10 kPa:
  // its sphere spans that at any pressure of the table, and beyond it
  // shrinks to the held point.
  CHECK(surface.spheres_at(5e3)[1].radius == Approx(2.0));
  CHECK(surface.spheres_at(5e3)[1].centre.y() == Approx(2.0));
  CHECK(surface.spheres_at(1e4)[1].radius == Approx(2.0));
  // Twenty points on one link, inflated unevenly over three rows: clusters
  // of at most eight that cover them, in a tree whose every sphere holds its
  // points at every pressure of its interval and its children's spheres.
  std::vector<Eigen::Vector3d> rest, inflated, more;
  for (int k = 0; k < 20; ++k)
    {
      rest.emplace_back(0.001 * k, 0.002 * (k % 3), 0.003 * (k % 2));
      inflated.push_back(rest.back() + Eigen::Vector3d(0.0, 0.0005 * k, 0.0));
      more.push_back(inflated.back() + Eigen::Vector3d(0.0002 * (k % 4), 0.0, -0.0006 * k));
    }
  const CollisionSurface many(std::vector<int>(20, 0), {{0.0, rest}, {2e4, inflated}, {4e4, more}}, 1);
  int covered = 0;
  for (const auto &cluster : many.clusters())
    {
      CHECK(cluster.end - cluster.begin <= 8);
      CHECK(cluster.begin == covered);
      covered = cluster.end;
    }
  const auto &nodes = many.nodes();
  REQUIRE(nodes.size() == 2 * many.clusters().size() - 1);
  for (const double p : {-1e3, 0.0, 1e4, 2e4, 3e4, 4e4, 6e4})
    {
      INFO("pressure " << p);
      const auto &spheres = many.spheres_at(p);
      REQUIRE(spheres.size() == nodes.size());
      many.offsets_at(p, offsets);
      int leaves = 0;
      for (std::size_t i = 0; i < nodes.size(); ++i)
        {
          const auto &node = nodes[i];
          for (int k = node.begin; k < node.end; ++k)
            CHECK((offsets[k] - spheres[i].centre).norm() <= spheres[i].radius * (1 + 1e-12));
          if (node.cluster >= 0)
            {
              CHECK(node.cluster == leaves++);
              CHECK(node.skip == static_cast<int>(i) + 1);
              CHECK(node.begin == many.clusters()[node.cluster].begin);
              continue;
            }
          const std::size_t left = i + 1, right = static_cast<std::size_t>(nodes[left].skip);
          CHECK(nodes[right].skip == node.skip);
          for (const std::size_t child : {left, right})
            CHECK((spheres[child].centre - spheres[i].centre).norm() + spheres[child].radius <=
                  spheres[i].radius * (1 + 1e-12));
        }
      CHECK(leaves == static_cast<int>(many.clusters().size()));
    }
  // Per interval, not over the whole table: some point at 40 kPa lies
  // outside the root's sphere of the first interval (0 to 20 kPa).
  const auto &first = many.spheres_at(1e4).front();
  CHECK(std::any_of(more.begin(), more.end(),
                    [&](const Eigen::Vector3d &x) { return (x - first.centre).norm() > first.radius; }));
  CHECK(nodes.front().skip == static_cast<int>(nodes.size()));
  CHECK(covered == 20);
  CHECK_THROWS_AS(CollisionSurface({1, 0}, {{0.0, {{0, 0, 0}, {0, 0, 0}}}}, 2), std::invalid_argument);
  CHECK_THROWS_AS(CollisionSurface({0}, {{1.0, {{0, 0, 0}}}}, 1), std::invalid_argument);

  // A solid box of nx x ny x nz hexahedra has (nx+1)(ny+1)(nz+1) -
  // (nx-1)(ny-1)(nz-1) boundary vertices, less the (ny+1)(nz+1) of the base
  // face; a hollow one adds none (its cavity faces are left out).
  for (const bool tetrahedra : {false, true})
    {
      testing::BoxMeshSpec spec;
      spec.nx = 6, spec.ny = 4, spec.nz = 4, spec.tetrahedra = tetrahedra;
      const auto solid = outer_surface_nodes(testing::box_mesh(spec));
      CHECK(solid.size() == std::size_t(7 * 5 * 5 - 5 * 3 * 3 - 5 * 5));
    }

  // Subdivided, a face's grid of m x m intervals: the boundary of the
  // (m nx + 1)(m ny + 1)(m nz + 1) lattice less the base face's points (on
  // a tetrahedral box the triangles' grids for m = 2 are the quadrilaterals'
  // too: a diagonal's midpoint is the face's centre). Each point lies on the
  // box's surface, and the links carry it there.
  for (const bool tetrahedra : {false, true})
    {
      testing::BoxMeshSpec spec;
      spec.nx = 6, spec.ny = 4, spec.nz = 4, spec.tetrahedra = tetrahedra;
      const auto       mesh  = testing::box_mesh(spec);
      // Joints from the base face on, so that every point has a link.
      const ChainModel box   = box_chain(spec, 0.03, 0.06);
      const int        m     = 2;
      const auto       fine  = rigid_collision_surface(box, mesh, m);
      CHECK(fine.n_points() == 13 * 9 * 9 - 11 * 7 * 7 - 9 * 9);
      CHECK(rigid_collision_surface(box, mesh, 1).n_points() ==
            static_cast<int>(outer_surface_nodes(mesh).size()));
      std::vector<Eigen::Vector3d> offsets;
      fine.offsets_at(0.0, offsets);
      const ChainPose rest = box.chain().rest_pose();
      int             on_surface = 0;
      for (int k = 0; k < fine.n_points(); ++k)
        {
          const int             b = fine.links()[k];
          const Eigen::Vector3d x = rest.joint_positions[b] + rest.link_rotations[b] * offsets[k];
          on_surface += std::abs(x.x() - spec.length) < 1e-12 || std::abs(x.y() - spec.y0) < 1e-12 ||
                        std::abs(x.y() - spec.y0 - spec.height) < 1e-12 ||
                        std::abs(std::abs(x.z()) - spec.width / 2) < 1e-12;
        }
      CHECK(on_surface == fine.n_points());
    }

  const int    n     = 2;
  ChainModel   model = uniform_finger(n, 0.02, {0.3, 0.2, 0.1});
  auto with_friction = plane(-0.01);
  with_friction.friction = -0.3;
  ChainEquilibrium solver(model);
  CHECK_THROWS_WITH(solver.solve(ChainLoad{0.0, {}, {plane(-0.01)}}),
                    Catch::Contains("no collision surface for obstacle 'table'"));
  model.set_collision_surface(palm_points(n, 0.02, 2, 0.003, 0.005));
  ChainEquilibrium frictional(model);
  CHECK_THROWS_WITH(frictional.solve(ChainLoad{0.0, {}, {with_friction}}),
                    Catch::Contains("friction coefficient must be >= 0"));
}

TEST_CASE("a plane skips the points between vertices: the same equilibrium, no point deeper")
{
  // A 90 mm box of 15 mm hexahedra; joint 2 at 37.5 mm, inside the cells
  // between 30 and 45 mm, joint 3 0.1 mm before the cell face at 60 mm (so
  // that the points on that face's edges, whose x a sum of weights gives
  // to round-off, lie on one link). Faces subdivided 3 x 3.
  testing::BoxMeshSpec spec;
  spec.nx = 6, spec.ny = 4, spec.nz = 4;
  const auto       mesh = testing::box_mesh(spec);
  const ChainModel box  = box_chain(spec, 0.0375, 0.0599);
  const CollisionSurface fine = rigid_collision_surface(box, mesh, 3);

  // Between vertices: every point that is not a mesh vertex, except where
  // a face's grid is split between two links: the faces of the cells
  // across joint 2 (30 to 45 mm) and across joint 3 (45 to 60 mm). There
  // the last grid points of a part (x = 35, 40 and 55 mm) on the faces'
  // edges are corners of their parts, and so are those next to the clamped
  // base (x = 5 mm), whose own grid points are left out.
  std::vector<Eigen::Vector3d> offsets;
  fine.offsets_at(0.0, offsets);
  const ChainPose rest = box.chain().rest_pose();
  const auto      at_rest = [&](int k) {
    const int b = fine.links()[k];
    return Eigen::Vector3d(rest.joint_positions[b] + rest.link_rotations[b] * offsets[k]);
  };
  std::vector<Eigen::Vector3d> vertices;
  for (const std::int64_t v : outer_surface_nodes(mesh))
    vertices.emplace_back(mesh.X[v][0], mesh.X[v][1], mesh.X[v][2]);
  const auto on_grid = [](const double t, const double origin, const double step) {
    const double cells = (t - origin) / step;
    return std::abs(cells - std::round(cells)) < 1e-9;
  };
  int between = 0;
  for (int k = 0; k < fine.n_points(); ++k)
    {
      const Eigen::Vector3d x      = at_rest(k);
      const bool            vertex = std::any_of(vertices.begin(), vertices.end(),
                                                 [&](const Eigen::Vector3d &v) { return (v - x).norm() < 1e-12; });
      const bool top_or_bottom = on_grid(x.y(), spec.y0, spec.height);
      const bool on_cell_edge  = top_or_bottom ? on_grid(x.z(), -spec.width / 2, spec.width / spec.nz)
                                               : on_grid(x.y(), spec.y0, spec.height / spec.ny);
      const bool part_corner   = on_cell_edge && (std::abs(x.x() - 0.005) < 1e-12 || std::abs(x.x() - 0.035) < 1e-12 ||
                                                std::abs(x.x() - 0.04) < 1e-12 || std::abs(x.x() - 0.055) < 1e-12);
      INFO("point at " << x.transpose());
      CHECK(fine.between_vertices(k) == (!vertex && !part_corner));
      between += fine.between_vertices(k);
    }
  CHECK(between > fine.n_points() / 2);

  // The same points with every one searched.
  std::vector<char> gives;
  for (int k = 0; k < fine.n_points(); ++k)
    gives.push_back(fine.gives(k));
  const CollisionSurface all(fine.links(), {{0.0, offsets}}, box.chain().n_joints(), gives);

  // A tip force of 0.5 N bends the box onto a table 4 mm under it.
  const ChainLoad load{0.0, {{Eigen::Vector3d(spec.length, 0.0, 0.0), Eigen::Vector3d(0.0, -0.5, 0.0)}},
                       {plane(spec.y0 - 0.004)}};
  ChainModel searched_at_vertices = box, searched_everywhere = box;
  searched_at_vertices.set_collision_surface(fine);
  searched_everywhere.set_collision_surface(all);
  ChainEquilibrium  at_vertices(searched_at_vertices), everywhere(searched_everywhere);
  const Equilibrium a = at_vertices.solve(load), b = everywhere.solve(load);
  REQUIRE(a.converged);
  REQUIRE(b.converged);
  const auto &touches = at_vertices.contact().touches();
  REQUIRE(!touches.empty());
  CHECK(touches.size() < everywhere.contact().touches().size());
  for (const auto &t : touches)
    CHECK_FALSE(fine.between_vertices(t.point));
  // No point of the surface lies deeper in the table than the deepest
  // touching one: the points left out are never reached first.
  const double deepest = at_vertices.contact().max_penetration();
  for (int k = 0; k < fine.n_points(); ++k)
    {
      const int             link = fine.links()[k];
      const Eigen::Vector3d x = at_vertices.pose().joint_positions[link] + at_vertices.pose().link_rotations[link] * offsets[k];
      CHECK(spec.y0 - 0.004 - x.y() <= deepest * (1 + 1e-9));
    }
  // Both searches hold the same constraint; they differ by how deep the
  // penalty lets the touching points sink, f / k_c per point: the joints
  // turn alike to that depth over the shortest lever to the touches
  // (about the box's 15 mm cells).
  const double depth = std::max(deepest, everywhere.contact().max_penetration());
  CHECK((a.angles - b.angles).lpNorm<Eigen::Infinity>() <= depth / 0.015);
  CHECK(depth < 1e-4 * spec.length);
}

TEST_CASE("a finger closing on a thin plate stops on its near side: no step carries a point through it")
{
  // The palm finger bends down towards a plate 1 mm thick, 14 mm under the
  // joint line; pressed by p its free pose lies far below it. A step that
  // moved a point by more than its clearance or the active set's reach
  // could cross the plate unseen and settle beyond it.
  const ChainModel                model = finger_with_palm();
  softchain::data::ObstacleRecord plate;
  plate.name       = "plate";
  plate.shape      = "box";
  plate.position   = {0.05, -0.0145, 0.0};
  plate.half_sizes = {0.1, 0.0005, 0.1};
  for (const double p : {4e4, 1e5, 3e5})
    {
      INFO("pressure " << p << " Pa");
      ChainEquilibrium  solver(model);
      const Equilibrium free = solver.solve(ChainLoad{p, {}});
      REQUIRE(free.converged);
      CHECK(solver.pose().tip_position.y() < -0.015); // the free finger passes the plate
      const Equilibrium e = solver.solve(ChainLoad{p, {}, {plate}});
      REQUIRE(e.converged);
      REQUIRE_FALSE(solver.contact().touches().empty());
      std::vector<Eigen::Vector3d> offsets;
      model.collision_surface()->offsets_at(p, offsets);
      for (int k = 0; k < model.collision_surface()->n_points(); ++k)
        {
          const int             b = model.collision_surface()->links()[k];
          const Eigen::Vector3d x = solver.pose().joint_positions[b] + solver.pose().link_rotations[b] * offsets[k];
          CHECK(x.y() > -0.0145); // above the plate's middle: at most the penalty's penetration into its top
        }
    }
}
