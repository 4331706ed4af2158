// Speed of the chain tier: one equilibrium of a 9-joint finger from
// rest (free, and in contact with a table and a cylinder, with and without friction), a sweep of 100 pressures with warm starts, a 5-finger hand (45
// joints), and the heap memory of one finger (model + solver workspace).
// The paper's SOFA chain took about 6 ms per finger (Sec. V).
// Run: chain_benchmark --benchmark_repetitions=10 --benchmark_report_aggregates_only=true
#include <softchain/chain/chain_equilibrium.h>
#include <softchain/chain/frictional_load_path.h>
#include <softchain/chain/link_geometry.h>

#include <benchmark/benchmark.h>

#include <malloc.h>

#include <algorithm>
#include <string>
#include <memory>
#include <stdexcept>

using namespace softchain::chain;

namespace
{
  constexpr int    n_joints = 9;
  constexpr double a        = 0.01;  // m, the paper's joint spacing
  constexpr double p_max    = 8e4;   // Pa, the paper's largest pressure

  // A PneuFlex-like finger: stiffness decreasing towards the tip, J_p such
  // that p_max bends it through about 200 deg.
  ChainModel finger(double scale = 1.0)
  {
    std::vector<Eigen::Vector3d> joints, k;
    Eigen::VectorXd              jp = Eigen::VectorXd::Zero(3 * n_joints);
    for (int i = 0; i < n_joints; ++i)
      {
        joints.emplace_back((i + 0.5) * a, -0.0003 * i, 0.0);
        k.push_back(scale * (1.0 - 0.05 * i) * Eigen::Vector3d(0.2, 0.05, 0.05));
        jp[3 * i + 2] = scale * (1.0 - 0.05 * i) * 0.05 * 0.39 / p_max;
      }
    return ChainModel("finger", KinematicChain(joints, {n_joints * a, -0.003, 0.0}),
                      JointStiffness(k), PressureActuation(jp));
  }

  // The same finger whose joints twist about an axis 5 mm above them (the
  // reduction's default gives P10 one 5 mm up).
  ChainModel finger_with_twist_axes()
  {
    const ChainModel plain = finger();
    return ChainModel("twist axes",
                      plain.chain().with_twist_offsets(
                        std::vector<Eigen::Vector3d>(n_joints, Eigen::Vector3d(0, 0.005, 0))),
                      plain.stiffness(), plain.actuation());
  }

  // The chain the reduction gives a finger by default: twist axes and links
  // shaped by the pressure (LinkGeometry, tabulated at 0, p_max / 2 and
  // p_max: 3 % longer and 0.2 mm lower per joint at p_max).
  ChainModel finger_as_reduced()
  {
    const ChainModel plain = finger();
    const auto       point = [](const Eigen::Vector3d &X, const double sink) {
      const auto line = [&](const int c) {
        const double at_p_max = 1.03 * X(c) - (c == 1 ? sink : 0.0);
        return PiecewiseLinear({0.0, 0.5 * p_max, p_max}, {X(c), 0.5 * (X(c) + at_p_max), at_p_max});
      };
      return LinkGeometry::PointInPressure{line(0), line(1), line(2)};
    };
    std::vector<LinkGeometry::PointInPressure> joints;
    for (int i = 0; i < n_joints; ++i)
      joints.push_back(point(plain.chain().joint_centre(i), 2e-4 * i));
    ChainModel model = finger_with_twist_axes();
    model.set_link_geometry(
      LinkGeometry(joints, point(plain.chain().tip(), 2e-3), point(Eigen::Vector3d::Zero(), 0.0)));
    return model;
  }

  // A contact-like force at the fingertip, in world axes.
  ChainLoad load(double pressure) { return {pressure, {{{n_joints * a, 0.0, 0.0}, {0.0, 0.3, 0.05}}}}; }

  // The outer surface of a 90 x 12 x 16 mm box finger (palm 2 mm below the joints),
  // a point every 7.5 mm along and 4 mm across, carried rigidly by the links:
  // 174 points, near the 217 surface vertices of P10's default mesh; with
  // `refine` = 3 every 2.5 mm along and 1.33 mm across, 1602 points, near
  // the 1849 of its default collision surface (3 x 3 intervals per face).
  CollisionSurface box_surface(const ChainModel &model, const int refine = 1)
  {
    std::vector<std::pair<int, Eigen::Vector3d>> points;
    const auto add = [&](const Eigen::Vector3d &X) {
      const int b = model.chain().link_of(X);
      if (b >= 0)
        points.emplace_back(b, X - model.chain().joint_centre(b));
    };
    const int m = refine;
    for (int i = 1; i <= 12 * m; ++i)
      for (int j = 0; j <= 3 * m; ++j)
        for (int k = 0; k <= 4 * m; ++k)
          if (j == 0 || j == 3 * m || k == 0 || k == 4 * m || i == 12 * m)
            add({0.0075 / m * i, -0.002 + 0.004 / m * j, -0.008 + 0.004 / m * k});
    std::sort(points.begin(), points.end(), [](const auto &x, const auto &y) { return x.first < y.first; });
    std::vector<int>             links;
    std::vector<Eigen::Vector3d> offsets;
    for (const auto &[link, offset] : points)
      {
        links.push_back(link);
        offsets.push_back(offset);
      }
    return CollisionSurface(links, {{0.0, offsets}}, model.chain().n_joints());
  }

