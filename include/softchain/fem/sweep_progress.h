#pragma once
// SweepProgress: one line per sample of a sweep,
//   [ 3/12] pressure 30000 Pa   converged   4 load steps  11 Newton it.  0.42 s  ETA 3.8 s  tip u = (...) mm
// The ETA is the mean solve time so far times the samples still to solve,
// divided by the number of sample groups working in parallel; the tip
// displacement is the mean over the mesh's tip nodes of x - X.
#include <softchain/data/actuation_database.h>
#include <softchain/fem/sample_set.h>

#include <cstddef>
#include <ostream>

namespace softchain::fem
{
  class SweepProgress
  {
  public:
    SweepProgress(std::ostream &out, std::size_t n_samples, std::size_t n_to_solve,
                  unsigned int n_groups);

    void cached(const Sample &sample, const data::SampleRecord &record);
    void solved(const Sample &sample, const data::SampleRecord &record,
                const data::MeshRecord &mesh);

  private:
    std::ostream &out;
    std::size_t   n_samples, n_to_solve, n_groups;
    std::size_t   n_done = 0, n_solved = 0;
    double        solve_time = 0.0;

    std::ostream &start_line(const Sample &sample);
  };
} // namespace softchain::fem
