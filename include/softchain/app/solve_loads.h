#pragma once
// The .prm's subsection Loads under Control = pressure, solved from the
// solver's current state: pressure, point loads, gravity and tip traction
// along one load path, then the tip motion from that state. The solve and
// accuracy commands share it.
#include <softchain/fem/parameters.h>
#include <softchain/fem/quasi_static_solver.h>

#include <ostream>

namespace softchain::app
{
  fem::QuasiStaticSolver::Result solve_loads(fem::QuasiStaticSolver &solver, const fem::Parameters &prm,
                                             std::ostream &out);
} // namespace softchain::app
