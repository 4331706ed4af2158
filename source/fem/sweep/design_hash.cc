#include <softchain/data/content_hash.h>
#include <softchain/fem/design_hash.h>


namespace softchain::fem
{
  using namespace dealii;

  namespace
  {
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
      for (const auto &sheet : mesh.sheets)
        {
          text += "h " + sheet.network + '\n';
          for (const auto &p : sheet.corners)
            text += point_text(p) + '\n';
          for (const auto &f : sheet.families)
            text += "fibre " + point_text(Point<3>(f.direction)) + ' ' + data::canonical(f.spacing) + '\n';
        }
      return text;
    }
  } // namespace

  // The laws the .prm names only by their parameters are part of the
  // design: a database solved under another tension-only law (the earlier
  // quadratic rounding over a strain band) is not this design's.
  std::string design_hash(const Parameters &prm, const FingerMesh &mesh)
  {
    return data::content_hash(prm.design_values + "tension law t (t - eps) = delta^2/4\n" +
                              "mesh\n" + mesh_text(mesh));
  }
} // namespace softchain::fem
