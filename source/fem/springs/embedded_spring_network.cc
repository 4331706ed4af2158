#include <softchain/data/input_error.h>
#include <softchain/fem/embedded_spring_network.h>
#include <softchain/fem/sheet_quadrature.h>

#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <cmath>
#include <sstream>

namespace softchain::fem
{
  using namespace dealii;

  EmbeddedSpringNetwork::EmbeddedSpringNetwork(
    const FiniteElementSpace            &space,
    const std::vector<SpringPolyline>   &polylines,
    const std::vector<FibreSheet>       &sheets,
    const std::map<std::string, double> &axial_rigidity,
    const double                         smoothing_strain)
    : tension_law(smoothing_strain)
  {
    const auto rigidity_of = [&](const std::string &network) {
      const auto rigidity = axial_rigidity.find(network);
      if (rigidity == axial_rigidity.end())
        throw data::InputError("Springs/Axial rigidity: no value for spring network '" + network + "'");
      if (network_index(network) == network_names.size())
        network_names.push_back(network);
      return rigidity->second;
    };
    // Two embedded nodes per link, both evaluated in the cell around the
    // link's midpoint (cell_conforming_polylines() puts each link in one cell).
    std::vector<Point<3>> ends, midpoints;
    for (const auto &polyline : polylines)
      {
        const double EA = rigidity_of(polyline.network);
        const auto        &p       = polyline.points;
        const unsigned int n       = p.size();
        const unsigned int n_links = n < 2 ? 0 : (polyline.closed ? n : n - 1);
        for (unsigned int k = 0; k < n_links; ++k)
          {
            const Point<3> &a = p[k], &b = p[(k + 1) % n];
            if (a.distance(b) < 1e-12) // a repeated node: no link
              continue;
            links.push_back({static_cast<unsigned int>(ends.size()),
                             static_cast<unsigned int>(ends.size() + 1), a.distance(b), EA,
                             network_index(polyline.network)});
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
          owned_links.push_back(k);
        }
    for (const auto &sheet : sheets)
      add_sheet(space, sheet, rigidity_of(sheet.network));
    with_sheets = !sheets.empty();
    double squares = 0;
    for (const unsigned int k : owned_links)
      {
        const LinkStencil &s = owned_stencils[k];
        const Tensor<1, 3> e = s.rest_vector / s.rest_vector.norm();
        const double       T = s.axial_rigidity * tension_law.tension(0.0);
        for (unsigned int i = 0; i < s.component.size(); ++i)
          squares += std::pow(T * s.delta[i] * e[s.component[i]], 2);
      }
    rest_force_norm = std::sqrt(Utilities::MPI::sum(squares, space.communicator));
    link_state.assign(owned_stencils.size(), tension_law.state_at(0.0));
    state_before = link_state;
    state_step.assign(owned_stencils.size(), {0.0, 0.0});
  }

  void EmbeddedSpringNetwork::add_sheet(const FiniteElementSpace &space, const FibreSheet &sheet,
                                        const double axial_rigidity)
  {
    const FiniteElement<3> &fe = *space.fe;
    for (const auto &rule : sheet_quadrature(space, sheet.corners))
      {
        FEValues<3> values(*space.mapping, fe, Quadrature<3>(rule.unit_points),
                           update_values | update_gradients | update_quadrature_points);
        values.reinit(rule.cell);
        std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
        rule.cell->get_dof_indices(dofs);
        for (unsigned int q = 0; q < rule.weights.size(); ++q)
          for (const auto &family : sheet.families)
            {
              LinkStencil s{dofs, {}, {}, family.direction, 1.0,
                            axial_rigidity / family.spacing * rule.weights[q]};
              SheetPlace  place{static_cast<unsigned int>(owned_stencils.size()),
                               values.quadrature_point(q),
                               {},
                               rule.weights[q],
                               network_index(sheet.network)};
              for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                {
                  const unsigned int c = fe.system_to_component_index(i).first;
                  s.component.push_back(c);
                  s.delta.push_back(values.shape_grad_component(i, q, c) * family.direction);
                  place.value.push_back(values.shape_value_component(i, q, c));
                }
              sheet_places.push_back(std::move(place));
              links_in_cell[rule.cell->active_cell_index()].push_back(owned_stencils.size());
              owned_links.push_back(owned_stencils.size());
              owned_stencils.push_back(std::move(s));
            }
      }
  }

  // The DoFs of the link's cell, in its order, each with
  // delta_i = N_i(b) - N_i(a).
  EmbeddedSpringNetwork::LinkStencil
  EmbeddedSpringNetwork::link_stencil(const Link &link) const
  {
    const auto &a = nodes->stencil(link.a), &b = nodes->stencil(link.b);
    LinkStencil result{a.dof,
                       a.component,
                       b.weight,
                       nodes->reference_point(link.b) - nodes->reference_point(link.a),
                       link.rest_length,
                       link.axial_rigidity};
    for (unsigned int i = 0; i < a.weight.size(); ++i)
      result.delta[i] -= a.weight[i];
    return result;
  }

  Tensor<1, 3> EmbeddedSpringNetwork::link_vector(const unsigned int k, const Vector<double> &u) const
  {
    const LinkStencil &s = owned_stencils[k];
    Tensor<1, 3>       d = s.rest_vector;
    for (unsigned int i = 0; i < s.component.size(); ++i)
      d[s.component[i]] += s.delta[i] * u[i];
    return d;
  }

  Tensor<1, 3> EmbeddedSpringNetwork::link_vector(const unsigned int                   k,
                                                  const TrilinosWrappers::MPI::Vector &u,
                                                  const bool with_rest) const
  {
    const LinkStencil &s = owned_stencils[k];
    Tensor<1, 3>       d = with_rest ? s.rest_vector : Tensor<1, 3>();
    for (unsigned int i = 0; i < s.component.size(); ++i)
      d[s.component[i]] += s.delta[i] * u[s.dof[i]];
    return d;
  }

  // The link's force uses its condensed tension T_eff = EA t_eff(eps; t, g)
  // (TensionOnlyLaw::condensed_tension) and the tangent the condensed
  // slope, dT_eff/dl = EA t / ((t + g) L); the geometric term keeps the
  // link's own tension EA t, so that K is the Jacobian of the whole system
  // (u, t, g) with (t, g) eliminated. On the law (set_link_states) both are
  // the law's T(eps) and dT/dl.
  double EmbeddedSpringNetwork::add_link(const unsigned int k, const Vector<double> &u,
                                         FullMatrix<double> *matrix, Vector<double> &rhs) const
  {
    const LinkStencil          &s     = owned_stencils[k];
    const TensionOnlyLaw::State state = link_state[k];
    const Tensor<1, 3>          d     = link_vector(k, u);
    const double                l     = d.norm();
    const double                eps   = (l - s.rest_length) / s.rest_length;
    const double                EA    = s.axial_rigidity;
    const double                T     = EA * tension_law.condensed_tension(state, eps);
    const Tensor<1, 3>          e     = d / l;
    double                      f_norm_squared = 0;
    for (unsigned int i = 0; i < s.component.size(); ++i)
      {
        const double f_i = s.delta[i] * e[s.component[i]];
        rhs(i) -= f_i * T;
        f_norm_squared += f_i * f_i;
      }
    if (matrix)
      {
        const double dT_dl = EA * tension_law.condensed_slope(state) / s.rest_length;
        const double T_own = EA * state.tension;
        double       H[3][3];
        for (unsigned int c = 0; c < 3; ++c)
          for (unsigned int c2 = 0; c2 < 3; ++c2)
            H[c][c2] = dT_dl * e[c] * e[c2] + T_own / l * ((c == c2) - e[c] * e[c2]);
        // K_ij = delta_i w^{c_i}_j with w^c_j = H_{c c_j} delta_j, formed once
        // per component: each row of K is then one contiguous, vectorised
        // update instead of a gather of H per entry. The rows w^c live in a
        // buffer per assembly thread, so that no link allocates.
        const unsigned int                n = s.component.size();
        thread_local std::vector<double> w;
        w.resize(3 * n);
        for (unsigned int c = 0; c < 3; ++c)
          for (unsigned int j = 0; j < n; ++j)
            w[c * n + j] = H[c][s.component[j]] * s.delta[j];
        for (unsigned int i = 0; i < n; ++i)
          {
            const double  delta_i = s.delta[i];
            const double *w_i     = &w[s.component[i] * n];
            double       *row     = &(*matrix)(i, 0);
            for (unsigned int j = 0; j < n; ++j)
              row[j] += delta_i * w_i[j];
          }
      }
    return std::abs(T - EA * tension_law.tension(eps)) * std::sqrt(f_norm_squared);
  }

  double EmbeddedSpringNetwork::assemble_cell(const unsigned int cell_index, const Vector<double> &cell_u,
                                              FullMatrix<double> *cell_matrix,
                                              Vector<double>     &cell_rhs) const
  {
    double mismatch = 0;
    for (const unsigned int k : links_in_cell[cell_index])
      mismatch += add_link(k, cell_u, cell_matrix, cell_rhs);
    return mismatch;
  }

  void EmbeddedSpringNetwork::set_link_states(const TrilinosWrappers::MPI::Vector &u)
  {
    for (const unsigned int k : owned_links)
      {
        const double L   = owned_stencils[k].rest_length;
        const double eps = (link_vector(k, u, true).norm() - L) / L;
        // At its rest length (to the round-off of the reference positions)
        // a link starts on the taut side of the knee (TensionOnlyLaw::rest_start).
        link_state[k] = std::abs(eps) <= 1e-12 ? tension_law.rest_start() : tension_law.state_at(eps);
      }
  }

  // The strain increment of a link for du is linearised at u:
  // d_eps = e . (du_b - du_a) / L.
  void EmbeddedSpringNetwork::prepare_link_updates(const TrilinosWrappers::MPI::Vector &u,
                                                   const TrilinosWrappers::MPI::Vector &du)
  {
    for (const unsigned int k : owned_links)
      {
        const double       L     = owned_stencils[k].rest_length;
        const Tensor<1, 3> d     = link_vector(k, u, true);
        const double       l     = d.norm();
        const double       d_eps = link_vector(k, du, false) * d / (l * L);
        state_before[k]          = link_state[k];
        state_step[k]            = tension_law.increment(link_state[k], (l - L) / L, d_eps);
      }
  }

  void EmbeddedSpringNetwork::move_link_states(const double a)
  {
    for (const unsigned int k : owned_links)
      link_state[k] = {state_before[k].tension + a * state_step[k].tension,
                       state_before[k].gap + a * state_step[k].gap};
  }

  unsigned int EmbeddedSpringNetwork::network_index(const std::string &network) const
  {
    return std::find(network_names.begin(), network_names.end(), network) - network_names.begin();
  }

  std::vector<EmbeddedSpringNetwork::SheetFibre>
  EmbeddedSpringNetwork::sheet_fibres(const TrilinosWrappers::MPI::Vector &u) const
  {
    std::vector<SheetFibre> fibres;
    for (const SheetPlace &place : sheet_places)
      {
        const LinkStencil &s = owned_stencils[place.link];
        Point<3>           x = place.reference;
        for (unsigned int i = 0; i < s.dof.size(); ++i)
          x[s.component[i]] += place.value[i] * u[s.dof[i]];
        const Tensor<1, 3> d = link_vector(place.link, u, true);
        fibres.push_back({x, d / d.norm(),
                          s.axial_rigidity / place.area * tension_law.tension(d.norm() - 1),
                          place.network});
      }
    return fibres;
  }

  std::vector<double>
  EmbeddedSpringNetwork::tensions(const TrilinosWrappers::MPI::Vector &u) const
  {
    const auto          x = nodes->deformed(u);
    std::vector<double> result;
    for (const auto &link : links)
      result.push_back(link.axial_rigidity *
                       tension_law.tension((x[link.a].distance(x[link.b]) - link.rest_length) /
                                           link.rest_length));
    return result;
  }
} // namespace softchain::fem
