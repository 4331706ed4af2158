#pragma once
// TipMotionProtocol: the samples of the paper's validation experiment (Sec.
// IV-B, Figs. 9-11), read from the .prm's subsection Protocol:
//
//   subsection Protocol
//     set Tip angle         = 90      # deg the inflation turns the tip; 0: no protocol
//     set Angle tolerance   = 0.5     # deg
//     set First pressure    = 2e4     # Pa, the first trial if no pressure-only
//                                     # sample is solved
//     set Lateral amplitude = 0.01    # m, tip moved along +-z of the tip frame
//     set Bending amplitude = 0.01    # m, along +-y of the tip frame
//     set Twist amplitude   = 20      # deg, tip turned about +-x of the tip frame
//     set Steps             = 4       # samples from 0 to each amplitude
//     set Tip contact       = point   # point | face
//   end
//
// First the finger is inflated until its tip frame has turned by the tip
// angle: the inflation pressure is found by interpolating the tip angles of
// the solved pressure-only samples (secant steps on angle(p), the pressure
// rounded to four significant digits so that the samples' ids do not change
// with round-off), each trial a database sample of role "protocol
// inflation". Then, from that state, the tip face is moved rigidly along
// each axis of the inflated tip frame in both directions, in `Steps` equal
// increments up to the amplitude: 6 continuation chains of samples of role
// "protocol", each with its tip motion in world axes. The lateral and
// bending motions move the tip by a point contact (the paper's chopstick: the
// mean of the tip face moved, the face free to turn) or, with Tip contact =
// face, the whole face rigidly; the twist always turns the whole face (the
// tip rolled between two chopsticks). The tip frame is the
// Kabsch fit of the tip face (data/tip_pose_fit.h): its x axis is the
// finger's axis at the tip, z the lateral direction (world z for a finger
// bending in its x-y plane).
#include <softchain/data/actuation_database.h>
#include <softchain/data/prm_file.h>
#include <softchain/data/tip_pose_fit.h>
#include <softchain/fem/sample_set.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace softchain::fem
{
  class TipMotionProtocol
  {
  public:
    // Throws data::InputError naming the file and parameter.
    static TipMotionProtocol read(const data::PrmFile &prm, const std::string &design_hash);

    bool   enabled() const { return tip_angle > 0; }
    double tip_angle_degrees() const { return tip_angle * 180.0 / M_PI; }

    // A tip angle [rad] the inflation reached at a pressure [Pa]; NaN angle:
    // no equilibrium there (the solve failed or met a limit point).
    struct Trial
    {
      double pressure = 0.0;
      double angle    = 0.0;
    };
    // The trial that reached the tip angle within the tolerance, if any.
    std::optional<Trial> reached(const std::vector<Trial> &trials) const;
    // The next pressure to try, from the trials so far (rest included).
    double next_pressure(const std::vector<Trial> &trials) const;
    // Trials before the search gives up.
    unsigned int max_trials() const { return 10; }
    // What the search needs, for messages.
    std::string target_text() const;

    // The inflation sample at pressure p.
    Sample inflation(double pressure) const;
    // One tip motion: its sample and, in the inflated tip frame, its kind
    // (lateral, bending, twist) and signed amount (mm or deg).
    struct Motion
    {
      Sample      sample;
      std::string kind;
      double      amount = 0.0;
      std::string unit;
    };
    // The motion samples from the inflated state `inflated` (its actuation
    // and tip pose): one chain per direction, by increasing amplitude.
    std::vector<std::vector<Motion>> motions(const data::Actuation &inflated,
                                             const data::TipPose   &tip) const;

    // The tip frame's rotation angle from the reference (rad).
    static double tip_angle_of(const data::TipPose &tip);

  private:
    std::string design_hash;
    double      tip_angle       = 0.0; // rad
    double      angle_tolerance = 0.0; // rad
    double      first_pressure  = 0.0; // Pa
    double      lateral         = 0.0; // m
    double      bending         = 0.0; // m
    double      twist           = 0.0; // rad
    int         steps           = 1;
    bool        point_contact   = true;
  };
} // namespace softchain::fem
