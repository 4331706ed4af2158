// Coulomb friction in the chain's contact (CoulombFriction, FrictionalLoadPath):
// a joint that bends a point onto a table, sliding and sticking, against
// the closed forms of the regularised law; the friction's energy gradient
// and tangent against central differences, in stick and slip, on a plane and
// a cylinder, with and without sections that give; the load path's
// independence of its steps in pure sliding, and its frictionless shortcut.
#include <softchain/chain/aitken_relaxation.h>
#include <softchain/chain/frictional_load_path.h>

#include "central_differences.h"
#include "contact_fixtures.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace softchain::chain;
using namespace softchain::chain::testing;

namespace
{
  // One joint at c = (a/2, 0, 0) with k_phi = k and J_p p = tau at p = 1,
  // turning a point l ahead of it down onto a table h below the joint line
  // (the frictionless closed form is in chain_contact_test.cc).
  constexpr double a = 0.1, l = a / 2, k = 0.1, tau = -0.08, h = 0.02, k_c = 1e5;

  ChainModel one_joint()
  {
    ChainModel model = uniform_finger(1, a, {1.0, 1.0, k}, {0.0, 0.0, tau});
    model.set_collision_surface(CollisionSurface({0}, {{0.0, {Eigen::Vector3d(l, 0, 0)}}}, 1));
    return model;
  }

  EquilibriumSettings with_penalty()
  {
    EquilibriumSettings settings;
    settings.contact_stiffness = k_c;
    return settings;
  }

  softchain::data::ObstacleRecord rough_table(const double mu)
  {
    softchain::data::ObstacleRecord table = plane(-h);
    table.friction                        = mu;
    return table;
  }

  // The root of f on [low, high] where f(low) and f(high) differ in sign.
  template <typename F>
  double bisect(const F &f, double low, double high)
  {
    const bool rising = f(high) > 0.0;
    for (int i = 0; i < 200; ++i)
      {
        const double middle = 0.5 * (low + high);
        ((f(middle) > 0.0) == rising ? high : low) = middle;
      }
    return 0.5 * (low + high);
  }

  // Joint residual k phi - t tau - M_z(phi) of a point at c + l (cos phi,
  // sin phi) carrying the force (F_x, F_y): M_z = l cos(phi) F_y - l sin(phi) F_x.
  double joint_residual(double phi, double t, double force_x, double force_y)
  {
    return k * phi - t * tau - (l * std::cos(phi) * force_y - l * std::sin(phi) * force_x);
  }

  // Anchors at the touching points of `solver`'s last evaluation, shifted
  // along the tangent e1 = n x e_z by `slip` times each one's elastic range
  // mu N / k_t, with N = the touch's normal force and k_t = 1 / (1 / k_c +
  // c_t N_b / N), N_b the normal forces of the touches on its link.
  std::vector<StickAnchor> shifted_anchors(const ChainEquilibrium &solver, double mu, const std::vector<double> &slips,
                                           double c_t = 0.0)
  {
    std::vector<Eigen::Vector3d> x;
    solver.contact().surface_positions(solver.pose(), x);
    std::vector<StickAnchor> anchors;
    const auto              &touches = solver.contact().touches();
    for (std::size_t i = 0; i < touches.size(); ++i)
      {
        const auto           &t     = touches[i];
        const double          N     = t.force.norm();
        const Eigen::Vector3d along = t.normal.cross(Eigen::Vector3d::UnitZ()).normalized();
        double                N_b   = 0.0;
        for (const auto &other : touches)
          N_b += other.link == t.link ? other.force.norm() : 0.0;
        const double          k_t   = 1.0 / (1.0 / solver.contact().stiffness() + c_t * N_b / N);
        const double          slip  = slips[i % slips.size()] * mu * N / k_t;
        anchors.push_back({t.link, t.point, t.obstacle, x[t.point] - slip * along, t.normal, N});
      }
    return anchors;
  }
} // namespace

