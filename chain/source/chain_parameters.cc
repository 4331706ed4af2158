#include <softchain/chain/chain_parameters.h>
#include <softchain/data/input_error.h>
#include <softchain/data/prm_file.h>

namespace softchain::chain
{
  namespace
  {
    // A compliance that is `measured` (nothing: the reduction's table), none
    // (0) or a value >= 0 in m/N.
    std::optional<double> compliance_setting(const data::PrmSection &section, const std::string &name)
    {
      const std::string text = section.get(name);
      if (text == "measured")
        return std::nullopt;
      if (text == "none")
        return 0.0;
      const double c = section.get_double(name);
      section.require(c >= 0, name, "must be measured, none or a compliance >= 0 in m/N");
      return c;
    }

    void declare(data::PrmSection &section)
    {
      section.declare("Stiffness method", "M2", "M1 (bounding box) or M2 (affine fit)");
      section.declare("Slab half-width", "0.5", "b / a of the stiffness CSV to use");
      section.declare("Stiffness column", "value", "value (largest load) or fit (least squares)");
      section.declare("Interpolate k_phi in pressure", "true",
                      "k_phi and J_p follow their pressure tables");
      section.declare("Link geometry", "pressure",
                      "pressure: the links stretched and sheared by the pressure as the "
                      "reduction measured them (<label>_link_geometry.csv), so that the chain "
                      "lands on the FEM finger's joints; rigid: rigid links between the "
                      "reference joint centres (the paper's chain)");
      section.declare("Link shift", "none",
                      "measured: each link shifts along its own frame as its joint turns in "
                      "the finger's plane away from the pressure-only state, by the shift per "
                      "radian the reduction fitted to the in-plane force samples "
                      "(<label>_link_shift.csv; no shift without it), so that a finger "
                      "straightened by an obstacle lengthens as the FEM's does (contact tips "
                      "closer, contact forces farther: docs/chain_fidelity.md); none: links "
                      "that do not shift. Ignored with Link geometry = rigid");
      section.declare("Link compliance", "measured",
                      "measured: the links give under forces, in series with the joints, with "
                      "the compliance c(p) the reduction fitted to the chord samples "
                      "(<label>_link_compliance.csv; links rigid without it); none: links rigid "
                      "under forces (the paper's chain). Ignored with Link geometry = rigid");
      section.declare("Joint law", "measured",
                      "measured: under forces each joint axis follows the torque-angle curve "
                      "the reduction measured over all force samples at each pressure "
                      "(<label>_joint_law.csv; linear springs without it); linear: springs "
                      "k(p) about the pressure-only state (the paper's chain)");
      section.declare("Missing stiffness", "rigid",
                      "a joint axis whose k is NaN or not positive in the CSV (no usable sample, "
                      "e.g. a joint in the solid base fill, or a torque opposite to the "
                      "rotation): rigid (held, k = 1e6 x the largest) or error");
      section.declare("Validation roles", "validation, pressure, contact",
                      "roles of the database samples compared with the chain (contact: the "
                      "finger pressed on obstacles, each compared in force too)");
      section.declare("Contact stiffness", "1e5",
                      "N/m, the penalty per point of the collision surface: a point that "
                      "carries f penetrates by f / stiffness");
      section.declare("Skin compliance", "measured",
                      "how far each link's section gives along its palm normal per newton of "
                      "contact force: measured (c_s(p) the reduction fitted to the skin samples, "
                      "<label>_skin_compliance.csv; rigid sections without it), none (rigid "
                      "sections), or a value in m/N");
      section.declare("Skin shear compliance", "measured",
                      "how far each link's section gives along the palm per newton of friction, "
                      "in series with each sticking point's penalty: measured (c_t(p) the "
                      "reduction fitted to the skin samples with 'shear F', "
                      "<label>_skin_shear_compliance.csv; sections rigid in shear without it), "
                      "none, or a value in m/N");
      section.declare("Surface subdivisions", "3",
                      "intervals per edge of the database mesh's outer faces on which the "
                      "collision surface takes its points: 1 takes the vertices, n a grid of "
                      "n x n intervals on each face (bilinear in its deformed vertices)");
      section.declare("Friction load steps", std::to_string(FrictionalPathSettings().steps),
                      "equal steps of the load path along which a contact sample with friction "
                      "is solved from rest (its stick anchors carried from step to step)");
      section.declare("Timed solves", "1",
                      "how often each validation sample is solved: its solve_time_us in "
                      "validation.csv is the median (1: the one cold solve; benchmarks take more)");
      section.declare("Baseline Young's modulus", "2.6e5", "Pa, for k_phi = E I_z / a");
      section.declare("Newton tolerance", "1e-10", "relative residual of the equilibrium");
      section.declare("Maximum Newton iterations", "50", "per equilibrium");
    }

    // Whether `name` is `yes` (else `no`, or an error naming both).
    bool either(const data::PrmSection &section, const std::string &name, const std::string &yes,
                const std::string &no)
    {
      const std::string value = section.get(name);
      section.require(value == yes || value == no, name, "'" + value + "' is neither " + yes + " nor " + no);
      return value == yes;
    }
  } // namespace

  ChainParameters ChainParameters::read(const data::PrmFile &file)
  {
    data::PrmSection section;
    declare(section);
    file.parse_section("Chain", section);

    ChainParameters p;
    p.method = section.get_enum<data::RotationMethod>("Stiffness method", data::rotation_methods());
    p.half_width_fraction = section.get_double("Slab half-width");
    section.require(p.half_width_fraction > 0, "Slab half-width", "must be positive");
    p.stiffness_column = section.get_enum<StiffnessColumn>(
      "Stiffness column", {{"value", StiffnessColumn::value}, {"fit", StiffnessColumn::fit}});
    p.in_pressure      = section.get_bool("Interpolate k_phi in pressure");
    p.pressure_link_geometry = either(section, "Link geometry", "pressure", "rigid");
    p.link_shift             = either(section, "Link shift", "measured", "none");
    p.link_compliance        = either(section, "Link compliance", "measured", "none");
    p.measured_joint_law     = either(section, "Joint law", "measured", "linear");
    p.rigid_where_missing    = either(section, "Missing stiffness", "rigid", "error");
    p.validation_roles = section.get_list("Validation roles");
    p.baseline_youngs_modulus = section.get_double("Baseline Young's modulus");
    section.require(p.baseline_youngs_modulus > 0, "Baseline Young's modulus", "must be positive");
    p.newton.tolerance = section.get_double("Newton tolerance");
    section.require(p.newton.tolerance > 0, "Newton tolerance", "must be positive");
    p.newton.contact_stiffness = section.get_double("Contact stiffness");
    section.require(p.newton.contact_stiffness > 0, "Contact stiffness", "must be positive");
    p.skin_compliance       = compliance_setting(section, "Skin compliance");
    p.skin_shear_compliance = compliance_setting(section, "Skin shear compliance");
    // Upper bounds far above any use (the collision surface grows with the
    // square of its subdivisions: 16 puts 28 times the points of the default
    // 3 on it), so that a mistyped value is an error, not hours of solves.
    p.surface_subdivisions    = section.get_integer("Surface subdivisions", 1, 16);
    p.timed_solves            = section.get_integer("Timed solves", 1, 1000);
    p.friction_path.steps     = section.get_integer("Friction load steps", 1, 1000);
    p.newton.max_iterations   = section.get_integer("Maximum Newton iterations", 1, 100000);
    return p;
  }
} // namespace softchain::chain
