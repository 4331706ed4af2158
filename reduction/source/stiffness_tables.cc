// StiffnessTables: the CSV files of one (method, b) reduction.
#include <softchain/reduction/link_compliance_fit.h>
#include <softchain/data/output_files.h>
#include <softchain/reduction/stiffness_tables.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace softchain::reduction
{
  using data::CsvTable;

  StiffnessTables::StiffnessTables(const MethodReduction &reduction, const ReductionParameters &parameters)
    : reduction_(reduction)
    , parameters_(parameters)
    , joint_law_(reduction.samples(), parameters, reduction.geometry().n_joints(), in_plane_stiffness())
  {}

  std::vector<const SampleReduction *> StiffnessTables::pressure_samples() const
  {
    std::vector<const SampleReduction *> selected;
    for (const auto &sample : reduction_.samples())
      if (reduction_.stiffness().feeds(sample, 2) && sample.pressure() != 0)
        selected.push_back(&sample);
    std::stable_sort(selected.begin(), selected.end(),
                     [](const SampleReduction *a, const SampleReduction *b) {
                       return a->pressure() < b->pressure();
                     });
    const auto same_pressure = [](const SampleReduction *a, const SampleReduction *b) {
      return a->pressure() == b->pressure();
    };
    selected.erase(std::unique(selected.begin(), selected.end(), same_pressure), selected.end());
    return selected;
  }

  CsvTable StiffnessTables::stiffness() const
  {
    CsvTable table({"joint", "x_ref", "Jx", "Jy", "Jz", "Sx", "Sy", "Sz", "k_psi", "k_theta", "k_phi",
                    "k_psi_fit", "k_theta_fit", "k_phi_fit", "n_psi", "n_theta", "n_phi"});
    const auto &joints = reduction_.stiffness().joints();
    for (std::size_t i = 0; i < joints.size(); ++i)
      {
        const JointGeometry  &geometry = reduction_.geometry();
        const Eigen::Vector3d J        = geometry.reference_centre(i);
        const Eigen::Vector3d S        = geometry.reference_twist_point(i);
        const JointStiffness &k        = joints[i];
        table.add_row(std::vector<double>{
          double(i + 1), geometry.x_joint(i), J(0), J(1), J(2), S(0), S(1), S(2), k.at_largest_load(0),
          k.at_largest_load(1), k.at_largest_load(2), k.fit(0), k.fit(1), k.fit(2),
          double(k.n_used[0]), double(k.n_used[1]), double(k.n_used[2])});
      }
    return table;
  }

  CsvTable StiffnessTables::samples() const
  {
    CsvTable table({"sample", "role", "pressure", "force_norm", "joint", "psi", "theta", "phi",
                    "tau_x", "tau_y", "tau_z", "stretch_1", "stretch_2", "stretch_3"});
    for (const auto &sample : reduction_.samples())
      for (std::size_t i = 0; i < sample.joints().size(); ++i)
        {
          const JointResult &r     = sample.joints()[i];
          std::vector<std::string> cells = {sample.id(), sample.role()};
          for (const double v :
               {sample.pressure(), sample.force_norm(), double(i + 1), r.angles.psi, r.angles.theta,
                r.angles.phi, r.torque(0), r.torque(1), r.torque(2), r.stretches(0),
                r.stretches(1), r.stretches(2)})
            cells.push_back(CsvTable::cell(v));
          table.add_row(cells);
        }
    return table;
  }

  std::vector<std::map<double, double>> StiffnessTables::in_plane_stiffness() const
  {
    std::vector<std::map<double, double>> k(reduction_.geometry().n_joints());
    const CsvTable table = kphi_vs_pressure();
    for (std::size_t row = 0; row < table.n_rows(); ++row)
      {
        const double value = table.number(row, "k_phi");
        if (std::isfinite(value))
          k[static_cast<std::size_t>(table.number(row, "joint")) - 1][table.number(row, "pressure")] = value;
      }
    return k;
  }

  // The pressure samples' k_phi, then for the joints that no pressure sample
  // loads the bending samples' per pressure (ForceIncrementStiffness).
  CsvTable StiffnessTables::kphi_vs_pressure() const
  {
    CsvTable table({"pressure", "joint", "k_phi"});
    const StiffnessExtraction &extraction = reduction_.stiffness();
    for (const auto *sample : pressure_samples())
      for (std::size_t i = 0; i < sample->joints().size(); ++i)
        table.add_row(std::vector<double>{sample->pressure(), double(i + 1), extraction.single(*sample, i, 2)});
    for (std::size_t i = 0; i < reduction_.geometry().n_joints(); ++i)
      if (extraction.phi_from_bending(i))
        for (const auto &[pressure, k] : extraction.force_increments(2).fit_by_pressure(i))
          if (!std::isnan(k))
            table.add_row(std::vector<double>{pressure, double(i + 1), k});
    return table;
  }

  // k_psi(p) or k_theta(p): per pressure of the force samples, the fit to
  // their increments over the pressure-only state (ForceIncrementStiffness).
  CsvTable StiffnessTables::k_vs_pressure(int axis) const
  {
    const ForceIncrementStiffness &increments = reduction_.stiffness().force_increments(axis);
    const std::size_t              n_joints   = reduction_.geometry().n_joints();
    std::vector<std::map<double, double>> k_of_joint;
    for (std::size_t i = 0; i < n_joints; ++i)
      k_of_joint.push_back(increments.fit_by_pressure(i));
    CsvTable table({"pressure", "joint", axis == 0 ? "k_psi" : "k_theta"});
    if (n_joints > 0)
      for (const auto &row : k_of_joint[0])
        for (std::size_t i = 0; i < n_joints; ++i)
          table.add_row(std::vector<double>{row.first, double(i + 1), k_of_joint[i].at(row.first)});
    return table;
  }

  CsvTable StiffnessTables::pressure_torque() const
  {
    CsvTable table({"pressure", "joint", "jp_x", "jp_y", "jp_z"});
    std::vector<const SampleReduction *> configurations = {&reduction_.rest()};
    for (const auto *sample : pressure_samples())
      configurations.push_back(sample);
    for (const auto *sample : configurations)
      for (std::size_t i = 0; i < sample->joints().size(); ++i)
        {
          const Eigen::Vector3d &jp = sample->joints()[i].pressure_torque;
          table.add_row(std::vector<double>{sample->pressure(), double(i + 1), jp(0), jp(1), jp(2)});
        }
    return table;
  }

  CsvTable StiffnessTables::link_geometry() const
  {
    CsvTable table({"pressure", "point", "x", "y", "z", "rx", "ry", "rz"});
    std::vector<const SampleReduction *> configurations = {&reduction_.rest()};
    for (const auto *sample : pressure_samples())
      configurations.push_back(sample);
    for (const auto *sample : configurations)
      {
        const auto &points = sample->link_geometry();
        for (std::size_t i = 0; i < points.size(); ++i)
          {
            const bool            tip      = i + 1 == points.size();
            const Eigen::Vector3d rotation = tip ? sample->tip_frame() : Eigen::Vector3d::Zero();
            table.add_row({CsvTable::cell(sample->pressure()), tip ? "tip" : std::to_string(i + 1),
                           CsvTable::cell(points[i](0)), CsvTable::cell(points[i](1)),
                           CsvTable::cell(points[i](2)), CsvTable::cell(rotation(0)),
                           CsvTable::cell(rotation(1)), CsvTable::cell(rotation(2))});
          }
      }
    return table;
  }

  std::vector<std::string> StiffnessTables::write(const std::string &directory) const
  {
    const data::StiffnessFileSet files(directory, reduction_.label());
    stiffness().write(files.table);
    samples().write(files.samples);
    kphi_vs_pressure().write(files.kphi_vs_pressure);
    k_vs_pressure(1).write(files.ktheta_vs_pressure);
    k_vs_pressure(0).write(files.kpsi_vs_pressure);
    pressure_torque().write(files.pressure_torque);
    if (!reduction_.rest().link_geometry().empty())
      link_geometry().write(files.link_geometry);
    joint_law_.table().write(files.joint_law);
    const LinkShiftFit shifts(reduction_, parameters_);
    shifts.table().write(files.link_shift);
    const LinkComplianceFit compliance(reduction_, parameters_);
    compliance.table().write(files.link_compliance);
    reduction_.skin_compliance().table().write(files.skin_compliance);
    reduction_.skin_shear_compliance().table().write(files.skin_shear_compliance);
    std::vector<std::string> warnings = shifts.warnings();
    for (const std::string &w : compliance.warnings())
      warnings.push_back(w);
    for (const SkinComplianceFit *skin : {&reduction_.skin_compliance(), &reduction_.skin_shear_compliance()})
      for (const std::string &w : skin->warnings())
        warnings.push_back(w);
    return warnings;
  }
} // namespace softchain::reduction