TEST_CASE("a joint slides a point along a rough table: Coulomb's closed form with the settled normal force")
{
  // From the touch on (phi = -asin(h / l) at t = 0.51) the point slides
  // towards -x, so the table holds it back with mu N along +x:
  //   k phi - tau - N l (cos phi - mu sin phi) = 0,   N = -k_c (l sin phi + h).
  // mu = 0.4 is below the ratio T / N = |tan phi| ~ 0.44 that sticking
  // would need, so the point slides from the touch on.
  const double        mu = 0.4;
  const ChainModel          model    = one_joint();
  const EquilibriumSettings settings = with_penalty();
  ChainEquilibrium          solver(model, settings);
  FrictionalLoadPath        path(solver);
  const ChainLoad    load{1.0, {}, {rough_table(mu)}};
  const Equilibrium  e = path.solve(load);
  REQUIRE(e.converged);
  const auto normal = [&](double phi) { return -k_c * (l * std::sin(phi) + h); };
  const double phi  = bisect([&](double p) { return joint_residual(p, 1.0, mu * normal(p), normal(p)); },
                             -std::asin(h / l), tau / k);
  // The friction uses the normal force of the pass before the last, which
  // differs from the last one's by at most the path's tolerance (1e-6
  // relative); phi moves by about that times the friction's share of M_z.
  CHECK(e.angles[2] == Approx(phi).epsilon(1e-6));
  const auto wrench = solver.contact().obstacle_wrenches();
  REQUIRE(wrench.size() == 1);
  CHECK(wrench[0].force[1] == Approx(-normal(phi)).epsilon(1e-5));
  CHECK(wrench[0].force[0] == Approx(-mu * normal(phi)).epsilon(1e-5)); // dragged along -x
  REQUIRE(solver.contact().friction().grips().size() == 1);
  CHECK(solver.contact().friction().grips()[0].sliding);
  // Without friction the table takes (k phi - tau) / (l cos phi): about
  // 15 % more, since the friction's moment takes the rest.
  ChainEquilibrium frictionless(model, settings);
  REQUIRE(frictionless.solve(ChainLoad{1.0, {}, {plane(-h)}}).converged);
  CHECK(frictionless.contact().obstacle_wrenches()[0].force[1] < 1.1 * wrench[0].force[1]);

  // Sliding all the way, the answer does not depend on the steps.
  for (const int steps : {3, 7, 50})
    {
      ChainEquilibrium   other(model, settings);
      FrictionalLoadPath other_path(other, {steps, 30, 1e-6});
      const Equilibrium  f = other_path.solve(load);
      REQUIRE(f.converged);
      CHECK(f.angles[2] == Approx(phi).epsilon(1e-6));
    }
}

