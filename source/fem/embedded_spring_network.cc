#include <softchain/data/input_error.h>
#include <softchain/fem/embedded_spring_network.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

namespace softchain::fem
{
  using namespace dealii;

  namespace
  {
    // Tension T and dT/dl of a link at current length l (smoothed law).
    std::pair<double, double>
    tension(const EmbeddedSpringNetwork::Link &link, const double l, const double d)
    {
      const double eps = (l - link.rest_length) / link.rest_length;
      const double EA  = link.axial_rigidity;
      if (eps <= 0)
        return {0.0, 0.0};
      if (eps < d)
        return {EA * eps * eps / (2 * d), EA * eps / d / link.rest_length};
      return {EA * (eps - d / 2), EA / link.rest_length};
    }
  } // namespace

  EmbeddedSpringNetwork::EmbeddedSpringNetwork(
    const FiniteElementSpace            &space,
    const std::vector<SpringPolyline>   &polylines,
    const std::map<std::string, double> &axial_rigidity,
    const double                         smoothing_strain)
    : smoothing(smoothing_strain)
  {
    // Two embedded nodes per link, both evaluated in the cell around the
    // link's midpoint (cell_conforming_polylines() puts each link in one cell).
    std::vector<Point<3>> ends, midpoints;
    for (const auto &polyline : polylines)
      {
        const auto rigidity = axial_rigidity.find(polyline.network);
        if (rigidity == axial_rigidity.end())
          throw data::InputError("Springs/Axial rigidity: no value for spring network '" +
                                 polyline.network + "'");
        auto name = std::find(network_names.begin(), network_names.end(), polyline.network);
        if (name == network_names.end())
          name = network_names.insert(network_names.end(), polyline.network);
        const auto        &p       = polyline.points;
        const unsigned int n       = p.size();
        const unsigned int n_links = n < 2 ? 0 : (polyline.closed ? n : n - 1);
        for (unsigned int k = 0; k < n_links; ++k)
          {
            const Point<3> &a = p[k], &b = p[(k + 1) % n];
            if (a.distance(b) < 1e-12) // a repeated node: no link
              continue;
            links.push_back({static_cast<unsigned int>(ends.size()),
                             static_cast<unsigned int>(ends.size() + 1), a.distance(b),
                             rigidity->second,
                             static_cast<unsigned int>(name - network_names.begin())});
            ends.insert(ends.end(), {a, b});
            const Point<3> middle = a + 0.5 * (b - a);
            midpoints.insert(midpoints.end(), {middle, middle});
          }
      }
    nodes = std::make_unique<EmbeddedPoints>(space, ends, midpoints, "spring node");
    owned_stencils.resize(links.size());
    for (unsigned int k = 0; k < links.size(); ++k)
      if (nodes->owned(links[k].a))
        owned_stencils[k] = link_stencil(links[k]);
  }

  EmbeddedSpringNetwork::LinkStencil
  EmbeddedSpringNetwork::link_stencil(const Link &link) const
  {
    LinkStencil result;
    std::map<types::global_dof_index, unsigned int> position;
    for (const unsigned int side : {0u, 1u})
      {
        const auto &s = nodes->stencil(side == 0 ? link.a : link.b);
        for (unsigned int i = 0; i < s.dof.size(); ++i)
          {
            const auto [it, inserted] = position.emplace(s.dof[i], result.dofs.size());
            if (inserted)
              {
                result.dofs.push_back(s.dof[i]);
                result.to_coordinate.emplace_back();
              }
            result.to_coordinate[it->second].emplace_back(3 * side + s.component[i],
                                                          s.weight[i]);
          }
      }
    return result;
  }

  void EmbeddedSpringNetwork::add_couplings(const AffineConstraints<double> &constraints,
                                            DynamicSparsityPattern          &pattern) const
  {
    for (const auto &stencil : owned_stencils)
      constraints.add_entries_local_to_global(stencil.dofs, pattern, false);
  }

  IndexSet EmbeddedSpringNetwork::touched_dofs(const types::global_dof_index n_dofs) const
  {
    IndexSet set(n_dofs);
    for (const auto &stencil : owned_stencils)
      for (const auto dof : stencil.dofs)
        set.add_index(dof);
    set.compress();
    return set;
  }

  void EmbeddedSpringNetwork::assemble(const TrilinosWrappers::MPI::Vector &u,
                                       const AffineConstraints<double>     &constraints,
                                       TrilinosWrappers::SparseMatrix      *matrix,
                                       TrilinosWrappers::MPI::Vector       &rhs) const
  {
    const auto x = nodes->deformed(u);
    for (unsigned int k = 0; k < links.size(); ++k)
      {
        const Link &link = links[k];
        if (!nodes->owned(link.a))
          continue;
        const Tensor<1, 3> d = x[link.b] - x[link.a];
        const double       l       = d.norm();
        const auto [T, dT_dl]      = tension(link, l, smoothing);
        if (T == 0.0)
          continue; // slack: no force, no stiffness
        const Tensor<1, 3> e = d / l;

        // Internal force on (x_a, x_b) and the 6x6 tangent [[H, -H], [-H, H]].
        double g[6], H[6][6] = {};
        for (unsigned int c = 0; c < 3; ++c)
          g[c] = -T * e[c], g[3 + c] = T * e[c];
        for (unsigned int c = 0; c < 3; ++c)
          for (unsigned int d2 = 0; d2 < 3; ++d2)
            {
              const double h = dT_dl * e[c] * e[d2] + T / l * ((c == d2) - e[c] * e[d2]);
              H[c][d2] = H[3 + c][3 + d2] = h;
              H[c][3 + d2] = H[3 + c][d2] = -h;
            }

        const LinkStencil &s = owned_stencils[k];
        const unsigned int n = s.dofs.size();
        Vector<double>     local_rhs(n);
        FullMatrix<double> local_matrix(n, n);
        for (unsigned int i = 0; i < n; ++i)
          for (const auto &[r, w] : s.to_coordinate[i])
            {
              local_rhs(i) -= w * g[r];
              if (matrix)
                for (unsigned int j = 0; j < n; ++j)
                  for (const auto &[q, v] : s.to_coordinate[j])
                    local_matrix(i, j) += w * H[r][q] * v;
            }
        if (matrix)
          constraints.distribute_local_to_global(local_matrix, local_rhs, s.dofs, *matrix, rhs);
        else
          constraints.distribute_local_to_global(local_rhs, s.dofs, rhs);
      }
  }

  std::vector<double>
  EmbeddedSpringNetwork::tensions(const TrilinosWrappers::MPI::Vector &u) const
  {
    const auto          x = nodes->deformed(u);
    std::vector<double> result;
    for (const auto &link : links)
      result.push_back(tension(link, x[link.a].distance(x[link.b]), smoothing).first);
    return result;
  }
} // namespace softchain::fem
