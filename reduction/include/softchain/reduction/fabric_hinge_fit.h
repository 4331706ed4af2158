#pragma once
// FabricHingeFit: per joint and pressure of the force samples, the
// data::FabricHinge (three linear springs and the fabric layer's two
// tension-only edge fibres) that best reproduces the torque increments of
// all force samples made there (torsion, lateral and bending roles), over
// the pressure-only state at the same pressure (as ForceIncrementStiffness
// measures them: d q = q_i(s) - q_i(b), d tau = tau_i(s) - tau_i(b)).
//
// The fit. At fixed lever ratio r, pre-stretch theta_0 and layer give g
// the torque is linear in (k_psi, k_theta, k_phi, kappa):
//   d tau = diag(k) d q + kappa t(d q; r, theta_0, g)   (FabricHinge, t the
//   fibres' torque per unit kappa)
// so it is a linear least-squares problem, each sample's rows weighted by
// 1 / |d tau| (every force level counts alike). k_psi has rows of its own
// (every sample's); (k_theta, k_phi, kappa) are solved on a grid of r in
// [-3, 3] (step 0.05), theta_0 in {0} and max|d theta| 2^(-i/2), i = 0..20,
// and g in {0} and 2^(l-2), l = 0..8, and the linear springs alone (kappa
// = 0); the smallest residual with every k > 0 and kappa >= 0 wins. A grid
// holds the r, theta_0 and g of a law it was made from, so such samples are
// fitted exactly (tested). The torsion samples' theta and phi rows are left
// out: a couple tilts theta with psi without a torque about theta, which no
// law reproduces (docs/chain_fidelity.md, "theta of the inflated finger").
//
// Inflated (p > 0) the layer is pre-stressed, and a law must (Constraints)
// - keep the in-plane tangent at the pressure state, k_phi + kappa f, at
//   the chain's k_phi(p) (in_plane): the secant that a blocked finger's
//   straightening spans;
// - have theta_0 > 0 and its knee torque 2 kappa theta_0 within the lateral
//   samples' |d tau_theta|: they show the stiff start and the soft
//   continuation (P10 at 40 and 50 kPa stays below its knee; a knee under
//   the lightest force let the blocked finger twist out of its plane);
// - keep k_theta at least the rest law's of the joint (inflating does not
//   soften the silicone);
// - at least halve the springs' residual (a quarter of its square): the
//   fibres add four parameters.
// Measured on P10: reduction/README.md, docs/chain_fidelity.md.
//
// Samples used: those turning the joint by at least the rotation threshold,
// per role and pressure by increasing force while |d q| and |d tau| keep
// growing and the FEM passed no limit point of the forces on the way: a
// force past a limit point (sideways buckling) and the heavier ones are left
// out and counted. The law holds up to the limit; the chain does not follow
// the finger past it. A (joint, pressure) whose samples admit no
// positive fit, or whose fit misses their torques by more than 15 %, gets no
// law: the chain keeps its linear springs there.

#include <softchain/data/csv_table.h>
#include <softchain/data/fabric_hinge.h>
#include <softchain/reduction/reduction_parameters.h>
#include <softchain/reduction/sample_reduction.h>

#include <limits>
#include <map>
#include <string>
#include <vector>

namespace softchain::reduction
{
  class FabricHingeFit
  {
  public:
    // `in_plane`: per joint, the chain's k_phi(p) at the pressures where it
    // has one (kphi_vs_pressure): an inflated law keeps it as its in-plane
    // tangent at the pressure state.
    FabricHingeFit(const std::vector<SampleReduction> &samples, const ReductionParameters &parameters,
                   std::size_t n_joints, const std::vector<std::map<double, double>> &in_plane = {});

    struct Fit
    {
      double            pressure = 0.0;
      std::size_t       joint    = 0; // 0-based
      data::FabricHinge hinge;
      int               n_samples = 0;
      double            relative_residual = 0.0; // |weighted residual| / |weighted d tau|
    };
    const std::vector<Fit> &fits() const { return fits_; }
    // (joint, pressure) pairs without a law (above), and increments left
    // out past a limit point (over all joints).
    int n_without_fit() const { return n_without_fit_; }
    int n_past_limit() const { return n_past_limit_; }

    // pressure,joint,k_psi,k_theta,k_phi,kappa,r,theta_0,samples,relative_residual
    data::CsvTable table() const;

    // One force sample's increment at one joint.
    struct Increment
    {
      // twist: a torsion role (only its psi rows are fitted); lateral: a
      // lateral role; bend: the other force roles.
      enum class Kind
      {
        twist,
        lateral,
        bend
      };
      std::string     role;
      double          pressure;
      double          force;  // N, the sample's force_norm
      Eigen::Vector3d angle;  // d q
      Eigen::Vector3d torque; // d tau
      bool            past_force_limit = false; // the sample buckled on the way
      Kind            kind             = Kind::bend;
    };
    // What an inflated law (p > 0) keeps (the header's rules): its in-plane
    // tangent at the pressure state (NaN: free), a knee torque 2 kappa
    // theta_0 within [knee_low, knee_high], k_theta of at least
    // k_theta_floor; at rest (inflated false) nothing.
    struct Constraints
    {
      bool   inflated      = false;
      double in_plane      = std::numeric_limits<double>::quiet_NaN();
      double knee_low      = 0.0;
      double knee_high     = 0.0;
      double k_theta_floor = 0.0;
      // Whether a fibre candidate (x = k_theta, k_phi, kappa, and its
      // weighted squared residual) meets them, the springs alone leaving
      // `springs_residual`.
      bool admit(const data::FabricHinge &trial, const Eigen::Vector3d &x, double residual,
                 double springs_residual) const;
    };
    // Those turning the joint by at least `threshold`, per role up to the
    // first past a limit point (the rest counted in `n_past_limit`).
    static std::vector<Increment> usable(const std::vector<Increment> &all, double threshold,
                                         int &n_past_limit);
    // The law of one joint at one pressure (hinge, n_samples and
    // relative_residual of `result`); false without a positive fit.
    static bool fit(const std::vector<Increment> &increments, Fit &result, const Constraints &constraints);
    static bool fit(const std::vector<Increment> &increments, Fit &result); // unconstrained

  private:
    // Inflated (p > 0): the chain's k_phi(p) of the joint as the in-plane
    // tangent to keep, the lateral samples' range of |d tau_theta| as the
    // knee's, and the rest law's k_theta as the floor of k_theta (fits_ so
    // far); at rest none.
    Constraints constraints(const std::vector<Increment> &increments, double pressure, std::size_t joint,
                            const std::vector<std::map<double, double>> &in_plane) const;
    // Per joint and pressure, the increments of every force sample that has
    // a pressure-only state at its pressure.
    static std::vector<std::map<double, std::vector<Increment>>>
    increments_of(const std::vector<SampleReduction> &samples, const ReductionParameters &parameters,
                  std::size_t n_joints);

    std::vector<Fit> fits_;
    int              n_without_fit_ = 0;
    int              n_past_limit_  = 0;
  };
} // namespace softchain::reduction
