#include "synthetic_finger.h"

#include <Eigen/Geometry>

#include <cmath>

namespace softchain::testing
{
  namespace
  {
    struct CrossSection
    {
      std::vector<Eigen::Vector2d> points; // (y, z)
      std::array<int, 4>           cavity_corners{}; // counter-clockwise in (y, z)
    };

    bool inside_cavity(double y, double z)
    {
      const double tol = 1e-3 * mm;
      return y > -2 * mm + tol && y < 4 * mm - tol && std::abs(z) < 3 * mm - tol;
    }

    int index_of(const std::vector<Eigen::Vector2d> &points, double y, double z)
    {
      for (std::size_t i = 0; i < points.size(); ++i)
        if ((points[i] - Eigen::Vector2d(y, z)).norm() < 1e-3 * mm)
          return static_cast<int>(i);
      return -1;
    }

    CrossSection cross_section()
    {
      CrossSection section;
      for (int iy = -3; iy <= 3; ++iy)
        for (int iz = -5; iz <= 5; iz += 2)
          if (!inside_cavity(2 * iy * mm, iz * mm))
            section.points.emplace_back(2 * iy * mm, iz * mm);
      section.cavity_corners = {index_of(section.points, -2 * mm, -3 * mm),
                                index_of(section.points, 4 * mm, -3 * mm),
                                index_of(section.points, 4 * mm, 3 * mm),
                                index_of(section.points, -2 * mm, 3 * mm)};
      return section;
    }

    // Appends triangle (a, b, c), swapped if needed so that its normal
    // points towards `inside`, a point inside the (convex) cavity.
    void add_triangle(data::MeshRecord &mesh, std::int64_t a, std::int64_t b, std::int64_t c,
                      const Eigen::Vector3d &inside)
    {
      const auto            P = [&](std::int64_t j) { return Eigen::Vector3d(mesh.X[j].data()); };
      const Eigen::Vector3d n = (P(b) - P(a)).cross(P(c) - P(a));
      if (n.dot(inside - (P(a) + P(b) + P(c)) / 3) < 0)
        std::swap(b, c);
      mesh.cavity_triangles.push_back({a, b, c});
    }
  } // namespace

  double SyntheticFinger::node_centroid_y() const
  {
    double sum = 0;
    for (const auto &p : mesh.X)
      sum += p[1];
    return sum / mesh.X.size();
  }

  std::vector<double> uniform_planes(double length, int n_intervals)
  {
    std::vector<double> planes;
    for (int k = 0; k <= n_intervals; ++k)
      planes.push_back(length * k / n_intervals);
    return planes;
  }

  SyntheticFinger hollow_box(const std::vector<double> &planes, const std::size_t first_cavity_plane)
  {
    SyntheticFinger finger;
    finger.planes            = planes;
    const CrossSection cs    = cross_section();
    const std::int64_t n_cs  = cs.points.size();
    for (const double x : planes)
      for (const auto &p : cs.points)
        finger.mesh.X.push_back({x, p(0), p(1)});
    const Eigen::Vector3d inside(0.5 * (planes[first_cavity_plane] + planes.back()),
                                 cavity_centroid_y, 0);
    const auto node = [&](std::size_t plane, int corner) {
      return std::int64_t(plane) * n_cs + cs.cavity_corners[corner % 4];
    };
    for (std::size_t k = first_cavity_plane; k + 1 < planes.size(); ++k)
      for (int c = 0; c < 4; ++c)
        {
          add_triangle(finger.mesh, node(k, c), node(k + 1, c), node(k + 1, c + 1), inside);
          add_triangle(finger.mesh, node(k, c), node(k + 1, c + 1), node(k, c + 1), inside);
        }
    for (const std::size_t end : {first_cavity_plane, planes.size() - 1})
      {
        add_triangle(finger.mesh, node(end, 0), node(end, 1), node(end, 2), inside);
        add_triangle(finger.mesh, node(end, 0), node(end, 2), node(end, 3), inside);
      }
    finger.mesh.nodes_per_cell = 8; // node cloud only: no cells needed here
    return finger;
  }

  std::vector<data::Point3> deform(const std::vector<data::Point3> &X, const Map &map)
  {
    std::vector<data::Point3> x;
    for (const auto &p : X)
      {
        const Eigen::Vector3d q = map(Eigen::Vector3d(p[0], p[1], p[2]));
        x.push_back({q(0), q(1), q(2)});
      }
    return x;
  }

  Map rigid_motion(const Eigen::Matrix3d &Q, const Eigen::Vector3d &t)
  {
    return [=](const Eigen::Vector3d &X) -> Eigen::Vector3d { return Q * X + t; };
  }

  Map arc_about_z(double R)
  {
    return [=](const Eigen::Vector3d &X) -> Eigen::Vector3d {
      const double a = X(0) / R;
      return Eigen::Vector3d(0, R, 0) + (R - X(1)) * Eigen::Vector3d(std::sin(a), -std::cos(a), 0) +
             Eigen::Vector3d(0, 0, X(2));
    };
  }

  Map arc_about_y(double R)
  {
    return [=](const Eigen::Vector3d &X) -> Eigen::Vector3d {
      const double a = X(0) / R;
      return Eigen::Vector3d(0, X(1), -R) + (R + X(2)) * Eigen::Vector3d(std::sin(a), 0, std::cos(a));
    };
  }

  Map twist_about_x(double kappa, double y_axis)
  {
    return [=](const Eigen::Vector3d &X) -> Eigen::Vector3d {
      const Eigen::AngleAxisd turn(kappa * X(0), Eigen::Vector3d::UnitX());
      const Eigen::Vector3d   axis(0, y_axis, 0);
      return axis + turn * Eigen::Vector3d(X(0), X(1) - y_axis, X(2));
    };
  }
} // namespace softchain::testing
