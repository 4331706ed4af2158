#include <softchain/geometry/contact_scene.h>
#include <softchain/geometry/stl_file.h>
#include <softchain/geometry/text_lines.h>
#include <softchain/geometry/triangulated_obstacle.h>

#include <softchain/data/content_hash.h>
#include <softchain/data/input_error.h>

#include <limits>

namespace softchain::geometry
{
  namespace
  {
    void declare_obstacle(data::PrmSection &section, const std::string &name)
    {
      const std::string p = name + "/";
      section.declare(p + "Shape", "plane", "plane | sphere | cylinder | box | stl");
      section.declare(p + "Position", "0, 0, 0",
                      "m: a point of the plane, the sphere's or box's centre, a point of the "
                      "cylinder's axis, where stl puts the origin of its file's coordinates");
      section.declare(p + "Normal", "0, 1, 0", "plane: unit normal pointing out of the obstacle");
      section.declare(p + "Axis", "0, 0, 1", "cylinder: direction of the axis");
      section.declare(p + "Radius", "0.01", "sphere, cylinder: m");
      section.declare(p + "Half sizes", "0.01, 0.01, 0.01", "box: half edge lengths along its axes, m");
      section.declare(p + "Rotation", "0, 0, 0",
                      "box, stl: its turn from the world axes x, y, z about Position, as a rotation "
                      "vector (the axis times the angle, rad)");
      section.declare(p + "File", "",
                      "stl: a closed, consistently oriented triangle surface in m (ASCII or binary "
                      "STL), relative to this file's directory");
      section.declare(p + "Friction coefficient", "0", "Coulomb's mu >= 0");
      section.declare(p + "Motion", "0, 0, 0",
                      "translation at the end of the load path, m (the obstacle moves "
                      "linearly along it: a table raised to the tip, an object pushed in)");
      section.declare(p + "Motion rotation", "0, 0, 0",
                      "turn at the end of the load path about Motion pivot, a rotation vector (the "
                      "axis times the angle, rad): at path parameter t the obstacle is turned by t "
                      "times it, then moved by t Motion");
      section.declare(p + "Motion pivot", "",
                      "m: the point Motion rotation turns the obstacle about; empty: Position");
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

    data::Point3 triple(const Eigen::Vector3d &v) { return {{v[0], v[1], v[2]}}; }

    Obstacle read_obstacle(const data::PrmSection &section, const std::string &name, const std::string &prm_path)
    {
      const std::string    p = name + "/";
      data::ObstacleRecord o;
      o.name     = name;
      o.shape    = section.get_selection(p + "Shape", {"plane", "sphere", "cylinder", "box", "stl"});
      o.position = triple(vector_entry(section, p + "Position"));
      if (o.shape == "plane" || o.shape == "cylinder")
        o.direction = triple(vector_entry(section, p + (o.shape == "plane" ? "Normal" : "Axis")));
      if (o.shape == "sphere" || o.shape == "cylinder")
        o.radius = positive_entry(section, p + "Radius");
      if (o.shape == "box")
        o.half_sizes = triple(vector_entry(section, p + "Half sizes"));
      if (o.shape == "box" || o.shape == "stl")
        o.rotation = triple(vector_entry(section, p + "Rotation"));
      if (o.shape == "stl")
        {
          section.require(!section.get(p + "File").empty(), p + "File", "Shape = stl needs the STL file");
          o.file = TextLines::beside(prm_path, section.get(p + "File"));
          try
            {
              for (const auto &t : StlFile::read(o.file).triangles)
                for (const auto &v : t)
                  o.vertices.push_back(triple(v));
            }
          catch (const data::InputError &e)
            {
              throw data::InputError(section.describe(p + "File") + ": " + e.what());
            }
        }
      o.friction = section.get_double(p + "Friction coefficient");
      section.require(o.friction >= 0, p + "Friction coefficient", "must be >= 0");
      o.motion          = triple(vector_entry(section, p + "Motion"));
      o.motion_rotation = triple(vector_entry(section, p + "Motion rotation"));
      if (o.motion_rotation != data::Point3{})
        o.motion_pivot = section.get(p + "Motion pivot").empty() ? o.position :
                                                                   triple(vector_entry(section, p + "Motion pivot"));
      try
        {
          return Obstacle(o);
        }
      catch (const data::InputError &e)
        {
          throw data::InputError(section.describe(p + "Shape") + ": " + e.what());
        }
    }

    Eigen::Vector3d eigen(const data::Point3 &p) { return {p[0], p[1], p[2]}; }

    // The file's triangles placed at Position, turned by Rotation about it.
    std::vector<TriangulatedObstacle::Triangle> placed_triangles(const data::ObstacleRecord &o)
    {
      const Eigen::Matrix3d R = RigidTransform::rotation_of(eigen(o.rotation));
      std::vector<TriangulatedObstacle::Triangle> triangles(o.vertices.size() / 3);
      for (std::size_t v = 0; v < 3 * triangles.size(); ++v)
        triangles[v / 3][v % 3] = eigen(o.position) + R * eigen(o.vertices[v]);
      return triangles;
    }

    std::shared_ptr<const RigidObstacle> body_of(const data::ObstacleRecord &o)
    {
      if (o.shape == "plane")
        return std::make_shared<PlaneObstacle>(eigen(o.position), eigen(o.direction));
      if (o.shape == "sphere")
        return std::make_shared<SphereObstacle>(eigen(o.position), o.radius);
      if (o.shape == "cylinder")
        return std::make_shared<CylinderObstacle>(eigen(o.position), eigen(o.direction), o.radius);
      if (o.shape == "box")
        return std::make_shared<BoxObstacle>(eigen(o.position), eigen(o.half_sizes),
                                             RigidTransform::rotation_of(eigen(o.rotation)));
      if (o.shape == "stl")
        return std::make_shared<TriangulatedObstacle>(placed_triangles(o), o.file);
      throw data::InputError("obstacle '" + o.name + "': unknown shape '" + o.shape +
                             "' (plane, sphere, cylinder, box or stl)");
    }
  } // namespace

