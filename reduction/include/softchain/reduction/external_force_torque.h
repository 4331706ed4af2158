#pragma once
// ExternalForceTorque: the J^T f part of the joint torques (paper Sec.
// III-C): the moment about the deformed joint centre J_i of the dead loads
// applied distal to joint i,
//   tau_i = R_i^0^T sum_{k : X_k,x > x_i} (x_k - J_i) x f_k,
// with X_k the reference and x_k the deformed force point, f_k in world axes.
#include <softchain/data/actuation_database.h>

#include <Eigen/Core>

namespace softchain::reduction
{
  class ExternalForceTorque
  {
  public:
    // Throws data::InputError naming the sample when the numbers of force
    // points and deformed force points differ.
    explicit ExternalForceTorque(const data::SampleRecord &sample);

    Eigen::Vector3d about(double x_joint, const Eigen::Vector3d &centre,
                          const Eigen::Matrix3d &frame) const;

  private:
    const data::SampleRecord &sample_;
  };
} // namespace softchain::reduction
