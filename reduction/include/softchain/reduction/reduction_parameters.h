#pragma once
// ReductionParameters: the "subsection Reduction" of a design's .prm file
// (reduction/README.md lists the entries). Everything else in the file belongs
// to the other tiers and is ignored here.
#include <softchain/data/prm_file.h>
#include <softchain/data/rotation_method.h>

#include <cmath>
#include <string>
#include <vector>

namespace softchain::reduction
{
  using data::RotationMethod;

  // Where the joints sit and what orients the links (joint_geometry.h).
  enum class JointPlacement
  {
    paper,                // joints at the slab bounding-box centres (Sec. III-C)
    strain_limiting_layer // joints on the layer that does not stretch
  };

  struct ReductionParameters
  {
    double                      joint_spacing = 0.01; // a [m]
    int                         n_joints      = 0;    // 0: round(L / a)
    JointPlacement              placement     = JointPlacement::strain_limiting_layer;
    double                      joint_height  = NAN;  // y_n [m]; NaN: measured
    double                      twist_axis_offset = NAN; // t [m] above the joints; NaN: fitted
    std::vector<double>         slab_half_width_fractions; // b / a
    std::vector<RotationMethod> methods;
    double                      rotation_threshold = 0.0; // rad
    std::vector<std::string>    pressure_roles;           // feed k_phi
    std::vector<std::string>    lateral_roles;            // feed k_theta
    std::vector<std::string>    torsion_roles;            // feed k_psi
    std::vector<std::string>    bending_roles;            // feed k_phi where no pressure does
    std::vector<std::string>    chord_roles;              // feed the links' compliance
    std::vector<std::string>    skin_roles;               // feed the sections' compliance
    int                         force_samples_per_fit = 1; // lightest per pressure; 0: all
    bool                        plots = true;

    // Parses and checks "subsection Reduction" of `file`; throws
    // data::InputError naming file, line and parameter.
    static ReductionParameters read(const data::PrmFile &file);
  };
} // namespace softchain::reduction
