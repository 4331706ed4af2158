#pragma once
// FabricHingeFit: per joint and pressure of the force samples, the
// data::FabricHinge (three linear springs and the fabric layer's two
// tension-only edge fibres) that best reproduces the torque increments of
// all force samples made there (torsion, lateral and bending roles), over
// the pressure-only state at the same pressure (as ForceIncrementStiffness
// measures them: d q = q_i(s) - q_i(b), d tau = tau_i(s) - tau_i(b)).
//
// The fit. At fixed lever ratio r and pre-stretch theta_0 the torque is
// linear in (k_psi, k_theta, k_phi, kappa):
//   d tau = diag(k) d q + kappa g(d q; r, theta_0)   (FabricHinge)
// so it is a linear least-squares problem, each sample's three rows weighted
// by 1 / |d tau| (every force level counts alike). k_psi has rows of its
// own; (k_theta, k_phi, kappa) are solved on a grid of r in [-3, 3] (step
// 0.05) and theta_0 in {0} and max|d theta| 2^(-i/2), i = 0..20, and the
// linear springs alone (kappa = 0); the smallest residual with every k > 0
// and kappa >= 0 wins. A grid holds the r and theta_0 of a law it was made
// from, so such samples are fitted exactly (tested).
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

#include <map>
#include <string>
#include <vector>

namespace softchain::reduction
{
  class FabricHingeFit
  {
  public:
    FabricHingeFit(const std::vector<SampleReduction> &samples, const ReductionParameters &parameters,
                   std::size_t n_joints);

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
      std::string     role;
      double          pressure;
      double          force;  // N, the sample's force_norm
      Eigen::Vector3d angle;  // d q
      Eigen::Vector3d torque; // d tau
      bool            past_force_limit = false; // the sample buckled on the way
    };
    // Those turning the joint by at least `threshold`, per role up to the
    // first past a limit point (the rest counted in `n_past_limit`).
    static std::vector<Increment> usable(const std::vector<Increment> &all, double threshold,
                                         int &n_past_limit);
    // The law of one joint at one pressure (hinge, n_samples and
    // relative_residual of `result`); false without a positive fit.
    static bool fit(const std::vector<Increment> &increments, Fit &result);

  private:
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
