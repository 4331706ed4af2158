#pragma once
// ObstacleRecord: a rigid obstacle as a contact sample of the database holds
// it -- its shape and pose, its friction coefficient and the translation and
// turn it makes along the sample's load path -- and ObstacleWrench, the force and
// moment the obstacle receives from the finger. deal.II- and Eigen-free, so
// that every tier can read a contact sample; the FEM's and the chain's
// obstacles are built from it (geometry::Obstacle).
#include <array>
#include <string>
#include <vector>

namespace softchain::data
{
  using Point3 = std::array<double, 3>;

  struct ObstacleRecord
  {
    std::string name;  // the user's name, the .prm's subsection Contact/<name>
    std::string shape; // "plane", "sphere", "cylinder", "box" or "stl"
    Point3      position{};   // a point of the plane or the axis, a centre, where stl puts its file's origin, m
    Point3      direction{};  // the plane's outward normal, the cylinder's axis (else zero)
    double      radius = 0;   // sphere, cylinder, m (else zero)
    Point3      half_sizes{}; // box, m (else zero)
    double      friction = 0; // Coulomb's coefficient
    Point3      motion{};     // translation at the end of the load path, m
    Point3      rotation{};   // box, stl: its turn from the world axes, axis times angle, rad (else zero)
    // The turn at the end of the load path, a rotation vector (axis times
    // angle, rad), about `motion_pivot` (m): at path parameter t the
    // obstacle is turned by t times it about the pivot, then moved by
    // t motion.
    Point3 motion_rotation{};
    Point3 motion_pivot{};
    // stl: the surface's triangles in the file's coordinates, m, three
    // vertices each (outward by the right-hand rule), and the file they
    // were read from (for messages; the sample does not need it).
    std::vector<Point3> vertices = {};
    std::string         file     = {};

    // The fields in a fixed order with canonical doubles: part of a contact
    // sample's canonical text, so of its id. A rotation, a turn along the
    // load path and the triangles enter only where they are not zero or
    // empty, so that the ids of other obstacles stay those of databases
    // written before obstacles could turn or be meshes: the triangles as
    // the content hash of their canonical text (the file's name is not part
    // of the id, its content is).
    std::string canonical_text() const;
  };

  // What an obstacle receives from the finger: force [N] and moment about
  // the origin [N m], world axes.
  struct ObstacleWrench
  {
    Point3 force{};
    Point3 moment{};
  };
} // namespace softchain::data
