#pragma once
// FrictionalLoadPath: an equilibrium with Coulomb friction, which depends on
// the way the load came (CoulombFriction). Like the FEM's load path of a
// contact sample (docs/contact.md), the load is applied in steps
// t = 1/n, 2/n, ..., 1: pressure t p, point forces t f, the obstacles at
// path parameter t of their motion. Each step starts from the last one's
// angles and stick anchors, and is solved again with the normal forces and
// normals it found, relaxed (Aitken), until they settle (the largest change
// of a point's normal force, 0 where it does not touch, and of N |dn| below
// `tolerance` times the largest normal force): then the friction is
// Coulomb's with the step's own normal forces, as in the FEM, where it is
// part of one Newton system. A point that comes into contact during a step
// sticks where it entered the obstacle on its way to the first solve that
// finds it inside (ChainContact::touching_anchors), and keeps that anchor
// for the step's other solves: re-anchoring it at each solve would be a
// fixed point without contraction (a sticking point sits at its anchor). At
// the step's end the anchors of sliding points follow them to the cone's
// edge (the return mapping). The steps before the last are solved to a
// relative residual of `step_tolerance` (the solver's own where that is
// looser), the last to the solver's: a step's residual moves the next
// step's start and anchors, not the answer (on P10's frictional samples
// 1e-4 gives the forces of 1e-10 to 0.003 points in 40 % of the Newton
// iterations, docs/history.md). Without friction the load is solved at
// once, its equilibrium not depending on the path.
#include <softchain/chain/chain_equilibrium.h>

namespace softchain::chain
{
  struct FrictionalPathSettings
  {
    int    steps      = 80;   // n: P10's grasps converge by 80 (docs/chain_fidelity.md)
    int    max_passes = 100;  // solves per step until the normal forces settle
    double tolerance  = 1e-6; // relative
    double step_tolerance = 1e-4; // Newton's relative residual on the steps before the last
  };

  class FrictionalLoadPath
  {
  public:
    using Settings = FrictionalPathSettings;

    // Keeps a reference to `solver`, which must outlive the path.
    explicit FrictionalLoadPath(ChainEquilibrium &solver, Settings settings = {});

    // The equilibrium at the end of the path; its iterations are every
    // pass's Newton iterations. A failure names the step.
    Equilibrium solve(const ChainLoad &load);
    // The solves of the last path (passes over all steps).
    int passes() const { return passes_; }

    static bool has_friction(const ChainLoad &load);

  private:
    // Sets the solver's tolerance for a step, and restores it when the path
    // ends (also when a solve throws).
    class ToleranceOfSteps
    {
    public:
      ToleranceOfSteps(ChainEquilibrium &solver, double steps);
      ~ToleranceOfSteps();
      void set(bool last_step) const;

    private:
      ChainEquilibrium &solver_;
      double            final_, steps_;
    };

    ChainLoad   at(const ChainLoad &load, double t) const;
    Equilibrium solve_step(ChainLoad load, const std::vector<StickAnchor> &anchors, const Eigen::VectorXd &start);
    bool      settled(const std::vector<StickAnchor> &before, const std::vector<StickAnchor> &after) const;

    ChainEquilibrium &solver_;
    Settings          settings_;
    int               passes_ = 0;
  };
} // namespace softchain::chain
