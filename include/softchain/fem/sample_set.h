#pragma once
// SampleSet: the actuation samples of a sweep (the paper's S_i = (p_i, force
// points, forces), Sec. III-A), read from the .prm's subsection Samples:
//
//   subsection Samples
//     set Pressure sweep     = 10e3, 20e3, 30e3   # Pa, no force; role pressure
//     set Volume sweep       = 2, 4               # V/V0 of the cavity, the
//                                                 # pressure solved for; role volume
//     set Lateral tip forces = 0.1, 0.2           # N along +z at the force
//                                                 # point; role lateral
//     set Torsion couples    = 0.1, 0.2           # N: +F y at force point
//                                                 # + (0,0,d), -F y at - (0,0,d),
//                                                 # role torsion
//     set Force sample pressures = 0              # Pa: the lateral and torsion
//                                                 # samples at each pressure
//     set Torsion arm        = 0                  # d [m]; 0: a quarter of the
//                                                 # tip face's extent along z
//     set Force point        =                    # x,y,z; empty: the centre of
//                                                 # the tip face
//     set Chord samples      = 20e3 : tip : chord 0.5 ; 0 : tip : 0.5,0,0
//                            # syntax of Validation samples (below); role
//                            # chord: a small tip force along the base-tip
//                            # chord of the pressure-only state at p, for the
//                            # links' compliance (not held out). 'chord F':
//                            # F newtons along that chord, which the sweep
//                            # measures on the pressure sample at p (it must
//                            # be in Pressure sweep; p = 0: the finger at rest)
//     set Validation samples = 40e3 : tip : 0,0,0.2 ; 20e3 : 0.07,0.006,0.009 : 0,-0.1,0
//                            # p : point : force [: point : force ...] ; ...
//                            # role validation; 'tip' is the force point
//     set Contact samples    = table : 10e3, 30e3 ; can : 20e3
//                            # obstacle : pressures ; ... role contact: the
//                            # finger inflated against the obstacle of
//                            # subsection Contact by that name
//     set Sample groups      = 0     # MPI sample groups (0: one per rank, each
//                                    # sample on one rank; 1: all ranks per solve)
//     set Continuation       = true  # start from the converged neighbour
//   end
//
// Samples with the same role, the same force points and (with forces) the
// same pressure form a continuation chain, ordered by increasing load, so
// that each continues from the one before it (and the sweep starts a chain's
// first sample from a pressure-only sample, SampleSweep). The inflations
// under pressure control, swept or held out, form one chain per sign of the
// pressure. A frictionless contact sample continues from the one at the
// next lower pressure against the same obstacle; with friction the state
// depends on the path, and each sample is a chain of its own, from rest.
// deal.II-free: the FEM tier checks that the points lie inside the
// body before any solve.
#include <softchain/data/actuation_database.h>
#include <softchain/data/prm_file.h>
#include <softchain/geometry/contact_scene.h>

#include <optional>
#include <string>
#include <vector>

namespace softchain::fem
{
  struct Sample
  {
    data::Actuation actuation;
    std::string     label; // for messages and progress lines, e.g. "lateral 0.3 N"
    std::string     id;    // data::sample_id(design hash, actuation)
  };

  // |p| + sum |f|, or V/V0 - 1 under volume control: the order of the
  // samples along a chain [mixed units, compared only within one chain].
  double load_size(const data::Actuation &actuation);

  // Whether an actuation inflates the finger alone (pressure or volume
  // control; no forces, no tip motion, no obstacles): the sweep solves these first, and
  // other chains start from the pressure-controlled ones (SampleSweep).
  bool pressure_only(const data::Actuation &actuation);

  class SampleSet
  {
  public:
    // The tip face (from the mesh), for the default force point and arm.
    struct TipFace
    {
      data::Point3 centre;
      double       width = 0.0; // extent along z
    };

    // Throws data::InputError naming file, parameter and sample. `contact`:
    // the obstacles the contact samples may name.
    static SampleSet read(const data::PrmFile &prm, const TipFace &tip,
                          const std::string &design_hash, const geometry::ContactScene &contact);

    // A sample whose forces' directions are measured on the pressure-only
    // state at its pressure, known once that state is (SampleSweep adds the
    // sample then): a chord sample's 'chord F' (F newtons along the base-tip
    // chord, role chord), or a skin sample's 'palm F' or 'shear F' at each of
    // its points (F newtons along the palm's inward normal there, or along
    // the palm towards the tip, role skin).
    struct MeasuredForceRequest
    {
      enum class Direction
      {
        chord,
        palm_normal,
        palm_shear
      };
      double                    pressure = 0;
      std::vector<data::Point3> points;
      std::vector<double>       forces; // N, one per point
      Direction                 direction = Direction::chord;
      std::string               label; // "chord 2", "skin 1"
      std::string               where; // file, parameter and sample, for messages
      std::string role() const { return direction == Direction::chord ? "chord" : "skin"; }
      // The force's keyword in the .prm: "chord", "palm" or "shear".
      std::string keyword() const
      {
        return direction == Direction::chord ? "chord" : direction == Direction::palm_normal ? "palm" : "shear";
      }
    };

    // The pressure-controlled sample at `pressure` without forces, if listed.
    std::optional<std::size_t> inflation_at(double pressure) const;
    // The sample of `request` with its forces along `directions` (unit
    // vectors, one per point); its id derives from the design hash and those
    // forces, so that it is cached as long as the state they were measured
    // on is.
    static Sample measured_sample(const MeasuredForceRequest &request,
                                  const std::vector<data::Point3> &directions,
                                  const std::string &design_hash);

    std::vector<Sample>                   samples; // chain after chain
    std::vector<std::vector<std::size_t>> chains;  // indices into samples
    std::vector<MeasuredForceRequest>     measured_requests; // in the order listed
    unsigned int                          sample_groups = 0; // 0: one per rank
    bool                                  continuation  = true;
  };
} // namespace softchain::fem