  ChainModel finger_with_surface(const int refine = 1)
  {
    ChainModel model = finger_as_reduced();
    model.set_collision_surface(box_surface(model, refine));
    return model;
  }

  softchain::data::ObstacleRecord obstacle(const std::string &shape, const Eigen::Vector3d &at)
  {
    softchain::data::ObstacleRecord o;
    o.name      = shape;
    o.shape     = shape;
    o.position  = {at.x(), at.y(), at.z()};
    o.direction = shape == "plane" ? softchain::data::Point3{0, -1, 0} : softchain::data::Point3{0, 0, 1};
    o.radius    = shape == "cylinder" ? 0.01 : 0.0;
    return o;
  }

  // This finger bends towards +y: the tip pressed on a table 10 mm above
  // its upper side; the middle wrapped round a 10 mm cylinder 4 mm above it
  // (P10's contact samples, on this finger).
  ChainLoad on_table(double pressure) { return {pressure, {}, {obstacle("plane", {0, 0.02, 0})}}; }
  ChainLoad on_cylinder(double pressure) { return {pressure, {}, {obstacle("cylinder", {0.05, 0.024, 0})}}; }

  void require(const Equilibrium &e)
  {
    if (!e.converged)
      throw std::runtime_error("benchmark equilibrium failed: " + e.failure);
  }

  void report_iterations(benchmark::State &state, int iterations, int solves)
  {
    state.counters["newton_iterations_per_solve"] = double(iterations) / solves;
  }
} // namespace

// One equilibrium from rest of `model` under `chain_load`.
static void equilibrium_from_rest(benchmark::State &state, const ChainModel &model,
                                  const ChainLoad &chain_load)
{
  ChainEquilibrium solver(model);
  int              iterations = 0;
  for (auto _ : state)
    {
      const Equilibrium e = solver.solve(chain_load);
      require(e);
      iterations = e.iterations;
      benchmark::DoNotOptimize(e.angles.data());
    }
  report_iterations(state, iterations, 1);
}
// Pressure only: K q = J_p p is linear, one Newton step.
BENCHMARK_CAPTURE(equilibrium_from_rest, pressure, finger(), ChainLoad{0.5 * p_max, {}});
// Pressure and a tip force: the nonlinear case, ~100 deg of bending.
BENCHMARK_CAPTURE(equilibrium_from_rest, pressure_and_force, finger(), load(0.5 * p_max));
// The two above with twist axes (psi about a pivot 5 mm above each joint).
BENCHMARK_CAPTURE(equilibrium_from_rest, pressure_twist_axes, finger_with_twist_axes(),
                  ChainLoad{0.5 * p_max, {}});
BENCHMARK_CAPTURE(equilibrium_from_rest, pressure_and_force_twist_axes, finger_with_twist_axes(),
                  load(0.5 * p_max));
// And with links shaped by the pressure: the reduction's default chain.
BENCHMARK_CAPTURE(equilibrium_from_rest, pressure_as_reduced, finger_as_reduced(), ChainLoad{0.5 * p_max, {}});
BENCHMARK_CAPTURE(equilibrium_from_rest, pressure_and_force_as_reduced, finger_as_reduced(), load(0.5 * p_max));
// Contact (ChainContact): the reduced finger's surface pressed on a table and
// wrapped round a cylinder at p_max / 2.
BENCHMARK_CAPTURE(equilibrium_from_rest, blocked_on_table, finger_with_surface(), on_table(0.5 * p_max));
BENCHMARK_CAPTURE(equilibrium_from_rest, grasp_of_cylinder, finger_with_surface(), on_cylinder(0.5 * p_max));
// The same with a surface three times as fine each way, as P10's default.
BENCHMARK_CAPTURE(equilibrium_from_rest, blocked_on_table_fine_surface, finger_with_surface(3),
                  on_table(0.5 * p_max));
BENCHMARK_CAPTURE(equilibrium_from_rest, grasp_of_cylinder_fine_surface, finger_with_surface(3),
                  on_cylinder(0.5 * p_max));

// 100 pressures 0..p_max with the tip force, each from the previous pose.
static void pressure_sweep_100_warm_start(benchmark::State &state)
{
  const ChainModel model = finger();
  ChainEquilibrium solver(model);
  int              iterations = 0;
  for (auto _ : state)
    {
      Eigen::VectorXd q = Eigen::VectorXd::Zero(3 * n_joints);
      iterations        = 0;
      for (int s = 1; s <= 100; ++s)
        {
          const Equilibrium e = solver.solve(load(p_max * s / 100.0), q);
          require(e);
          q = e.angles;
          iterations += e.iterations;
        }
      benchmark::DoNotOptimize(q.data());
    }
  report_iterations(state, iterations, 100);
}
BENCHMARK(pressure_sweep_100_warm_start)->Unit(benchmark::kMicrosecond);

