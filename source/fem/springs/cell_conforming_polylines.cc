#include <softchain/fem/cell_conforming_polylines.h>
#include <softchain/fem/cell_locator.h>

#include <tuple>

namespace softchain::fem
{
  using namespace dealii;

  namespace
  {
    using Cell = CellLocator::Cell;

    bool inside(const CellLocator &locator, const Cell &cell, const Point<3> &p)
    {
      return locator.unit_point(cell, p).has_value();
    }

    // The cell the segment at(t) runs through just after t: the first cell
    // found at t + step (step growing) that is not `current`. Returns the
    // cell and that parameter; an invalid cell if the segment leaves the body.
    template <class Segment>
    std::pair<Cell, double> next_cell(const CellLocator &locator,
                                      const Segment &at, const double t, const Cell &current)
    {
      for (double step = 1e-9; t + step < 1; step *= 4)
        {
          const Cell cell = locator.locate(at(t + step)).first;
          if (cell.state() != IteratorState::valid || cell != current)
            return {cell, t + step};
        }
      return {current, 1.0};
    }

    // Appends to `out` the points where segment p -> q leaves one cell for the
    // next (p and q excluded). Cells are convex (affine tetrahedra, hexahedra
    // with planar faces), so the segment leaves each cell once.
    void crossings(const CellLocator &locator,
                   const Point<3> &p, const Point<3> &q, const double min_fraction,
                   std::vector<Point<3>> &out)
    {
      const double length = p.distance(q);
      const auto   at     = [&](const double t) { return Point<3>(p + t * (q - p)); };
      auto [cell, t_in]   = next_cell(locator, at, 0.0, Cell());
      double t0           = 0;
      while (cell.state() == IteratorState::valid && !inside(locator, cell, q))
        {
          double lo = t_in, hi = 1; // at(lo) inside the cell, at(hi) outside
          while ((hi - lo) * length > 1e-12 * (1 + length))
            {
              const double mid = (lo + hi) / 2;
              (inside(locator, cell, at(mid)) ? lo : hi) = mid;
            }
          const double min_length = min_fraction * cell->minimum_vertex_distance();
          if ((1 - hi) * length < min_length)
            return;
          if ((hi - t0) * length >= min_length)
            {
              out.push_back(at(hi));
              t0 = hi;
            }
          const auto next = next_cell(locator, at, hi, cell);
          if (next.first == cell) // q is within round-off of this cell
            return;
          std::tie(cell, t_in) = next; // invalid if the segment leaves the body
        }
    }
  } // namespace

  std::vector<SpringPolyline> cell_conforming_polylines(const std::vector<SpringPolyline> &polylines,
                                                        const Triangulation<3> &mesh,
                                                        const Mapping<3>       &mapping,
                                                        const double            min_fraction)
  {
    const CellLocator           locator(mesh, mapping);
    std::vector<SpringPolyline> result;
    for (const auto &line : polylines)
      {
        const std::vector<Point<3>> &nodes = line.points;
        SpringPolyline split{line.network, {}, line.closed};
        const unsigned int n_segments = line.closed ? nodes.size() : nodes.size() - 1;
        for (unsigned int k = 0; k < nodes.size(); ++k)
          {
            split.points.push_back(nodes[k]);
            if (k < n_segments && nodes.size() > 1)
              crossings(locator, nodes[k], nodes[(k + 1) % nodes.size()], min_fraction,
                        split.points);
          }
        result.push_back(std::move(split));
      }
    return result;
  }
} // namespace softchain::fem
