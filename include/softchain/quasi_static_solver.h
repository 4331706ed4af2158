#pragma once
// QuasiStaticSolver: total-Lagrangian, quasi-static, large-deformation
// equilibrium of a hyperelastic body with a follower cavity pressure,
// embedded tension-only springs and point loads:
//     R(u) = f_int(u) + f_springs(u) - f_pressure(u) - f_points = 0,
// solved by Newton-Raphson with the exact tangent K = dR/du, adaptive load
// stepping (cut on divergence or J <= 0, grow after easy steps) and a
// backtracking line search on |R|.
#include <softchain/dead_surface_traction.h>
#include <softchain/embedded_points.h>
#include <softchain/embedded_spring_network.h>
#include <softchain/finite_element_space.h>
#include <softchain/follower_pressure.h>
#include <softchain/hyperelastic_material.h>
#include <softchain/load_state.h>
#include <softchain/parameters.h>
#include <softchain/serial_direct_solver.h>

#include <deal.II/base/timer.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace softchain
{
  class QuasiStaticSolver
  {
  public:
    struct Result
    {
      bool                converged = false;
      std::string         reason; // why not converged
      bool                limit_point = false; // stopped at a physical limit point
      double              load_factor_reached = 0.0;
      unsigned int        newton_iterations   = 0;
      unsigned int        load_steps          = 0;
      double              wall_time           = 0.0;
      std::vector<double> residual_history; // |R| of every Newton iteration
    };

    // `material_names[id]` names the .prm material region of material id.
    QuasiStaticSolver(const Parameters                  &parameters,
                      const Triangulation<3>            &serial_mesh,
                      const std::vector<std::string>    &material_names,
                      const std::vector<SpringPolyline> &springs,
                      MPI_Comm                           communicator,
                      std::ostream                      &log);

    // Moves the current state (rest, or the last converged state) to
    // `target` along the straight load path between them.
    Result solve(const LoadState &target);
    // Back to the undeformed state with no load.
    void reset();

    // The pieces, for tests and output.
    const FiniteElementSpace            &space() const { return *fe_space; }
    const TrilinosWrappers::MPI::Vector &displacement() const { return u_ghosted; }
    void set_displacement(const TrilinosWrappers::MPI::Vector &owned_u);
    // Restart from a stored equilibrium: `owned_u` balances `state` (the
    // next solve() continues from there; used by the sample sweep).
    void set_state(const TrilinosWrappers::MPI::Vector &owned_u, const LoadState &state)
    {
      set_displacement(owned_u);
      load = state;
    }
    // Assembles rhs = -R(u) (and K = dR/du when with_matrix) at `state`.
    // Returns false if some quadrature point has J <= 0.
    bool assemble(const LoadState &state, bool with_matrix);
    const TrilinosWrappers::SparseMatrix &tangent() const { return matrix; }
    const TrilinosWrappers::MPI::Vector  &negative_residual() const { return rhs; }
    const FollowerPressure              &pressure_load() const { return *pressure; }
    const EmbeddedSpringNetwork         *spring_network() const { return springs.get(); }
    const HyperelasticMaterial &material(types::material_id id) const { return *materials.at(id); }
    // Deformed positions of `points` (reference, inside the body).
    std::vector<Point<3>> deformed_points(const std::vector<Point<3>> &points) const;
    TimerOutput          &timer() { return computing_timer; }

  private:
    const Parameters                                   &prm;
    std::ostream                                       &log;
    std::unique_ptr<FiniteElementSpace>                 fe_space;
    std::vector<std::unique_ptr<HyperelasticMaterial>> materials;
    std::unique_ptr<FollowerPressure>                   pressure;
    std::unique_ptr<DeadSurfaceTraction>                tip_traction;
    std::unique_ptr<EmbeddedSpringNetwork>              springs;
    TimerOutput                                         computing_timer;
    std::unique_ptr<SerialDirectSolver>                 serial_direct; // UMFPACK, one rank

    TrilinosWrappers::SparseMatrix matrix;
    TrilinosWrappers::MPI::Vector  rhs;       // writable ghosts
    TrilinosWrappers::MPI::Vector  u_owned;   // the displacement
    TrilinosWrappers::MPI::Vector  u_ghosted; // same, with ghost values
    TrilinosWrappers::MPI::Vector  du;
    IndexSet                       writable_dofs;
    LoadState                      load; // at u
    double                         f_ext_norm = 0.0;

    void setup_system();
    bool assemble_cells(bool with_matrix, double gravity_factor);
    void assemble_point_loads(const std::vector<PointLoad> &point_loads);
    bool solve_linear(); // false if the linear solver failed

    struct NewtonOutcome
    {
      bool         converged;
      bool         inverted;
      unsigned int iterations;
    };
    NewtonOutcome newton(const LoadState &state, Result &result);
    bool          converged(double residual, double update) const;
    bool          line_search(const LoadState &state, double s0, bool valid);
    std::string   classify_failure(const std::vector<std::pair<double, double>> &pv,
                                   bool inverted) const;
  };
} // namespace softchain