// Closing on an obstacle as a simulation does: 20 pressures up to p_max / 2,
// each equilibrium from the previous one (from rest for the first), the
// table's and the cylinder's path. Time per equilibrium.
static void contact_ramp_20_warm_start(benchmark::State &state, const ChainLoad &obstacle_load)
{
  const ChainModel model = finger_with_surface();
  ChainEquilibrium solver(model);
  int              iterations = 0, touching = 0;
  for (auto _ : state)
    {
      ChainLoad load = obstacle_load;
      iterations = touching = 0;
      Eigen::VectorXd q;
      for (int s = 1; s <= 20; ++s)
        {
          load.pressure       = 0.5 * p_max * s / 20.0;
          const Equilibrium e = s == 1 ? solver.solve(load) : solver.solve(load, q);
          require(e);
          q = e.angles;
          iterations += e.iterations;
          touching += solver.contact().touches().empty() ? 0 : 1;
        }
      benchmark::DoNotOptimize(q.data());
    }
  report_iterations(state, iterations, 20);
  state.counters["touching_equilibria"] = touching;
  state.counters["us_per_solve"] =
    benchmark::Counter(20.0, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK_CAPTURE(contact_ramp_20_warm_start, table, on_table(0.0))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(contact_ramp_20_warm_start, cylinder, on_cylinder(0.0))->Unit(benchmark::kMicrosecond);

// With Coulomb friction (mu = 0.5) on the same obstacles: the sample's load
// path from rest (FrictionalLoadPath, 20 steps, a quarter of the default,
// each solved until its normal forces settle; the steps before the last to
// the default's 1e-4, or with `_exact_steps` to the solver's 1e-10). Time
// per path; solves and Newton iterations per path.
static void frictional_path(benchmark::State &state, const ChainLoad &obstacle_load, const double step_tolerance)
{
  const ChainModel   model = finger_with_surface();
  ChainEquilibrium   solver(model);
  FrictionalPathSettings twenty_steps;
  twenty_steps.steps          = 20;
  twenty_steps.step_tolerance = step_tolerance;
  FrictionalLoadPath path(solver, twenty_steps);
  ChainLoad          load = obstacle_load;
  load.obstacles.front().friction = 0.5;
  int iterations = 0;
  for (auto _ : state)
    {
      const Equilibrium e = path.solve(load);
      require(e);
      iterations = e.iterations;
      benchmark::DoNotOptimize(e.angles.data());
    }
  state.counters["solves_per_path"]            = path.passes();
  state.counters["newton_iterations_per_path"] = iterations;
}
static void frictional_path_20_steps(benchmark::State &state, const ChainLoad &obstacle_load)
{
  frictional_path(state, obstacle_load, FrictionalPathSettings().step_tolerance);
}
static void frictional_path_20_exact_steps(benchmark::State &state, const ChainLoad &obstacle_load)
{
  frictional_path(state, obstacle_load, EquilibriumSettings().tolerance);
}
BENCHMARK_CAPTURE(frictional_path_20_steps, table, on_table(0.5 * p_max))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(frictional_path_20_steps, cylinder, on_cylinder(0.5 * p_max))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(frictional_path_20_exact_steps, table, on_table(0.5 * p_max))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(frictional_path_20_exact_steps, cylinder, on_cylinder(0.5 * p_max))->Unit(benchmark::kMicrosecond);

// Five fingers of different stiffness (45 joints), each under pressure and
// its own tip force, solved from rest.
static void hand_5_fingers_from_rest(benchmark::State &state)
{
  std::vector<ChainModel> fingers;
  for (int f = 0; f < 5; ++f)
    fingers.push_back(finger(0.8 + 0.1 * f));
  std::vector<std::unique_ptr<ChainEquilibrium>> solvers;
  for (const ChainModel &m : fingers)
    solvers.push_back(std::make_unique<ChainEquilibrium>(m));
  for (auto _ : state)
    for (auto &solver : solvers)
      {
        const Equilibrium e = solver->solve(load(0.5 * p_max));
        require(e);
        benchmark::DoNotOptimize(e.angles.data());
      }
}
BENCHMARK(hand_5_fingers_from_rest)->Unit(benchmark::kMicrosecond);

// Heap bytes of one finger: model and solver workspace after a solve
// (glibc's count of allocated bytes, so including allocator overhead).
static void memory_per_finger(benchmark::State &state)
{
  double bytes = 0.0;
  for (auto _ : state)
    {
      const std::size_t before = mallinfo2().uordblks;
      auto              model  = std::make_unique<ChainModel>(finger());
      auto              solver = std::make_unique<ChainEquilibrium>(*model);
      require(solver->solve(load(0.5 * p_max)));
      bytes = double(mallinfo2().uordblks - before) + sizeof(ChainModel) + sizeof(ChainEquilibrium);
      benchmark::DoNotOptimize(solver.get());
    }
  state.counters["heap_bytes_per_finger"] = bytes;
}
BENCHMARK(memory_per_finger)->Iterations(1);

BENCHMARK_MAIN();
