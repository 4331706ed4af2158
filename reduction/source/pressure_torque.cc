// PressureTorque: J_p from the deformed cavity triangles distal to the
// section plane through the joint centre, clipped at the plane.
#include <softchain/reduction/pressure_torque.h>
#include <softchain/data/vector_of_point.h>

#include <Eigen/Geometry>

namespace softchain::reduction
{
  namespace
  {
    using Polygon = std::vector<Eigen::Vector3d>;

    // Sutherland-Hodgman clip of a triangle to the half space s(y) >= 0 with
    // s(y) = (y - centre) . normal; keeps the vertex order (orientation).
    Polygon clip_distal(const std::array<Eigen::Vector3d, 3> &triangle,
                        const Eigen::Vector3d &centre, const Eigen::Vector3d &normal)
    {
      Polygon kept;
      for (int v = 0; v < 3; ++v)
        {
          const Eigen::Vector3d &p  = triangle[v];
          const Eigen::Vector3d &q  = triangle[(v + 1) % 3];
          const double           sp = (p - centre).dot(normal);
          const double           sq = (q - centre).dot(normal);
          if (sp >= 0)
            kept.push_back(p);
          if ((sp >= 0) != (sq >= 0))
            kept.push_back(p + (q - p) * (sp / (sp - sq)));
        }
      return kept;
    }

    // Moment about `centre` of the force -a (one pascal) on a flat polygon,
    // fanned into triangles (c_t - centre) x (-a_t).
    Eigen::Vector3d polygon_moment(const Polygon &polygon, const Eigen::Vector3d &centre)
    {
      Eigen::Vector3d moment = Eigen::Vector3d::Zero();
      for (std::size_t v = 1; v + 1 < polygon.size(); ++v)
        {
          const Eigen::Vector3d area =
            0.5 * (polygon[v] - polygon[0]).cross(polygon[v + 1] - polygon[0]);
          const Eigen::Vector3d centroid = (polygon[0] + polygon[v] + polygon[v + 1]) / 3.0;
          moment += (centroid - centre).cross(-area);
        }
      return moment;
    }
  } // namespace

  PressureTorque::PressureTorque(const std::vector<std::array<std::int64_t, 3>> &cavity_triangles,
                                 const std::vector<data::Point3>                &x)
  {
    for (const auto &t : cavity_triangles)
      triangles_.push_back({data::vector_of(x[t[0]]), data::vector_of(x[t[1]]), data::vector_of(x[t[2]])});
  }

  Eigen::Vector3d PressureTorque::per_pascal(const Eigen::Vector3d &centre,
                                             const Eigen::Matrix3d &frame,
                                             const Eigen::Vector3d &normal) const
  {
    return per_pascal_about(centre, centre, frame, normal);
  }

  Eigen::Vector3d PressureTorque::per_pascal_about(const Eigen::Vector3d &moment_point,
                                                   const Eigen::Vector3d &centre,
                                                   const Eigen::Matrix3d &frame,
                                                   const Eigen::Vector3d &normal) const
  {
    Eigen::Vector3d moment = Eigen::Vector3d::Zero();
    for (const auto &triangle : triangles_)
      moment += polygon_moment(clip_distal(triangle, centre, normal), moment_point);
    return frame.transpose() * moment;
  }
} // namespace softchain::reduction
