#include <softchain/fem/boundary_ids.h>
#include <softchain/fem/database_export.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>
#include <set>
#include <unordered_map>

namespace softchain::fem
{
  using namespace dealii;

  namespace
  {
    using Cell  = DoFHandler<3>::active_cell_iterator;
    using Index = std::int64_t;

    // The support point from the cell's vertices with the linear mapping's
    // weights (the solver's mapping is linear). The terms are summed in
    // sorted order, so every cell sharing the node, on any rank, gives the
    // same bits.
    Point<3> canonical_point(const Cell &cell, const Point<3> &unit)
    {
      Point<3> point;
      for (unsigned int c = 0; c < 3; ++c)
        {
          std::vector<double> terms;
          for (const unsigned int v : cell->vertex_indices())
            terms.push_back(cell->reference_cell().d_linear_shape_function(unit, v) *
                            cell->vertex(v)[c]);
          std::sort(terms.begin(), terms.end());
          point[c] = std::accumulate(terms.begin(), terms.end(), 0.0);
        }
      return point;
    }

    template <class T>
    std::vector<T> concatenate(const std::vector<std::vector<T>> &parts)
    {
      std::vector<T> all;
      for (const auto &part : parts)
        all.insert(all.end(), part.begin(), part.end());
      return all;
    }

    // Lattice coordinates (i, j) of the face's support points: p = u0 +
    // (i e1 + j e2) / degree in the unit cell, u0..u2 the face's first three
    // vertices (a parallelogram or triangle lattice).
    struct FaceLattice
    {
      Tensor<1, 3> e1, e2;
      Point<3>     u0;
      unsigned int degree;

      bool locate(const Point<3> &p, std::pair<int, int> &ij) const
      {
        const Tensor<1, 3> d   = p - u0;
        const double       a11 = e1 * e1, a12 = e1 * e2, a22 = e2 * e2;
        const double       det = a11 * a22 - a12 * a12;
        const double       s   = (a22 * (e1 * d) - a12 * (e2 * d)) / det;
        const double       t   = (a11 * (e2 * d) - a12 * (e1 * d)) / det;
        if ((d - s * e1 - t * e2).norm() > 1e-10) // unit-cell coordinates
          return false;
        ij = {int(std::lround(degree * s)), int(std::lround(degree * t))};
        return true;
      }
    };

    // Linear sub-triangles of a face's (degree+1)-node lattice.
    std::vector<std::array<std::pair<int, int>, 3>> sub_triangles(const bool quad, const int k)
    {
      std::vector<std::array<std::pair<int, int>, 3>> t;
      for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j)
          if (quad)
            {
              t.push_back({{{i, j}, {i + 1, j}, {i + 1, j + 1}}});
              t.push_back({{{i, j}, {i + 1, j + 1}, {i, j + 1}}});
            }
          else if (i + j < k)
            {
              t.push_back({{{i, j}, {i + 1, j}, {i, j + 1}}});
              if (i + j < k - 1)
                t.push_back({{{i + 1, j}, {i + 1, j + 1}, {i, j + 1}}});
            }
      return t;
    }

    // The triangle turned so that it points along `outward`, then rotated
    // (orientation kept) to start at its smallest node.
    std::array<Index, 3> oriented(std::array<Index, 3> t, const std::vector<data::Point3> &X,
                                  const Tensor<1, 3> &outward)
    {
      const auto   p = [&](int k) { return Point<3>(X[t[k]][0], X[t[k]][1], X[t[k]][2]); };
      const double s = cross_product_3d(p(1) - p(0), p(2) - p(0)) * outward;
      if (s < 0)
        std::swap(t[1], t[2]);
      std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
      return t;
    }

    // The nodes of face f of `cell` by lattice position; node(b) is the node
    // of the cell's base-element support point b.
    std::map<std::pair<int, int>, Index>
    face_nodes(const Cell &cell, const unsigned int f, const FiniteElement<3> &base,
               const unsigned int degree, const std::function<Index(unsigned int)> &node)
    {
      const auto           &units = base.get_unit_support_points();
      const auto            face  = cell->face(f);
      std::vector<Point<3>> u; // the face's vertices in unit cell coordinates
      for (const unsigned int fv : face->vertex_indices())
        for (const unsigned int v : cell->vertex_indices())
          if (cell->vertex_index(v) == face->vertex_index(fv))
            u.push_back(units[v]); // vertex support points come first
      const FaceLattice lattice{u[1] - u[0], u[2] - u[0], u[0], degree};
      std::map<std::pair<int, int>, Index> nodes;
      std::pair<int, int>                  ij;
      for (unsigned int b = 0; b < base.n_dofs_per_cell(); ++b)
        if (lattice.locate(units[b], ij))
          nodes[ij] = node(b);
      return nodes;
    }

