// SampleReduction: angles and torques tau_i = (J^T f)_i + J_p,i p per joint.
#include <softchain/reduction/external_force_torque.h>
#include <softchain/reduction/joint_frames.h>
#include <softchain/reduction/pressure_torque.h>
#include <softchain/reduction/sample_reduction.h>
#include <softchain/reduction/vector_of_point.h>

namespace softchain::reduction
{
  SampleReduction::SampleReduction(const data::SampleRecord &sample, const data::MeshRecord &mesh,
                                   const std::vector<SlabSelection> &slabs, RotationMethod method)
    : id_(sample.id)
    , role_(sample.actuation.role)
    , pressure_(sample.actuation.pressure)
    , force_norm_(0.0)
  {
    for (const auto &f : sample.actuation.point_forces)
      force_norm_ += vector_of(f.force).norm();
    const JointFrames         frames(method, slabs, mesh.X, sample.x, sample.id);
    const PressureTorque      pressure_torque(mesh.cavity_triangles, sample.x);
    const ExternalForceTorque external(sample);
    for (std::size_t i = 0; i < frames.size(); ++i)
      {
        const JointFrame &frame = frames[i];
        JointResult       joint;
        joint.angles          = frames.relative_angles(i);
        joint.pressure_torque = pressure_torque.per_pascal(frame.centre, frame.rotation);
        joint.torque          = external.about(slabs[i].x_joint(), frame.centre, frame.rotation) +
                       joint.pressure_torque * pressure_;
        joint.stretches = frame.stretches;
        joints_.push_back(joint);
      }
  }
} // namespace softchain::reduction
