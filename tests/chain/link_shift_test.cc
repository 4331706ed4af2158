// Links that shift as their joint turns in the plane (LinkShiftPerTurn,
// KinematicChain::assign_link_shift): the pose against its closed form, the
// pressure-only state unchanged, and the equilibrium's residual and exact
// tangent against central differences of its energy and residual.
#include <softchain/chain/chain_equilibrium.h>
#include <softchain/chain/stiffness_files.h>
#include <softchain/data/input_error.h>

#include "../data/scratch_directory.h"
#include "central_differences.h"
#include "reduction_output.h"

#include <catch2/catch.hpp>

#include <fstream>

using namespace softchain::chain;

namespace
{
  constexpr int n = 5;

  std::vector<Eigen::Vector3d> centres()
  {
    std::vector<Eigen::Vector3d> c;
    for (int i = 0; i < n; ++i)
      c.emplace_back((i + 0.5) * 0.01, 0.0, 0.0);
    return c;
  }

  // g_i = (2 + i, 3 - 2 i, 0) mm/rad, the same at every pressure.
  LinkShiftPerTurn shifts()
  {
    std::vector<LinkShiftPerTurn::ShiftInPressure> links;
    for (int i = 0; i < n; ++i)
      links.push_back({PiecewiseLinear({0.0}, {1e-3 * (2 + i)}), PiecewiseLinear({0.0}, {1e-3 * (3 - 2 * i)})});
    return LinkShiftPerTurn(std::move(links));
  }

  Eigen::VectorXd angles()
  {
    Eigen::VectorXd q(3 * n);
    for (int j = 0; j < q.size(); ++j)
      q[j] = 0.4 * std::sin(2.3 * j + 1.0);
    return q;
  }
} // namespace

TEST_CASE("a joint's in-plane turn shifts its link by R_i g_i (phi_i - phi_i^p)")
{
  const KinematicChain rigid(centres(), {0.05, 0.004, 0});
  KinematicChain       shifted = rigid;
  const LinkShiftPerTurn g     = shifts();
  const Eigen::VectorXd  q     = angles();
  // About the angles q themselves: no turn, no shift.
  shifted.assign_link_shift([&](const int i) { return g.at(0.0, i); }, [&](const int i) { return q[3 * i + 2]; });
  ChainPose a = rigid.rest_pose(), b = shifted.rest_pose();
  rigid.update_pose(q, a);
  shifted.update_pose(q, b);
  CHECK((a.tip_position - b.tip_position).norm() <= 1e-15);
  // About phi^p = phi - 0.1 rad at joint 2 only: link 2 and everything
  // distal move by R_2 g_2 0.1, joint 2 itself does not (round-off only).
  shifted.assign_link_shift([&](const int i) { return i == 2 ? g.at(0.0, i) : Eigen::Vector3d::Zero(); },
                            [&](const int i) { return q[3 * i + 2] - (i == 2 ? 0.1 : 0.0); });
  shifted.update_pose(q, b);
  const Eigen::Vector3d moved = a.link_rotations[2] * g.at(0.0, 2) * 0.1;
  CHECK((b.joint_positions[2] - a.joint_positions[2]).norm() <= 1e-15);
  CHECK((b.link_origins[2] - a.joint_positions[2] - moved).norm() <= 1e-15);
  for (int i = 3; i < n; ++i)
    CHECK((b.joint_positions[i] - a.joint_positions[i] - moved).norm() <= 1e-15);
  CHECK((b.tip_position - a.tip_position - moved).norm() <= 1e-15);
  const Eigen::Vector3d X(0.028, 0.002, 0.001); // a point of link 2
  CHECK((shifted.point_position(b, 2, X) - rigid.point_position(a, 2, X) - moved).norm() <= 1e-15);
  // The rolling pivot: phi_2 turns the tip about c_2 + a_phi x R_2 g_2, so
  // the tip's central difference in phi_2 (h = 1e-6, error h^2 |x'''| ~ 1e-14 m)
  // is a_phi x (tip - pivot).
  Eigen::VectorXd plus = q, minus = q;
  plus[8] += 1e-6;
  minus[8] -= 1e-6;
  ChainPose p = b, m = b;
  shifted.update_pose(plus, p);
  shifted.update_pose(minus, m);
  const Eigen::Vector3d rate = (p.tip_position - m.tip_position) / 2e-6;
  CHECK((rate - b.joint_axes[2].col(2).cross(b.tip_position - b.pivot(2, 2))).norm() <= 1e-9);
  CHECK((b.pivot(2, 2) - b.joint_positions[2]).norm() == Approx(g.at(0.0, 2).norm()).epsilon(1e-12));
}

