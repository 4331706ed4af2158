#pragma once
// The softchain commands that run the FEM tier (docs/conventions.md,
// "Command line and exit codes"); main.cc calls the other tiers' entry points
// directly. Each takes the .prm read once by main and returns the process
// exit status: 0 success, 1 bad input, 2 some sample failed.
#include <softchain/data/prm_file.h>

namespace softchain::app
{
  // One FEM solve of subsection Loads; VTU output and solve_summary.csv.
  int solve_command(const data::PrmFile &prm);
  // The sample sweep into <output dir>/database.h5 (fem::SampleSweep).
  int sweep_command(const data::PrmFile &prm);
  // The design's FEM discretisation error: Loads on its mesh against the
  // converged estimate from three finer meshes with fibre sheets;
  // <output dir>/fem_accuracy.csv.
  int accuracy_command(const data::PrmFile &prm);
  // The whole pipeline: sweep, reduction, chain, report; lists every output file.
  int run_command(const data::PrmFile &prm);
} // namespace softchain::app
