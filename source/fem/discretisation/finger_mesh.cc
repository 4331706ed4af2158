#include <softchain/fem/boundary_ids.h>
#include <softchain/fem/built_in_bender.h>
#include <softchain/fem/cell_orientation.h>
#include <softchain/data/input_error.h>
#include <softchain/fem/finger_mesh.h>
#include <softchain/geometry/generate_design.h>
#include <softchain/geometry/spring_network_file.h>

#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>

#include <fstream>
#include <map>
#include <sstream>
#include <set>

namespace softchain::fem
{
  using namespace dealii;

  namespace
  {
    // gmsh $PhysicalNames: tag -> name, for dimension 2 (faces) and 3 (volumes).
    std::map<std::pair<int, int>, std::string> physical_names(const std::string &file)
    {
      std::ifstream in(file);
      std::string   line;
      std::map<std::pair<int, int>, std::string> names;
      while (std::getline(in, line) && line != "$PhysicalNames")
        ;
      int n = 0;
      if (!(in >> n))
        return names;
      for (int k = 0; k < n; ++k)
        {
          int         dim, tag;
          std::string name;
          in >> dim >> tag;
          std::getline(in, name);
          const auto first = name.find('"'), last = name.rfind('"');
          names[{dim, tag}] = name.substr(first + 1, last - first - 1);
        }
      return names;
    }

    Point<3> to_point(const Eigen::Vector3d &p)
    {
      return Point<3>(p[0], p[1], p[2]);
    }

    void read_springs(const std::string &file, FingerMesh &mesh)
    {
      for (const auto &network : geometry::SpringNetworkFile::read(file))
        {
          for (const auto &polyline : network.polylines)
            {
              SpringPolyline line{network.name, {}, polyline.closed};
              for (const auto &p : polyline.points)
                line.points.push_back(to_point(p));
              mesh.springs.push_back(line);
            }
          for (const auto &sheet : network.sheets)
            {
              FibreSheet fem_sheet{network.name, {}, {}};
              for (const auto &p : sheet.corners)
                fem_sheet.corners.push_back(to_point(p));
              for (const auto &f : sheet.families)
                fem_sheet.families.push_back({to_point(f.direction), f.spacing});
              mesh.sheets.push_back(fem_sheet);
            }
        }
    }
  } // namespace

  void read_gmsh_mesh(const std::string &file, FingerMesh &mesh)
  {
    std::ifstream in(file);
    if (!in)
      throw data::InputError(file + ": cannot open the mesh file");
    mesh.triangulation.clear();
    GridIn<3> grid_in(mesh.triangulation);
    try
      {
        grid_in.read_msh(in);
      }
    catch (const ExceptionBase &e)
      {
        throw data::InputError(file + ": not a readable gmsh mesh (ASCII msh 2.2 or 4.1)");
      }
    const auto names = physical_names(file);
    const std::map<std::string, types::boundary_id> face_ids{
      {"base", boundary::base}, {"cavity", boundary::cavity}, {"tip", boundary::tip}};
    std::set<std::string> seen;
    for (const auto &face : mesh.triangulation.active_face_iterators())
      if (face->at_boundary())
        {
          const auto name = names.find({2, int(face->boundary_id())});
          const auto id   = name == names.end() ? face_ids.end() : face_ids.find(name->second);
          face->set_boundary_id(id == face_ids.end() ? boundary::other : id->second);
          if (id != face_ids.end())
            seen.insert(id->first);
        }
    // A cavity is optional: a solid body under tip traction or point loads
    // needs none (a pressure on such a mesh is refused where it is applied).
    for (const std::string group : {"base", "tip"})
      if (!seen.count(group))
        throw data::InputError(file + ": no boundary face in the physical group '" + group + "'");

    // Material ids become indices into material_names.
    std::map<types::material_id, types::material_id> new_id;
    mesh.material_names.clear();
    for (const auto &cell : mesh.triangulation.active_cell_iterators())
      {
        const auto tag = cell->material_id();
        if (!new_id.count(tag))
          {
            const auto name = names.find({3, int(tag)});
            if (name == names.end())
              throw data::InputError(file + ": volume tag " + std::to_string(tag) +
                                     " has no physical name (the material region's name)");
            new_id[tag] = mesh.material_names.size();
            mesh.material_names.push_back(name->second);
          }
        cell->set_material_id(new_id[tag]);
      }
  }

  void FingerMesh::build(const Parameters &prm, FingerMesh &mesh)
  {
    if (prm.mesh.source == MeshParameters::Source::built_in_bender)
      BuiltInBender(prm).build(mesh);
    else
      {
        std::string mesh_file = prm.mesh.mesh_file, spring_file = prm.mesh.spring_file;
        if (prm.finger_design)
          {
            const auto design = geometry::generate_design(*prm.finger_design, ".cache/meshes");
            mesh_file         = design.mesh_file;
            spring_file       = design.spring_file;
          }
        read_gmsh_mesh(mesh_file, mesh);
        mesh.triangulation.refine_global(prm.mesh.global_refinements);
        mesh.springs.clear();
        mesh.sheets.clear();
        if (!spring_file.empty())
          read_springs(spring_file, mesh);
        mesh.description = mesh_file;
      }
    if (prm.mesh.node_jitter > 0) // boundary nodes stay: the shape is kept
      GridTools::distort_random(prm.mesh.node_jitter, mesh.triangulation, true);
    check_cell_orientation(mesh.triangulation, prm.file + ": the mesh (" + mesh.description +
                                                 (prm.mesh.node_jitter > 0 ? ", Mesh/Node jitter = " +
                                                    std::to_string(prm.mesh.node_jitter) : "") +
                                                 ")");
    check_spring_rigidities(prm, mesh);
  }

  // Every spring network of the mesh needs its EA in Springs/Axial rigidity:
  // said before any solve, naming the file and the networks the mesh has.
  void FingerMesh::check_spring_rigidities(const Parameters &prm, const FingerMesh &mesh)
  {
    std::set<std::string> networks;
    for (const auto &polyline : mesh.springs)
      networks.insert(polyline.network);
    for (const auto &sheet : mesh.sheets)
      networks.insert(sheet.network);
    for (const auto &network : networks)
      if (prm.springs.axial_rigidity.count(network) == 0)
        {
          std::string listed;
          for (const auto &n : networks)
            listed += (listed.empty() ? "" : ", ") + n;
          throw data::InputError(prm.file + ": parameter 'Axial rigidity' in subsection 'Springs': no "
                                 "value for spring network '" + network + "' (the mesh has: " + listed +
                                 ")");
        }
  }
} // namespace softchain::fem