    // The rows of k indices of all ranks, sorted and unique, so that the
    // order does not depend on the partition.
    std::vector<std::vector<Index>> gathered_rows(const std::vector<Index> &local,
                                                  const std::size_t k, const MPI_Comm comm)
    {
      const auto all = concatenate(Utilities::MPI::all_gather(comm, local));
      std::vector<std::vector<Index>> rows;
      for (std::size_t r = 0; r + k <= all.size(); r += k)
        rows.emplace_back(all.begin() + r, all.begin() + r + k);
      std::sort(rows.begin(), rows.end());
      rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
      return rows;
    }
  } // namespace

  DatabaseExport::DatabaseExport(const FiniteElementSpace &fe_space)
    : space(fe_space)
  {
    number_nodes();
    collect_faces_and_cells();
  }

  void DatabaseExport::number_nodes()
  {
    const FiniteElement<3> &base = space.fe->base_element(0);
    std::vector<double>                  coords;
    std::vector<types::global_dof_index> dofs, cell_dofs(space.fe->n_dofs_per_cell());
    std::set<types::global_dof_index>    seen;
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(cell_dofs);
          for (unsigned int b = 0; b < base.n_dofs_per_cell(); ++b)
            {
              const auto first = cell_dofs[space.fe->component_to_system_index(0, b)];
              if (!space.owned_dofs.is_element(first) || !seen.insert(first).second)
                continue;
              const Point<3> p = canonical_point(cell, base.get_unit_support_points()[b]);
              for (unsigned int c = 0; c < 3; ++c)
                {
                  coords.push_back(p[c]);
                  dofs.push_back(cell_dofs[space.fe->component_to_system_index(c, b)]);
                }
            }
        }
    const auto all_coords = concatenate(Utilities::MPI::all_gather(space.communicator, coords));
    const auto all_dofs   = concatenate(Utilities::MPI::all_gather(space.communicator, dofs));
    std::vector<std::size_t> order(all_coords.size() / 3);
    std::iota(order.begin(), order.end(), 0);
    const auto point = [&](std::size_t n) {
      return data::Point3{{all_coords[3 * n], all_coords[3 * n + 1], all_coords[3 * n + 2]}};
    };
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return point(a) < point(b); });
    for (const auto n : order)
      {
        record.X.push_back(point(n));
        node_dofs.insert(node_dofs.end(), &all_dofs[3 * n], &all_dofs[3 * n] + 3);
      }
  }

  void DatabaseExport::collect_faces_and_cells()
  {
    std::unordered_map<types::global_dof_index, Index> node_of;
    for (std::size_t n = 0; n < record.X.size(); ++n)
      node_of[node_dofs[3 * n]] = n;
    const FiniteElement<3> &base = space.fe->base_element(0);
    record.nodes_per_cell        = base.reference_cell().n_vertices();
    std::vector<Index>                   triangles, tip, clamped, cells;
    std::vector<types::global_dof_index> cell_dofs(space.fe->n_dofs_per_cell());
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        cell->get_dof_indices(cell_dofs);
        const auto node = [&](unsigned int b) {
          return node_of.at(cell_dofs[space.fe->component_to_system_index(0, b)]);
        };
        for (const unsigned int v : cell->vertex_indices())
          cells.push_back(node(v)); // vertex support points come first
        for (const unsigned int f : cell->face_indices())
          {
            const auto face = cell->face(f);
            const auto id   = face->at_boundary() ? face->boundary_id() : boundary::other;
            if (id == boundary::tip || id == boundary::base)
              for (const auto &[ij, n] : face_nodes(cell, f, base, space.degree, node))
                (id == boundary::tip ? tip : clamped).push_back(n);
            if (id == boundary::cavity)
              add_cavity_triangles(face_nodes(cell, f, base, space.degree, node),
                                   face->n_vertices() == 4, face->center() - cell->center(),
                                   triangles);
          }
      }
    for (const auto &t : gathered_rows(triangles, 3, space.communicator))
      record.cavity_triangles.push_back({{t[0], t[1], t[2]}});
    for (const auto &n : gathered_rows(tip, 1, space.communicator))
      record.tip_nodes.push_back(n[0]);
    for (const auto &n : gathered_rows(clamped, 1, space.communicator))
      record.base_nodes.push_back(n[0]);
    for (const auto &c : gathered_rows(cells, record.nodes_per_cell, space.communicator))
      record.cells.insert(record.cells.end(), c.begin(), c.end());
  }

  void DatabaseExport::add_cavity_triangles(const std::map<std::pair<int, int>, Index> &nodes,
                                            const bool quad, const Tensor<1, 3> &outward,
                                            std::vector<Index> &triangles) const
  {
    for (const auto &t : sub_triangles(quad, space.degree))
      {
        const auto o = oriented({{nodes.at(t[0]), nodes.at(t[1]), nodes.at(t[2])}}, record.X, outward);
        triangles.insert(triangles.end(), o.begin(), o.end());
      }
  }

  std::vector<data::Point3>
  DatabaseExport::deformed_nodes(const TrilinosWrappers::MPI::Vector &ghosted_u) const
  {
    std::vector<double> flat(3 * record.X.size(), 0.0);
    for (std::size_t n = 0; n < record.X.size(); ++n)
      if (space.owned_dofs.is_element(node_dofs[3 * n]))
        for (unsigned int c = 0; c < 3; ++c)
          flat[3 * n + c] = record.X[n][c] + ghosted_u[node_dofs[3 * n + c]];
    MPI_Allreduce(MPI_IN_PLACE, flat.data(), flat.size(), MPI_DOUBLE, MPI_SUM,
                  space.communicator);
    std::vector<data::Point3> x(record.X.size());
    for (std::size_t n = 0; n < x.size(); ++n)
      x[n] = {{flat[3 * n], flat[3 * n + 1], flat[3 * n + 2]}};
    return x;
  }

  TrilinosWrappers::MPI::Vector
  DatabaseExport::displacement(const std::vector<data::Point3> &x) const
  {
    TrilinosWrappers::MPI::Vector u(space.owned_dofs, space.communicator);
    for (std::size_t n = 0; n < record.X.size(); ++n)
      if (space.owned_dofs.is_element(node_dofs[3 * n]))
        for (unsigned int c = 0; c < 3; ++c)
          u[node_dofs[3 * n + c]] = x[n][c] - record.X[n][c];
    u.compress(VectorOperation::insert);
    return u;
  }
} // namespace softchain::fem
