#include <softchain/report/obstacle_outline.h>

#include <cmath>

namespace softchain::report
{
  namespace
  {
    constexpr int segments = 32; // of a circle

    Eigen::Vector3d vector(const data::Point3 &p) { return {p[0], p[1], p[2]}; }

    // The turn of the rotation vector v: about v / |v| by |v| rad.
    Eigen::Matrix3d turn(const data::Point3 &v)
    {
      const double angle = vector(v).norm();
      return angle > 0 ? Eigen::AngleAxisd(angle, vector(v) / angle).toRotationMatrix() : Eigen::Matrix3d::Identity();
    }

    // Two unit vectors normal to `n` and to each other.
    std::pair<Eigen::Vector3d, Eigen::Vector3d> normal_plane(const Eigen::Vector3d &n)
    {
      const Eigen::Vector3d helper = std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
      const Eigen::Vector3d u      = n.cross(helper).normalized();
      return {u, n.cross(u)};
    }

    Outline circle(const Eigen::Vector3d &centre, const Eigen::Vector3d &n, const double r)
    {
      const auto [u, v] = normal_plane(n);
      Outline points;
      for (int k = 0; k < segments; ++k)
        {
          const double a = 2 * M_PI * k / segments;
          points.push_back(centre + r * (std::cos(a) * u + std::sin(a) * v));
        }
      return points;
    }

    // The rectangle of the plane through p with normal n under `around`,
    // widened by half its size.
    std::vector<Outline> plane(const Eigen::Vector3d &p, const Eigen::Vector3d &n,
                               const Eigen::AlignedBox3d &around)
    {
      const auto [u, v] = normal_plane(n);
      const Eigen::Vector3d c = around.center() - n.dot(around.center() - p) * n;
      const double          a = 0.75 * around.sizes().dot(u.cwiseAbs()) + 1e-3;
      const double          b = 0.75 * around.sizes().dot(v.cwiseAbs()) + 1e-3;
      return {{c - a * u - b * v, c + a * u - b * v, c + a * u + b * v, c - a * u + b * v}};
    }

    // The cylinder between the planes normal to its axis that bound the
    // finger's box, widened a little.
    std::vector<Outline> cylinder(const Eigen::Vector3d &p, const Eigen::Vector3d &axis,
                                  const double r, const Eigen::AlignedBox3d &around)
    {
      const Eigen::Vector3d a    = axis.normalized();
      const double          half = 0.5 * around.sizes().dot(a.cwiseAbs()) + 0.2 * r;
      const Eigen::Vector3d mid  = p + a.dot(around.center() - p) * a;
      const Outline         low = circle(mid - half * a, a, r), high = circle(mid + half * a, a, r);
      std::vector<Outline>  outline{low, high};
      for (int k = 0; k < segments; ++k)
        outline.push_back({low[k], low[(k + 1) % segments], high[(k + 1) % segments], high[k]});
      return outline;
    }

    // The six faces of the box with centre c and half sizes h along the
    // columns of R.
    std::vector<Outline> box(const Eigen::Vector3d &c, const Eigen::Vector3d &h, const Eigen::Matrix3d &R)
    {
      std::vector<Outline> faces;
      for (int axis = 0; axis < 3; ++axis)
        for (const double side : {-1.0, 1.0})
          {
            const int       i = (axis + 1) % 3, j = (axis + 2) % 3;
            Outline         face;
            for (const auto &[s, t] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}})
              {
                Eigen::Vector3d y = Eigen::Vector3d::Zero();
                y[axis]           = side * h[axis];
                y[i]              = s * h[i];
                y[j]              = t * h[j];
                face.push_back(c + R * y);
              }
            faces.push_back(face);
          }
      return faces;
    }
  } // namespace

  std::vector<Outline> obstacle_outline(const data::ObstacleRecord &o, const Eigen::AlignedBox3d &around,
                                        const ObliqueView &view)
  {
    // The end of the load path: turned by Motion rotation about its pivot,
    // then moved by Motion.
    const Eigen::Matrix3d T     = turn(o.motion_rotation);
    const Eigen::Vector3d pivot = vector(o.motion_pivot), motion = vector(o.motion);
    const auto            end   = [&](const Eigen::Vector3d &y) { return Eigen::Vector3d(T * (y - pivot) + pivot + motion); };
    const Eigen::Vector3d at    = end(vector(o.position));
    if (o.shape == "plane")
      return plane(at, T * vector(o.direction).normalized(), around);
    if (o.shape == "cylinder")
      return cylinder(at, T * vector(o.direction), o.radius, around);
    if (o.shape == "sphere")
      return {circle(at, view.toward_viewer().normalized(), o.radius)};
    if (o.shape == "box")
      return box(at, vector(o.half_sizes), T * turn(o.rotation));
    if (o.shape == "stl")
      {
        const Eigen::Matrix3d R = turn(o.rotation);
        std::vector<Outline>  triangles;
        for (std::size_t v = 0; v + 2 < o.vertices.size(); v += 3)
          triangles.push_back({end(vector(o.position) + R * vector(o.vertices[v])),
                               end(vector(o.position) + R * vector(o.vertices[v + 1])),
                               end(vector(o.position) + R * vector(o.vertices[v + 2]))});
        return triangles;
      }
    return {};
  }
} // namespace softchain::report
