#include <softchain/fem/cell_orientation.h>
#include <softchain/data/input_error.h>

#include <algorithm>
#include <limits>
#include <sstream>

namespace softchain::fem
{
  using namespace dealii;

  namespace
  {
    double scaled_determinant(const Tensor<1, 3> &a, const Tensor<1, 3> &b, const Tensor<1, 3> &c)
    {
      return scalar_product(a, cross_product_3d(b, c)) / (a.norm() * b.norm() * c.norm());
    }

    // Hexahedron, deal.II's lexicographic vertices: vertex v has reference
    // coordinates (v & 1, v & 2, v & 4), so its neighbour along the k-th
    // reference axis is v ^ (1 << k). The edges point along +xi, +eta, +zeta.
    double hexahedron_scaled_jacobian(const Triangulation<3>::cell_iterator &cell)
    {
      double smallest = std::numeric_limits<double>::max();
      for (unsigned int v = 0; v < 8; ++v)
        {
          Tensor<1, 3> edge[3];
          for (unsigned int k = 0; k < 3; ++k)
            {
              const unsigned int w = v ^ (1u << k);
              edge[k]              = (v & (1u << k)) ? cell->vertex(v) - cell->vertex(w) :
                                                       cell->vertex(w) - cell->vertex(v);
            }
          smallest = std::min(smallest, scaled_determinant(edge[0], edge[1], edge[2]));
        }
      return smallest;
    }

    // Tetrahedron: reference vertices 0, e_x, e_y, e_z.
    double tetrahedron_scaled_jacobian(const Triangulation<3>::cell_iterator &cell)
    {
      return scaled_determinant(cell->vertex(1) - cell->vertex(0), cell->vertex(2) - cell->vertex(0),
                                cell->vertex(3) - cell->vertex(0));
    }

    double scaled_jacobian(const Triangulation<3>::cell_iterator &cell)
    {
      return cell->reference_cell() == ReferenceCells::Hexahedron ?
               hexahedron_scaled_jacobian(cell) :
               tetrahedron_scaled_jacobian(cell);
    }
  } // namespace

  double smallest_scaled_jacobian(const Triangulation<3> &mesh)
  {
    double smallest = std::numeric_limits<double>::max();
    for (const auto &cell : mesh.active_cell_iterators())
      smallest = std::min(smallest, scaled_jacobian(cell));
    return smallest;
  }

  void check_cell_orientation(const Triangulation<3> &mesh, const std::string &source)
  {
    for (const auto &cell : mesh.active_cell_iterators())
      {
        const double q = scaled_jacobian(cell);
        if (q > 0)
          continue;
        std::ostringstream what;
        what << source << ": cell " << cell->active_cell_index() << " at (" << cell->center()
             << ") is inverted (scaled Jacobian " << q
             << " <= 0 at a corner); fix the mesh before solving";
        throw data::InputError(what.str());
      }
  }
} // namespace softchain::fem
