#pragma once
// SolutionOutput: ParaView files of a solved state. The body as VTU (PVTU
// under MPI) with displacement, Cauchy stress, von Mises stress, J and
// material id, high-order cells for Q2/P2; the springs as a second VTU of
// line cells with their tension; with fibre sheets, their quadrature points
// (deformed) with each family's direction and tension per unit width; with
// contact, a VTU of the contact
// quadrature points (deformed) with their normal pressure, tangential
// traction, gap and status (0 open, 1 stick, 2 slip); a .pvd series of
// each over load steps or samples.
#include <softchain/fem/quasi_static_solver.h>

#include <string>
#include <utility>
#include <vector>

namespace softchain::fem
{
  class SolutionOutput
  {
  public:
    SolutionOutput(const std::string &directory, unsigned int subdivisions);

    // Writes `name`_NNNN files for `solver`'s current state and adds them to
    // the series; returns the body file name.
    std::string write(const QuasiStaticSolver &solver, const std::string &name, double time);

  private:
    std::string                                 directory;
    unsigned int                                subdivisions;
    unsigned int                                counter = 0;
    std::vector<std::pair<double, std::string>> body_series, spring_series, sheet_series, contact_series;

    // `name`_`part`_NNNN.vtu by `write_part`, added to `series` and its .pvd.
    template <typename WritePart>
    void write_series_part(const QuasiStaticSolver &solver, const std::string &name, const std::string &part,
                           double time, std::vector<std::pair<double, std::string>> &series,
                           WritePart write_part);
    void write_springs(const QuasiStaticSolver &solver, const std::string &file) const;
    void write_sheets(const QuasiStaticSolver &solver, const std::string &file) const;
    void write_contact(const QuasiStaticSolver &solver, const std::string &file) const;
  };
} // namespace softchain::fem
