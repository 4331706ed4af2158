#pragma once
// MjcfExport: the chain as a MuJoCo model (MJCF XML) for multi-body and grasp
// simulation. Each spherical joint becomes three hinges in one body, axes
// x, y, z in this order: MuJoCo composes the joints of a body as successive
// rotations about their axes in the body's current frame, so the body's
// rotation is Rx(q1) Ry(q2) Rz(q3) = E(psi, theta, phi), the chain's Euler
// convention, and the hinge springs -k q give exactly the energy
// 1/2 q^T K q of the diagonal K. A joint with a twist axis of its own puts
// its psi hinge's anchor (`pos`) on the twist pivot: MuJoCo turns each hinge
// about its anchor in the body's current frame, as the chain does
// (KinematicChain). Bodies sit at the joint centres (of the link geometry
// at p*), each link
// is a capsule from its joint to the next joint (the last one to the tip,
// marked by the site "tip"). Pressure is one actuator: a fixed tendon with
// the rest J_p as joint coefficients, driven by a motor whose control is the
// pressure in Pa (joint torque = J_p p). Hinge damping c = k * damping_time
// makes MuJoCo's Euler step (implicit in damping) stable for timestep
// < 2 c / k = 2 damping_time whatever the link inertia; the model uses
// damping_time / 10. MJCF has one K and one J_p: with `pressure` > 0 those
// of the chain at that pressure, K(p*) and J_p(p*), with the links of p*, so
// that plain MuJoCo finds the chain's pose exactly at p* (and at 0 if the
// links do not change with p); otherwise the CSV's K and the rest J_p.
// exported_model() is the chain plain MuJoCo then simulates.
// The chain's K(p), J_p(p) and link geometry U(p) go along as <custom>
// tables (PressureTables) on [0, max(pressure, max_pressure)], from which
// MujocoPressureActuation sets the model of any pressure in that range; the
// pressure tendon lists every hinge whose J_p is non-zero at some pressure.
// Where the sections give (MjcfOptions::skin_links and the chain's c_s(p)),
// a link's capsule sits in a child body "skin<i>" on a slide joint along
// the link's +y, of stiffness 1 / c_s(p*) and damping time damping_time:
// the chain's skin s_b as one more degree of freedom per link.
#include <softchain/chain/chain_model.h>
#include <softchain/chain/pressure_tables.h>

#include <string>
#include <vector>

namespace softchain::chain
{
  struct MjcfOptions
  {
    double link_radius  = 0.005; // m, capsule radius
    double density      = 1070;  // kg/m^3, silicone rubber
    double damping_time = 0.01;  // s, hinge damping / stiffness
    double max_pressure = 0.0;   // Pa, control range of the pressure (0: unlimited)
    double pressure     = 0.0;   // Pa, p* whose K and J_p are exported (0: CSV K, rest J_p)
    // Per link, whether its section gives under contact: its capsule then
    // hangs on a slide joint "skin<i>" along the link's +y (the palm's
    // inward normal) of stiffness 1 / c_s(p) (ChainContact's skin), where the
    // chain has a skin compliance. Empty: no link gives.
    std::vector<char> skin_links;
    // Half the distance [m] between two capsules per link, side by side along
    // the link's z at +-this (0: one capsule on the joint line). Two lines of
    // contact resist the rolling of a finger pressed on a plane, as the FEM's
    // flat palm does.
    double capsule_offset = 0.0;
  };

  class MjcfExport
  {
  public:
    MjcfExport(const ChainModel &model, MjcfOptions options);

    std::string text() const;
    // The chain with the exported constant K and J_p (what plain MuJoCo simulates).
    ChainModel exported_model() const;
    // Writes the model to `path` (parent directories created); InputError
    // naming the file if it cannot be written.
    void write(const std::string &path) const;

  private:
    std::string body(int i) const;
    bool        gives(int i) const; // link i has a skin joint
    bool        any_skin() const;
    std::string pressure_actuator() const;

    MjcfOptions    options_;
    ChainModel     exported_;
    PressureTables tables_;
  };
} // namespace softchain::chain