TEST_CASE("a shift per turn out of the link's plane or not finite is refused")
{
  KinematicChain chain(centres(), {0.05, 0.004, 0});
  CHECK_THROWS_WITH(chain.assign_link_shift([](int) { return Eigen::Vector3d(0, 0, 1e-3); }, [](int) { return 0.0; }),
                    Catch::Contains("joint 1's link shift must be finite and in the link's x-y plane"));
  CHECK_THROWS_AS(LinkShiftPerTurn({{PiecewiseLinear({0.0}, {NAN}), PiecewiseLinear({0.0}, {0.0})}}),
                  std::invalid_argument);
}

TEST_CASE("with links that shift the tangent is exact and the residual is the energy's gradient")
{
  // The twist_joint_test.cc case (soft joints, 1 N forces at and between the
  // joints, angles up to 0.4 rad, twist axes above and below the joints)
  // with every link shifting 2-6 mm/rad: central differences with h = 1e-5
  // err by 1e-8 of |H| (tangent) and of |r| (gradient).
  std::vector<Eigen::Vector3d> offsets;
  for (int i = 0; i < n; ++i)
    offsets.emplace_back(0.0, (i % 2 ? -1.0 : 1.0) * (0.003 + 0.0015 * i), 0.001 * i);
  ChainModel model("shifting links", KinematicChain(centres(), {0.05, 0.004, 0}).with_twist_offsets(offsets),
                   JointStiffness(std::vector<Eigen::Vector3d>(n, {0.03, 0.01, 0.02})),
                   PressureActuation(Eigen::Vector3d(0.01, -0.02, 0.05).replicate(n, 1)));
  model.set_link_shift(shifts());
  ChainEquilibrium solver(model);
  const ChainLoad  load{0.5,
                       {{{0.022, 0.002, -0.001}, {0.2, -1.0, 0.3}},
                        {{0.05, 0.004, 0.0}, {-0.5, 0.1, 0.8}},
                        {{0.037, -0.003, 0.002}, {0.0, 0.7, -0.6}}}};
  solver.set_load(load);
  const Eigen::VectorXd q = angles();
  const Eigen::MatrixXd tangent = solver.tangent(q);
  const auto            errors  = testing::derivative_errors(solver, q, 1e-5);
  CHECK(errors.tangent < 1e-8);
  CHECK(errors.gradient < 1e-8);
  // The shifts matter: without them the tangent differs.
  ChainEquilibrium rigid(model.without_link_shift());
  rigid.set_load(load);
  CHECK((rigid.tangent(q) - tangent).cwiseAbs().maxCoeff() > 1e-3 * tangent.cwiseAbs().maxCoeff());
  // The pressure-only state K q = J_p p is still the answer without forces.
  const Equilibrium free = solver.solve({0.5, {}});
  REQUIRE(free.converged);
  CHECK(free.iterations == 0);
}

TEST_CASE("the reduction's link shift file is read, a bad one refused naming file and row")
{
  softchain::testing::ScratchDirectory dir("chain_link_shift");
  const StiffnessFiles files(dir.path().string(), softchain::data::RotationMethod::affine_fit, 0.5);
  testing::UniformReduction reduction;
  reduction.n = 2;
  testing::write_reduction(files, reduction);
  const Eigen::Vector3d tip(0.03, 0, 0);
  const auto            write = [&](const std::string &rows) {
    std::ofstream(files.link_shift_path()) << "pressure,link,shift_x,shift_y,turn_rms,samples\n" << rows;
  };
  const auto error = [&]() -> std::string {
    try
      {
        files.read_model("M2", tip, StiffnessColumn::value, true);
      }
    catch (const softchain::data::InputError &e)
      {
        return e.what();
      }
    return "no error";
  };
  // A table without rows (a design without in-plane force samples) is no shift.
  write("");
  CHECK(error() == "no error");
  // A table is read, but shifts move the links of a link geometry: without
  // one (these files have none) the chain has no shift.
  write("0,1,0,0,0,1\n0,2,0,0,0,1\n2e4,1,1e-3,2e-3,0.1,1\n2e4,2,3e-3,-1e-3,0.1,1\n");
  CHECK(error() == "no error");
  CHECK_FALSE(files.read_model("M2", tip, StiffnessColumn::value, true).has_link_shift());
  write("0,1,0,0,0,1\n0,3,0,0,0,1\n");
  CHECK_THAT(error(), Catch::Contains(files.link_shift_path() + ", row 2") && Catch::Contains("link 3 is not one of 1..2"));
  write("0,1,0,0,0,1\n0,1,1e-3,0,0,1\n0,2,0,0,0,1\n");
  CHECK_THAT(error(), Catch::Contains(files.link_shift_path() + ", row 2") && Catch::Contains("listed twice"));
  write("0,1,0,0,0,1\n");
  CHECK_THAT(error(), Catch::Contains(files.link_shift_path()) && Catch::Contains("no row for link 2"));
  write("0,1,nan,0,0,1\n0,2,0,0,0,1\n");
  CHECK_THAT(error(), Catch::Contains(files.link_shift_path() + ", row 1"));
}
