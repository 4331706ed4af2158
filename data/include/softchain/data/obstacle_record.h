#pragma once
// ObstacleRecord: a rigid obstacle as a contact sample of the database holds
// it -- its shape and pose, its friction coefficient and the translation it
// makes along the sample's load path -- and ObstacleWrench, the force and
// moment the obstacle receives from the finger. deal.II- and Eigen-free, so
// that every tier can read a contact sample; the FEM's and the chain's
// obstacles are built from it (geometry::Obstacle).
#include <array>
#include <string>

namespace softchain::data
{
  using Point3 = std::array<double, 3>;

  struct ObstacleRecord
  {
    std::string name;  // the user's name, the .prm's subsection Contact/<name>
    std::string shape; // "plane", "sphere", "cylinder" or "box"
    Point3      position{};   // a point of the plane or the axis, a centre, m
    Point3      direction{};  // the plane's outward normal, the cylinder's axis (else zero)
    double      radius = 0;   // sphere, cylinder, m (else zero)
    Point3      half_sizes{}; // box, m (else zero)
    double      friction = 0; // Coulomb's coefficient
    Point3      motion{};     // translation at the end of the load path, m
    Point3      rotation{};   // box: its turn from the world axes, axis times angle, rad (else zero)

    // The fields in a fixed order with canonical doubles: part of a contact
    // sample's canonical text, so of its id. A box's rotation enters only
    // where it is not zero, so that the ids of unrotated obstacles stay those
    // of databases written before boxes could turn.
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
