#pragma once
// TinyDesign: a built-in bender small enough that each solve takes a few
// milliseconds (Q1, 4 cells along the length: 112 nodes, 50 cells), in a
// scratch directory, with helpers that run the softchain executable on it.
#include <softchain/data/actuation_database.h>

#include "../data/scratch_directory.h"

#include <csignal>
#include <string>

namespace softchain::testing
{
  class TinyDesign
  {
  public:
    // `samples`: the body of subsection Samples; `extra`: more subsections.
    TinyDesign(const std::string &name, const std::string &samples, const std::string &extra = "");

    void write(const std::string &samples, const std::string &extra = "") const;

    struct Outcome
    {
      int         status;
      std::string output; // stdout and stderr
    };
    // `softchain COMMAND FILE.prm`, on `ranks` MPI ranks (mpirun if > 1).
    Outcome run(const std::string &command, unsigned int ranks = 1) const;
    // `softchain sweep`, sent `signal` once `lines` progress lines of solved
    // samples were printed; returns the output until then (and the exit
    // status, 128 + signal if the signal killed it).
    std::string sweep_killed_after(int lines, int signal = SIGKILL, int *exit_status = nullptr) const;

    std::string prm() const { return dir.file("tiny.prm"); }
    std::string output() const { return dir.file("out"); }
    std::string database() const { return dir.file("out/database.h5"); }

  private:
    ScratchDirectory dir;
  };

  // A tiny design for `softchain run` (a few seconds of solves): pressure,
  // lateral, torsion and validation samples; the fabric springs, so that
  // pressure bends it; joints 2 cm apart and b = a, so that every slab holds
  // several node planes of the 4-cell mesh (planes 19 mm apart); a rotation
  // threshold lowered below the small loads' rotations (~1e-4 rad).
  // `plots`: the reduction's gnuplot PNGs; `more`: more subsections.
  TinyDesign pipeline_design(const std::string &name, bool plots, const std::string &more = "");
  // Its subsection Samples and the subsections after it (TinyDesign::write's arguments).
  std::string pipeline_samples();
  std::string pipeline_settings(bool plots, const std::string &more = "");

  // The first difference between the stored samples of a and b, comparing
  // everything but the wall times bit for bit; "" if there is none.
  std::string sample_difference(const data::ActuationDatabase &a, const data::ActuationDatabase &b);
} // namespace softchain::testing