TEST_CASE("a point on a rough table sticks where it entered it, its section sheared in series with the penalty")
{
  // mu = 1 holds the point (T / N ~ 0.44 < 1). Along 20 steps it enters
  // the table within the step from t = 0.5 (phi = tau / 2k = -0.4, above
  // the table: x_s = c + l (cos 0.4, -sin 0.4)) to 0.55, where the first
  // solve, frictionless for it, puts it at x_1 (k phi - 0.55 tau - N l cos
  // phi = 0). It sticks
  // at the zero of the gap interpolated from x_s to x_1, a = x_s + g_s /
  // (g_s - g_1) (x_1 - x_s), and the penalty holds it there from then on,
  // F = (-k_t (x - a_x), -k_c (l sin phi + h)), with the section's shear c_t
  // in series: k_t = 1 / (1 / k_c + c_t) (one point on its link).
  const double mu = 1.0;
  for (const double c_t : {0.0, 2e-4})
    {
      INFO("shear compliance " << c_t << " m/N");
      ChainModel model = one_joint();
      if (c_t > 0.0)
        model.set_skin_shear_compliance(PiecewiseLinear({0.0}, {c_t}));
      const EquilibriumSettings settings = with_penalty();
      ChainEquilibrium          solver(model, settings);
      // Every step solved to the solver's 1e-10: the closed form's exact path.
      FrictionalLoadPath        path(solver, {20, 30, 1e-6, 1e-10});
      const Equilibrium         e = path.solve(ChainLoad{1.0, {}, {rough_table(mu)}});
      REQUIRE(e.converged);
      // Relative to the joint.
      const auto point   = [&](double phi) { return Eigen::Vector2d(l * std::cos(phi), l * std::sin(phi)); };
      const auto force_y = [&](double phi) { return -k_c * (point(phi).y() + h); };
      const Eigen::Vector2d start = point(-0.4);
      const double          touch = -std::asin(h / l);
      const Eigen::Vector2d first =
        point(bisect([&](double p) { return joint_residual(p, 0.55, 0.0, force_y(p)); }, touch, 0.55 * tau / k));
      const double before = start.y() + h, after = first.y() + h;
      const double anchor = start.x() + before / (before - after) * (first.x() - start.x());
      const double k_t    = 1.0 / (1.0 / k_c + c_t);
      const auto   force_x = [&](double phi) { return -k_t * (point(phi).x() - anchor); };
      const double phi = bisect([&](double p) { return joint_residual(p, 1.0, force_x(p), force_y(p)); }, touch,
                                tau / k);
      // The settled normal force (1e-6) enters the cone's test only: in stick
      // the answer is the penalty's, to round-off of the solves (tolerance
      // 1e-10) amplified by the stiff tangential penalty.
      CHECK(e.angles[2] == Approx(phi).epsilon(1e-9));
      REQUIRE(std::abs(force_x(phi)) < mu * force_y(phi)); // inside the cone: it sticks
      const auto &grips = solver.contact().friction().grips();
      REQUIRE(grips.size() == 1);
      CHECK_FALSE(grips[0].sliding);
      CHECK(solver.contact().friction().stiffness(0) == Approx(k_t).epsilon(1e-12));
      CHECK(grips[0].force.x() == Approx(force_x(phi)).margin(1e-5 * force_y(phi)));
      // The friction carries a share: T / N ~ 0.43 rigid (0 without
      // friction), 0.02 where the section shears: at c_t = 2e-4 m/N the
      // point slips 21 times farther for the same force.
      CHECK(force_x(phi) > (c_t > 0.0 ? 0.01 : 0.3) * force_y(phi));
    }
}

TEST_CASE("the points sticking on one link share its section's shear by their normal forces")
{
  CoulombFriction friction;
  const double    c_t = 1e-3;
  const auto      anchor = [](int link, int point, double N) {
    return StickAnchor{link, point, 0, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitY(), N};
  };
  // k_t = 1 / (1 / k_c + c_t N_b / N_k). Two anchors on link 2 (1 and 2 N),
  // one on link 0, one with no normal force (it does not act, and does not
  // count), listed out of link order.
  const std::vector<StickAnchor> anchors = {anchor(2, 5, 1.0), anchor(0, 1, 1.0), anchor(2, 6, 0.0),
                                            anchor(2, 7, 2.0)};
  friction.set({0.5}, k_c, c_t, anchors);
  REQUIRE(friction.anchors().size() == 3);
  CHECK(friction.anchors()[0].link == 0);
  CHECK(friction.stiffness(0) == Approx(1.0 / (1.0 / k_c + c_t)).epsilon(1e-14));
  CHECK(friction.anchors()[1].point == 5);
  CHECK(friction.stiffness(1) == Approx(1.0 / (1.0 / k_c + 3 * c_t)).epsilon(1e-14));
  CHECK(friction.stiffness(2) == Approx(1.0 / (1.0 / k_c + 1.5 * c_t)).epsilon(1e-14));
  // Each reaches the cone mu N_k at the same slip of the section, mu c_t N_b.
  CHECK(0.5 * 1.0 / friction.stiffness(1) - 0.5 * 1.0 / k_c == Approx(0.5 * c_t * 3.0).epsilon(1e-12));
  CHECK(0.5 * 2.0 / friction.stiffness(2) - 0.5 * 2.0 / k_c == Approx(0.5 * c_t * 3.0).epsilon(1e-12));
  // Equal normal forces: m_b points sticking alike carry the link's series
  // stiffness 1 / (c_t + 1 / (m_b k_c)) together.
  friction.set({0.5}, k_c, c_t, {anchor(3, 1, 0.7), anchor(3, 2, 0.7), anchor(3, 3, 0.7)});
  CHECK(3 * friction.stiffness(0) == Approx(1.0 / (c_t + 1.0 / (3 * k_c))).epsilon(1e-14));
  // A point that grazes the obstacle takes a share that vanishes with its
  // force, and leaves its neighbour's as it was.
  friction.set({0.5}, k_c, c_t, {anchor(3, 1, 1.0), anchor(3, 2, 1e-9)});
  CHECK(friction.stiffness(0) == Approx(1.0 / (1.0 / k_c + c_t)).epsilon(1e-8));
  CHECK(friction.stiffness(1) < 1e-5);
  friction.set({0.5}, k_c, 0.0, anchors);
  CHECK(friction.stiffness(1) == Approx(k_c).epsilon(1e-14));
  CHECK_THROWS_WITH(friction.set({0.5}, k_c, -1e-3, anchors), Catch::Contains("shear compliance is negative"));
}

