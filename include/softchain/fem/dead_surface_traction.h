#pragma once
// DeadSurfaceTraction: a traction t0 [N/m^2] per unit reference area on one
// boundary part, fixed in direction and magnitude (a dead load):
//     f_ext_i = int_Gamma0 N_i . t0 dA.
// Used for tip loads (cantilever, Cook's membrane) where a point load would
// be a singular load in a 3D continuum.
#include <softchain/fem/finite_element_space.h>

#include <deal.II/lac/trilinos_vector.h>

namespace softchain::fem
{
  class DeadSurfaceTraction
  {
  public:
    DeadSurfaceTraction(const FiniteElementSpace &space, dealii::types::boundary_id boundary);

    // rhs += f_ext for traction t0.
    void assemble(const dealii::Tensor<1, 3>              &traction,
                  const dealii::AffineConstraints<double> &constraints,
                  dealii::TrilinosWrappers::MPI::Vector   &rhs) const;
    // Reference area of the boundary part (all ranks).
    double area() const { return total_area; }

  private:
    const FiniteElementSpace &space;
    dealii::types::boundary_id        boundary;
    double                    total_area;
  };
} // namespace softchain::fem
