// ReductionParameters: declares, reads and checks "subsection Reduction".
#include <softchain/data/input_error.h>
#include <softchain/data/prm_file.h>
#include <softchain/reduction/joint_layout.h>
#include <softchain/reduction/reduction_parameters.h>

#include <algorithm>

namespace softchain::reduction
{
  namespace
  {
    void declare(data::PrmSection &section)
    {
      section.declare("Joint spacing", "0.01", "a [m]: distance between joints");
      section.declare("Number of joints", "0", "0: round(L/a), L the x-extent of the mesh");
      section.declare("Joint placement", "strain-limiting layer",
                      "strain-limiting layer | paper (bounding-box centres, Sec. III-C)");
      section.declare("Joint height", "auto",
                      "y of the strain-limiting layer [m]; auto: fitted to the pressure samples");
      section.declare("Twist axis offset", "auto",
                      "height [m] of the joints' twist axis above them; auto: fitted to the "
                      "torsion samples");
      section.declare("Slab half-widths", "1, 0.5, 0.3333333333333333", "b as fractions of a");
      section.declare("Methods", "M1, M2", "M1: bounding box, M2: affine fit");
      section.declare("Rotation threshold", "0.0017453292519943296",
                      "rad: a smaller |angle| gives no stiffness");
      section.declare("Pressure roles", "pressure", "sample roles feeding k_phi");
      section.declare("Lateral roles", "lateral", "sample roles feeding k_theta");
      section.declare("Torsion roles", "torsion", "sample roles feeding k_psi");
      section.declare("Bending roles", "bending",
                      "sample roles (in-plane tip forces) feeding k_phi of the joints that the "
                      "pressure does not load");
      section.declare("Chord roles", "chord",
                      "sample roles (tip forces along the base-tip chord) feeding the links' "
                      "compliance c(p)");
      section.declare("Skin roles", "skin",
                      "sample roles (forces pressing the palm along its normal) feeding the "
                      "sections' compliance c_s(p)");
      section.declare("Force samples per fit", "1",
                      "k_psi(p), k_theta(p) and the bending samples' k_phi(p) are fitted to the "
                      "lightest this many force samples per pressure that turn the joint "
                      "measurably (the chain's springs are linear about the pressure-only "
                      "state); 0: all");
      section.declare("Plots", "true", "PNG plots via gnuplot when it is installed");
    }

    std::vector<RotationMethod> read_methods(const data::PrmSection &section)
    {
      std::vector<RotationMethod> result;
      const auto &methods = data::rotation_methods();
      for (const auto &name : section.get_list("Methods"))
        {
          const auto known = std::find_if(methods.begin(), methods.end(),
                                          [&](const auto &m) { return m.first == name; });
          section.require(known != methods.end(), "Methods",
                          "unknown method '" + name + "' (M1 or M2)");
          result.push_back(known->second);
        }
      section.require(!result.empty(), "Methods", "no method given");
      return result;
    }

    JointPlacement read_placement(const data::PrmSection &section)
    {
      const std::string name = section.get("Joint placement");
      section.require(name == "strain-limiting layer" || name == "paper", "Joint placement",
                      "unknown placement '" + name + "' (strain-limiting layer or paper)");
      return name == "paper" ? JointPlacement::paper : JointPlacement::strain_limiting_layer;
    }

    // "auto" (NaN: measured) or a height in metres.
    // A length in metres, or NaN for `auto` (measured by the reduction).
    double read_length_or_auto(const data::PrmSection &section, const std::string &name)
    {
      if (section.get(name) == "auto")
        return NAN;
      const double y = section.get_double(name);
      section.require(std::isfinite(y), name, "must be a number of metres or auto");
      return y;
    }
  } // namespace

  ReductionParameters ReductionParameters::read(const data::PrmFile &file)
  {
    data::PrmSection section;
    declare(section);
    file.parse_section("Reduction", section);

    ReductionParameters p;
    p.joint_spacing = section.get_double("Joint spacing");
    section.require(p.joint_spacing > 0, "Joint spacing", "must be positive");
    p.n_joints = section.get_integer("Number of joints");
    section.require(p.n_joints >= 0, "Number of joints", "must be >= 0");
    section.require(p.n_joints <= max_joints, "Number of joints",
                    "must be at most " + std::to_string(max_joints));
    p.placement    = read_placement(section);
    p.joint_height      = read_length_or_auto(section, "Joint height");
    p.twist_axis_offset = read_length_or_auto(section, "Twist axis offset");
    p.slab_half_width_fractions = section.get_double_list("Slab half-widths");
    section.require(!p.slab_half_width_fractions.empty(), "Slab half-widths", "no value given");
    for (const double f : p.slab_half_width_fractions)
      section.require(f > 0, "Slab half-widths", "fractions must be positive");
    p.methods            = read_methods(section);
    p.rotation_threshold = section.get_double("Rotation threshold");
    section.require(p.rotation_threshold >= 0, "Rotation threshold", "must be >= 0");
    p.pressure_roles = section.get_list("Pressure roles");
    p.lateral_roles  = section.get_list("Lateral roles");
    p.torsion_roles  = section.get_list("Torsion roles");
    p.bending_roles  = section.get_list("Bending roles");
    p.chord_roles    = section.get_list("Chord roles");
    p.skin_roles     = section.get_list("Skin roles");
    p.force_samples_per_fit = section.get_integer("Force samples per fit");
    section.require(p.force_samples_per_fit >= 0, "Force samples per fit", "must be >= 0");
    p.plots          = section.get_bool("Plots");
    return p;
  }
} // namespace softchain::reduction
