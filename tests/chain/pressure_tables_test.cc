// PressureTables: the chain's K(p), J_p(p) and link geometry U(p) sampled
// at the union of their tables' pressures reproduce the chain between them,
// the MJCF's <custom> layout, and rows that do not fit.
#include <softchain/chain/pressure_tables.h>

#include "../data/occurrences.h"
#include "tapered_finger.h"

#include <catch2/catch.hpp>

using namespace softchain::chain;
using namespace softchain::chain::testing;

TEST_CASE("The pressure tables are sampled at the union of the chain's table pressures up to the top")
{
  const ChainModel model = tapered_finger_in_pressure(5e4);
  // k_phi and U tabulated at 0 and 5e4, J_p at 0, 2e4 and 5e4.
  CHECK(PressureTables::of_model(model, 5e4).pressures() == std::vector<double>{0, 2e4, 5e4});
  CHECK(PressureTables::of_model(model, 3e4).pressures() == std::vector<double>{0, 2e4, 3e4});
  CHECK(PressureTables::of_model(model, 0).pressures() == std::vector<double>{0});
  CHECK(PressureTables::of_model(tapered_finger(), 5e4).pressures() == std::vector<double>{0, 5e4});
}

TEST_CASE("Interpolated in pressure, the tables are the chain's K(p), J_p(p) and U(p)")
{
  const ChainModel     model  = tapered_finger_in_pressure(5e4);
  const PressureTables tables = PressureTables::of_model(model, 5e4);
  // To rounding: a few ulps of k ~ 0.2 N m/rad, J_p ~ 3e-7 N m/Pa, U ~ 0.09 m
  // (the tables split the chain's intervals at the other tables' pressures).
  for (const double p : {0.0, 7e3, 2e4, 3.3e4, 5e4})
    {
      INFO("pressure " << p << " Pa");
      CHECK((tables.stiffness(p) - model.stiffness().diagonal(p)).cwiseAbs().maxCoeff() < 1e-15);
      CHECK((tables.torque_per_pascal(p) - model.actuation().torque_per_pascal(p)).cwiseAbs().maxCoeff() < 1e-21);
      const KinematicChain  links  = model.chain_at(p);
      const Eigen::VectorXd points = tables.link_points(p);
      for (int i = 0; i < 9; ++i)
        CHECK((points.segment<3>(3 * i) - links.link_joint(i)).norm() < 1e-16);
      CHECK((points.tail<3>() - links.link_tip()).norm() < 1e-16);
    }
  CHECK_THROWS_AS(tables.stiffness(5.1e4), std::out_of_range);
}

TEST_CASE("The MJCF's custom element holds one numeric field per table, row after row")
{
  const std::string xml = PressureTables::of_model(tapered_finger_in_pressure(5e4), 5e4).mjcf("  ");
  CHECK(xml.find("  <custom>\n    <numeric name=\"softchain_pressure\" data=\"0 20000 50000\"/>\n") == 0);
  CHECK(softchain::testing::occurrences(xml, "<numeric name=") == 4);
  // 3 pressures x 27 hinges: 81 values, the first row k_psi, k_theta, k_phi of joint 1 at 0 Pa.
  const auto stiffness = xml.find("softchain_stiffness\" data=\"");
  CHECK(xml.substr(stiffness + 27, 16) == "0.20000000000000");
  const std::string link_points = xml.substr(xml.find("softchain_link_points"));
  CHECK(softchain::testing::occurrences(link_points.substr(0, link_points.find("/>")), " ") == 3 * 30);
}

TEST_CASE("Tables with pressures not increasing from 0 or rows of the wrong length are rejected")
{
  const PressureTables::Rows k = PressureTables::Rows::Ones(2, 3), points = PressureTables::Rows::Zero(2, 6);
  CHECK_NOTHROW(PressureTables({0, 1e4}, k, k, points));
  CHECK_THROWS_WITH(PressureTables({1e3, 1e4}, k, k, points), Catch::Contains("start at 0"));
  CHECK_THROWS_WITH(PressureTables({0, 0}, k, k, points), Catch::Contains("increase strictly"));
  CHECK_THROWS_WITH(PressureTables({0, 1e4}, k, k, PressureTables::Rows::Zero(2, 3)),
                    Catch::Contains("one row per pressure"));
  CHECK_THROWS_WITH(PressureTables({0, 1e4}, k, PressureTables::Rows::Constant(2, 3, NAN), points),
                    Catch::Contains("not finite"));
}
