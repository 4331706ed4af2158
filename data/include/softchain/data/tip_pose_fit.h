#pragma once
// TipPoseFit: the FEM tip frame, fitted to the nodes of the tip face (the
// chain tier's validation and the FEM tier's prescribed-motion protocol).
// Position: centroid of the deformed tip nodes. Rotation: the best-fit
// rotation of the centred reference onto the centred deformed nodes,
//   R = argmin sum_j |(x_j - x_c) - R (X_j - X_c)|^2        (Kabsch, 1976)
// from the SVD H = sum_j (X_j - X_c)(x_j - x_c)^T = U S V^T as
//   R = V diag(1, 1, det(V U^T)) U^T.
// The tip nodes are coplanar, so H has rank 2: a rotation is still
// determined (the sign fix picks the proper one), an affine fit would not be.
#include <softchain/data/actuation_database.h>

#include <Eigen/Core>
#include <vector>

namespace softchain::data
{
  struct TipPose
  {
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  };

  class TipPoseFit
  {
  public:
    // Reference tip nodes: at least 3, not collinear (std::invalid_argument).
    explicit TipPoseFit(const std::vector<Eigen::Vector3d> &reference_nodes);
    // The tip face of a database mesh (/mesh/tip_nodes); InputError naming
    // `source` if it has none.
    static TipPoseFit of_mesh(const MeshRecord &mesh, const std::string &source);

    const Eigen::Vector3d &reference_centroid() const { return centroid_; }
    // Pose of the same nodes, deformed (same count and order).
    TipPose fit(const std::vector<Eigen::Vector3d> &deformed_nodes) const;

  private:
    Eigen::Vector3d              centroid_;
    std::vector<Eigen::Vector3d> centred_;
  };

  // The nodes `indices` of the positions x (e.g. a sample's tip nodes).
  std::vector<Eigen::Vector3d> select_nodes(const std::vector<Point3>  &x,
                                            const std::vector<std::int64_t> &indices);

  // Angle of the rotation that takes `a` to `b` (rad, in [0, pi]).
  double rotation_angle_between(const Eigen::Matrix3d &a, const Eigen::Matrix3d &b);
} // namespace softchain::data
