// Links shaped by the pressure (KinematicChain::with_link_geometry,
// LinkGeometry, the reduction's _link_geometry.csv): closed-form forward
// kinematics, material points carried along stretched links, the
// equilibrium's tangent on such a chain, and the file's checks.
#include <softchain/chain/chain_equilibrium.h>
#include <softchain/chain/link_geometry.h>
#include <softchain/chain/stiffness_files.h>
#include <softchain/data/input_error.h>

#include "../data/scratch_directory.h"
#include "central_differences.h"
#include "reduction_output.h"
#include "uniform_finger.h"

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

using namespace softchain::chain;
namespace data = softchain::data;

namespace
{
  constexpr double a = 0.01;

  Eigen::Matrix3d rz(const double angle)
  {
    return Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  }

  // Two joints at 5 and 15 mm, tip at 20 mm; under pressure the links
  // stretch, the first shears down, and the tip frame turns by 0.1 rad.
  KinematicChain two_links()
  {
    return KinematicChain({{0.005, 0, 0}, {0.015, 0, 0}}, {0.02, 0, 0});
  }
  const std::vector<Eigen::Vector3d> U = {{0.0052, 0.0003, 0}, {0.0155, -0.0008, 0.0001}};
  const Eigen::Vector3d              U_T(0.0212, -0.0007, 0.0002);

  PiecewiseLinear line(const double at_rest, const double at_p1, const double p1)
  {
    return PiecewiseLinear({0.0, p1}, {at_rest, at_p1});
  }
} // namespace

TEST_CASE("a chain with link geometry: closed-form joints, tip and tip frame")
{
  const KinematicChain chain = two_links().with_link_geometry(U, U_T, rz(0.1));
  ChainPose            pose  = chain.rest_pose();
  CHECK(pose.joint_positions[0] == U[0]);
  CHECK(pose.tip_position == U_T);
  Eigen::VectorXd q(6);
  q << 0, 0, 0.3, 0, 0, -0.2;
  chain.update_pose(q, pose);
  const Eigen::Vector3d c1  = U[0] + rz(0.3) * (U[1] - U[0]);
  const Eigen::Vector3d tip = c1 + rz(0.1) * (U_T - U[1]);
  // One or two products of O(1e-2) m: round-off.
  CHECK((pose.joint_positions[1] - c1).norm() < 1e-17);
  CHECK((pose.tip_position - tip).norm() < 1e-17);
  CHECK((pose.tip_rotation - rz(0.2)).norm() < 1e-15);
  // Material points move with their link, stretched linearly along it: the
  // reference tip to the chain's tip, the middle of link 1 to the middle of
  // its chord, a point on the base not at all.
  CHECK((chain.point_position(pose, 1, chain.tip()) - tip).norm() < 1e-17);
  const Eigen::Vector3d middle = 0.5 * (chain.joint_centre(0) + chain.joint_centre(1)) + Eigen::Vector3d(0, 0.002, 0);
  CHECK((chain.point_position(pose, 0, middle) -
         (U[0] + rz(0.3) * (0.5 * (U[1] - U[0]) + Eigen::Vector3d(0, 0.002, 0))))
          .norm() < 1e-17);
  CHECK(chain.point_position(pose, -1, Eigen::Vector3d(0.001, 0, 0)) == Eigen::Vector3d(0.001, 0, 0));
  // Out of order along x: not a chain.
  CHECK_THROWS_AS(two_links().with_link_geometry({U[1], U[0]}, U_T, rz(0)), std::invalid_argument);
  CHECK_THROWS_AS(two_links().with_link_geometry({U[0]}, U_T, rz(0)), std::invalid_argument);
}

TEST_CASE("LinkGeometry interpolates in pressure, holds beyond, and carries the twist pivots")
{
  const double                                p1 = 4e4;
  std::vector<LinkGeometry::PointInPressure> joints;
  for (int i = 0; i < 2; ++i)
    joints.push_back({line(two_links().joint_centre(i).x(), U[i].x(), p1), line(0, U[i].y(), p1),
                      line(0, U[i].z(), p1)});
  const LinkGeometry geometry(joints, {line(0.02, U_T.x(), p1), line(0, U_T.y(), p1), line(0, U_T.z(), p1)},
                              {line(0, 0, p1), line(0, 0, p1), line(0, 0.1, p1)});
  const KinematicChain half = geometry.at(0.5 * p1, two_links());
  CHECK((half.link_joint(1) - 0.5 * (two_links().joint_centre(1) + U[1])).norm() < 1e-17);
  CHECK((geometry.at(2 * p1, two_links()).link_tip() - U_T).norm() == 0.0);
  CHECK((geometry.at(0, two_links()).link_tip() - two_links().tip()).norm() == 0.0);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(6);
  ChainPose       pose = half.rest_pose();
  half.update_pose(q, pose);
  CHECK((pose.tip_rotation - rz(0.05)).norm() < 1e-15);
  // A twist axis 5 mm above each joint rides with its joint.
  const Eigen::Vector3d up(0, 0.005, 0);
  const KinematicChain  twisted = geometry.at(p1, two_links().with_twist_offsets({up, up}));
  ChainPose             rest    = twisted.rest_pose();
  CHECK((rest.twist_pivots[1] - (U[1] + up)).norm() < 1e-17);
  CHECK(rest.joint_positions[1] == U[1]);
}