  Obstacle::Obstacle(const data::ObstacleRecord &o)
    : description(o)
    , body(body_of(o))
  {
    if (!(o.friction >= 0))
      throw data::InputError("obstacle '" + o.name + "': the friction coefficient must be >= 0");
  }

  RigidTransform Obstacle::pose(const double t) const
  {
    return RigidTransform::along_path(t, eigen(description.motion_rotation), eigen(description.motion_pivot),
                                      eigen(description.motion));
  }

  std::vector<data::ObstacleRecord> ContactScene::descriptions() const
  {
    std::vector<data::ObstacleRecord> all;
    for (const auto &o : obstacles)
      all.push_back(o.description);
    return all;
  }

  std::string ContactScene::law_text() const
  {
    std::string text = "surfaces";
    for (const auto &s : surfaces)
      text += " " + s;
    return text + " penalty " + data::canonical(penalty_factor) + " tolerance " +
           data::canonical(penetration_tolerance) + " augmentations " +
           std::to_string(max_augmentations);
  }

  ContactScene ContactScene::with(const std::vector<data::ObstacleRecord> &chosen) const
  {
    ContactScene scene = *this;
    scene.obstacles.clear();
    scene.in_solve.clear();
    for (const auto &o : chosen)
      {
        scene.obstacles.emplace_back(o);
        scene.in_solve.push_back(o.name);
      }
    return scene;
  }

  const Obstacle *ContactScene::find(const std::string &name) const
  {
    for (const auto &o : obstacles)
      if (o.name() == name)
        return &o;
    return nullptr;
  }

  ContactScene ContactScene::solve_scene() const
  {
    std::vector<data::ObstacleRecord> chosen;
    for (const auto &name : in_solve)
      chosen.push_back(find(name)->description);
    return with(chosen);
  }

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
    section.declare("Obstacles in solve", "all",
                    "the obstacles `softchain solve` puts in its scene: all, none, or names");
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
      scene.obstacles.push_back(read_obstacle(section, name, file.path()));
    const auto in_solve = section.get_list("Obstacles in solve");
    if (in_solve == std::vector<std::string>{"all"})
      scene.in_solve = names;
    else if (in_solve != std::vector<std::string>{"none"})
      for (const auto &name : in_solve)
        {
          section.require(scene.find(name) != nullptr, "Obstacles in solve",
                          "'" + name + "' is no obstacle of subsection Contact (all, none, or names)");
          scene.in_solve.push_back(name);
        }
    return scene;
  }
} // namespace softchain::geometry
