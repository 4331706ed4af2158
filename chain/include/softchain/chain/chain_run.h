#pragma once
// ChainRun: `softchain chain FILE.prm` (and the chain step of `softchain run`).
//  1. reads subsection Chain of the .prm (ChainParameters);
//  2. builds the chain of the selected method from
//     <output_dir>/stiffness/<M>_b<f>a*.csv (the other method too if its files
//     exist) with the tip at the reference centroid of the database's tip
//     nodes (required: they also give the FEM tip pose), and the
//     beam-theory baseline from the database mesh with the same J_p;
//  3. compares each with the FEM tip pose of the samples of the validation
//     roles: <output_dir>/chain/validation.csv, validation_summary.csv and
//     validation.png (gnuplot);
//  4. with export_mjcf, writes <output_dir>/chain/finger.xml (MjcfExport).
// Returns 0, or 2 if some chain equilibrium failed (named on stderr; the
// tables are written anyway). Bad input throws data::InputError.
#include <softchain/data/prm_file.h>

#include <string>

namespace softchain::chain
{
  int run_chain(const data::PrmFile &prm, const std::string &database_path,
                const std::string &output_dir, bool export_mjcf);
} // namespace softchain::chain
