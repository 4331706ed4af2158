#pragma once
// EmbeddedPoints: points given in reference coordinates inside the body (spring
// nodes, force points), each located once in the mesh (cell + reference
// coordinates) and then carried by the displacement field through the shape
// functions: x = X + sum_i N_i(xi) u_i. This generalises the paper's
// barycentric weights (Sec. III-A) to any Lagrange element.
#include <softchain/fem/finite_element_space.h>

#include <deal.II/lac/trilinos_vector.h>

#include <string>
#include <vector>

namespace softchain::fem
{
  class EmbeddedPoints
  {
  public:
    // How a point's displacement depends on the DoFs: for component c,
    // u_c = sum_k weight[k] u[dof[k]] over the entries with component[k] == c.
    struct Stencil
    {
      std::vector<dealii::types::global_dof_index> dof;
      std::vector<unsigned int>            component;
      std::vector<double>                  weight;
      // The cell whose DoFs these are (dof in that cell's order): its
      // active_cell_index() on the rank that owns the point.
      unsigned int cell = 0;

      // For the all-gather of stencils across ranks (boost serialization).
      template <class Archive>
      void serialize(Archive &archive, const unsigned int)
      {
        archive &dof &component &weight &cell;
      }
    };

    // Locates every point. Throws data::InputError naming `what` and the
    // point index and coordinates if a point lies outside the body.
    EmbeddedPoints(const FiniteElementSpace    &space,
                   const std::vector<dealii::Point<3>> &reference_points,
                   const std::string           &what);
    // Point k is evaluated in the cell around `locators[k]`: points on a
    // cell face then use the cell their link lies in. A point may lie
    // outside that cell by 10 % of the unit cell (the shape functions are
    // smooth polynomials there).
    EmbeddedPoints(const FiniteElementSpace    &space,
                   const std::vector<dealii::Point<3>> &reference_points,
                   const std::vector<dealii::Point<3>> &locators,
                   const std::string           &what);

    unsigned int size() const { return reference.size(); }
    // Whether this rank assembles the contributions of point k (each point has
    // exactly one owning rank).
    bool                 owned(unsigned int k) const { return owner[k] == my_rank; }
    const Stencil       &stencil(unsigned int k) const { return stencils[k]; }
    const dealii::Point<3>      &reference_point(unsigned int k) const { return reference[k]; }

    // Deformed positions of all points, identical on every rank.
    std::vector<dealii::Point<3>> deformed(const dealii::TrilinosWrappers::MPI::Vector &ghosted_u) const;

  private:
    std::vector<dealii::Point<3>>     reference;
    std::vector<unsigned int> owner;
    std::vector<Stencil>      stencils; // all points, on every rank
    unsigned int              my_rank;
    MPI_Comm                  communicator;
  };
} // namespace softchain::fem
