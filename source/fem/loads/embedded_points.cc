#include <softchain/data/input_error.h>
#include <softchain/fem/cell_locator.h>
#include <softchain/fem/embedded_points.h>

#include <deal.II/base/mpi.h>

#include <limits>
#include <sstream>

namespace softchain::fem
{
  using namespace dealii;

  namespace
  {
    EmbeddedPoints::Stencil make_stencil(const FiniteElementSpace &space,
                                         const DoFHandler<3>::active_cell_iterator &cell,
                                         const Point<3> &unit_point)
    {
      const FiniteElement<3> &fe = *space.fe;
      EmbeddedPoints::Stencil s;
      s.cell = cell->active_cell_index();
      s.dof.resize(fe.n_dofs_per_cell());
      cell->get_dof_indices(s.dof);
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        {
          s.component.push_back(fe.system_to_component_index(i).first);
          s.weight.push_back(fe.shape_value(i, unit_point));
        }
      return s;
    }
  } // namespace

  EmbeddedPoints::EmbeddedPoints(const FiniteElementSpace    &space,
                                 const std::vector<Point<3>> &points,
                                 const std::string           &what)
    : EmbeddedPoints(space, points, points, what)
  {}

  EmbeddedPoints::EmbeddedPoints(const FiniteElementSpace    &space,
                                 const std::vector<Point<3>> &points,
                                 const std::vector<Point<3>> &locators,
                                 const std::string           &what)
    : reference(points)
    , owner(points.size())
    , stencils(points.size())
    , my_rank(Utilities::MPI::this_mpi_process(space.communicator))
    , communicator(space.communicator)
  {
    const CellLocator         locator(space.triangulation, *space.mapping);
    const unsigned int        none    = std::numeric_limits<unsigned int>::max();
    const unsigned int        n_ranks = Utilities::MPI::n_mpi_processes(communicator);
    // Each rank's best find per point: rank r in the locator's cell scores r,
    // in the point's own cell (the fallback) n_ranks + r; the lowest wins.
    std::vector<unsigned int> score(points.size(), none);
    std::vector<Stencil>      local(points.size());
    const auto use = [&](const unsigned int k, const CellLocator::Cell &cell, const Point<3> &unit,
                         const unsigned int rank_score) {
      score[k] = rank_score;
      local[k] = make_stencil(space, DoFHandler<3>::active_cell_iterator(
                                       &space.triangulation, cell->level(), cell->index(),
                                       &space.dof_handler),
                              unit);
    };
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        const auto cell = locator.locate(locators[k]).first;
        if (cell.state() == IteratorState::valid && cell->is_locally_owned())
          if (const auto unit = locator.unit_point(cell, points[k], 0.1))
            {
              use(k, cell, *unit, my_rank);
              continue;
            }
        const auto [own_cell, unit] = locator.locate(points[k]);
        if (own_cell.state() == IteratorState::valid && own_cell->is_locally_owned())
          use(k, own_cell, unit, n_ranks + my_rank);
      }
    MPI_Allreduce(MPI_IN_PLACE, score.data(), score.size(), MPI_UNSIGNED, MPI_MIN, communicator);
    for (unsigned int k = 0; k < points.size(); ++k)
      owner[k] = score[k] == none ? none : score[k] % n_ranks;
    for (unsigned int k = 0; k < points.size(); ++k)
      if (owner[k] == none)
        {
          std::ostringstream msg;
          msg << what << " " << k << " at (" << points[k] << ") lies outside the body";
          throw data::InputError(msg.str());
        }
    // Every rank gets every stencil (a link may join points of two ranks).
    const auto gathered = Utilities::MPI::all_gather(communicator, local);
    for (unsigned int k = 0; k < points.size(); ++k)
      stencils[k] = gathered[owner[k]][k];
  }

  std::vector<Point<3>>
  EmbeddedPoints::deformed(const TrilinosWrappers::MPI::Vector &u) const
  {
    std::vector<double> flat(3 * size(), 0.0);
    for (unsigned int k = 0; k < size(); ++k)
      if (owned(k))
        {
          const Stencil &s = stencils[k];
          for (unsigned int i = 0; i < s.dof.size(); ++i)
            flat[3 * k + s.component[i]] += s.weight[i] * u[s.dof[i]];
        }
    MPI_Allreduce(MPI_IN_PLACE, flat.data(), flat.size(), MPI_DOUBLE, MPI_SUM, communicator);
    std::vector<Point<3>> x(size());
    for (unsigned int k = 0; k < size(); ++k)
      x[k] = reference[k] + Point<3>(flat[3 * k], flat[3 * k + 1], flat[3 * k + 2]);
    return x;
  }
} // namespace softchain::fem
