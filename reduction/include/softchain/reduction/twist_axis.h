#pragma once
// TwistAxis: the height t above the joints of the axis about which the
// finger's sections twist (the section's twist centre). P10's joints sit on
// its bottom layer, far below the twist centre of its hollow section; a
// chain that twists about the joints swings its tip sideways under a
// torsion couple, which the FEM finger does not.
//
// A chain whose joint i twists about the proximal link's x axis through
// J_i,0 + s, s = (0, t, 0), and bends about J_i,0 carries the tip face's
// reference centroid T_0 to
//   o_1 = J_1,0 + (I - Rx(psi_1)) s,
//   o_i = o_i-1 + R_i-1 (J_i,0 - J_i-1,0 + (I - Rx(psi_i)) s),
//   R_i = R_i-1 E(q_i),   T = o_n + R_n (T_0 - J_n,0)
// (E(q) = Rx(psi) Ry(theta) Rz(phi); t = 0 is the chain tier's
// KinematicChain), at the relative angles q_i the slabs' frames give. t is
// the height at which this chain lands closest on the FEM's tip-face
// centroid over the torsion samples, E(t) = sum_s |T_s(t) - T_s,FEM|^2,
// scanned in 0.25 mm steps from 0 to the top of the body. Without torsion
// samples t = 0.
#include <softchain/data/actuation_database.h>
#include <softchain/reduction/joint_geometry.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace softchain::reduction
{
  class TwistAxis
  {
  public:
    // `highest`: the largest t scanned [m] (the body's top above the joints).
    TwistAxis(const JointGeometry &geometry, const data::MeshRecord &mesh,
              const std::vector<const data::SampleRecord *> &torsion_samples, double highest,
              const std::string &source);

    double offset() const { return offset_; }
    // One sentence for the reduction's log.
    std::string description() const;

    struct ChainTip
    {
      Eigen::Vector3d position; // T
      Eigen::Matrix3d rotation; // R_n
    };
    // The chain above for one sample's frames, on the reference links.
    static ChainTip chain_tip(const JointGeometry &geometry, const JointFrames &frames,
                              const Eigen::Vector3d &tip_reference, double t);
    // The reference links J_i,0 and the tip face's reference centroid T_0.
    static std::vector<Eigen::Vector3d> reference_links(const JointGeometry &geometry,
                                                        const Eigen::Vector3d &tip_reference);
    // The same on links U_1..U_n, U_T (the reference J_i,0 and T_0 above).
    static ChainTip chain_tip(const JointFrames &frames, const std::vector<Eigen::Vector3d> &links,
                              double t);
    // The chain tier's links at a sample whose frames and deformed positions
    // x give the joint centres J_i, and whose tip-face centroid is T
    // (SampleReduction's link geometry): U_1 = J_1, U_i+1 = U_i + R_i^T
    // (J_i+1 - J_i), J_n+1 = T, R_i the slab rotation of link i.
    static std::vector<Eigen::Vector3d> links_of(const JointGeometry &geometry, const JointFrames &frames,
                                                 const std::vector<data::Point3> &x, const Eigen::Vector3d &tip);

  private:
    double offset_    = 0.0;
    double residual_  = 0.0; // rms |T(t) - T_FEM| at t [m]
    double at_joints_ = 0.0; // the same at t = 0
    int    n_samples_ = 0;
  };
} // namespace softchain::reduction
