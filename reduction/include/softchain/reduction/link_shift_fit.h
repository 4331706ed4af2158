#pragma once
// LinkShiftFit: how far each link of the chain shifts, in its own frame, per
// radian that its joint turns in the finger's plane away from the
// pressure-only state (the chain tier's LinkShiftPerTurn).
//
// An inflated finger straightened against its pressure lengthens: on P10 at
// 50 kPa, blocked by a table, the links from joint 3 to joint 7 are 0.4-0.5 mm
// longer than in the free finger at that pressure, and carry their distal
// joint up to 0.8 mm higher (docs/chain_fidelity.md, "Links that follow the
// pressure"). Rigid links at the pressure state's geometry cannot follow; a
// link whose geometry follows its joint's in-plane turn can:
//   U_{i+1} - U_i = (U_{i+1} - U_i)(p) + g_i(p) (phi_i - phi_i(p)),
// g_i = (g_x, g_y) in link i's frame (x along the finger, y towards the top).
//
// Per pressure p of the in-plane force samples (the `Bending roles`, which
// curl the finger, and the `Chord roles`, which pull it straighter), with
// their link changes dU_s,i and turns dphi_s,i from the pressure state at p
// (the first pressure sample at p, the rest configuration at 0), the
// least-squares slope through the origin with a ridge term,
//   g_i(p) = sum_s dphi_s,i dU_s,i / (sum_s dphi_s,i^2 + turn_resolution^2):
// a sample turning the joint by less than turn_resolution measures no shift
// per radian (the slabs resolve a link's change to about 0.05 mm, so a turn of
// 0.01 rad cannot resolve a few mm/rad), and the ridge shrinks g there
// instead of amplifying that noise. A joint that the pressure state leaves
// unturned gets no shift (g_i = 0): every joint at rest, where nothing
// inflates the finger, and a joint without pressure torque (P10's first, in
// the solid base fill), whose rotation the reduction passes on to the next
// joint in the pressure states, so that its turn under a force is no
// straightening of the inflated finger. Samples without a pressure state at
// their pressure are skipped with a warning.
#include <softchain/data/csv_table.h>
#include <softchain/reduction/method_reduction.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace softchain::reduction
{
  struct LinkShiftAtPressure
  {
    double                       pressure; // Pa
    std::vector<Eigen::Vector2d> shift;    // g_i per link (joint i to joint i+1, the last to the tip), m/rad
    std::vector<double>          turn_rms; // rms of dphi_s,i over the samples, rad
    int                          samples;
  };

  class LinkShiftFit
  {
  public:
    static constexpr double turn_resolution = 0.01; // rad

    // One link's turns dphi_s and link changes dU_s (link frame, x and y).
    struct Observation
    {
      double          turn;
      Eigen::Vector2d change;
    };
    // g = sum dphi dU / (sum dphi^2 + turn_resolution^2); zero without observations.
    static Eigen::Vector2d shift_per_turn(const std::vector<Observation> &observations);

    LinkShiftFit(const MethodReduction &reduction, const ReductionParameters &parameters);

    const std::vector<LinkShiftAtPressure> &values() const { return values_; }
    // pressure,link,shift_x,shift_y,turn_rms,samples, by pressure and link.
    data::CsvTable table() const;
    const std::vector<std::string> &warnings() const { return warnings_; }

  private:
    std::vector<LinkShiftAtPressure> values_;
    std::vector<std::string>         warnings_;
  };
} // namespace softchain::reduction
