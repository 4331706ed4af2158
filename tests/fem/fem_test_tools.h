#pragma once
// Helpers of the FEM-tier tests: parameters from .prm text, solvers on the
// built-in bender, random smooth displacement fields.
#include <softchain/finger_mesh.h>
#include <softchain/parameters.h>
#include <softchain/quasi_static_solver.h>

#include <memory>
#include <sstream>
#include <string>

namespace softchain::test
{
  // Writes `text` to a file named after `name` in the test directory and reads it.
  Parameters parameters_from_text(const std::string &name, const std::string &text);

  // A .prm text for the built-in bender with the given element and options
  // appended (later `set` lines override earlier ones per subsection).
  std::string bender_prm(const std::string &element, unsigned int cells,
                         const std::string &extra_subsections = "");

  struct SolverFixture
  {
    explicit SolverFixture(const Parameters &p);
    Parameters                         prm;
    FingerMesh                         mesh;
    std::ostringstream                 log;
    std::unique_ptr<QuasiStaticSolver> solver;
  };

  // A smooth displacement field (a bend plus a twist plus a stretch of
  // amplitude `scale`) plus seeded noise of relative size `noise`, zero on the
  // clamped base.
  TrilinosWrappers::MPI::Vector smooth_displacement(const QuasiStaticSolver &solver,
                                                    double scale, double noise,
                                                    unsigned int seed);
} // namespace softchain::test
