#pragma once
// PressureTorque: the column J_p of the paper's tau = J^T f + J_p p (Sec.
// III-C), computed from the deformed cavity geometry. The gas at pressure p
// pushes each cavity wall away from the cavity: on a triangle with area
// vector a = (x1 - x0) x (x2 - x0) / 2, which points into the cavity, the
// force is -p a, applied at the triangle's centroid c. The torque per pascal
// about the joint centre J_i, from the walls on the distal side of the
// section plane through J_i with normal n_i (JointGeometry::section_normal),
// is
//   J_p,i = R_i^0^T sum_t (c_t - J_i) x (-a_t),
// where triangles crossing the plane are clipped at it (Sutherland-Hodgman)
// and the clipped polygon is fanned into triangles; the sum is exact for
// flat triangles since pressure is uniform.
#include <softchain/data/actuation_database.h>

#include <Eigen/Core>

#include <array>
#include <vector>

namespace softchain::reduction
{
  class PressureTorque
  {
  public:
    PressureTorque(const std::vector<std::array<std::int64_t, 3>> &cavity_triangles,
                   const std::vector<data::Point3>                &x);

    // J_p of the joint whose deformed centre is `centre` and whose frame is
    // `frame` (columns: joint axes in world coordinates), in that frame, for
    // the section through the centre with the given normal.
    Eigen::Vector3d per_pascal(const Eigen::Vector3d &centre, const Eigen::Matrix3d &frame,
                               const Eigen::Vector3d &normal) const;
    // The same distal walls' moment about another point (a joint's twist
    // axis point), the section still through `centre`.
    Eigen::Vector3d per_pascal_about(const Eigen::Vector3d &moment_point,
                                     const Eigen::Vector3d &centre, const Eigen::Matrix3d &frame,
                                     const Eigen::Vector3d &normal) const;

  private:
    std::vector<std::array<Eigen::Vector3d, 3>> triangles_;
  };
} // namespace softchain::reduction
