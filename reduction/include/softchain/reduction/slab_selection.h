#pragma once
// SlabSelection: the set A_i of reference nodes between the planes
// x = x_i - b and x = x_i + b (paper Sec. III-C, Fig. 4), its reference
// bounding box B_i (axis-aligned, like the frames F_i,0) and the reference
// joint centre J_i,0 = centre of B_i.
#include <softchain/data/actuation_database.h>

#include <Eigen/Geometry>

#include <string>
#include <vector>

namespace softchain::reduction
{
  class SlabSelection
  {
  public:
    // `joint` (1..n) only names the slab in messages.
    SlabSelection(const std::vector<data::Point3> &X, int joint, double x_joint, double half_width);

    const std::vector<std::size_t> &nodes() const { return nodes_; }
    const Eigen::AlignedBox3d       &reference_box() const { return box_; }
    Eigen::Vector3d                  reference_centre() const { return box_.center(); }
    int                              joint() const { return joint_; }
    double                           x_joint() const { return x_joint_; }
    // "joint I (x_i = X m, b = B m)", for messages.
    std::string label() const;

  private:
    int                      joint_;
    double                   x_joint_;
    double                   half_width_;
    std::vector<std::size_t> nodes_;
    Eigen::AlignedBox3d      box_;
  };
} // namespace softchain::reduction
