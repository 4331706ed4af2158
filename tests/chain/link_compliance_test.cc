// LinkCompliance and the chain with its links in series with its joints:
// the deflection c(p) s f of a load against the closed form, the tip held
// against the closed forms of a spring in series (along a straight chain's
// axis, where rigid links hold any force, and across a single joint), the
// base wrench of the held tip, and the reduction's file read or refused.
#include <softchain/chain/base_wrench.h>
#include <softchain/chain/link_compliance.h>
#include <softchain/chain/stiffness_files.h>
#include <softchain/chain/tip_constrained_equilibrium.h>
#include <softchain/data/input_error.h>

#include "../data/scratch_directory.h"
#include "reduction_output.h"
#include "uniform_finger.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>

using namespace softchain::chain;
namespace data = softchain::data;
using softchain::chain::testing::uniform_finger;

namespace
{
  // c = 1 mm/N at rest, 3 mm/N at 20 kPa: P10's order of magnitude.
  LinkCompliance compliance() { return LinkCompliance(PiecewiseLinear({0.0, 2e4}, {1e-3, 3e-3})); }

  ChainModel compliant_finger(int n, double a, const Eigen::Vector3d &k)
  {
    ChainModel model = uniform_finger(n, a, k);
    model.set_link_compliance(compliance());
    return model;
  }

  // The constrained solve converges to 1e-10 relative (EquilibriumSettings);
  // 1e-8 bounds the relative errors below with a 100x margin.
  constexpr double tolerance = 1e-8;
} // namespace

TEST_CASE("the links deflect the tip by c(p) times the force, scaled by where it acts")
{
  const double         a      = 0.01;
  const KinematicChain chain  = testing::straight_chain(4, a); // joint 1 at a/2, tip at 4a
  const LinkCompliance links  = compliance();
  const Eigen::Vector3d f(0.3, -0.2, 0.1);
  const double          c_mid = 2e-3; // halfway in pressure between the two rows
  const auto deflection = [&](double x) {
    return links.tip_deflection(ChainLoad{1e4, {{Eigen::Vector3d(x, 0, 0), f}}}, chain);
  };
  CHECK((deflection(4 * a) - c_mid * f).norm() < 1e-15);
  CHECK(deflection(0.5 * a).norm() == 0.0);
  CHECK((deflection(0.5 * a + 0.25 * 3.5 * a) - 0.25 * c_mid * f).norm() < 1e-15);
  CHECK((deflection(6 * a) - c_mid * f).norm() < 1e-15); // clamped to the tip's share
  CHECK(links.at(5e4) == 3e-3);                          // held beyond the last row
  CHECK_THROWS_AS(LinkCompliance(PiecewiseLinear({0.0}, {-1e-3})), std::invalid_argument);
  CHECK_THROWS_AS(LinkCompliance(PiecewiseLinear({0.0}, {NAN})), std::invalid_argument);
}

TEST_CASE("a straight chain pulled along its axis: the links alone give, f = d / c")
{
  // Rigid links cannot move the tip along a straight chain's axis (the
  // constraint is rank deficient); with the links in series the force is
  // the displacement over their compliance, and the joints stay straight.
  const double     a = 0.01, d = 0.5e-3;
  const ChainModel model = compliant_finger(3, a, Eigen::Vector3d(0.1, 0.05, 0.05));
  TipConstrainedEquilibrium solver(model);
  const auto result =
    solver.solve(ChainLoad{}, Eigen::Vector3d(3 * a + d, 0, 0), Eigen::VectorXd::Zero(9));
  INFO(result.failure);
  REQUIRE(result.converged);
  CHECK(std::abs(result.contact_force.x() - d / 1e-3) < tolerance * d / 1e-3);
  CHECK(result.contact_force.tail<2>().norm() < tolerance * d / 1e-3);
  CHECK(result.angles.lpNorm<Eigen::Infinity>() < tolerance);
  const Wrench w = base_wrench(model.chain(), solver.pose(),
                               solver.with_contact(ChainLoad{}, result.contact_force), Eigen::Vector3d::Zero());
  CHECK((w.force - result.contact_force).norm() < 1e-15);
  CHECK(w.moment.norm() < tolerance * d / 1e-3 * a);

  // Rigid links: the same target is out of reach along the axis and no
  // force holds it there.
  const ChainModel          rigid_model = model.without_link_compliance();
  TipConstrainedEquilibrium rigid_solver(rigid_model);
  const auto rigid = rigid_solver.solve(ChainLoad{}, Eigen::Vector3d(3 * a + d, 0, 0), Eigen::VectorXd::Zero(9));
  CHECK(std::abs(rigid.contact_force.x()) < 1e-6 * d / 1e-3);
}