TEST_CASE("the equilibrium on stretched links: closed form under pressure, exact tangent under forces")
{
  const KinematicChain reference = testing::straight_chain(4, a);
  std::vector<Eigen::Vector3d> stretched;
  for (int i = 0; i < 4; ++i)
    stretched.push_back(reference.joint_centre(i) * 1.03 + Eigen::Vector3d(0, -0.0002 * i, 0.0001));
  const Eigen::Vector3d tip = reference.tip() * 1.03 + Eigen::Vector3d(0, -0.001, 0);
  std::vector<LinkGeometry::PointInPressure> joints;
  for (const auto &u : stretched)
    joints.push_back({PiecewiseLinear({0.0}, {u.x()}), PiecewiseLinear({0.0}, {u.y()}),
                      PiecewiseLinear({0.0}, {u.z()})});
  ChainModel model("stretched", reference, JointStiffness(std::vector<Eigen::Vector3d>(4, {0.03, 0.01, 0.02})),
                   PressureActuation(Eigen::Vector3d(0, 0, 1e-7).replicate(4, 1)));
  model.set_link_geometry(LinkGeometry(
    joints, {PiecewiseLinear({0.0}, {tip.x()}), PiecewiseLinear({0.0}, {tip.y()}), PiecewiseLinear({0.0}, {tip.z()})},
    {PiecewiseLinear({0.0}, {0}), PiecewiseLinear({0.0}, {0}), PiecewiseLinear({0.0}, {0})}));
  {
    // Pressure alone: phi = J_p p / k at every joint, the tip where the
    // stretched links put it.
    ChainEquilibrium  solver(model);
    const Equilibrium e = solver.solve({4e4, {}});
    REQUIRE(e.converged);
    const double    phi = 1e-7 * 4e4 / 0.02;
    Eigen::Vector3d c   = stretched[0];
    for (int i = 0; i < 4; ++i)
      c += rz((i + 1) * phi) * ((i + 1 < 4 ? stretched[i + 1] : tip) - stretched[i]);
    CHECK((solver.pose().tip_position - c).norm() < 1e-15);
  }
  // The tangent against central differences (the error model of
  // chain_equilibrium_test.cc: 1e-8 of |H|), forces inside and at the end
  // of stretched links.
  ChainEquilibrium solver(model);
  solver.set_load({4e4, {{{0.012, 0.002, -0.001}, {0.2, -1.0, 0.3}}, {{0.04, 0.0, 0.004}, {-0.5, 0.1, 0.8}}}});
  Eigen::VectorXd q(12);
  for (int j = 0; j < q.size(); ++j)
    q[j] = 0.4 * std::sin(2.3 * j + 1.0);
  const Eigen::MatrixXd tangent    = solver.tangent(q);
  const Eigen::MatrixXd difference = testing::central_differences(solver, q, 1e-5);
  CHECK((tangent - difference).cwiseAbs().maxCoeff() < 1e-8 * tangent.cwiseAbs().maxCoeff());
}

TEST_CASE("the link geometry file: read with the pressure tables, its rest rows checked")
{
  softchain::testing::ScratchDirectory dir("chain_link_geometry");
  const StiffnessFiles                 files(dir.path().string(), data::RotationMethod::affine_fit, 0.5);
  const testing::UniformReduction      r;
  testing::write_reduction(files, r);
  const Eigen::Vector3d tip(r.n * r.a, 0, 0);
  const auto write = [&](const double rest_shift, const double joint3_shift = 0.0, const bool tip_row = true) {
    softchain::data::CsvTable table({"pressure", "point", "x", "y", "z", "rx", "ry", "rz"});
    for (const double p : {0.0, r.p_max})
      for (int i = 0; i <= r.n; ++i)
        {
          const double stretch = p > 0 ? 1.02 : 1.0;
          const double x = (i < r.n ? (i + 0.5) * r.a : r.n * r.a) * stretch + (p > 0 ? 0 : rest_shift) +
                           (p > 0 && i == 2 ? joint3_shift : 0.0);
          if (i == r.n && p > 0 && !tip_row)
            continue;
          table.add_row({softchain::data::CsvTable::cell(p), i < r.n ? std::to_string(i + 1) : "tip",
                         softchain::data::CsvTable::cell(x), "0", "0", "0", "0",
                         i < r.n || p == 0 ? "0" : "0.02"});
        }
    table.write(files.link_geometry_path());
  };
  write(0.0);
  const ChainModel model = files.read_model("M2", tip, StiffnessColumn::value, true);
  REQUIRE(model.has_link_geometry());
  CHECK(model.chain_at(0.5 * r.p_max).link_tip().x() == Approx(1.01 * r.n * r.a).epsilon(1e-15));
  CHECK(model.with_rigid_links().chain_at(r.p_max).link_tip() == tip);
  // Without the pressure tables the links are the reference's.
  CHECK_FALSE(files.read_model("M2", tip, StiffnessColumn::value, false).has_link_geometry());
  // Rest rows that are not the stiffness table's joints: another reduction's.
  write(1e-4);
  CHECK_THROWS_WITH(files.read_model("M2", tip, StiffnessColumn::value, true),
                    Catch::Contains(files.link_geometry_path()) && Catch::Contains("joint 1") &&
                      Catch::Contains("different reductions"));
  // Joints out of order along x at a pressure: the chain would fold back.
  write(0.0, -0.015);
  CHECK_THROWS_WITH(files.read_model("M2", tip, StiffnessColumn::value, true),
                    Catch::Contains(files.link_geometry_path()) && Catch::Contains("at pressure 80000") &&
                      Catch::Contains("joint 3 does not lie beyond joint 2"));
  // A pressure without the tip's row.
  write(0.0, 0.0, false);
  CHECK_THROWS_WITH(files.read_model("M2", tip, StiffnessColumn::value, true),
                    Catch::Contains("no row for the tip at pressure 80000"));
  // Without the file (a reduction before link geometry): rigid links.
  std::filesystem::remove(files.link_geometry_path());
  CHECK_FALSE(files.read_model("M2", tip, StiffnessColumn::value, true).has_link_geometry());
}
