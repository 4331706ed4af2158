#pragma once
// BoundingBoxFrame, method M1 of the paper (Sec. III-C): "after the
// deformation, the edges of the bounding box B_i define a new reference
// frame F_i". Made precise here: for each axis k of the reference box, the
// edge vector e_k is the deformed centroid of the slab nodes on the box's
// max-k face minus that of the nodes on its min-k face (faces taken in the
// reference configuration). The frame is Gram-Schmidt from the long axis:
//   x_hat = e_x / |e_x|,  y_hat = (e_y - (e_y.x_hat) x_hat) / |...|,
//   z_hat = x_hat cross y_hat,
// and R_i^0 = [x_hat y_hat z_hat] (the reference frame F_i,0 is the world's).
#include <softchain/reduction/slab_selection.h>

#include <Eigen/Core>

namespace softchain::reduction
{
  class BoundingBoxFrame
  {
  public:
    // Throws data::InputError naming joint and sample when an edge vector
    // vanishes or e_z points against z_hat (a reflected slab).
    BoundingBoxFrame(const SlabSelection &slab, const std::vector<data::Point3> &X,
                     const std::vector<data::Point3> &x, const std::string &sample);

    const Eigen::Matrix3d &rotation() const { return R_; }

  private:
    Eigen::Matrix3d R_;
  };
} // namespace softchain::reduction