TEST_CASE("a single joint with its tip moved across: the joint and the links in series")
{
  // Small displacement d across the link of length L: the tip moves by
  // L^2 / k (joint) + c (links) per newton, f_y = d / (L^2 / k + c) to
  // first order in d / L = 1e-4: the relative error is O(1e-4), checked
  // with a 10x margin.
  const double     a = 0.02, k = 0.03, L = 0.5 * a, d = 1e-4 * L;
  const ChainModel model = compliant_finger(1, a, Eigen::Vector3d(50, 50, k));
  TipConstrainedEquilibrium solver(model);
  const auto result = solver.solve(ChainLoad{}, Eigen::Vector3d(a, d, 0), Eigen::VectorXd::Zero(3));
  INFO(result.failure);
  REQUIRE(result.converged);
  const double f_y = d / (L * L / k + 1e-3);
  CHECK(result.contact_force.y() == Approx(f_y).epsilon(1e-3));
  // Exactly, at the solution: k phi = (r x f)_z with r the rigid link, and
  // the rigid tip plus the links' c f is the target.
  const double          phi = result.angles(2);
  const Eigen::Vector3d r   = solver.pose().tip_position - model.chain().joint_centre(0);
  CHECK(std::abs(k * phi - r.cross(result.contact_force).z()) < tolerance * k * std::abs(phi));
  CHECK((solver.pose().tip_position + 1e-3 * result.contact_force - Eigen::Vector3d(a, d, 0)).norm() <
        tolerance * a);
}

TEST_CASE("the reduction's link compliance file is read, a bad one refused naming file and row")
{
  softchain::testing::ScratchDirectory dir("chain_link_compliance");
  const StiffnessFiles                 files(dir.path().string(), data::RotationMethod::affine_fit, 0.5);
  testing::write_reduction(files, testing::UniformReduction{});
  const Eigen::Vector3d tip(0.09, 0, 0);
  CHECK_FALSE(files.read_model("M2", tip, StiffnessColumn::value, true).has_link_compliance());

  const auto write = [&](const std::string &rows) {
    std::ofstream(files.link_compliance_path()) << "pressure,compliance,samples,chord_angle_deg\n" << rows;
  };
  write("");
  CHECK_FALSE(files.read_model("M2", tip, StiffnessColumn::value, true).has_link_compliance());
  write("0,1e-3,1,0\n4e4,2e-3,1,3\n");
  const ChainModel model = files.read_model("M2", tip, StiffnessColumn::value, true);
  REQUIRE(model.has_link_compliance());
  CHECK(model.link_compliance(2e4) == Approx(1.5e-3).epsilon(1e-14));
  CHECK_FALSE(files.read_model("M2", tip, StiffnessColumn::value, false).has_link_compliance());
  CHECK_FALSE(model.with_rigid_links().has_link_compliance());

  write("0,1e-3,1,0\n4e4,-2e-3,1,3\n");
  try
    {
      files.read_model("M2", tip, StiffnessColumn::value, true);
      FAIL("no error");
    }
  catch (const softchain::data::InputError &e)
    {
      CHECK_THAT(e.what(), Catch::Contains(files.link_compliance_path() + ", row 2") &&
                             Catch::Contains("negative"));
    }
}
