#pragma once
// JointForceLaw: the joints' response to forces, the reduction's
// <label>_joint_law.csv. Per joint i and pressure p_j of its force samples,
// a data::FabricHinge: linear springs and the fabric layer's two
// tension-only edge fibres, in the joint's angle increments d = q_i - q_p,i
// over the pressure-only state. Between two tabulated pressures p_lo < p <
// p_hi, w = (p - p_lo) / (p_hi - p_lo), the two laws' energies are blended
// linearly in p (a convex combination of convex energies stays convex):
//   W(d) = (1 - w) W_lo(d) + w W_hi(d);
// beyond the first and last one the end law holds (as PiecewiseLinear holds
// k).
//
// From rest (p_lo = 0) to the first inflated law the lateral turn theta
// blends in series instead: its compliance, not its stiffness, is what
// interpolates linearly in p. At rest the fabric layer is slack and the
// finger soft sideways; inflated it holds a lateral turn stiffly up to a
// knee. Measured on a P10 variant's tip under a lateral force of 0.1-0.2 N
// (docs/history.md, "From rest to the first inflated law: theta in series"):
// 66, 43 and 21.5 mm/N at 0, 10 and 20 kPa, where the compliances' mean is
// 44 mm/N and the stiffnesses' 33. The blended energy is then the infimal
// convolution in theta (psi and phi stay blended in parallel; x is theta of
// the law at rest, the law at p_hi takes the rest of d_theta):
//   W(d) = min_x (1 - w) W_lo(x; d_psi, d_phi)
//                + w W_hi((d_theta - (1 - w) x) / w; d_psi, d_phi),
// convex in d as a partial infimal convolution of convex functions. At the
// minimiser both laws carry the same theta torque, which is the blend's;
// its tangent is the Schur complement of the minimisation (joint_force_law.cc).
// For linear springs at both ends: k_theta = 1 / ((1 - w) / k_lo + w / k_hi).
//
// The chain's spring torque of a joint with a law is then
//   tau_i(q) = J_p,i p + T_i(p, q_i - q_p,i),   q_p = K(p)^-1 J_p p
// (ChainEquilibrium): the pressure-only state q_p stays that of the linear
// springs K(p), which hold it exactly, and forces turn the joint from there
// along the fitted law instead of the lightest force's slopes k(p). Joints
// without a law keep tau_i = K_i(p) q_i.

#include <softchain/chain/joint_stiffness.h>
#include <softchain/data/fabric_hinge.h>

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace softchain::chain
{
  class JointForceLaw
  {
  public:
    struct Table
    {
      std::vector<double>            pressures; // strictly increasing
      std::vector<data::FabricHinge> hinges;    // one per pressure
    };

    // One table per joint; an empty table: no law (linear springs).
    // std::invalid_argument if a table's pressures do not increase strictly
    // or its counts differ.
    explicit JointForceLaw(std::vector<Table> per_joint);

    // The same laws, each joint tabulated at every pressure of any joint's
    // law and of the springs' k(p) tables: where the reduction fitted none
    // (the samples there do not follow a FabricHinge), the linear springs
    // `springs` at that pressure (kappa = 0). A law then blends into the
    // linear springs by the next tabulated pressure instead of holding where
    // it was not fitted.
    JointForceLaw completed_with(const JointStiffness &springs) const;

    int          n_joints() const { return static_cast<int>(per_joint_.size()); }
    bool         has_law(int joint) const { return !per_joint_[joint].pressures.empty(); }
    const Table &table(int joint) const { return per_joint_[joint]; }

    // The law of `joint` at `pressure` (see above): two hinges and the
    // weight of the second, to evaluate at many increments.
    struct Blend
    {
      const data::FabricHinge *lower  = nullptr; // nullptr: no law
      const data::FabricHinge *upper  = nullptr;
      double                   weight = 0.0;
      bool                     theta_in_series = false; // from rest: theta blends in series (above)
      // Without fibres at either end the law is linear springs: their
      // stiffness (k blended), the chain's fast path; else nullopt.
      std::optional<Eigen::Vector3d> springs;
      data::FabricHinge::Value       evaluate(const Eigen::Vector3d &increment) const;

    private:
      static constexpr int     max_series_iterations = 50;
      data::FabricHinge::Value in_series(const Eigen::Vector3d &increment) const;
    };
    Blend at(double pressure, int joint) const;

  private:
    std::vector<Table> per_joint_;
  };
} // namespace softchain::chain