TEST_CASE("friction: residual = energy gradient, tangent = central differences, in stick and slip")
{
  const int    n  = 4;
  const double mu = 0.5;
  for (const double skin : {0.0, 0.01})
    for (const double shear : {0.0, 0.005})
    for (auto obstacle : {plane(-0.012), cylinder({0.05, -0.016, 0.0}, 0.008)})
      {
        INFO("skin compliance " << skin << " m/N, shear compliance " << shear << " m/N, " << obstacle.shape);
        obstacle.friction = mu;
        ChainModel model  = uniform_finger(n, 0.02, {0.3, 0.2, 0.1}, {0.0, 0.0, -2e-6});
        model.set_collision_surface(palm_points(n, 0.02, 3, 0.004, 0.006, skin > 0.0));
        if (skin > 0.0)
          model.set_skin_compliance(PiecewiseLinear({0.0}, {skin}));
        if (shear > 0.0)
          model.set_skin_shear_compliance(PiecewiseLinear({0.0}, {shear}));
        // A soft penalty (penetrations ~1 mm, elastic slips mu N / k_t ~
        // 0.5 mm), so that no point lies within the differences' reach of a
        // kink (g = 0 or |delta| = delta_s).
        EquilibriumSettings soft;
        soft.contact_stiffness       = 100.0;
        ChainEquilibrium solver(model, soft);
        softchain::data::ObstacleRecord frictionless = obstacle;
        frictionless.friction                        = 0.0;
        const Equilibrium base = solver.solve(ChainLoad{1e4, {}, {frictionless}});
        REQUIRE(base.converged);
        // Anchors half within their elastic range (stick), half beyond (slip).
        ChainLoad load{1e4, {}, {obstacle}};
        load.anchors = shifted_anchors(solver, mu, {0.3, 3.0}, shear);
        REQUIRE(load.anchors.size() >= 2);
        Eigen::VectorXd q = base.angles;
        for (int i = 0; i < 3 * n; ++i)
          q[i] += 2e-4 * std::sin(1.0 + i);
        solver.set_load(load);
        const Eigen::VectorXd r = solver.residual(q);
        const auto &grips = solver.contact().friction().grips();
        REQUIRE(grips.size() == load.anchors.size());
        int sliding = 0;
        for (const auto &g : grips)
          {
            const auto   i       = static_cast<std::size_t>(&g - grips.data());
            const double elastic = mu * solver.contact().friction().anchors()[i].normal_force /
                                   solver.contact().friction().stiffness(i);
            REQUIRE(std::abs(g.slip - elastic) > 0.05 * elastic); // clear of the cone's kink
            sliding += g.sliding;
          }
        CHECK(sliding > 0);
        CHECK(sliding < static_cast<int>(grips.size()));
        // Central differences err by h^2 |U'''| / 6 + eps |U| / h, ~1e-9 here.
        const Eigen::VectorXd g = testing::energy_gradient(solver, q, 1e-6);
        CHECK((r - g).lpNorm<Eigen::Infinity>() < 1e-7 * r.lpNorm<Eigen::Infinity>());
        const Eigen::MatrixXd H = solver.tangent(q);
        const Eigen::MatrixXd D = testing::central_differences(solver, q, 1e-7);
        CHECK((H - D).lpNorm<Eigen::Infinity>() < 1e-6 * H.lpNorm<Eigen::Infinity>());
        // The obstacle receives the friction too: its force has a part
        // along the table.
        Eigen::Vector3d friction = Eigen::Vector3d::Zero();
        for (const auto &grip : grips)
          friction -= grip.force;
        const auto wrench = solver.contact().obstacle_wrenches();
        double     normal_x = 0.0;
        for (const auto &t : solver.contact().touches())
          normal_x -= t.force.x();
        CHECK(wrench[0].force[0] == Approx(normal_x + friction.x()).margin(1e-12));
        CHECK(std::abs(friction.x()) > 1e-3 * std::abs(wrench[0].force[1]));
        // The step with the friction's rows is the exact tangent's Newton
        // step where that brings no other point into contact (else the
        // model's active set takes it in).
        const Eigen::VectorXd step = solver.newton_step(q);
        Eigen::VectorXd dense = -H.llt().solve(r);
        dense *= std::min(1.0, 1.5 / dense.lpNorm<Eigen::Infinity>());
        const auto touching = solver.contact().touches().size();
        solver.residual(q + dense);
        if (solver.contact().touches().size() == touching)
          CHECK((step - dense).lpNorm<Eigen::Infinity>() < 1e-9 * dense.lpNorm<Eigen::Infinity>());
      }
}

