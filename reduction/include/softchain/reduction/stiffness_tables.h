#pragma once
// StiffnessTables: the CSV files of one MethodReduction, read by the chain
// tier (columns documented in reduction/README.md; SI units, "nan" for no
// value):
//   <label>.csv                   per joint: reference centre, k at the largest
//                                 load, least-squares k, samples used
//   <label>_samples.csv           per sample and joint: angles, torques, stretches
//   <label>_kphi_vs_pressure.csv  per pressure sample and joint: k_phi
//   <label>_ktheta_vs_pressure.csv,
//   <label>_kpsi_vs_pressure.csv  per pressure of the lateral (torsion)
//                                 samples and joint: their least-squares k
//   <label>_joint_law.csv         per pressure of the force samples and joint:
//                                 the FabricHinge law fitted to their
//                                 increments (FabricHingeFit)
//   <label>_pressure_torque.csv   J_p per joint at rest (pressure 0) and at
//                                 each pressure sample
//   <label>_link_geometry.csv     the chain's link geometry (joints 1..n and
//                                 the tip at zero angles, the tip frame in
//                                 the last link's) at rest and at each
//                                 pressure sample; not written for a mesh
//                                 without a tip face
//   <label>_link_shift.csv        per pressure of the in-plane force samples
//                                 and link: the link's shift per radian of
//                                 its joint's in-plane turn (LinkShiftFit); no
//                                 rows without such samples
//   <label>_link_compliance.csv   the links' compliance c per pressure of the
//                                 chord samples (LinkComplianceFit); no rows
//                                 without chord samples
#include <softchain/data/csv_table.h>
#include <softchain/reduction/fabric_hinge_fit.h>
#include <softchain/reduction/link_shift_fit.h>
#include <softchain/reduction/method_reduction.h>

#include <string>

namespace softchain::reduction
{
  class StiffnessTables
  {
  public:
    StiffnessTables(const MethodReduction &reduction, const ReductionParameters &parameters);

    data::CsvTable stiffness() const;
    data::CsvTable samples() const;
    data::CsvTable kphi_vs_pressure() const;
    // axis 0 (psi) or 1 (theta): k over the samples feeding it at each of
    // their distinct pressures, by increasing pressure.
    data::CsvTable k_vs_pressure(int axis) const;
    data::CsvTable pressure_torque() const;
    data::CsvTable link_geometry() const;
    // The joints' law under forces (written as <label>_joint_law.csv).
    const FabricHingeFit &joint_law() const { return joint_law_; }

    // Writes the files into `directory` (created if missing); returns the
    // link compliance fit's warnings.
    std::vector<std::string> write(const std::string &directory) const;

  private:
    // The samples fed to k_phi, one per distinct nonzero pressure (the first
    // in sample id order), by increasing pressure: the pressure tables hold
    // one row per (pressure, joint), the rest configuration being p = 0.
    std::vector<const SampleReduction *> pressure_samples() const;
    // Per joint, k_phi(p) of kphi_vs_pressure (the chain's in-plane springs).
    std::vector<std::map<double, double>> in_plane_stiffness() const;

    const MethodReduction     &reduction_;
    ReductionParameters        parameters_;
    FabricHingeFit             joint_law_;
  };
} // namespace softchain::reduction
