#include <softchain/fem/sheet_quadrature.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/mapping.h>

#include <algorithm>

namespace softchain::fem
{
  using namespace dealii;

  namespace
  {
    using Polygon = std::vector<Point<3>>;

    // The part of `polygon` on the side n . (p - c) >= 0 of a plane
    // (Sutherland-Hodgman; distances within `tol` count as on the plane).
    Polygon clip(const Polygon &polygon, const Tensor<1, 3> &n, const Point<3> &c, const double tol)
    {
      Polygon kept;
      for (std::size_t k = 0; k < polygon.size(); ++k)
        {
          const Point<3> &p = polygon[k], &q = polygon[(k + 1) % polygon.size()];
          const double    dp = n * (p - c), dq = n * (q - c);
          if (dp >= -tol)
            kept.push_back(p);
          if ((dp > tol && dq < -tol) || (dp < -tol && dq > tol))
            kept.push_back(p + dp / (dp - dq) * (q - p));
        }
      return kept;
    }

    // Unit normal of a planar face, pointing into `cell`. A quadrilateral's
    // vertices are numbered lexicographically: its diagonals are 0-3 and 1-2.
    Tensor<1, 3> inward_normal(const DoFHandler<3>::active_cell_iterator &cell, const unsigned int f)
    {
      const auto   face = cell->face(f);
      Tensor<1, 3> n =
        face->n_vertices() == 4 ?
          cross_product_3d(face->vertex(3) - face->vertex(0), face->vertex(2) - face->vertex(1)) :
          cross_product_3d(face->vertex(1) - face->vertex(0), face->vertex(2) - face->vertex(0));
      n /= n.norm();
      return n * (cell->center() - face->center()) > 0 ? n : -n;
    }

    // The polygon's part inside the cell. A polygon in the plane of an
    // interior face stays in the cell its normal points into.
    Polygon clip_to_cell(Polygon polygon, const Tensor<1, 3> &sheet_normal,
                         const DoFHandler<3>::active_cell_iterator &cell)
    {
      const double tol = 1e-10 * cell->diameter();
      for (const unsigned int f : cell->face_indices())
        {
          const Tensor<1, 3> n = inward_normal(cell, f);
          const Point<3>     c = cell->face(f)->center();
          const bool         in_plane =
            std::all_of(polygon.begin(), polygon.end(),
                        [&](const Point<3> &p) { return std::abs(n * (p - c)) <= tol; });
          if (in_plane)
            {
              if (!cell->face(f)->at_boundary() && n * sheet_normal < 0)
                return {};
              continue;
            }
          polygon = clip(polygon, n, c, tol);
          if (polygon.size() < 3)
            return {};
        }
      return polygon;
    }
  } // namespace

  std::vector<CellSheetQuadrature> sheet_quadrature(const FiniteElementSpace    &space,
                                                    const std::vector<Point<3>> &corners)
  {
    Tensor<1, 3> normal = cross_product_3d(corners[1] - corners[0], corners[2] - corners[0]);
    normal /= normal.norm();
    const BoundingBox<3>   sheet_box(corners);
    const QGaussSimplex<2> triangle_rule(3);
    std::vector<CellSheetQuadrature> result;
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        BoundingBox<3> cell_box = cell->bounding_box();
        cell_box.extend(1e-10 * cell->diameter());
        if (cell_box.get_neighbor_type(sheet_box) == NeighborType::not_neighbors)
          continue;
        const Polygon piece = clip_to_cell(corners, normal, cell);
        CellSheetQuadrature cell_rule{cell, {}, {}};
        // Fanned about the vertices' mean, so that a symmetric piece gets a
        // symmetric rule.
        Point<3> centre;
        for (const Point<3> &p : piece)
          centre += p / static_cast<double>(piece.size());
        for (std::size_t t = 0; t < piece.size(); ++t)
          {
            const Tensor<1, 3> e1 = piece[t] - centre, e2 = piece[(t + 1) % piece.size()] - centre;
            const double       area = 0.5 * cross_product_3d(e1, e2).norm();
            for (unsigned int q = 0; q < triangle_rule.size(); ++q)
              {
                const Point<2> &s = triangle_rule.point(q);
                const Point<3>  p = centre + s[0] * e1 + s[1] * e2;
                cell_rule.unit_points.push_back(space.mapping->transform_real_to_unit_cell(cell, p));
                cell_rule.weights.push_back(2 * area * triangle_rule.weight(q));
              }
          }
        if (!cell_rule.weights.empty())
          result.push_back(cell_rule);
      }
    return result;
  }
} // namespace softchain::fem
