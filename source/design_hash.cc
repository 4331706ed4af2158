#include <softchain/data/content_hash.h>
#include <softchain/design_hash.h>

#include <sstream>

namespace softchain
{
  namespace
  {
    // The statements of the .prm that shape the solution, one per line.
    std::string design_statements(const data::PrmFile &prm)
    {
      std::istringstream in(
        prm.text_without({"Design", "Loads", "Samples", "Output", "Reduction", "Chain"}));
      std::string line, text;
      while (std::getline(in, line))
        {
          line = line.substr(0, line.find('#'));
          const auto first = line.find_first_not_of(" \t\r");
          if (first != std::string::npos)
            text += line.substr(first, line.find_last_not_of(" \t\r") - first + 1) + '\n';
        }
      return text;
    }

    std::string point_text(const Point<3> &p)
    {
      return data::canonical(p[0]) + ' ' + data::canonical(p[1]) + ' ' + data::canonical(p[2]);
    }

    std::string mesh_text(const FingerMesh &mesh)
    {
      std::string text;
      for (const auto &v : mesh.triangulation.get_vertices())
        text += "v " + point_text(v) + '\n';
      for (const auto &cell : mesh.triangulation.active_cell_iterators())
        {
          text += "c " + std::to_string(cell->material_id());
          for (const unsigned int v : cell->vertex_indices())
            text += ' ' + std::to_string(cell->vertex_index(v));
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              text += " f" + std::to_string(f) + ':' + std::to_string(cell->face(f)->boundary_id());
          text += '\n';
        }
      for (const auto &name : mesh.material_names)
        text += "m " + name + '\n';
      for (const auto &spring : mesh.springs)
        {
          text += "s " + spring.network + (spring.closed ? " closed" : " open") + '\n';
          for (const auto &p : spring.points)
            text += point_text(p) + '\n';
        }
      return text;
    }
  } // namespace

  std::string design_hash(const data::PrmFile &prm, const FingerMesh &mesh)
  {
    return data::content_hash(design_statements(prm) + "mesh\n" + mesh_text(mesh));
  }
} // namespace softchain
