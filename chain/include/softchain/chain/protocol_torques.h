#pragma once
// ProtocolTorques: the paper's validation experiment (Sec. IV-B, Figs. 10-11)
// on the samples the sweep listed in <output>/protocol_samples.csv (sample,
// motion, amount, unit; first the inflated state): the finger inflated until
// its tip turned by a target angle, then its tip moved -- left and right
// (+-z of the inflated tip frame), down and up (+-y), twisted (+-x).
// The FEM's base torques (each sample's base wrench) are the ground truth;
// each chain model is driven through the same motions and its base torques
// compared with them.
//
// The trace: per motion kind (lateral, bending, twist) the amplitudes 0 ->
// +a -> 0 -> -a -> 0 through the stored samples, as the paper's fingertip
// went left and right; a state visited twice is one sample.
//
// The chain: its free equilibrium at the inflation pressure gives its own
// tip point x0 and frame R0; a sample with the tip motion (t, theta) (world
// axes, as the FEM prescribed it) holds the chain's tip point at x0 + t and,
// unless the motion is a point contact, its tip frame at Rot(theta) R0
// (TipConstrainedEquilibrium), so that each model is moved from its own
// inflated state as the FEM finger was from its own. Base torque: the moment about the base face's centroid of the
// contact force at the tip plus the contact couple (base_wrench).
// Error per torque component: the RMS over the trace of the chain's minus
// the FEM's torque, in percent of the FEM's range (max - min) of that
// component over the trace.
#include <softchain/chain/chain_equilibrium.h>
#include <softchain/chain/chain_model.h>
#include <softchain/data/actuation_database.h>
#include <softchain/data/csv_table.h>

#include <Eigen/Core>
#include <string>
#include <vector>

namespace softchain::chain
{
  class ProtocolTorques
  {
  public:
    // Reads the samples `listing` names from `database`; no listing file:
    // empty(). InputError naming the file if a listed sample is missing or
    // the inflated state did not converge.
    ProtocolTorques(const data::ActuationDatabase &database, const std::string &listing);

    bool empty() const { return points_.empty(); }
    double pressure() const { return pressure_; }

    // Drives `model` through the trace and records its base torques.
    void compare(const ChainModel &model, const EquilibriumSettings &settings);

    // step, motion, amount (mm or deg), sample, fem_Tx..Tz, then per model
    // <model>_Tx..Tz [N m], then the base forces fem_Fx..Fz and per model
    // <model>_Fx..Fz [N] (NaN where its equilibrium failed).
    data::CsvTable trace_table() const;
    // model, torque, fem_range_Nm, rms_error_Nm, rms_error_percent_range,
    // max_error_percent_range, n_failed_points (trace points without an
    // equilibrium; a twice-visited state counts twice).
    data::CsvTable summary_table() const;
    // The models compared so far, in order.
    std::vector<std::string> models() const;
    // Chain equilibria that failed, "model on sample: why".
    const std::vector<std::string> &failures() const { return failures_; }

  private:
    // One state of the trace.
    struct TracePoint
    {
      std::string     motion; // lateral, bending, twist
      double          amount = 0.0; // mm or deg, in the tip frame
      std::string     sample;       // id (the inflation sample for amount 0)
      Eigen::Vector3d translation = Eigen::Vector3d::Zero(); // world, m
      Eigen::Vector3d rotation    = Eigen::Vector3d::Zero(); // world, rad
      bool            point_contact = false;                  // the tip point held, its frame free
      Eigen::Vector3d fem_torque  = Eigen::Vector3d::Zero(); // N m
      Eigen::Vector3d fem_force   = Eigen::Vector3d::Zero(); // N
    };
    struct ModelTrace
    {
      std::string                  name;
      std::vector<Eigen::Vector3d> torque; // per trace point (NaN: failed)
      std::vector<Eigen::Vector3d> force;  // per trace point (NaN: failed)
    };

    double                   pressure_ = 0.0;
    Eigen::Vector3d          base_centroid_ = Eigen::Vector3d::Zero();
    std::vector<TracePoint>  points_;
    std::vector<ModelTrace>  traces_;
    std::vector<std::string> failures_;
  };
} // namespace softchain::chain
