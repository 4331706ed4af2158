// Patch tests (Zienkiewicz & Taylor, The Finite Element Method, Vol. 1,
// Ch. 9): on a distorted mesh,
//  - a homogeneous deformation x = F0 X + c, which every element type
//    (Q1/Q2 on trilinear-mapped hexahedra, P1/P2 on affine tetrahedra)
//    interpolates exactly, has a constant stress, so the internal force
//    f_i = int P : Grad N_i dV0 = P : (closed-surface integral of N_i N dA)
//    vanishes at every DoF whose shape function is zero on the boundary;
//  - a rigid rotation has zero stress, so the residual vanishes everywhere.
// Gauss quadrature of degree + 1 points integrates Grad N_i JxW exactly on
// these elements, so both hold to round-off.
#include "fem_test_tools.h"

#include <softchain/fem/boundary_ids.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/numerics/vector_tools.h>
#include <deal.II/physics/transformations.h>

#include <catch2/catch.hpp>

using namespace dealii;
using namespace softchain;
using namespace softchain::fem;

namespace
{
  constexpr double       edge  = 0.01; // block edge [m]
  constexpr unsigned int cells = 3; // per edge
  constexpr double       E = 2.6e5, nu = 0.48;

  // A cells^3 block with randomly moved interior vertices, clamped at
  // x = 0, as hexahedra or split into tetrahedra.
  void distorted_block(const bool tetrahedra, Triangulation<3> &mesh)
  {
    Triangulation<3> hexes;
    GridGenerator::subdivided_hyper_rectangle(hexes, {cells, cells, cells}, Point<3>(),
                                              Point<3>(edge, edge, edge));
    GridTools::distort_random(0.25, hexes, /*keep_boundary*/ true, /*seed*/ 7);
    if (tetrahedra)
      GridGenerator::convert_hypercube_to_simplex_mesh(hexes, mesh);
    else
      mesh.copy_triangulation(hexes);
    for (const auto &face : mesh.active_face_iterators())
      if (face->at_boundary())
        face->set_boundary_id(face->center()[0] < 1e-9 * edge ? boundary::base : boundary::other);
  }

  class AffineDisplacement : public Function<3>
  {
  public:
    AffineDisplacement(const Tensor<2, 3> &grad_u, const Tensor<1, 3> &shift)
      : Function<3>(3), grad_u(grad_u), shift(shift)
    {}
    double value(const Point<3> &p, const unsigned int c) const override
    {
      return (grad_u * p + shift)[c];
    }

  private:
    Tensor<2, 3> grad_u;
    Tensor<1, 3> shift;
  };

  // -R(u) at u = grad_u X + shift, interpolated.
  TrilinosWrappers::MPI::Vector residual(QuasiStaticSolver &solver, const Tensor<2, 3> &grad_u,
                                         const Tensor<1, 3> &shift)
  {
    const auto                   &space = solver.space();
    TrilinosWrappers::MPI::Vector u(space.owned_dofs, space.communicator);
    VectorTools::interpolate(*space.mapping, space.dof_handler, AffineDisplacement(grad_u, shift),
                             u);
    solver.set_displacement(u);
    REQUIRE(solver.assemble(LoadState(), false));
    return solver.negative_residual();
  }

  // Largest |R_i| over the owned DoFs in (or, with inside = false, outside)
  // the set `dofs`, on all ranks.
  double max_entry(const TrilinosWrappers::MPI::Vector &r, const IndexSet &dofs, const bool inside)
  {
    double m = 0;
    for (const auto i : r.locally_owned_elements())
      if (dofs.is_element(i) == inside)
        m = std::max(m, std::abs(r[i]));
    return Utilities::MPI::max(m, MPI_COMM_WORLD);
  }

  // The DoFs on the boundary of the body (all ranks' boundary faces).
  IndexSet boundary_dofs(const FiniteElementSpace &space)
  {
    const IndexSet mine = DoFTools::extract_boundary_dofs(space.dof_handler);
    IndexSet       all(space.dof_handler.n_dofs());
    for (const auto &part : Utilities::MPI::all_gather(space.communicator, mine))
      all.add_indices(part);
    return all;
  }

  // `prm_name` names the .prm file, one per test case (safe under ctest -j).
  std::unique_ptr<test::MeshSolverFixture> block_solver(const std::string &prm_name,
                                                        const std::string &element,
                                                        const std::string &energy)
  {
    Triangulation<3> mesh;
    distorted_block(element[0] == 'P', mesh);
    return std::make_unique<test::MeshSolverFixture>(
      test::parameters_from_text(prm_name,
                                 test::solid_prm(element, energy, E, nu)),
      mesh);
  }
} // namespace

TEST_CASE("patch test: a homogeneous deformation is in equilibrium inside", "[fem][patch]")
{
  const Tensor<2, 3> grad_u({{0.10, 0.05, -0.02}, {0.03, -0.08, 0.04}, {0.02, 0.06, 0.12}});
  const Tensor<1, 3> shift({1e-4, -2e-4, 3e-4});
  for (const std::string energy : {"log", "split"})
    for (const std::string element : {"Q1", "Q2", "P1", "P2"})
      {
        INFO(element << ", " << energy << " strain energy");
        auto       f        = block_solver("patch_homogeneous", element, energy);
        const auto r        = residual(*f->solver, grad_u, shift);
        const auto boundary = boundary_dofs(f->solver->space());
        // The boundary DoFs carry the traction P N dA of the homogeneous
        // stress (~ |P| h^2); the interior sums cancel a few hundred terms of
        // that size, each exact to ~1e-16 relative. Measured: interior
        // <= 3e-14 of the boundary entries; 1e-11 leaves a margin of > 300
        // and fails for any stress gradient above 1e-11 of the stress.
        const double traction_scale = max_entry(r, boundary, true);
        REQUIRE(traction_scale > 0);
        const double interior = max_entry(r, boundary, false);
        INFO("max interior |R| = " << interior << ", max boundary |R| = " << traction_scale);
        CHECK(interior <= 1e-11 * traction_scale);
      }
}

TEST_CASE("patch test: a rigid rotation has zero stress", "[fem][patch]")
{
  // 70 degrees about an oblique axis: far from small strain.
  const Tensor<2, 3> rotation = Physics::Transformations::Rotations::rotation_matrix_3d(
    Tensor<1, 3>({1.0, 2.0, 3.0}) / std::sqrt(14.0), 70.0 * numbers::PI / 180.0);
  const Tensor<1, 3> shift({1e-3, 2e-3, -1e-3});
  const double       mu = ElasticConstants(E, nu).mu;
  for (const std::string energy : {"log", "split"})
    for (const std::string element : {"Q1", "Q2", "P1", "P2"})
      {
        INFO(element << ", " << energy << " strain energy");
        auto       f = block_solver("patch_rotation", element, energy);
        const auto r = residual(*f->solver, rotation - unit_symmetric_tensor<3>(), shift);
        // R R^T = I to ~1e-16, so the stress is ~1e-15 mu and each nodal
        // force (a few cells of area h^2) ~1e-15 mu h^2 (measured: <= 5e-14
        // mu h^2); 1e-11 mu h^2 is the force of a strain of ~1e-11, far below
        // any real stress.
        const double h = edge / cells;
        const IndexSet none(r.size());
        const double   largest = max_entry(r, none, false); // over all DoFs
        INFO("max |R| = " << largest << " N; mu h^2 = " << mu * h * h << " N");
        CHECK(largest <= 1e-11 * mu * h * h);
      }
}
