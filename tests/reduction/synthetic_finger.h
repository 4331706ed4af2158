#pragma once
// Synthetic fingers for the reduction tests: a hollow prismatic box of nodes
// with a closed box-shaped cavity, and closed-form deformations of it.
//
// Cross-section (mm): nodes on the grid y in {-6,-4,...,6}, z in {-5,-3,...,5}
// minus the grid points strictly inside the cavity y in (-2, 4), z in (-3, 3).
// Every node plane x = planes[k] carries the same cross-section, so a slab is
// a product of its planes and the cross-section, symmetric under z -> -z.
// The cavity runs from the first to the last plane (end caps there), its
// walls split into two triangles per interval between planes, oriented so
// that (x1-x0)x(x2-x0) points into the cavity.
#include <softchain/data/actuation_database.h>

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace softchain::testing
{
  constexpr double mm = 1e-3;
  // The cavity's cross-section: 6 mm x 6 mm, centroid at y = 1 mm, z = 0.
  constexpr double cavity_area       = 36 * mm * mm;
  constexpr double cavity_centroid_y = 1 * mm;

  struct SyntheticFinger
  {
    std::vector<double> planes;
    data::MeshRecord    mesh;
    // Mean of the cross-section's node y (the slabs' centroid axis).
    double node_centroid_y() const;
  };

  // The cavity runs from plane `first_cavity_plane` to the last (a solid
  // base section before it, like P10's base fill).
  SyntheticFinger hollow_box(const std::vector<double> &planes, std::size_t first_cavity_plane = 0);
  std::vector<double> uniform_planes(double length, int n_intervals);

  using Map = std::function<Eigen::Vector3d(const Eigen::Vector3d &)>;
  std::vector<data::Point3> deform(const std::vector<data::Point3> &X, const Map &map);

  // x -> Q x + t.
  Map rigid_motion(const Eigen::Matrix3d &Q, const Eigen::Vector3d &t);
  // Bending onto a circular arc of signed radius R about z: the section at X
  // turns by Rz(X / R) about the centre of curvature (0, R, 0); a fibre at
  // height Y keeps its distance R - Y from that centre.
  Map arc_about_z(double R);
  // The same about y: section at X turns by Ry(X / R), centre (0, ., -R).
  Map arc_about_y(double R);
  // Twist at rate kappa about the line y = y_axis, z = 0: Rx(kappa X).
  Map twist_about_x(double kappa, double y_axis);
} // namespace softchain::testing
