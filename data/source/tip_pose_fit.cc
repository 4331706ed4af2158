#include <softchain/data/tip_pose_fit.h>
#include <softchain/data/input_error.h>

#include <Eigen/LU>
#include <Eigen/SVD>

#include <cmath>
#include <stdexcept>

namespace softchain::data
{
  namespace
  {
    Eigen::Vector3d centroid_of(const std::vector<Eigen::Vector3d> &points)
    {
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for (const Eigen::Vector3d &p : points)
        sum += p;
      return sum / static_cast<double>(points.size());
    }
  } // namespace

  TipPoseFit::TipPoseFit(const std::vector<Eigen::Vector3d> &reference_nodes)
    : centroid_(reference_nodes.empty() ? Eigen::Vector3d::Zero() : centroid_of(reference_nodes))
  {
    Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
    for (const Eigen::Vector3d &X : reference_nodes)
      {
        centred_.push_back(X - centroid_);
        spread += centred_.back() * centred_.back().transpose();
      }
    // Rank 2 at least: the second singular value must not vanish against the first.
    const Eigen::Vector3d s = Eigen::JacobiSVD<Eigen::Matrix3d>(spread).singularValues();
    if (reference_nodes.size() < 3 || !(s[1] > 1e-12 * s[0]))
      throw std::invalid_argument("TipPoseFit: need at least 3 tip nodes, not all on a line");
  }

  TipPoseFit TipPoseFit::of_mesh(const MeshRecord &mesh, const std::string &source)
  {
    if (mesh.tip_nodes.empty())
      throw InputError(source + ": /mesh/tip_nodes is empty: no tip face for the chain");
    return TipPoseFit(select_nodes(mesh.X, mesh.tip_nodes));
  }

  std::vector<Eigen::Vector3d> select_nodes(const std::vector<Point3>  &x,
                                            const std::vector<std::int64_t> &indices)
  {
    std::vector<Eigen::Vector3d> nodes;
    for (const std::int64_t i : indices)
      {
        if (i < 0 || i >= static_cast<std::int64_t>(x.size()))
          throw InputError("node index " + std::to_string(i) + " out of range (" +
                                 std::to_string(x.size()) + " nodes)");
        nodes.emplace_back(x[i][0], x[i][1], x[i][2]);
      }
    return nodes;
  }

  TipPose TipPoseFit::fit(const std::vector<Eigen::Vector3d> &deformed_nodes) const
  {
    if (deformed_nodes.size() != centred_.size())
      throw std::invalid_argument("TipPoseFit: deformed and reference node counts differ");
    TipPose         pose;
    pose.position     = centroid_of(deformed_nodes);
    Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
    for (std::size_t j = 0; j < centred_.size(); ++j)
      h += centred_[j] * (deformed_nodes[j] - pose.position).transpose();
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3d                         sign = Eigen::Matrix3d::Identity();
    sign(2, 2)    = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0 ? -1.0 : 1.0;
    pose.rotation = svd.matrixV() * sign * svd.matrixU().transpose();
    return pose;
  }

  double rotation_angle_between(const Eigen::Matrix3d &a, const Eigen::Matrix3d &b)
  {
    // For R = a^T b: trace(R) = 1 + 2 cos(angle) and the axial vector of
    // R - R^T is 2 sin(angle) n; atan2 of both is accurate at every angle.
    const Eigen::Matrix3d r = a.transpose() * b;
    const Eigen::Vector3d axial(r(2, 1) - r(1, 2), r(0, 2) - r(2, 0), r(1, 0) - r(0, 1));
    return std::atan2(0.5 * axial.norm(), 0.5 * (r.trace() - 1.0));
  }
} // namespace softchain::data
