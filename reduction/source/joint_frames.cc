// JointFrames: R_i^0 by M1 or M2, J_i = A_i J_i,0 + u_i, R_i = R_{i-1}^T R_i^0.
#include <softchain/reduction/affine_slab_fit.h>
#include <softchain/reduction/bounding_box_frame.h>
#include <softchain/reduction/joint_frames.h>

#include <limits>

namespace softchain::reduction
{
  JointFrames::JointFrames(RotationMethod method, const std::vector<SlabSelection> &slabs,
                           const std::vector<data::Point3> &X, const std::vector<data::Point3> &x,
                           const std::string &sample)
  {
    const double no_value = std::numeric_limits<double>::quiet_NaN();
    for (const auto &slab : slabs)
      {
        const AffineSlabFit fit(slab, X, x, sample);
        JointFrame          frame;
        frame.centre = fit.map(slab.reference_centre());
        if (method == RotationMethod::affine_fit)
          {
            frame.rotation  = fit.rotation();
            frame.stretches = fit.principal_stretches();
          }
        else
          {
            frame.rotation  = BoundingBoxFrame(slab, X, x, sample).rotation();
            frame.stretches = Eigen::Vector3d::Constant(no_value);
          }
        frames_.push_back(frame);
      }
  }

  data::JointAngles JointFrames::relative_angles(std::size_t i) const
  {
    const Eigen::Matrix3d previous =
      i == 0 ? Eigen::Matrix3d::Identity() : frames_[i - 1].rotation;
    return data::angles_from_rotation(previous.transpose() * frames_[i].rotation);
  }
} // namespace softchain::reduction
