#include <softchain/fem/cell_locator.h>

#include <deal.II/boost_adaptors/bounding_box.h>
#include <deal.II/boost_adaptors/point.h>
#include <deal.II/grid/reference_cell.h>

#include <boost/geometry/index/rtree.hpp>

#include <iterator>
#include <limits>
#include <vector>

namespace softchain::fem
{
  using namespace dealii;

  namespace
  {
    // How far unit point xi lies outside the reference cell (<= 0: inside).
    double outside_distance(const ReferenceCell &reference, const Point<3> &xi)
    {
      if (reference == ReferenceCells::Tetrahedron)
        return std::max({-xi[0], -xi[1], -xi[2], xi[0] + xi[1] + xi[2] - 1});
      double d = -std::numeric_limits<double>::max();
      for (unsigned int k = 0; k < 3; ++k)
        d = std::max({d, -xi[k], xi[k] - 1});
      return d;
    }
  } // namespace

  CellLocator::CellLocator(const Triangulation<3> &mesh, const Mapping<3> &mapping)
    : mapping(mapping)
    , cache(mesh, mapping)
  {}

  std::optional<Point<3>>
  CellLocator::unit_point(const Cell &cell, const Point<3> &p, const double tolerance) const
  {
    Point<3> xi;
    if (cell->reference_cell() == ReferenceCells::Tetrahedron)
      {
        // x = v0 + [v1 - v0, v2 - v0, v3 - v0] xi for an affine tetrahedron.
        Tensor<2, 3> edges;
        for (unsigned int v = 1; v < 4; ++v)
          for (unsigned int d = 0; d < 3; ++d)
            edges[d][v - 1] = cell->vertex(v)[d] - cell->vertex(0)[d];
        xi = Point<3>(invert(edges) * (p - cell->vertex(0)));
      }
    else
      try
        {
          xi = mapping.transform_real_to_unit_cell(cell, p);
        }
      catch (const Mapping<3>::ExcTransformationFailed &)
        {
          return std::nullopt;
        }
    if (outside_distance(cell->reference_cell(), xi) > tolerance)
      return std::nullopt;
    return xi;
  }

  std::pair<CellLocator::Cell, Point<3>> CellLocator::locate(const Point<3> &p,
                                                             const double    tolerance) const
  {
    namespace bgi = boost::geometry::index;
    std::vector<std::pair<BoundingBox<3>, Cell>> candidates;
    cache.get_cell_bounding_boxes_rtree().query(bgi::intersects(p),
                                                std::back_inserter(candidates));
    std::pair<Cell, Point<3>> best{Cell(), Point<3>()};
    double                    best_distance = std::numeric_limits<double>::max();
    for (const auto &candidate : candidates)
      if (const auto xi = unit_point(candidate.second, p, tolerance))
        {
          const double d = outside_distance(candidate.second->reference_cell(), *xi);
          if (d < best_distance)
            {
              best          = {candidate.second, *xi};
              best_distance = d;
            }
        }
    return best;
  }
} // namespace softchain::fem
