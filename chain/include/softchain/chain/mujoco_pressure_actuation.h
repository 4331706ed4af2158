#pragma once
// MujocoPressureActuation: a MuJoCo model exported by MjcfExport, made equal
// to the chain at any pressure of its tables. Plain MuJoCo holds one hinge
// stiffness k, one pressure-tendon coefficient J_p and one body position per
// link, those of the export pressure p*; the chain's equilibrium
//
//   K(p) q = J_p(p) p + J(q)^T f,   the links at U(p)          (ChainModel)
//
// changes all three with p. apply() sets them from the MJCF's <custom>
// tables (PressureTables) before the steps at pressure p: MuJoCo's hinge
// springs then give -k(p) q, its pressure motor (control p on the fixed
// tendon with coefficients J_p(p)) the torque J_p(p) p, and its bodies sit
// at U_1(p), U_{i+1}(p) - U_i(p), so that MuJoCo's static equilibrium is the
// chain's (three hinges x, y, z per joint are its Euler angles exactly,
// MjcfExport). Each hinge keeps its exported damping time c / k, the
// capsules and the tip site follow the links; masses and inertias stay
// those of the exported model (the chain is quasi-static, they do not enter
// its equilibrium). A link exported with a skin (slide joint "skin<i>")
// gets the stiffness 1 / c_s(p), keeping its damping time; a link with two
// capsules (link<i>, link<i>_side) keeps them side by side along the body's
// z, at their exported distance. MuJoCo allows
// model fields to change between steps.
#include <softchain/chain/pressure_tables.h>

#include <mujoco/mujoco.h>

#include <vector>

namespace softchain::chain
{
  class MujocoPressureActuation
  {
  public:
    // Reads the tables and finds the hinges joint<i>_<axis>, bodies and
    // capsules link<i>, the site "tip" and the tendon and motor "pressure";
    // data::InputError naming what is missing or inconsistent.
    explicit MujocoPressureActuation(const mjModel *model);

    const PressureTables &tables() const { return tables_; }
    // Sets `model`'s fields to pressure p and the pressure control of `data`
    // to p; std::out_of_range if p lies outside the tables (nothing changed).
    void apply(double pressure, mjModel *model, mjData *data) const;

  private:
    // One hinge of the chain in the model.
    struct Hinge
    {
      int    joint;        // MuJoCo joint id
      int    dof;          // its degree of freedom
      int    tendon_wrap;  // its entry in the pressure tendon, -1: none
      double damping_time; // c / k as exported, s
    };

    void set_links(const Eigen::VectorXd &points, mjModel *model) const;

    PressureTables     tables_;
    std::vector<Hinge> hinges_;
    std::vector<Hinge> skins_; // the slide joints skin<i>, where exported
    std::vector<int>   bodies_, capsules_;
    std::vector<int>   sides_;      // capsule link<i>_side per link, -1 where none
    std::vector<double> side_offset_; // its offset along the body's z (and -that for link<i>)
    int                tip_site_, pressure_motor_;
  };
} // namespace softchain::chain
