// Forward kinematics of the chain against angle sets whose poses are known by
// hand, and the kinematic Jacobian against finite differences.
#include <softchain/chain/kinematic_chain.h>
#include <softchain/data/joint_angles.h>

#include "uniform_finger.h"

#include <catch2/catch.hpp>

#include <complex>

using namespace softchain::chain;
using softchain::chain::testing::straight_chain;

namespace
{
  // Round-off of a few rotations and sums of O(1) terms, on lengths of O(a).
  constexpr double exact = 1e-14;

  ChainPose pose_of(const KinematicChain &chain, const Eigen::VectorXd &q)
  {
    ChainPose pose = chain.rest_pose();
    chain.update_pose(q, pose);
    return pose;
  }
} // namespace

TEST_CASE("rest angles leave the chain at its reference joints and tip")
{
  const KinematicChain chain = straight_chain(4, 0.01);
  const ChainPose      pose  = pose_of(chain, Eigen::VectorXd::Zero(12));
  for (int i = 0; i < 4; ++i)
    CHECK((pose.joint_positions[i] - chain.joint_centre(i)).norm() < exact);
  CHECK((pose.tip_position - chain.tip()).norm() < exact);
}

TEST_CASE("a single joint rotates the distal link by Rx(psi) Ry(theta) Rz(phi)")
{
  // Link of length 1 along x from the joint at the origin, so the tip is the
  // image of e_x. By hand: Rz(90) e_x = e_y; Ry(90) e_x = -e_z; Rx(90) leaves
  // e_x but maps e_y to e_z; Rx(90) Ry(90) e_x = Rx(90) (-e_z) = e_y; and
  // Rx(90) Ry(90) Rz(90) e_x = Rx(90) Ry(90) e_y = Rx(90) e_y = e_z; the
  // link's y axis is Rx(90) Ry(90) Rz(90) e_y = Rx(90) Ry(90) (-e_x) = Rx(90) e_z = -e_y.
  const KinematicChain chain({Eigen::Vector3d::Zero()}, Eigen::Vector3d::UnitX());
  const double         r = M_PI / 2;
  struct Case
  {
    Eigen::Vector3d angles, tip, link_y;
  };
  const std::vector<Case> cases = {
    {{0, 0, r}, Eigen::Vector3d::UnitY(), -Eigen::Vector3d::UnitX()},
    {{0, r, 0}, -Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitY()},
    {{r, 0, 0}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitZ()},
    {{r, r, 0}, Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()},
    {{r, r, r}, Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitY()}};
  for (const Case &c : cases)
    {
      const ChainPose pose = pose_of(chain, c.angles);
      CHECK((pose.tip_position - c.tip).norm() < exact);
      CHECK((pose.link_rotations[0].col(1) - c.link_y).norm() < exact);
    }
}

TEST_CASE("the chain's link rotations are the data layer's Euler convention")
{
  const KinematicChain chain({Eigen::Vector3d::Zero()}, Eigen::Vector3d::UnitX());
  for (const Eigen::Vector3d &angles : {Eigen::Vector3d(0.3, -0.7, 2.5), Eigen::Vector3d(-2.9, 1.2, -0.4),
                                       Eigen::Vector3d(1.0, 0.0, -3.1)})
    {
      const Eigen::Matrix3d expected =
        softchain::data::rotation_from_angles({angles[0], angles[1], angles[2]});
      CHECK((pose_of(chain, angles).link_rotations[0] - expected).norm() < exact);
    }
}

TEST_CASE("equal principal bending angles give the polygon of the closed form")
{
  // Joints at x = (i + 1/2) a, joint 0 fixed; with phi = beta at every joint,
  // link m (length a, the last one a/2) points at angle (m + 1) beta, so in
  // the complex plane c_k = c_0 + a sum_{m=1..k} e^{i m beta}
  //                        = c_0 + a e^{i beta} (e^{i k beta} - 1) / (e^{i beta} - 1).
  const int            n = 9;
  const double         a = 0.01, beta = 25.0 * M_PI / 180.0; // 225 deg in total
  const KinematicChain chain = straight_chain(n, a);
  Eigen::VectorXd      q     = Eigen::VectorXd::Zero(3 * n);
  for (int i = 0; i < n; ++i)
    q[3 * i + 2] = beta;
  const ChainPose           pose = pose_of(chain, q);
  const std::complex<double> turn = std::polar(1.0, beta);
  for (int k = 0; k < n; ++k)
    {
      const std::complex<double> c =
        0.5 * a + a * turn * (std::pow(turn, k) - 1.0) / (turn - 1.0);
      CHECK(std::abs(pose.joint_positions[k].x() - c.real()) < exact);
      CHECK(std::abs(pose.joint_positions[k].y() - c.imag()) < exact);
    }
  const std::complex<double> tip =
    0.5 * a + a * turn * (std::pow(turn, n - 1) - 1.0) / (turn - 1.0) + 0.5 * a * std::pow(turn, n);
  CHECK(std::abs(pose.tip_position.x() - tip.real()) < exact);
  CHECK(std::abs(pose.tip_position.y() - tip.imag()) < exact);
}

TEST_CASE("the joint axes give the derivative of the tip, checked by central differences")
{
  // d tip / d q_{i,alpha} = a_{i,alpha} x (tip - c_i). Central differences
  // with step h err by h^2/6 |d3 tip| (<= h^2 L / 6 with L = 0.1 m: 1.7e-12
  // for h = 1e-5) plus round-off eps L / h (1e-12); 1e-10 bounds both.
  const KinematicChain chain = straight_chain(5, 0.02);
  Eigen::VectorXd      q(15);
  for (int j = 0; j < 15; ++j)
    q[j] = 0.3 * std::sin(1.7 * j + 0.4); // a generic angle set
  const ChainPose pose = pose_of(chain, q);
  const double    h    = 1e-5;
  for (int j = 0; j < 15; ++j)
    {
      Eigen::VectorXd plus = q, minus = q;
      plus[j] += h;
      minus[j] -= h;
      const Eigen::Vector3d difference =
        (pose_of(chain, plus).tip_position - pose_of(chain, minus).tip_position) / (2 * h);
      const Eigen::Vector3d analytic = pose.joint_axes[j / 3].col(j % 3).cross(
        pose.tip_position - pose.joint_positions[j / 3]);
      CHECK((difference - analytic).norm() < 1e-10);
    }
}

TEST_CASE("material points belong to the link after the last joint before them")
{
  const KinematicChain chain = straight_chain(3, 0.01); // joints at 5, 15, 25 mm
  CHECK(chain.link_of({0.004, 0, 0}) == -1);
  CHECK(chain.link_of({0.005, 0, 0}) == 0);
  CHECK(chain.link_of({0.0149, 0, 0}) == 0);
  CHECK(chain.link_of({0.02, 0, 0}) == 1);
  CHECK(chain.link_of({0.03, 0, 0}) == 2);
  CHECK_THROWS_AS(KinematicChain({{0.01, 0, 0}, {0.01, 0, 0}}, {0.02, 0, 0}), std::invalid_argument);
}
