// Displacement control of point forces through a limit point: a shallow
// clamped arch under a load at its crown snaps through. Force control stops
// at the peak of the load; displacement control follows the crown through
// the peak, the drop and the rise on the inverted side to the force asked
// for.
#include "fem_test_tools.h"

#include <softchain/fem/boundary_ids.h>
#include <softchain/data/actuation_database.h>
#include <softchain/fem/displacement_controlled_forces.h>
#include <softchain/fem/finger_mesh.h>
#include <softchain/fem/sample_group.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

using namespace dealii;
using namespace softchain;
using namespace softchain::fem;

namespace
{
  constexpr double half_span = 0.05, rise = 0.006, thickness = 0.002, width = 0.01; // m

  // A parabolic arch y = rise (1 - (x / half_span)^2) (its lower face) of
  // `cells` Q2 hexahedra along the span, one across; both ends clamped.
  void shallow_arch(Triangulation<3> &mesh, const unsigned int cells)
  {
    GridGenerator::subdivided_hyper_rectangle(mesh, {cells, 1, 1}, Point<3>(-half_span, 0, 0),
                                              Point<3>(half_span, thickness, width));
    GridTools::transform(
      [](const Point<3> &p) {
        const double s = p[0] / half_span;
        return Point<3>(p[0], p[1] + rise * (1 - s * s), p[2]);
      },
      mesh);
    for (const auto &face : mesh.active_face_iterators())
      if (face->at_boundary())
        face->set_boundary_id(std::abs(std::abs(face->center()[0]) - half_span) < 1e-9 ?
                                boundary::base :
                                boundary::other);
  }

  const Point<3> crown(0, rise + thickness / 2, width / 2);

  LoadState crown_load(const double force)
  {
    LoadState load;
    load.point_loads.push_back({crown, Tensor<1, 3>({0, -force, 0})});
    return load;
  }
} // namespace

TEST_CASE("displacement control passes the snap-through of a shallow arch", "[fem][stability]")
{
  Triangulation<3> mesh;
  shallow_arch(mesh, 16);
  // Steps of at most 0.5 mm of the crown (0.5 % of the arch's diagonal), so
  // that the path resolves the peak; force control's steps stay as fine.
  // Every step converges to the final tolerances, so that the path's states
  // are equilibria to compare.
  test::MeshSolverFixture f(
    test::parameters_from_text("arch", test::solid_prm("Q2", "log", 2.6e5, 0.48,
                                                       "subsection Solver\n"
                                                       "  set Initial load step = 0.005\n"
                                                       "  set Maximum load step = 0.005\n"
                                                       "  set Intermediate tolerance = 1e-6\n"
                                                       "end\n")),
    mesh);
  const double force    = 0.01; // N, about five times the snap-through load
  const auto   by_force = f.solver->solve(crown_load(force));
  REQUIRE(!by_force.converged); // force control stops at the peak
  const double stopped_at = by_force.load_factor_reached;

  f.solver->reset();
  DisplacementControlledForces control(*f.solver, f.prm, crown_load(force));
  const auto result = control.solve();
  INFO(result.reason);
  REQUIRE(result.converged);
  REQUIRE(result.limit_fraction);
  const auto &path = result.path;
  // The limit point: the first step after which the load falls.
  const auto peak =
    std::adjacent_find(path.begin(), path.end(), [](const auto &a, const auto &b) { return b.load < a.load; });
  REQUIRE(peak != path.end());
  WARN("force control stopped at " << stopped_at * force << " N; displacement control peaked at "
                                   << peak->load << " N (crown " << 1e3 * peak->displacement
                                   << " mm down), fell to the minimum and reached " << force
                                   << " N with the crown "
                                   << -1e3 * test::displacement_at(*f.solver, crown)[1]
                                   << " mm down, " << result.load_steps << " steps, "
                                   << result.newton_iterations << " Newton iterations");
  // The peak is the load where force control stopped: force control stops
  // within its last cut step below the true peak, and the path samples the
  // peak every 0.5 mm of the crown (measured: 0.05 % apart; 0.5 % asserted).
  CHECK(*result.limit_fraction == Approx(peak->load / force));
  CHECK(peak->load == Approx(stopped_at * force).epsilon(0.005));
  // Past the peak the load falls before it rises again on the inverted side.
  const auto lowest = std::min_element(peak, path.end(), [](const auto &a, const auto &b) { return a.load < b.load; });
  CHECK(lowest->load < 0.9 * peak->load);
  // The crown ends through the arch's chord: inverted (its lower face at
  // y = -rise and below for a symmetric snap).
  const double crown_down = -test::displacement_at(*f.solver, crown)[1];
  CHECK(crown_down > rise);
  // The end is an equilibrium under the force asked for.
  REQUIRE(f.solver->assemble(crown_load(force), false));
  CHECK(f.solver->residual_norm() <= f.prm.solver.residual_tolerance * force);
  // A state before the peak is force control's equilibrium at its load: the
  // crown where force control puts it, within the displacement tolerance
  // both converged to (1e-6; measured 1e-14).
  const auto before = path.begin() + (peak - path.begin()) / 2;
  REQUIRE(before != path.begin());
  f.solver->reset();
  REQUIRE(f.solver->solve(crown_load(before->load)).converged);
  CHECK(-test::displacement_at(*f.solver, crown)[1] == Approx(before->displacement).epsilon(1e-6));
}

