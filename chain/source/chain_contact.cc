#include <softchain/chain/chain_contact.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <stdexcept>

namespace softchain::chain
{
  void ChainContact::set(const CollisionSurface *surface, const double pressure,
                         const std::vector<data::ObstacleRecord> &obstacles, const double stiffness)
  {
    obstacles_.clear();
    poses_.clear();
    touches_.clear();
    surface_   = surface;
    stiffness_ = stiffness;
    if (obstacles.empty())
      return;
    if (surface == nullptr)
      throw std::invalid_argument("chain contact: the model has no collision surface for obstacle '" +
                                  obstacles.front().name + "'");
    if (!(stiffness > 0.0) || !std::isfinite(stiffness))
      throw std::invalid_argument("chain contact: the contact stiffness must be positive and finite");
    for (const data::ObstacleRecord &record : obstacles)
      {
        if (record.friction != 0.0)
          throw std::invalid_argument("chain contact: obstacle '" + record.name + "' has friction " +
                                      std::to_string(record.friction) +
                                      "; the chain's contact is frictionless");
        obstacles_.emplace_back(record);
        poses_.push_back(obstacles_.back().pose(1.0));
      }
    surface->offsets_at(pressure, offsets_);
  }

  // The touches are the points inside an obstacle: g < 0.
  double ChainContact::update(const ChainPose &pose)
  {
    candidates(pose, 0.0, touches_);
    double energy = 0.0;
    for (const Touch &touch : touches_)
      energy += 0.5 * stiffness_ * touch.gap * touch.gap;
    return energy;
  }

  void ChainContact::jacobian_row(const ChainPose &pose, const Touch &touch, const Eigen::Vector3d &e,
                                  Eigen::Ref<Eigen::RowVectorXd, 0, Eigen::InnerStride<>> row) const
  {
    row.setZero();
    for (int i = 0; i <= touch.link; ++i)
      for (int alpha = 0; alpha < 3; ++alpha)
        {
          const Eigen::Vector3d &pivot = alpha == 0 ? pose.twist_pivots[i] : pose.joint_positions[i];
          row[3 * i + alpha] = pose.joint_axes[i].col(alpha).dot((touch.position - pivot).cross(e));
        }
  }

  // The normal row (weight k_c) if `normal`, and each eigenvector e of H_g
  // with eigenvalue mu != 0 (a round obstacle's 1/radius) with weight
  // k_c g mu.
  void ChainContact::append_rows(const Touch &touch, const bool normal,
                                 std::vector<std::pair<Eigen::Vector3d, double>> &directions) const
  {
    if (normal)
      directions.emplace_back(touch.normal, stiffness_);
    if (touch.curvature.isZero())
      return;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
    eigen.computeDirect(touch.curvature);
    const double largest = eigen.eigenvalues().cwiseAbs().maxCoeff();
    for (int i = 0; i < 3; ++i)
      if (std::abs(eigen.eigenvalues()[i]) > 1e-9 * largest)
        directions.emplace_back(eigen.eigenvectors().col(i), stiffness_ * touch.gap * eigen.eigenvalues()[i]);
  }

  void ChainContact::fill_rows(const ChainPose &pose,
                               const std::vector<std::pair<Eigen::Vector3d, double>> &directions,
                               const std::vector<int> &owner, const int n_angles, Eigen::MatrixXd &rows,
                               Eigen::VectorXd &weights) const
  {
    rows.resize(static_cast<Eigen::Index>(directions.size()), n_angles);
    weights.resize(static_cast<Eigen::Index>(directions.size()));
    for (std::size_t r = 0; r < directions.size(); ++r)
      {
        jacobian_row(pose, touches_[owner[r]], directions[r].first, rows.row(r));
        weights[r] = directions[r].second;
      }
  }

  void ChainContact::tangent_rows(const ChainPose &pose, const int n_angles, Eigen::MatrixXd &rows,
                                  Eigen::VectorXd &weights) const
  {
    rows_of_touches(pose, true, n_angles, rows, weights);
  }

  void ChainContact::curvature_rows(const ChainPose &pose, const int n_angles, Eigen::MatrixXd &rows,
                                    Eigen::VectorXd &weights) const
  {
    rows_of_touches(pose, false, n_angles, rows, weights);
  }

  void ChainContact::rows_of_touches(const ChainPose &pose, const bool normals, const int n_angles,
                                     Eigen::MatrixXd &rows, Eigen::VectorXd &weights) const
  {
    std::vector<std::pair<Eigen::Vector3d, double>> directions;
    std::vector<int>                                owner;
    for (std::size_t t = 0; t < touches_.size(); ++t)
      {
        append_rows(touches_[t], normals, directions);
        owner.resize(directions.size(), static_cast<int>(t));
      }
    fill_rows(pose, directions, owner, n_angles, rows, weights);
  }

  // Cluster by cluster (CollisionSurface), so that the points come sorted
  // by link; a cluster whose bounding sphere lies farther than `margin`
  // from an obstacle (g(centre) > radius + margin, g being 1-Lipschitz) has
  // no point within it. A point inside (g < 0) carries f = -k_c g n.
  void ChainContact::candidates(const ChainPose &pose, const double margin, std::vector<Touch> &near) const
  {
    near.clear();
    if (obstacles_.empty())
      return;
    for (const CollisionSurface::Cluster &cluster : surface_->clusters())
      {
        const Eigen::Matrix3d &R      = pose.link_rotations[cluster.link];
        const Eigen::Vector3d &c      = pose.joint_positions[cluster.link];
        const Eigen::Vector3d  centre = c + R * cluster.centre;
        for (std::size_t o = 0; o < obstacles_.size(); ++o)
          {
            const geometry::Obstacle &obstacle = obstacles_[o];
            if (obstacle.body->gap(centre, poses_[o]) > cluster.radius + margin)
              continue;
            for (int k = cluster.begin; k < cluster.end; ++k)
              {
                const Eigen::Vector3d x = c + R * offsets_[k];
                if (!(obstacle.body->gap(x, poses_[o]) < margin))
                  continue;
                const geometry::SignedDistance d = obstacle.body->distance(x, poses_[o]);
                near.push_back({cluster.link, k, static_cast<int>(o), x, d.normal,
                                d.gap < 0.0 ? Eigen::Vector3d(-stiffness_ * d.gap * d.normal)
                                            : Eigen::Vector3d::Zero(),
                                d.gap, d.hessian});
              }
          }
      }
  }

  std::vector<data::ObstacleWrench> ChainContact::obstacle_wrenches() const
  {
    std::vector<Eigen::Vector3d> force(obstacles_.size(), Eigen::Vector3d::Zero()),
      moment(obstacles_.size(), Eigen::Vector3d::Zero());
    for (const Touch &touch : touches_)
      {
        force[touch.obstacle] -= touch.force;
        moment[touch.obstacle] -= touch.position.cross(touch.force);
      }
    std::vector<data::ObstacleWrench> wrenches(obstacles_.size());
    for (std::size_t o = 0; o < obstacles_.size(); ++o)
      for (int i = 0; i < 3; ++i)
        {
          wrenches[o].force[i]  = force[o][i];
          wrenches[o].moment[i] = moment[o][i];
        }
    return wrenches;
  }

  double ChainContact::max_penetration() const
  {
    double deepest = 0.0;
    for (const Touch &touch : touches_)
      deepest = std::max(deepest, -touch.gap);
    return deepest;
  }
} // namespace softchain::chain
