#pragma once
// JointGeometry: where the chain's joints sit and which slab of material
// gives each joint's distal frame, for one placement and slab half-width b.
//
// Paper placement (Sec. III-C): joint i at x_i = (i - 1/2) a, its slab the
// mesh nodes with |X_x - x_i| <= b, its reference centre J_i,0 the centre of
// the slab's bounding box, deformed by the slab's affine fit; the pressure
// section through J_i is normal to the joint frame's x axis.
//
// Strain-limiting-layer placement (the default): joint i at
//   J_i,0 = (x_i, y_n, z_c),
// on the layer that does not stretch (NeutralLayer: y_n) in the middle of
// the body in z. Link i, from joint i to joint i+1 (the last one to the
// tip face x = L), is oriented by its own slab: the body lattice points
// (BodySamples) with |X_x - m_i| <= b l_i / a around the link's middle
// m_i = (x_i + x_i+1) / 2 (l_i = x_i+1 - x_i, a/2 for the last link), so that
// b = a/2 is the link's span. The deformed
// joint centre is the material point J_i,0 moved with the FEM field, and the
// pressure section through it is normal to the bisector of the x axes of the
// links it joins, R_i-1 e_x + R_i e_x (R_0 = identity, the clamped base).
// Rigid links between joints on a layer that keeps its length follow the
// finger exactly where it bends like a beam.
//
// Twist axis (strain-limiting-layer placement): joint i twists (psi) about
// the proximal link's x axis through S_i,0 = J_i,0 + (0, t, 0), the section's
// twist centre t above the joint (TwistAxis), and bends (theta, phi) about
// J_i. The torque that twists it is the moment about S_i. t = 0 (the paper's
// placement, and the default until set) twists about the joint centre.
#include <softchain/reduction/body_samples.h>
#include <softchain/reduction/joint_frames.h>
#include <softchain/reduction/joint_layout.h>
#include <softchain/reduction/reduction_parameters.h>
#include <softchain/reduction/slab_selection.h>

#include <memory>
#include <vector>

namespace softchain::reduction
{
  class JointGeometry
  {
  public:
    // The paper's placement on the mesh nodes.
    JointGeometry(const JointLayout &layout, const data::MeshRecord &mesh, double half_width);
    // Joints on the layer at height `layer_height`; throws data::InputError
    // naming the joint whose centre lies outside the body.
    JointGeometry(const JointLayout &layout, std::shared_ptr<const BodySamples> body,
                  double layer_height, double half_width);

    JointPlacement placement() const { return placement_; }
    std::size_t    n_joints() const { return reference_centres_.size(); }
    // Slab k gives the distal frame of joint k (0-based).
    const std::vector<SlabSelection> &slabs() const { return slabs_; }
    // The material points the slabs index: reference and for a sample.
    const std::vector<data::Point3> &reference_points() const { return reference_points_; }
    std::vector<data::Point3>        points(const std::vector<data::Point3> &x) const;

    double                 x_joint(std::size_t i) const { return x_joints_[i]; }
    const Eigen::Vector3d &reference_centre(std::size_t i) const { return reference_centres_[i]; }
    // J_i of a sample whose slabs gave `frames` (x: the sample's nodes).
    Eigen::Vector3d deformed_centre(std::size_t i, const JointFrames &frames,
                                    const std::vector<data::Point3> &x) const;
    // The twist axis: t, S_i,0, and S_i of a sample (J_i moved by the sample
    // plus R_i-1 (0, t, 0), R_i-1 the proximal slab's rotation).
    void            set_twist_offset(double t) { twist_offset_ = t; }
    double          twist_offset() const { return twist_offset_; }
    Eigen::Vector3d reference_twist_point(std::size_t i) const;
    Eigen::Vector3d deformed_twist_point(std::size_t i, const JointFrames &frames,
                                         const std::vector<data::Point3> &x) const;
    // Normal of the section through J_i that splits the finger at joint i.
    Eigen::Vector3d section_normal(std::size_t i, const JointFrames &frames) const;

  private:
    JointPlacement                     placement_;
    std::shared_ptr<const BodySamples> body_;
    std::vector<data::Point3>          reference_points_;
    std::vector<SlabSelection>         slabs_;
    std::vector<double>                x_joints_;
    std::vector<Eigen::Vector3d>       reference_centres_;
    std::vector<CellPoint>             located_centres_;
    double                             twist_offset_ = 0.0;
  };
} // namespace softchain::reduction
