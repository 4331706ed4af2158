#pragma once
// ForceIncrementStiffness: a joint's stiffness about one axis from force
// samples made at pressure (Samples/Force sample pressures). Per force sample
// s and joint i, the increment over the pressure-only state b at the same
// pressure (the rest at p = 0),
//   d q = q_i(s) - q_i(b),   d tau = tau_i(s) - tau_i(b)   (the axis' angle
// and torque), with q_i(b) the joint's free angle in b (SampleReduction: the
// rotation a torque-free joint passes on there), and k = d tau / d q.
// Increments, not totals: the pressure alone turns the joints a little about
// psi and theta too (the helical threads), which would otherwise be charged
// to the force.
//
// The chain's springs are linear about the pressure-only state, so per
// pressure the fit uses the smallest loads that turn the joint measurably:
// the `smallest_loads` lightest usable increments (0: all). A finger's
// response to a tip force is not linear in it: inflated, P10 resists a small
// lateral force by twisting and bends sideways only as the force grows
// (theta grows like f^2 at 20 kPa), and past about 0.7 N it buckles. A fit
// over all forces would give the chain the slope of the large ones.
//
// Uses: k_phi of the joints that no pressure sample loads (the in-plane tip
// force samples: a closed cavity's pressure has no net moment about a
// section distal to which the whole cavity lies, P10's joint 1 in the solid
// base fill), and k_theta(p), k_psi(p) (lateral and torsion samples).
// |d q| below the threshold gives no value; a force sample without a
// pressure-only state at its pressure gives nothing (counted). Nor does an
// increment whose torque about this axis is less than a quarter of the
// joint's torque increment |d tau| (all three axes): the joint then turns
// about this axis mostly through its coupling to the others, and d tau / d q
// is not its stiffness. P10 at 40 kPa is curled by 92 degrees, so the torsion
// couple (at the tip, about the base's x axis) bends joints 8 and 9 rather
// than twisting them (0.10 and 0.004 of their torque about psi, against
// 0.31-1 at joints 1-7), and gave them k_psi = 0.040 and 0.0027 N m/rad
// against 0.066 and 0.072 at 20 kPa; the chain then twisted sideways under
// the blocked force (docs/chain_fidelity.md, "Contact in the chain"). Such a
// pressure gets no value, and the chain interpolates k(p) from the others.
#include <softchain/reduction/sample_reduction.h>

#include <map>
#include <string>
#include <vector>

namespace softchain::reduction
{
  // The pressure-only state at `pressure` that force samples there are
  // measured from: a sample of one of `pressure_roles`, or the rest (nullptr
  // with `found`) at p = 0; `found` false if there is none.
  const SampleReduction *pressure_state(const std::vector<SampleReduction> &samples,
                                        const std::vector<std::string>     &pressure_roles,
                                        double pressure, bool &found);

  class ForceIncrementStiffness
  {
  public:
    // axis: 0 = psi, 1 = theta, 2 = phi.
    ForceIncrementStiffness(const std::vector<SampleReduction> &samples,
                            const std::vector<std::string>     &force_roles,
                            const std::vector<std::string>     &pressure_roles,
                            int axis, double threshold, int smallest_loads);

    // Over all pressures and loads; NaN where no increment gives a value.
    double at_largest_load(std::size_t joint) const;
    double fit(std::size_t joint) const;
    int    n_used(std::size_t joint) const;
    // Least-squares k per pressure of the force samples over the
    // `smallest_loads` lightest usable increments; NaN where none is usable.
    std::map<double, double> fit_by_pressure(std::size_t joint) const;
    // Force samples that had no pressure-only state at their pressure.
    int n_without_base() const { return n_without_base_; }

  private:
    struct Increment
    {
      double              pressure;
      double              force;
      std::vector<double> angle;  // d q per joint
      std::vector<double> torque; // d tau per joint
      std::vector<double> share;  // |d tau about the axis| / |d tau| per joint
    };
    static constexpr double min_share = 0.25;
    bool   usable(const Increment &increment, std::size_t joint) const;
    double fit_over(const std::vector<const Increment *> &increments, std::size_t joint) const;

    std::vector<Increment> increments_; // by increasing load: pressure, then force
    double                 threshold_;
    int                    smallest_loads_;
    int                    n_without_base_ = 0;
  };
} // namespace softchain::reduction
