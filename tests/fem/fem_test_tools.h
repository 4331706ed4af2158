#pragma once
// Helpers of the FEM-tier tests: parameters from .prm text, solvers on the
// built-in bender or on a mesh made in the test, random smooth displacement
// fields, displacements at points.
#include <softchain/fem/finger_mesh.h>
#include <softchain/fem/parameters.h>
#include <softchain/fem/quasi_static_solver.h>

#include <memory>
#include <sstream>
#include <string>

namespace softchain::fem::test
{
  // Writes `text` to `name`.prm in the test directory, whole at once (rank 0 writes, all
  // ranks wait for it) and returns the file name.
  std::string write_prm(const std::string &name, const std::string &text);

  // Writes `text` as with write_prm and reads it.
  Parameters parameters_from_text(const std::string &name, const std::string &text);

  // A .prm text for the built-in bender with the given element and options
  // appended (later `set` lines override earlier ones per subsection).
  std::string bender_prm(const std::string &element, unsigned int cells,
                         const std::string &extra_subsections = "");

  // A .prm text for a test-built mesh with one material region `solid`:
  // element type, strain energy ("log" | "split"), E [Pa] and nu, plus
  // `extra_subsections`.
  std::string solid_prm(const std::string &element, const std::string &strain_energy,
                        double youngs_modulus, double poissons_ratio,
                        const std::string &extra_subsections = "");

  // A block [0, length] x [0, height] x [0, height] of `cells` hexahedra
  // per direction, with the boundary ids `base` (x = 0, clamped) and `tip`
  // (x = length): the cantilever of the verification tests.
  void cantilever_block(dealii::Triangulation<3> &mesh, const std::vector<unsigned int> &cells,
                        double length, double height);

  // A solver on a mesh built in the test (material id 0 = region `solid`,
  // boundary ids of boundary_ids.h), no springs.
  struct MeshSolverFixture
  {
    MeshSolverFixture(const Parameters &p, const dealii::Triangulation<3> &mesh);
    Parameters                         prm;
    std::ostringstream                 log;
    std::unique_ptr<QuasiStaticSolver> solver;
  };

  // Displacement of the solver's current state at reference point `p`
  // (inside the body or on its boundary), the same on every rank.
  dealii::Tensor<1, 3> displacement_at(const QuasiStaticSolver &solver, const dealii::Point<3> &p);

  struct SolverFixture
  {
    explicit SolverFixture(const Parameters &p);
    Parameters                         prm;
    FingerMesh                         mesh;
    std::ostringstream                 log;
    std::unique_ptr<QuasiStaticSolver> solver;
  };

  // K v at u and the central difference (R(u + h v) - R(u - h v)) / (2h)
  // of the residual (K = dR/du), both under `load` and zero at the fixed
  // DoFs; the solver is left at u - h v.
  std::pair<dealii::TrilinosWrappers::MPI::Vector, dealii::TrilinosWrappers::MPI::Vector>
  tangent_and_difference(QuasiStaticSolver &solver, const LoadState &load,
                         const dealii::TrilinosWrappers::MPI::Vector &u,
                         const dealii::TrilinosWrappers::MPI::Vector &v, double h);

  // A smooth displacement field (a bend plus a twist plus a stretch of
  // amplitude `scale`) plus seeded noise of relative size `noise`, zero on the
  // clamped base.
  dealii::TrilinosWrappers::MPI::Vector smooth_displacement(const QuasiStaticSolver &solver,
                                                    double scale, double noise,
                                                    unsigned int seed);
} // namespace softchain::fem::test
