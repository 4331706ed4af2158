#pragma once
// LoadPath: follows a path parameter s from 0 (a converged start) to 1 (the
// target) in adaptive steps (AdaptiveLoadStepping), each solved by Newton
// (NewtonSolver). What s controls is the problem's business
// (LoadPathProblem): the loads under pressure control and prescribed motion
// (QuasiStaticSolver), the cavity volume under volume control
// (VolumeControlledInflation), the forces' conjugate displacement under
// displacement control (DisplacementControlledForces). A problem predicts where a step starts,
// keeps the converged states and returns to the last one when a step fails;
// the path cuts the failed step and tries again.
//
// The path ends when s reaches 1, when the problem has reached its goal
// before (goal_reached(): displacement control stops where the forces
// reach theirs), when a cut step falls below Solver/Minimum load step (or
// the path's own smallest step), or after Solver/Maximum load step attempts
// (converged and failed steps together): every input ends in bounded time.
#include <softchain/fem/newton_solver.h>
#include <softchain/fem/parameters.h>

#include <ostream>
#include <string>
#include <vector>

namespace softchain::fem
{
  class LoadPathProblem
  {
  public:
    virtual ~LoadPathProblem() = default;
    // Aims at the state at path parameter s and moves x to where Newton
    // starts (a prediction from the converged states); returns the system
    // Newton iterates on.
    virtual NewtonSystem &begin_step(double s) = 0;
    // The step to s converged: x is its equilibrium.
    virtual void accept_step(double s) = 0;
    // The step failed: x back to the last converged state.
    virtual void reject_step() = 0;
    // After Newton converged at the path's end: updates the problem's
    // multipliers (an augmented Lagrangian's Uzawa step) and returns true if
    // Newton must solve on with them; false when the state is accepted.
    virtual bool augment() { return false; }
    // After a converged step: true ends the path there, short of s = 1.
    virtual bool goal_reached() const { return false; }
  };

  class LoadPath
  {
  public:
    enum class Stop
    {
      finished,          // s = 1 (or the problem's goal) reached
      step_too_small,    // a cut step fell below Minimum load step
      too_many_attempts  // Maximum load step attempts used up
    };
    struct Result
    {
      Stop                 stop              = Stop::finished;
      double               reached           = 0.0; // s of the last converged state
      unsigned int         newton_iterations = 0;
      unsigned int         load_steps        = 0;   // converged steps
      unsigned int         attempts          = 0;   // converged and failed
      unsigned int         augmentations     = 0;   // Newton solves again after augment()
      NewtonSolver::Status last_failure      = NewtonSolver::Status::converged;
      bool                 finished() const { return stop == Stop::finished; }
    };

    // `name` names s in the log ("load factor", "volume factor"); the path
    // is given up once a cut step falls below `min_step` (default: Solver/
    // Minimum load step).
    LoadPath(const Parameters &prm, double first_step, std::string name, std::ostream &log);
    LoadPath(const Parameters &prm, double first_step, double min_step, std::string name,
             std::ostream &log);

    // From s = 0 to 1; appends every Newton iterate's |R| to `history`.
    Result follow(LoadPathProblem &problem, std::vector<double> *history = nullptr);

  private:
    const Parameters &prm;
    const double      first_step;
    const double      min_step;
    const std::string name;
    std::ostream     &log;
  };

  // Why a path stopped, for people: "an element inverted, J <= 0" and so on.
  std::string describe(NewtonSolver::Status status);
} // namespace softchain::fem
