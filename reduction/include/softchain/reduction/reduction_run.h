#pragma once
// ReductionRun: `softchain reduce` -- the .prm's subsection Reduction and the
// database in, the stiffness CSV files (and plots) under
// <output_dir>/stiffness/ out.
#include <softchain/data/prm_file.h>
#include <softchain/reduction/reduction_parameters.h>

#include <string>

namespace softchain::reduction
{
  struct ReductionSummary
  {
    int n_samples_used   = 0; // converged samples reduced
    int n_failed_skipped = 0; // failed samples skipped (warning)
    int n_below_threshold = 0; // (sample, joint, axis, method, b) without k (warning)
    int n_past_limit      = 0; // (sample, joint, method, b) increments the joint law leaves out (warning)
    int n_without_law     = 0; // (joint, pressure, method, b) without a joint law (warning)
    bool plots_drawn      = false;
  };

  class ReductionRun
  {
  public:
    // Parses subsection Reduction of `prm` (throws data::InputError).
    ReductionRun(const data::PrmFile &prm, std::string database_path, std::string output_dir);

    // Throws data::InputError for bad input; prints the warnings to stderr.
    ReductionSummary run() const;

  private:
    ReductionParameters parameters_;
    std::string database_path_;
    std::string output_dir_;
  };

  // The command line's entry point: 0 on success; throws data::InputError.
  int run_reduction(const data::PrmFile &prm, const std::string &database_path,
                    const std::string &output_dir);
} // namespace softchain::reduction
