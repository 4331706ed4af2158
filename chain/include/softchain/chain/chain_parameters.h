#pragma once
// ChainParameters: the chain tier's subsection of the design's .prm file
// (other subsections belong to the other tiers and are ignored here):
//   subsection Chain
//     set Stiffness method = M2                  # M1 | M2: which reduction
//     set Slab half-width = 0.5                  # b / a: selects the CSV
//     set Stiffness column = value               # value | fit
//     set Interpolate k_phi in pressure = true   # k_phi(p) and J_p(p) tables
//     set Link geometry = pressure               # pressure | rigid
//     set Link compliance = measured             # measured | none
//     set Joint law = measured                   # measured | linear
//     set Validation roles = validation, pressure
//     set Baseline Young's modulus = 2.6e5       # Pa, beam-theory baseline
//     set Newton tolerance = 1e-10               # relative residual
//     set Maximum Newton iterations = 50
//   end
// Bad values are InputErrors naming file, line and parameter.
#include <softchain/chain/frictional_load_path.h>
#include <softchain/chain/stiffness_files.h>
#include <softchain/data/prm_file.h>

#include <optional>
#include <string>
#include <vector>

namespace softchain::chain
{
  struct ChainParameters
  {
    data::RotationMethod     method              = data::RotationMethod::affine_fit;
    double                   half_width_fraction = 0.5;
    StiffnessColumn          stiffness_column    = StiffnessColumn::value;
    bool                     in_pressure         = true;
    bool                     pressure_link_geometry = true; // links as the pressure shapes them (LinkGeometry)
    bool                     link_shift          = false; // links shift as their joints turn (LinkShiftPerTurn)
    bool                     link_compliance     = true; // links in series with the joints (LinkCompliance)
    // The sections' give under contact (ChainModel::skin_compliance): none:
    // the reduction's table; a value: that compliance at every pressure, m/N
    // (0: rigid sections).
    std::optional<double>    skin_compliance;
    // The sections' give along the palm under friction
    // (ChainModel::skin_shear_compliance), the same way.
    std::optional<double>    skin_shear_compliance;
    bool                     measured_joint_law  = true; // joints follow the measured curves (JointForceLaw)
    bool                     rigid_where_missing = true; // NaN or k <= 0: rigid joint (or an error)
    std::vector<std::string> validation_roles    = {"validation", "pressure"};
    double                   baseline_youngs_modulus = 2.6e5;
    EquilibriumSettings      newton;
    FrictionalPathSettings   friction_path; // the load path of a contact sample with friction
    int                      surface_subdivisions = 3; // intervals per edge of the collision surface's mesh faces
    int                      timed_solves = 1; // solves of each validation sample, solve_time_us their median

    static ChainParameters read(const data::PrmFile &file);
  };
} // namespace softchain::chain