TEST_CASE("the sweep stores a force sample past a limit point with its limit", "[fem][stability]")
{
  // The arch as a sample group's finger: its solve of a crown force beyond
  // the snap-through (load control fails there) goes on by displacement
  // control, and the record says where the limit lay.
  FingerMesh mesh;
  shallow_arch(mesh.triangulation, 16);
  mesh.material_names = {"solid"};
  const Parameters  prm = test::parameters_from_text("arch_sweep", test::solid_prm("Q2", "log", 2.6e5, 0.48));
  std::ostringstream log;
  SampleGroup        group(prm, mesh, MPI_COMM_WORLD, log);
  Sample             sample;
  sample.label                  = "crown 10 mN";
  sample.actuation.role         = "crown";
  sample.actuation.point_forces = {{{{crown[0], crown[1], crown[2]}}, {{0.0, -0.01, 0.0}}}};
  sample.id                     = data::sample_id("arch", sample.actuation);
  const auto record             = group.solve(sample, nullptr, nullptr, 0);
  INFO(record.reason);
  REQUIRE(record.converged());
  CHECK(record.load_factor_reached == 1.0);
  // Load control hands over once a cut step falls below 1 % of the path
  // (SampleGroup::smallest_load_step): it does not creep towards the peak
  // in steps finer than that (down to Minimum load step, 1e-4).
  std::istringstream lines(log.str());
  unsigned int       fine_cuts = 0; // load control's cuts to a step below 1e-2
  for (std::string line; std::getline(lines, line) && line.find("displacement factor") == std::string::npos;)
    if (const auto at = line.find("cutting the step to "); at != std::string::npos)
      fine_cuts += std::stod(line.substr(at + 20)) < 1e-2;
  CHECK(fine_cuts == 1); // the cut that gives load control up
  CHECK_THAT(log.str(), Catch::Contains("displacement factor"));
  // The limit is the largest force the path held, a lower bound of the
  // snap-through load of the test above (2.117 mN): load control stopped
  // within the step that failed there, at most 4 % of the 10 mN asked for
  // (a quarter of it is below 1 %), and displacement control's states
  // after it are past the peak or below it (measured 2.0065 mN).
  CHECK(record.force_limit <= 2.117e-3 * (1 + 1e-3));
  CHECK(record.force_limit >= 2.117e-3 - 0.04 * 0.01);
  CHECK_THAT(record.reason, Catch::Contains("passed a limit point of the forces"));
  // The crown went through: it lies below the supports (7 mm above them at rest).
  REQUIRE(record.force_points_deformed.size() == 1);
  CHECK(record.force_points_deformed[0][1] < 0.0);
}
