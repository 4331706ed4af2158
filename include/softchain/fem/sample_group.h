#pragma once
// SampleGroup: the solver of one MPI sample group (a sub-communicator of the
// sweep): one QuasiStaticSolver on the group's ranks, its DatabaseExport, and
// the solve of one sample starting from rest or from a stored converged
// neighbour (continuation).
#include <softchain/fem/base_reaction.h>
#include <softchain/fem/database_export.h>
#include <softchain/fem/finger_mesh.h>
#include <softchain/fem/quasi_static_solver.h>
#include <softchain/fem/sample_set.h>

#include <ostream>
#include <vector>

namespace softchain::fem
{
  class SampleGroup
  {
  public:
    SampleGroup(const Parameters &prm, const FingerMesh &mesh, MPI_Comm group, std::ostream &log);

    const data::MeshRecord &mesh() const { return nodes.mesh(); }
    // Rank 0 of the group: it sends the group's results to world rank 0.
    bool leader() const
    {
      return dealii::Utilities::MPI::this_mpi_process(solver.space().communicator) == 0;
    }

    // Throws data::InputError naming the file and the first sample with a
    // pressure on a mesh without a cavity, a force point outside the body or
    // an obstacle that the finger at rest penetrates.
    void check_samples(const std::vector<Sample> &samples);

    // Solves `sample` from rest (start == nullptr) or from the converged
    // sample `start` (its stored positions and actuation); a sample with a
    // cavity volume ratio by volume control, the record's pressure the one
    // found. A sample with a tip motion needs `anchor`, the equilibrium its
    // motion is relative to (InputError without). A contact sample is solved
    // against its own obstacles (the obstacles at their place from the
    // start) and records the wrench each receives. A force sample that load
    // control cannot solve (a limit point of the forces: the finger buckles
    // sideways) is solved on by displacement control; its record's
    // force_limit and reason then say where the limit lay. A failed solve returns the last converged state,
    // its reason and load factor along the path from the start. Writes
    // vtu/sample_<id>_* when Output/Write VTU.
    data::SampleRecord solve(const Sample &sample, const data::SampleRecord *start,
                             const data::SampleRecord *anchor, unsigned int index);

    // Wall time of assembly and linear solves over all samples solved so
    // far, to the log (Output/Verbose).
    void print_timing() { solver.timer().print_summary(); }

  private:
    const Parameters  prm; // the solver's (it keeps a reference), without obstacles
    QuasiStaticSolver solver;
    DatabaseExport    nodes;
    BaseReaction      base; // each sample's base wrench
    double            rest_volume; // of the cavity (0 without one)

    // The first load factor of a solve from `start` to `target`: the .prm's
    // initial load step scaled so that the first increment is as large as
    // that of a solve from rest (a continued sample often needs one step).
    double first_step(const data::Actuation *start, const data::Actuation &target) const;
    // The smallest load step of load control from the current state to
    // `target`: larger where displacement control can take over.
    double smallest_load_step(const LoadState &target) const;
    // A volume-controlled sample: the cavity inflated to volume `target`
    // from the current state; `pressure` receives the pressure reached.
    QuasiStaticSolver::Result inflate(double target, double &pressure);
    // A force sample that load control could not solve, continued from its
    // last converged state by displacement control (DisplacementControlledForces)
    // where only its forces change on the way; else `failed` unchanged.
    QuasiStaticSolver::Result pass_force_limit(const LoadState &target,
                                               const QuasiStaticSolver::Result &failed,
                                               data::SampleRecord &record);
  };
} // namespace softchain::fem
