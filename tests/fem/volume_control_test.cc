// Volume-controlled inflation: the cavity's volume is prescribed
// and the pressure solved for, which traces the pressure-volume curve of an
// unreinforced bender through its balloon limit point, where pressure
// control stops.
#include "fem_test_tools.h"

#include <softchain/app/commands.h>
#include <softchain/data/prm_file.h>
#include <softchain/fem/volume_controlled_inflation.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

using namespace dealii;
using namespace softchain;
using namespace softchain::fem;

namespace
{
  // The demo bender without fabric and threads (Q1, 4 cells along x): its
  // flat 2 mm walls balloon and pressure control stops near 25 kPa.
  test::SolverFixture unreinforced_bender()
  {
    return test::SolverFixture(test::parameters_from_text(
      "volume_control",
      test::bender_prm("Q1", 4, "subsection Springs\n  set Generate for bender = false\nend\n")));
  }
} // namespace

TEST_CASE("the unit-pressure load is the derivative of the cavity volume", "[fem][volume]")
{
  // g . v = dV/du . v, checked by central differences at a deformed state:
  // truncation error ~ eps^2 V''' ~ 1e-12 relative, round-off ~ 1e-16 V /
  // (eps |g . v|) ~ 1e-9, so 1e-6 has a wide margin.
  auto       f = unreinforced_bender();
  const auto u = test::smooth_displacement(*f.solver, 2e-3, 0.05, 5);
  const auto v = test::smooth_displacement(*f.solver, 1e-3, 0.5, 11);
  f.solver->set_displacement(u);
  VolumeControlledInflation inflation(*f.solver, f.prm);
  const TrilinosWrappers::MPI::Vector g = inflation.unit_load();
  const double eps = 1e-3;
  auto         shifted = [&](const double t) {
    TrilinosWrappers::MPI::Vector w(u);
    w.add(t, v);
    f.solver->set_displacement(w);
    return inflation.volume();
  };
  const double difference = (shifted(eps) - shifted(-eps)) / (2 * eps);
  CHECK(g * v == Approx(difference).epsilon(1e-6));
}

TEST_CASE("volume control passes the balloon limit point where pressure control stops",
          "[fem][volume][stability]")
{
  auto      f = unreinforced_bender();
  LoadState load;
  load.pressure          = 40e3;
  const auto by_pressure = f.solver->solve(load);
  REQUIRE(!by_pressure.converged);
  CHECK(by_pressure.failure == QuasiStaticSolver::Failure::limit_point);
  const double p_limit = by_pressure.load_factor_reached * load.pressure;

  f.solver->reset();
  VolumeControlledInflation inflation(*f.solver, f.prm);
  const double v0     = inflation.volume();
  const auto   result = inflation.solve(3.0 * v0);
  INFO(result.reason);
  REQUIRE(result.converged);
  const auto peak = std::max_element(result.curve.begin(), result.curve.end(),
                                     [](const auto &a, const auto &b) { return a.pressure < b.pressure; });
  for (std::size_t k = 0; k < result.curve.size(); k += std::max<std::size_t>(1, result.curve.size() / 12))
    WARN("V / V0 = " << result.curve[k].volume / v0 << "  p = " << result.curve[k].pressure << " Pa");
  WARN("pressure control stopped at " << p_limit << " Pa; volume control peaks at "
                                      << peak->pressure << " Pa (V / V0 = " << peak->volume / v0
                                      << ") and ends at " << result.curve.back().pressure
                                      << " Pa, V / V0 = " << result.curve.back().volume / v0 << ", "
                                      << result.newton_iterations << " Newton iterations");
  // The volume rises step by step and reaches the target.
  for (std::size_t k = 1; k < result.curve.size(); ++k)
    CHECK(result.curve[k].volume > result.curve[k - 1].volume);
  CHECK(result.curve.back().volume == Approx(3.0 * v0).epsilon(1e-6));
  // The peak is the limit pressure. Pressure control stops within its last
  // load-step cut below the peak (minimum step 1e-4 of 40 kPa = 4 Pa, but
  // Newton fails earlier as the tangent turns singular): 3 % is asserted.
  CHECK(peak->pressure == Approx(p_limit).epsilon(0.03));
  CHECK(peak != result.curve.end() - 1);
  CHECK(result.curve.back().pressure < peak->pressure); // past the peak: softening
}

namespace
{
  // The numbers of <directory>/solve_summary.csv by column name.
  std::map<std::string, double> solve_summary(const std::string &directory)
  {
    std::ifstream in(directory + "/solve_summary.csv");
    std::string   header, row;
    std::getline(in, header);
    std::getline(in, row);
    std::istringstream            names(header), values(row);
    std::map<std::string, double> summary;
    for (std::string name, value; std::getline(names, name, ',') && std::getline(values, value, ',');)
      summary[name] = std::stod(value);
    return summary;
  }

  // `softchain solve` of the unreinforced bender with these Loads entries.
  std::map<std::string, double> solve_bender(const std::string &name, const std::string &loads)
  {
    const std::string prm = test::write_prm(
      name, test::bender_prm("Q1", 4,
                             "subsection Springs\n  set Generate for bender = false\nend\n"
                             "subsection Design\n  set Output directory = " + name + "\nend\n"
                             "subsection Loads\n" + loads + "end\n"));
    REQUIRE(softchain::app::solve_command(data::PrmFile::read(prm)) == 0);
    return solve_summary(name);
  }
} // namespace

// Loads/Control = volume in `softchain solve`: the cavity reaches the volume
// asked for, the pressure it reports is the one that pressure control needs
// for that state (the same equilibrium, solved the other way round), and the
// pressure-volume curve is written.
TEST_CASE("softchain solve under volume control finds the pressure of the volume asked for",
          "[fem][volume]")
{
  const double ratio = 1.2; // 13 kPa, where dp/dV is still well above zero (the limit is near 25 kPa)
  const auto by_volume = solve_bender("volume_control_solve",
                                      "  set Control = volume\n  set Cavity volume ratio = " +
                                        std::to_string(ratio) + "\n");
  const double pressure = by_volume.at("cavity_pressure");
  REQUIRE(by_volume.at("converged") == 1);
  CHECK(pressure > 0);

  std::ifstream curve("volume_control_solve/pressure_volume.csv");
  std::string   line, last;
  while (std::getline(curve, line))
    last = line;
  // volume_ratio of the last step: the target, to Newton's volume tolerance (1e-6 relative).
  CHECK(std::stod(last.substr(last.find(',') + 1)) == Approx(ratio).epsilon(1e-6));

  std::ostringstream p;
  p.precision(17);
  p << pressure;
  const auto by_pressure = solve_bender("pressure_control_solve", "  set Pressure = " + p.str() + "\n");
  // Both solves stop at relative residuals and updates of 1e-6 (Solver
  // defaults), so their states may differ by about that; measured 7e-10 in
  // the volume and 1.7e-8 in the tip's axial displacement (the tip's y is
  // zero by symmetry, 3e-16 m apart). A wrong pressure (e.g. one load step
  // short) would be off by percent.
  CHECK(by_pressure.at("cavity_volume") == Approx(by_volume.at("cavity_volume")).epsilon(1e-6));
  for (const std::string u : {"tip_displacement_x", "tip_displacement_y"})
    CHECK(by_pressure.at(u) == Approx(by_volume.at(u)).epsilon(1e-6).margin(1e-9));
  CHECK(by_pressure.at("cavity_pressure") == Approx(pressure).epsilon(1e-12));
}
