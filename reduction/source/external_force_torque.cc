// ExternalForceTorque: moment of the distal dead loads about J_i.
#include <softchain/data/input_error.h>
#include <softchain/reduction/external_force_torque.h>
#include <softchain/data/vector_of_point.h>

#include <Eigen/Geometry>

namespace softchain::reduction
{
  ExternalForceTorque::ExternalForceTorque(const data::SampleRecord &sample)
    : sample_(sample)
  {
    if (sample.force_points_deformed.size() != sample.actuation.point_forces.size())
      throw data::InputError("sample '" + sample.id + "': " +
                             std::to_string(sample.actuation.point_forces.size()) +
                             " force points but " +
                             std::to_string(sample.force_points_deformed.size()) +
                             " deformed force points");
  }

  Eigen::Vector3d ExternalForceTorque::about(double x_joint, const Eigen::Vector3d &centre,
                                             const Eigen::Matrix3d &frame) const
  {
    Eigen::Vector3d moment = Eigen::Vector3d::Zero();
    const auto     &forces = sample_.actuation.point_forces;
    for (std::size_t k = 0; k < forces.size(); ++k)
      if (forces[k].point[0] > x_joint)
        moment += (data::vector_of(sample_.force_points_deformed[k]) - centre)
                    .cross(data::vector_of(forces[k].force));
    return frame.transpose() * moment;
  }
} // namespace softchain::reduction