TEST_CASE("a load without friction takes one solve, bad friction input is named")
{
  const ChainModel          model    = one_joint();
  const EquilibriumSettings settings = with_penalty();
  ChainEquilibrium          solver(model, settings), direct(model, settings);
  FrictionalLoadPath path(solver);
  const ChainLoad    load{1.0, {}, {plane(-h)}};
  const Equilibrium  e = path.solve(load);
  REQUIRE(e.converged);
  CHECK(path.passes() == 1);
  CHECK(e.angles == direct.solve(load).angles);

  ChainLoad anchored{1.0, {}, {rough_table(0.5)}};
  anchored.anchors.push_back({0, 0, 3, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitY(), 1.0});
  CHECK_THROWS_WITH(solver.solve(anchored), Catch::Contains("names obstacle 3 of 1"));
  CHECK_THROWS_WITH(path.solve(anchored), Catch::Contains("starts at rest"));
  CHECK_THROWS_AS(FrictionalLoadPath(solver, {0, 30, 1e-6}), std::invalid_argument);
  CHECK_THROWS_AS(FrictionalLoadPath(solver, {20, 30, 1e-6, 0.0}), std::invalid_argument);
}

TEST_CASE("a frictional path whose steps stop at 1e-4 lands where exact steps do, in fewer iterations")
{
  // Four joints closing on a rough cylinder (the tangents' finger above,
  // the default penalty), in contact from about a third of the path on,
  // its points sticking and sliding.
  const int  n        = 4;
  ChainModel model    = uniform_finger(n, 0.02, {0.3, 0.2, 0.1}, {0.0, 0.0, -2e-6});
  model.set_collision_surface(palm_points(n, 0.02, 3, 0.004, 0.006, false));
  softchain::data::ObstacleRecord can = cylinder({0.05, -0.016, 0.0}, 0.008);
  can.friction                        = 0.5;
  const ChainLoad load{1e4, {}, {can}};
  const auto      solve = [&](const double step_tolerance, ChainEquilibrium &solver) {
    FrictionalLoadPath path(solver, {40, 100, 1e-6, step_tolerance});
    const Equilibrium  e = path.solve(load);
    REQUIRE(e.converged);
    return e;
  };
  ChainEquilibrium  exact_solver(model), loose_solver(model);
  const Equilibrium exact = solve(1e-10, exact_solver);
  const Equilibrium loose = solve(1e-4, loose_solver);
  REQUIRE(exact_solver.contact().friction().grips().size() >= 2);
  const double force = Eigen::Vector3d(exact_solver.contact().obstacle_wrenches()[0].force.data()).norm();
  const double loose_force = Eigen::Vector3d(loose_solver.contact().obstacle_wrenches()[0].force.data()).norm();
  // Measured: the angles agree to 1.1e-11 rad (of 0.2) and the force to
  // 2.5e-10 of itself, in 141 Newton iterations against 286. The Newton
  // iteration that passes 1e-4 lands far below it (Newton converges
  // quadratically), so each step starts nearly where the exact one does;
  // the bounds leave a hundred times that.
  CHECK((loose.angles - exact.angles).lpNorm<Eigen::Infinity>() < 1e-9);
  CHECK(loose_force == Approx(force).epsilon(1e-8));
  CHECK(loose.iterations < 0.7 * exact.iterations);
  // The path leaves the solver at its own tolerance.
  CHECK(loose_solver.tolerance() == EquilibriumSettings().tolerance);
}

