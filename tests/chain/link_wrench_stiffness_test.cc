// LinkWrenchStiffness against rows of the chain's own kinematics: the
// motion of a material point of a link along a direction, differentiated
// by central differences of KinematicChain::update_pose, with twist pivots
// off the joint centres so that psi's pivot is exercised.
#include <softchain/chain/link_wrench_stiffness.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace softchain::chain;

namespace
{
  // e . dx/dq of the point L (link frame) of `link`, by central differences.
  Eigen::VectorXd row_by_differences(const KinematicChain &chain, const Eigen::VectorXd &q, const int link,
                                     const Eigen::Vector3d &L, const Eigen::Vector3d &e)
  {
    const double    h = 1e-6;
    Eigen::VectorXd row(q.size());
    ChainPose       pose = chain.rest_pose();
    for (Eigen::Index i = 0; i < q.size(); ++i)
      {
        Eigen::Vector3d x[2];
        for (const int side : {0, 1})
          {
            Eigen::VectorXd moved = q;
            moved[i] += side == 0 ? h : -h;
            chain.update_pose(moved, pose);
            x[side] = pose.joint_positions[link] + pose.link_rotations[link] * L;
          }
        row[i] = e.dot(x[0] - x[1]) / (2 * h);
      }
    return row;
  }
} // namespace

TEST_CASE("a link's rows and forces, gathered per link, equal the chain's point rows")
{
  const int n = 4;
  std::vector<Eigen::Vector3d> centres, offsets;
  for (int i = 0; i < n; ++i)
    {
      centres.emplace_back(0.02 * i, 0.0, 0.0);
      offsets.emplace_back(0.0, 0.004 + 0.001 * i, -0.002);
    }
  const KinematicChain chain = KinematicChain(centres, {0.02 * n, 0.0, 0.0}).with_twist_offsets(offsets);
  Eigen::VectorXd      q(3 * n);
  for (int i = 0; i < 3 * n; ++i)
    q[i] = 0.3 * std::sin(1.0 + 2.0 * i);
  ChainPose pose = chain.rest_pose();
  chain.update_pose(q, pose);

  // Rows on links 1 and 3 (none on 0 and 2), weights of both signs.
  struct Row
  {
    int             link;
    Eigen::Vector3d L, e;
    double          weight, force;
  };
  const std::vector<Row> rows{{1, {0.01, -0.003, 0.002}, {0.0, 1.0, 0.0}, 2.0, 0.5},
                              {1, {0.004, 0.005, -0.001}, Eigen::Vector3d(1, 2, -1).normalized(), -0.7, -1.5},
                              {3, {0.02, 0.0, 0.003}, Eigen::Vector3d(0.3, -1, 0.2).normalized(), 1.3, 2.0}};
  LinkWrenchStiffness links;
  links.reset(n);
  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  Eigen::VectorXd expected_force = Eigen::VectorXd::Zero(3 * n);
  for (const Row &r : rows)
    {
      const Eigen::Vector3d x = pose.joint_positions[r.link] + pose.link_rotations[r.link] * r.L;
      const Eigen::VectorXd v = row_by_differences(chain, q, r.link, r.L, r.e);
      expected += r.weight * v * v.transpose();
      expected_force += r.force * v;
      links.add_row(r.link, LinkWrenchStiffness::point_row(x, r.e), r.weight);
      links.add_force(r.link, LinkWrenchStiffness::point_row(x, r.e), r.force);
    }
  // Central differences of a smooth map err by h^2 |x'''| / 6 + eps |x| / h,
  // ~1e-10 of the rows here.
  const double tolerance = 1e-8 * expected.lpNorm<Eigen::Infinity>();
  Eigen::MatrixXd whole = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  links.add_to(pose, whole);
  CHECK((whole - expected).lpNorm<Eigen::Infinity>() < tolerance);
  CHECK(whole.isApprox(whole.transpose(), 1e-14));
  Eigen::MatrixXd lower = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  links.add_to_lower(pose, lower);
  const Eigen::MatrixXd lower_expected = expected.triangularView<Eigen::Lower>();
  const Eigen::MatrixXd lower_got      = lower.triangularView<Eigen::Lower>();
  CHECK((lower_got - lower_expected).lpNorm<Eigen::Infinity>() < tolerance);
  Eigen::VectorXd force = Eigen::VectorXd::Zero(3 * n);
  links.add_generalised_force(pose, force);
  CHECK((force - expected_force).lpNorm<Eigen::Infinity>() < 1e-8 * expected_force.lpNorm<Eigen::Infinity>());
  // reset leaves nothing.
  links.reset(n);
  Eigen::MatrixXd none = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  links.add_to(pose, none);
  CHECK(none.isZero(0.0));
}
