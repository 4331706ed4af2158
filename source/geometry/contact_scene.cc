#include <softchain/geometry/contact_scene.h>

#include <softchain/data/input_error.h>

#include <limits>

namespace softchain::geometry
{
  namespace
  {
    void declare_obstacle(data::PrmSection &section, const std::string &name)
    {
      const std::string p = name + "/";
      section.declare(p + "Shape", "plane", "plane | sphere | cylinder | box");
      section.declare(p + "Position", "0, 0, 0",
                      "m: a point of the plane, the sphere's or box's centre, a point of the "
                      "cylinder's axis");
      section.declare(p + "Normal", "0, 1, 0", "plane: unit normal pointing out of the obstacle");
      section.declare(p + "Axis", "0, 0, 1", "cylinder: direction of the axis");
      section.declare(p + "Radius", "0.01", "sphere, cylinder: m");
      section.declare(p + "Half sizes", "0.01, 0.01, 0.01", "box: half edge lengths along x, y, z, m");
      section.declare(p + "Friction coefficient", "0", "Coulomb's mu >= 0");
      section.declare(p + "Motion", "0, 0, 0",
                      "translation at the end of the load path, m (the obstacle moves "
                      "linearly along it: a table raised to the tip, an object pushed in)");
    }

    Eigen::Vector3d vector_entry(const data::PrmSection &section, const std::string &name)
    {
      const std::vector<double> v = section.get_double_list(name);
      section.require(v.size() == 3, name, "needs three numbers x, y, z");
      return {v[0], v[1], v[2]};
    }

    double positive_entry(const data::PrmSection &section, const std::string &name)
    {
      const double value = section.get_double(name);
      section.require(value > 0, name, "must be > 0");
      return value;
    }

    Obstacle read_obstacle(const data::PrmSection &section, const std::string &name)
    {
      const std::string p = name + "/";
      Obstacle          o;
      o.name           = name;
      const auto shape = section.get_selection(p + "Shape", {"plane", "sphere", "cylinder", "box"});
      const auto where = vector_entry(section, p + "Position");
      try
        {
          if (shape == "plane")
            o.body = std::make_shared<PlaneObstacle>(where, vector_entry(section, p + "Normal"));
          else if (shape == "sphere")
            o.body = std::make_shared<SphereObstacle>(where, positive_entry(section, p + "Radius"));
          else if (shape == "cylinder")
            o.body = std::make_shared<CylinderObstacle>(where, vector_entry(section, p + "Axis"),
                                                        positive_entry(section, p + "Radius"));
          else
            o.body = std::make_shared<BoxObstacle>(where, vector_entry(section, p + "Half sizes"));
        }
      catch (const data::InputError &e)
        {
          throw data::InputError(section.describe(p + "Shape") + ": " + e.what());
        }
      o.friction = section.get_double(p + "Friction coefficient");
      section.require(o.friction >= 0, p + "Friction coefficient", "must be >= 0");
      o.motion = vector_entry(section, p + "Motion");
      return o;
    }
  } // namespace

  ContactScene ContactScene::read(const data::PrmFile &file)
  {
    data::PrmSection section;
    section.declare("Surfaces", "all",
                    "all: every boundary face but the clamped base; else a list of the "
                    "boundary groups tip, outer, cavity");
    section.declare("Penalty factor", "10",
                    "epsilon = factor E / h per unit reference area; the penetration is "
                    "t_N / (factor E) of the face size h");
    section.declare("Penetration tolerance", "0.01",
                    "deepest penetration allowed, as a fraction of the local face size; "
                    "beyond it Uzawa updates of the contact pressure follow");
    section.declare("Maximum augmentations", "10", "Uzawa updates per load step");
    const auto names = file.subsection_names("Contact");
    for (const auto &name : names)
      declare_obstacle(section, name);
    file.parse_section("Contact", section);

    ContactScene scene;
    scene.file     = file.path();
    scene.surfaces = section.get_list("Surfaces");
    section.require(!scene.surfaces.empty(), "Surfaces", "names no boundary group");
    for (const auto &s : scene.surfaces)
      section.require(s == "all" ? scene.surfaces.size() == 1 : (s == "tip" || s == "outer" || s == "cavity"),
                      "Surfaces", "'" + s + "' is no boundary group (all, or tip, outer, cavity)");
    scene.penalty_factor        = positive_entry(section, "Penalty factor");
    scene.penetration_tolerance = positive_entry(section, "Penetration tolerance");
    const int augmentations     = section.get_integer("Maximum augmentations");
    section.require(augmentations >= 0 && augmentations <= 1000, "Maximum augmentations",
                    "must lie in [0, 1000]");
    scene.max_augmentations = static_cast<unsigned int>(augmentations);
    for (const auto &name : names)
      scene.obstacles.push_back(read_obstacle(section, name));
    return scene;
  }
} // namespace softchain::geometry
