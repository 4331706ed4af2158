#include <softchain/chain/mjcf_export.h>
#include <softchain/data/input_error.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace softchain::chain
{
  namespace
  {
    std::string triple(const Eigen::Vector3d &v)
    {
      std::ostringstream s;
      s.precision(17);
      s << v.x() << " " << v.y() << " " << v.z();
      return s.str();
    }

    std::string number(double v)
    {
      std::ostringstream s;
      s.precision(17);
      s << v;
      return s.str();
    }

    const char *axis_names[3] = {"psi", "theta", "phi"};
    const char *axis_vectors[3] = {"1 0 0", "0 1 0", "0 0 1"};

    std::string joint_name(int i, int axis)
    {
      return "joint" + std::to_string(i + 1) + "_" + axis_names[axis];
    }

    // The chain with K and J_p frozen at pressure p* (> 0), or with the
    // CSV's K and the rest J_p (p* = 0): one K and one J_p, as in MJCF.
    ChainModel constant_model(const ChainModel &model, double pressure)
    {
      std::vector<Eigen::Vector3d> k;
      const Eigen::VectorXd diagonal = model.stiffness().diagonal(pressure);
      for (int i = 0; i < model.chain().n_joints(); ++i)
        k.push_back(pressure > 0 ? Eigen::Vector3d(diagonal.segment<3>(3 * i)) : model.stiffness().joint(i));
      const Eigen::VectorXd jp = pressure > 0 ? model.actuation().torque_per_pascal(pressure)
                                              : model.actuation().rest_torque_per_pascal();
      return ChainModel(model.name(), model.without_link_shift().chain_at(pressure), JointStiffness(k), PressureActuation(jp));
    }
  } // namespace

  MjcfExport::MjcfExport(const ChainModel &model, MjcfOptions options)
    : options_(options)
    , exported_(constant_model(model, options.pressure))
    , tables_(PressureTables::of_model(model, std::max(options.pressure, options.max_pressure)))
  {}

  ChainModel MjcfExport::exported_model() const { return exported_; }

  // Body of link i (nested: the XML of the distal links inside).
  std::string MjcfExport::body(int i) const
  {
    const KinematicChain &chain = exported_.chain();
    const bool            last  = i + 1 == chain.n_joints();
    const Eigen::Vector3d to_next =
      (last ? chain.link_tip() : chain.link_joint(i + 1)) - chain.link_joint(i);
    const Eigen::Vector3d offset =
      i == 0 ? chain.link_joint(0) : Eigen::Vector3d(chain.link_joint(i) - chain.link_joint(i - 1));
    const std::string indent(2 * i + 4, ' ');
    std::ostringstream s;
    s << indent << "<body name=\"link" << i + 1 << "\" pos=\"" << triple(offset) << "\">\n";
    for (int axis = 0; axis < 3; ++axis)
      {
        // MuJoCo turns a body's hinges in order, each about its anchor `pos`
        // in the body's current frame: psi about the twist pivot J_i + o_i,
        // then theta and phi about the joint centre J_i (KinematicChain).
        const Eigen::Vector3d &pivot = chain.twist_offset(i);
        const double           k     = exported_.stiffness().joint(i)[axis];
        s << indent << "  <joint name=\"" << joint_name(i, axis) << "\" axis=\"" << axis_vectors[axis] << "\"";
        if (axis == 0 && pivot != Eigen::Vector3d::Zero())
          s << " pos=\"" << triple(pivot) << "\"";
        s << " stiffness=\"" << number(k) << "\" damping=\"" << number(k * options_.damping_time) << "\"/>\n";
      }
    const Eigen::Vector3d side(0.0, 0.0, options_.capsule_offset);
    std::string           capsule =
      "<geom name=\"link" + std::to_string(i + 1) + "\" fromto=\"" + triple(-side) + " " + triple(to_next - side) + "\"/>\n";
    if (options_.capsule_offset > 0.0)
      capsule += indent + "  <geom name=\"link" + std::to_string(i + 1) + "_side\" fromto=\"" + triple(side) + " " +
                 triple(to_next + side) + "\"/>\n";
    if (gives(i))
      {
        const double k = 1.0 / tables_.skin_compliance(options_.pressure);
        s << indent << "  <body name=\"skin" << i + 1 << "\">\n"
          << indent << "    <joint name=\"skin" << i + 1 << "\" type=\"slide\" axis=\"0 1 0\" stiffness=\""
          << number(k) << "\" damping=\"" << number(k * options_.damping_time) << "\"/>\n"
          << indent << "    " << capsule << indent << "  </body>\n";
      }
    else
      s << indent << "  " << capsule;
    if (last)
      s << indent << "  <site name=\"tip\" pos=\"" << triple(to_next) << "\"/>\n";
    else
      s << body(i + 1);
    s << indent << "</body>\n";
    return s.str();
  }

  // A link with a skin leaves its capsule's mass to the skin body: MuJoCo's
  // lower bound on every body's mass and inertia keeps the link body's
  // hinges defined (1 mg, negligible beside a capsule's grams).
  bool MjcfExport::any_skin() const
  {
    for (std::size_t i = 0; i < options_.skin_links.size(); ++i)
      if (gives(static_cast<int>(i)))
        return true;
    return false;
  }

  bool MjcfExport::gives(const int i) const
  {
    return tables_.has_skin() && static_cast<std::size_t>(i) < options_.skin_links.size() &&
           options_.skin_links[i];
  }

  // A fixed tendon over every hinge that the pressure turns at some tabulated
  // pressure (coefficient J_p(p*), possibly 0), and the motor driving it.
  std::string MjcfExport::pressure_actuator() const
  {
    const Eigen::VectorXd &jp = exported_.actuation().rest_torque_per_pascal();
    std::ostringstream     coefficients;
    for (Eigen::Index j = 0; j < jp.size(); ++j)
      if (tables_.turns_hinge(static_cast<int>(j)))
        coefficients << "      <joint joint=\"" << joint_name(int(j / 3), int(j % 3))
                     << "\" coef=\"" << number(jp[j]) << "\"/>\n";
    if (coefficients.str().empty())
      return "";
    const std::string range = options_.max_pressure > 0
                                ? " ctrllimited=\"true\" ctrlrange=\"0 " + number(options_.max_pressure) + "\""
                                : " ctrllimited=\"false\"";
    return "  <tendon>\n    <fixed name=\"pressure\">\n" + coefficients.str() +
           "    </fixed>\n  </tendon>\n  <actuator>\n    <motor name=\"pressure\" tendon=\"pressure\" "
           "gear=\"1\"" + range + "/>\n  </actuator>\n";
  }

  std::string MjcfExport::text() const
  {
    std::ostringstream s;
    s << "<mujoco model=\"" << exported_.name() << "\">\n"
      << "  <!-- SoftChain chain tier: spherical joint = hinges x, y, z (R = Rx Ry Rz),\n"
      << "       stiffness from the reduction's CSV, control 'pressure' in Pa. The custom\n"
      << "       numeric fields are the chain's stiffness k(p), pressure torque per pascal\n"
      << "       J_p(p) and link points U(p) (joints 1..n, tip) at the pressures of\n"
      << "       softchain_pressure, linear between them; set them at every pressure for a\n"
      << "       finger exact at all pressures (SoftChain docs/chain_fidelity.md, MuJoCo). -->\n"
      << "  <compiler angle=\"radian\"" << (any_skin() ? " boundmass=\"1e-6\" boundinertia=\"1e-12\"" : "")
      << "/>\n"
      << "  <option timestep=\"" << number(0.1 * options_.damping_time)
      << "\" integrator=\"Euler\"/>\n"
      << "  <default>\n"
      << "    <joint type=\"hinge\" limited=\"false\"/>\n"
      << "    <geom type=\"capsule\" size=\"" << number(options_.link_radius) << "\" density=\""
      << number(options_.density) << "\" contype=\"0\" conaffinity=\"1\"/>\n"
      << "  </default>\n"
      << "  <worldbody>\n"
      << body(0) << "  </worldbody>\n"
      << pressure_actuator() << tables_.mjcf("  ") << "</mujoco>\n";
    return s.str();
  }

  void MjcfExport::write(const std::string &path) const
  {
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    if (!parent.empty())
      std::filesystem::create_directories(parent);
    std::ofstream out(path);
    out << text();
    if (!out)
      throw data::InputError("cannot write MJCF file '" + path + "'");
  }
} // namespace softchain::chain
