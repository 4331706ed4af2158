#include <softchain/data/input_error.h>
#include <softchain/geometry/msh_file.h>
#include <softchain/geometry/text_lines.h>

#include <iomanip>
#include <sstream>
#include <unordered_map>

namespace softchain::geometry
{
  namespace
  {
    // Skips to the next "$Section" line.
    bool next_section(TextLines &lines, std::string &name)
    {
      for (std::string line; lines.next(line);)
        if (!line.empty() && line[0] == '$')
          {
            name = line.substr(0, line.find_last_not_of(' ') + 1);
            return true;
          }
      return false;
    }

    // gmsh element type: number of nodes and whether it is a cell (3D), a
    // facet (2D) or skipped (points and lines).
    enum class Role
    {
      cell,
      facet,
      skipped
    };
    struct ElementType
    {
      std::size_t n_nodes;
      Role        role;
    };
    const std::unordered_map<int, ElementType> element_types = {{15, {1, Role::skipped}},
                                                                {1, {2, Role::skipped}},
                                                                {2, {3, Role::facet}},
                                                                {3, {4, Role::facet}},
                                                                {4, {4, Role::cell}},
                                                                {5, {8, Role::cell}}};

    void read_format(TextLines &lines)
    {
      double version = 0;
      int    file_type = -1;
      lines.next_stream() >> version >> file_type;
      if (version < 2.0 || version >= 3.0 || file_type != 0)
        lines.fail("expected an ASCII msh 2.x file (gmsh -format msh22)");
    }

    void read_physical_names(TextLines &lines, MshFile &mesh)
    {
      std::size_t n = 0;
      lines.next_stream() >> n;
      for (std::size_t i = 0; i < n; ++i)
        {
          PhysicalGroup group;
          std::string   name;
          auto          line = lines.next_stream();
          if (!(line >> group.dimension >> group.tag >> std::quoted(name)))
            lines.fail("malformed physical name");
          mesh.groups[name] = group;
        }
    }

    void read_nodes(TextLines &lines, MshFile &mesh, std::unordered_map<std::size_t, std::size_t> &index)
    {
      std::size_t n = 0;
      lines.next_stream() >> n;
      mesh.nodes.resize(n);
      for (std::size_t i = 0; i < n; ++i)
        {
          std::size_t id = 0;
          auto        line = lines.next_stream();
          if (!(line >> id >> mesh.nodes[i].x() >> mesh.nodes[i].y() >> mesh.nodes[i].z()))
            lines.fail("malformed node");
          index[id] = i;
        }
    }

    MshElement read_element(TextLines &lines, const std::unordered_map<std::size_t, std::size_t> &index,
                            Role &role)
    {
      MshElement element;
      int        type = 0, n_tags = 0;
      auto       line = lines.next_stream();
      line >> element.id >> type >> n_tags;
      const auto known = element_types.find(type);
      if (!line || known == element_types.end())
        lines.fail("element type " + std::to_string(type) +
                   " is not a first-order point, line, triangle, quadrilateral, "
                   "tetrahedron or hexahedron");
      role = known->second.role;
      std::vector<int> tags(n_tags);
      for (int &tag : tags)
        line >> tag;
      element.physical = tags.empty() ? 0 : tags[0];
      for (std::size_t k = 0; k < known->second.n_nodes; ++k)
        {
          std::size_t id = 0;
          if (!(line >> id) || !index.count(id))
            lines.fail("element " + std::to_string(element.id) + " names an unknown node");
          element.nodes.push_back(index.at(id));
        }
      return element;
    }

    void read_elements(TextLines &lines, MshFile &mesh,
                       const std::unordered_map<std::size_t, std::size_t> &index)
    {
      std::size_t n = 0;
      lines.next_stream() >> n;
      for (std::size_t i = 0; i < n; ++i)
        {
          Role             role;
          const MshElement element = read_element(lines, index, role);
          if (role == Role::cell)
            mesh.cells.push_back(element);
          else if (role == Role::facet)
            mesh.facets.push_back(element);
        }
    }
  } // namespace

  MshFile MshFile::read(const std::string &path)
  {
    MshFile mesh;
    mesh.path = path;
    TextLines                                    lines(path, "mesh file");
    std::unordered_map<std::size_t, std::size_t> index; // node number -> position
    bool                                         has_format = false;
    for (std::string section; next_section(lines, section);)
      {
        if (section == "$MeshFormat")
          {
            has_format = true;
            read_format(lines);
          }
        else if (section == "$PhysicalNames")
          read_physical_names(lines, mesh);
        else if (section == "$Nodes")
          read_nodes(lines, mesh, index);
        else if (section == "$Elements")
          read_elements(lines, mesh, index);
      }
    if (!has_format || mesh.cells.empty())
      lines.fail("not a gmsh mesh with volume cells ($MeshFormat, $Nodes, $Elements)");
    return mesh;
  }

  bool MshFile::has_group(const std::string &name, int dimension) const
  {
    const auto it = groups.find(name);
    return it != groups.end() && it->second.dimension == dimension;
  }

  std::vector<const MshElement *> MshFile::facets_of(const std::string &group) const
  {
    if (!has_group(group, 2))
      throw data::InputError(path + ": the surface physical group '" + group + "' is missing");
    const int                       tag = groups.at(group).tag;
    std::vector<const MshElement *> result;
    for (const auto &facet : facets)
      if (facet.physical == tag)
        result.push_back(&facet);
    return result;
  }
} // namespace softchain::geometry