TEST_CASE("Aitken's relaxation settles an oscillating or creeping fixed point of the normal forces in a few solves")
{
  // A linear model of a step's solve: the normal forces found from lagged
  // ones N, F(N) = b + A N with A = -0.95 (the back and forth of a grasp)
  // on one point and -0.3 on another; the fixed point N* = (I - A)^-1 b.
  // The plain iteration's error shrinks by 0.95 per solve (about 400
  // solves to 1e-10); relaxed, the secant step along the residual lands in
  // a few.
  const Eigen::Vector2d A(-0.95, -0.3), b(0.2, 0.1);
  const Eigen::Vector2d fixed = b.cwiseQuotient(Eigen::Vector2d::Ones() - A);
  const auto            anchors = [](const Eigen::Vector2d &N) {
    std::vector<StickAnchor> a;
    for (int i = 0; i < 2; ++i)
      a.push_back({0, i, 0, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitY(), N[i]});
    return a;
  };
  const auto forces = [](const std::vector<StickAnchor> &a) {
    Eigen::Vector2d N = Eigen::Vector2d::Zero();
    for (const StickAnchor &x : a)
      N[x.point] = x.normal_force;
    return N;
  };
  AitkenRelaxation relaxation;
  Eigen::Vector2d  N(0.1, 0.1);
  int              solves = 0;
  for (; solves < 50 && (b + A.cwiseProduct(N) - N).norm() > 1e-10; ++solves)
    N = forces(relaxation.next(anchors(N), anchors(b + A.cwiseProduct(N))));
  CHECK(solves <= 12);
  CHECK((N - fixed).norm() < 1e-9);
  CHECK(relaxation.factor() < 0.9); // relaxed, not the plain iteration
  // Where the plain iteration creeps (A = 0.8 on both points, about 100
  // solves to 1e-10), the factor grows beyond 1 and lands in a few.
  const Eigen::Vector2d creep(0.8, 0.8);
  AitkenRelaxation      over;
  N = Eigen::Vector2d(0.1, 0.1);
  solves = 0;
  for (; solves < 50 && (b + creep.cwiseProduct(N) - N).norm() > 1e-10; ++solves)
    N = forces(over.next(anchors(N), anchors(b + creep.cwiseProduct(N))));
  CHECK(solves <= 6);
  CHECK((N - b / 0.2).norm() < 1e-9);
  // A point whose relaxed force is not positive loses its anchor.
  AitkenRelaxation fresh;
  CHECK(fresh.next(anchors({0.1, 0.1}), {anchors({0.1, 0.1})[0]}).size() == 1);
}
