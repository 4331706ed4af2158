#include <softchain/data/input_error.h>
#include <softchain/fem/embedded_spring_network.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <sstream>

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
    links_in_cell.resize(space.triangulation.n_active_cells());
    for (unsigned int k = 0; k < links.size(); ++k)
      if (nodes->owned(links[k].a))
        {
          const auto &a = nodes->stencil(links[k].a), &b = nodes->stencil(links[k].b);
          if (!nodes->owned(links[k].b) || a.cell != b.cell || a.dof != b.dof)
            {
              std::ostringstream message;
              message << "spring link " << k << " of network '" << network_names[links[k].network]
                      << "' from (" << nodes->reference_point(links[k].a) << ") to ("
                      << nodes->reference_point(links[k].b)
                      << ") does not lie in one cell of the mesh";
              throw data::InputError(message.str());
            }
          owned_stencils[k] = link_stencil(links[k]);
          links_in_cell[a.cell].push_back(k);
        }
  }

  // The DoFs of the link's cell, in its order, each with
  // delta_i = N_i(b) - N_i(a).
  EmbeddedSpringNetwork::LinkStencil
  EmbeddedSpringNetwork::link_stencil(const Link &link) const
  {
    const auto &a = nodes->stencil(link.a), &b = nodes->stencil(link.b);
    LinkStencil result{a.component, b.weight,
                       nodes->reference_point(link.b) - nodes->reference_point(link.a)};
    for (unsigned int i = 0; i < a.weight.size(); ++i)
      result.delta[i] -= a.weight[i];
    return result;
  }

  void EmbeddedSpringNetwork::add_link(const Link &link, const LinkStencil &s,
                                       const Vector<double> &u, FullMatrix<double> *matrix,
                                       Vector<double> &rhs) const
  {
    Tensor<1, 3> d = s.rest_vector;
    for (unsigned int i = 0; i < s.component.size(); ++i)
      d[s.component[i]] += s.delta[i] * u[i];
    const double l        = d.norm();
    const auto [T, dT_dl] = tension(link, l, smoothing);
    if (T == 0.0)
      return; // slack: no force, no stiffness
    const Tensor<1, 3> e = d / l;
    for (unsigned int i = 0; i < s.component.size(); ++i)
      rhs(i) -= s.delta[i] * T * e[s.component[i]];
    if (!matrix)
      return;
    double H[3][3];
    for (unsigned int c = 0; c < 3; ++c)
      for (unsigned int c2 = 0; c2 < 3; ++c2)
        H[c][c2] = dT_dl * e[c] * e[c2] + T / l * ((c == c2) - e[c] * e[c2]);
    for (unsigned int i = 0; i < s.component.size(); ++i)
      for (unsigned int j = 0; j < s.component.size(); ++j)
        (*matrix)(i, j) += s.delta[i] * H[s.component[i]][s.component[j]] * s.delta[j];
  }

  void EmbeddedSpringNetwork::assemble_cell(const unsigned int cell_index, const Vector<double> &cell_u,
                                            FullMatrix<double> *cell_matrix,
                                            Vector<double>     &cell_rhs) const
  {
    for (const unsigned int k : links_in_cell[cell_index])
      add_link(links[k], owned_stencils[k], cell_u, cell_matrix, cell_rhs);
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
