#include <softchain/chain/mujoco_scene.h>
#include <softchain/chain/mujoco_model_file.h>
#include <softchain/data/input_error.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace softchain::chain
{
  namespace
  {
    constexpr double cylinder_half_length = 0.1; // m, longer than the finger is wide
    // s. The exported 1 ms is 10 times inside the hinges' stability limit
    // 2 c / k = 0.02 s (MjcfExport); 5 ms keeps 4 steps in MuJoCo's default
    // contact time constant (0.02 s, at least 2 steps needed) and gives the
    // P10 steady contact forces of 1 ms within 0.03 %, 5 times faster.
    constexpr double scene_timestep = 0.005;
    // The no-slip passes with friction: 30 and 100 gave the same P10 forces
    // to 0.05 %, 20 with the pyramidal cone left the rough cylinder 11 % light.
    constexpr int noslip_iterations = 30;

    std::string triple(const data::Point3 &x)
    {
      std::ostringstream s;
      s.precision(17);
      s << x[0] << ' ' << x[1] << ' ' << x[2];
      return s.str();
    }

    std::string error_prefix(const data::ObstacleRecord &o)
    {
      return "subsection Contact/" + o.name + ": ";
    }

    // The obstacle as a MuJoCo geom named "obstacle", fixed in the world.
    std::string obstacle_geom(const data::ObstacleRecord &o)
    {
      if (o.motion != data::Point3{})
        throw data::InputError(error_prefix(o) + "Motion = " + triple(o.motion) +
                               ": softchain simulate holds the obstacle still (set Motion = 0, 0, 0)");
      if (o.motion_rotation != data::Point3{})
        throw data::InputError(error_prefix(o) + "Motion rotation = " + triple(o.motion_rotation) +
                               ": softchain simulate holds the obstacle still (set Motion rotation = 0, 0, 0)");
      std::ostringstream geom;
      geom.precision(17);
      geom << "<geom name=\"obstacle\" pos=\"" << triple(o.position) << "\" ";
      if (o.shape == "plane")
        geom << "type=\"plane\" zaxis=\"" << triple(o.direction) << "\" size=\"1 1 0.01\"";
      else if (o.shape == "sphere")
        geom << "type=\"sphere\" size=\"" << o.radius << "\"";
      else if (o.shape == "cylinder")
        geom << "type=\"cylinder\" zaxis=\"" << triple(o.direction) << "\" size=\"" << o.radius << ' '
             << cylinder_half_length << "\"";
      else if (o.shape == "box")
        {
          geom << "type=\"box\" size=\"" << triple(o.half_sizes) << "\"";
          // A turned box: its rotation vector as MuJoCo's axis and angle
          // (the finger's MJCF sets the compiler to radians).
          const Eigen::Vector3d turn(o.rotation[0], o.rotation[1], o.rotation[2]);
          if (turn.norm() > 0)
            geom << " axisangle=\"" << turn.x() / turn.norm() << ' ' << turn.y() / turn.norm() << ' '
                 << turn.z() / turn.norm() << ' ' << turn.norm() << "\"";
        }
      else
        throw data::InputError(error_prefix(o) + "Shape = " + o.shape +
                               " has no MuJoCo primitive (plane, sphere, cylinder or box)");
      // contype 1 meets the finger's capsules (contype 0, conaffinity 1).
      geom << " contype=\"1\" conaffinity=\"0\" rgba=\"0.6 0.6 0.7 1\"/>";
      return geom.str();
    }

    // The finger's MJCF with the obstacle in its world body.
    std::string scene_text(const std::string &finger_mjcf, const data::ObstacleRecord &o)
    {
      std::ifstream in(finger_mjcf);
      if (!in)
        throw data::InputError("cannot read the finger's MJCF '" + finger_mjcf +
                               "' (write it with softchain chain FILE.prm --export-mjcf)");
      std::stringstream text;
      text << in.rdbuf();
      std::string       xml = text.str();
      const std::size_t end = xml.rfind("</worldbody>");
      if (end == std::string::npos)
        throw data::InputError("the finger's MJCF '" + finger_mjcf + "' has no </worldbody>");
      return xml.insert(end, "  " + obstacle_geom(o) + "\n  ");
    }

    // The scene's MJCF written to `scene_path`, or the finger's own without obstacle.
    std::string scene_file(const std::string &finger_mjcf, const std::optional<data::ObstacleRecord> &obstacle,
                           const std::string &scene_path)
    {
      if (!obstacle)
        return finger_mjcf;
      const std::string text = scene_text(finger_mjcf, *obstacle);
      const auto        parent = std::filesystem::path(scene_path).parent_path();
      if (!parent.empty())
        std::filesystem::create_directories(parent);
      std::ofstream out(scene_path);
      if (!(out << text))
        throw data::InputError("cannot write the MuJoCo scene '" + scene_path + "'");
      return scene_path;
    }
  } // namespace

  MujocoScene::MujocoScene(const std::string &finger_mjcf, const std::optional<data::ObstacleRecord> &obstacle,
                           const double collision_radius, const std::string &scene_path)
    : model_(load_mujoco_model(scene_file(finger_mjcf, obstacle, scene_path)))
    , data_(mj_makeData(model_))
    , obstacle_geom_(mj_name2id(model_, mjOBJ_GEOM, "obstacle"))
    , tip_site_(-1)
  {
    try
      {
        actuation_.emplace(model_);
        tip_site_ = mj_name2id(model_, mjOBJ_SITE, "tip");
      }
    catch (...)
      {
        mj_deleteData(data_);
        mj_deleteModel(model_);
        throw;
      }
    mju_zero3(model_->opt.gravity);
    model_->opt.timestep = scene_timestep;
    // Friction and contact dimension are each the larger of a pair's geoms:
    // all geoms get the obstacle's, frictionless (condim 1) or a cone.
    const double friction = obstacle ? obstacle->friction : 0.0;
    for (int g = 0; g < model_->ngeom; ++g)
      {
        model_->geom_condim[g]       = friction > 0 ? 3 : 1;
        model_->geom_friction[3 * g] = friction;
        if (g != obstacle_geom_ && collision_radius > 0)
          model_->geom_size[3 * g] = collision_radius;
      }
    // MuJoCo's contacts are soft: under a steady tangential load a sticking
    // contact creeps, and over a slow ramp the friction relaxes away (P10
    // closing on a rough cylinder pressed it 16-20 % less hard than the
    // FEM). Coulomb's elliptic cone and the no-slip pass after each solve
    // (MuJoCo documentation, "Computation: Solver") make it hold: within
    // 3 % (docs/chain_fidelity.md, "Contact in MuJoCo").
    if (friction > 0)
      {
        model_->opt.cone              = mjCONE_ELLIPTIC;
        model_->opt.noslip_iterations = noslip_iterations;
      }
    mj_forward(model_, data_);
  }

  MujocoScene::~MujocoScene()
  {
    mj_deleteData(data_);
    mj_deleteModel(model_);
  }

  // mj_contactForce gives each contact's force in its frame, whose first
  // axis is the normal from geom1 to geom2: the force geom1 exerts on geom2
  // is frame^T f (MuJoCo documentation, "Contacts").
  std::vector<ObstacleContact> MujocoScene::obstacle_contacts() const
  {
    std::vector<ObstacleContact> contacts;
    for (int c = 0; c < data_->ncon; ++c)
      {
        const mjContact &contact = data_->contact[c];
        if (contact.geom1 != obstacle_geom_ && contact.geom2 != obstacle_geom_)
          continue;
        mjtNum local[6];
        mj_contactForce(model_, data_, c, local);
        const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> frame(contact.frame);
        const Eigen::Vector3d on_geom2 = frame.transpose() * Eigen::Map<const Eigen::Vector3d>(local);
        const bool            second   = contact.geom2 == obstacle_geom_;
        contacts.push_back({model_->geom_bodyid[second ? contact.geom1 : contact.geom2],
                            Eigen::Map<const Eigen::Vector3d>(contact.pos), second ? on_geom2 : -on_geom2});
      }
    return contacts;
  }

  Eigen::Vector3d MujocoScene::obstacle_force() const
  {
    Eigen::Vector3d total = Eigen::Vector3d::Zero();
    for (const ObstacleContact &c : obstacle_contacts())
      total += c.force;
    return total;
  }

  Eigen::Vector3d MujocoScene::tip_position() const
  {
    return Eigen::Map<const Eigen::Vector3d>(data_->site_xpos + 3 * tip_site_);
  }

  Eigen::Vector4d MujocoScene::tip_orientation() const
  {
    return Eigen::Map<const Eigen::Vector4d>(data_->xquat + 4 * model_->site_bodyid[tip_site_]);
  }

  double palm_capsule_radius(const data::MeshRecord &mesh, const PressureTables &tables)
  {
    double palm = std::numeric_limits<double>::infinity();
    for (const data::Point3 &x : mesh.X)
      palm = std::min(palm, x[1]);
    const Eigen::VectorXd points = tables.link_points(0.0);
    double                lowest = std::numeric_limits<double>::infinity();
    for (int i = 0; i < tables.n_joints(); ++i)
      lowest = std::min(lowest, points[3 * i + 1]);
    if (!(lowest > palm))
      throw data::InputError("the chain's joints lie below the FEM mesh's palm: no capsule radius fits");
    return lowest - palm;
  }
} // namespace softchain::chain
