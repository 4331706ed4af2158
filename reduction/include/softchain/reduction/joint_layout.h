#pragma once
// JointLayout: where the chain's spherical joints sit along the finger
// (docs/conventions.md, "Joints"): joint i = 1..n at x_i = (i - 1/2) a on the
// long axis x, the base face being x = 0; n = round(L / a) with L the
// x-extent of the reference mesh unless the .prm fixes n.
#include <softchain/data/actuation_database.h>

#include <string>
#include <vector>

namespace softchain::reduction
{
  // The most joints a chain may have: its equilibrium solves a dense system
  // of 3n unknowns, n^3 work, and a joint spacing below the mesh's cells
  // has no slab of its own anyway.
  constexpr int max_joints = 1000;

  class JointLayout
  {
  public:
    // Throws data::InputError naming `source` when no joint fits or more
    // than max_joints would.
    JointLayout(const std::vector<data::Point3> &X, double spacing, int n_requested,
                const std::string &source);

    int    n_joints() const { return n_joints_; }
    double spacing() const { return spacing_; }
    // Reference abscissa x_i of joint i = 1..n.
    double x(int joint) const { return (joint - 0.5) * spacing_; }

  private:
    double spacing_;
    int    n_joints_;
  };
} // namespace softchain::reduction
