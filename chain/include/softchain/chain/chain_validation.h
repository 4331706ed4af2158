#pragma once
// ChainValidation: the point of the pipeline (paper Sec. IV-B):
// the chain's tip pose against the FEM tip pose for database samples that
// were not (all) used in the extraction. Per sample and model: tip position
// error |x_chain - x_FEM| (mm and % of the finger length L) and orientation
// error angle(R_chain^T R_FEM) (deg), where the FEM pose is the TipPoseFit of
// the tip-face nodes and the chain's is its tip point and last link frame.
// Summaries per model and sample role (and over all roles): max and mean.
// Each record also keeps the chain's tip pose and the wall time of its solve.
//
// Contact samples (role "contact": the finger pressed on obstacles, each
// obstacle at the end of its motion) are solved with the model's collision
// surface (ChainContact), along their load path where an obstacle has
// friction (FrictionalLoadPath), and compared in the force the obstacles
// receive too, 100 (|F_chain| - |F_FEM|) / |F_FEM|. Their records take the
// role "blocked force" where the obstacle is a plane (the tip pressed on a
// table, the actuator's classic characterisation) and "grasp" for any other
// shape, followed by " with friction" where it has some.
#include <softchain/chain/frictional_load_path.h>
#include <softchain/data/tip_pose_fit.h>
#include <softchain/data/actuation_database.h>
#include <softchain/data/csv_table.h>

#include <cmath>
#include <string>
#include <vector>

namespace softchain::chain
{
  struct ValidationRecord
  {
    std::string sample, role, model;
    double      pressure          = 0.0;
    double      force_norm        = 0.0; // N, sum of |f_k|
    double      position_error    = 0.0; // m (NaN if the chain failed)
    double      orientation_error = 0.0; // rad (NaN if the chain failed)
    int         iterations        = 0;
    bool        converged         = false;
    std::string failure; // why the equilibrium failed (empty if converged)
    // The chain's own tip pose, so that it can be compared with another
    // reference than this database (benchmarks/p10_error_time):
    Eigen::Vector3d tip_position = Eigen::Vector3d::Constant(NAN); // m
    double          tip_rotation_angle = NAN; // rad, of the last link frame from rest
    double          solve_time         = NAN; // s, wall time of this equilibrium from rest (median of the timed solves)
    std::vector<Eigen::Vector3d> joint_positions; // c_i at equilibrium, m (empty if failed)
    // Contact samples: the force the obstacles receive, N, world (NaN otherwise).
    Eigen::Vector3d contact_force     = Eigen::Vector3d::Constant(NAN); // the chain's
    Eigen::Vector3d fem_contact_force = Eigen::Vector3d::Constant(NAN); // the FEM's
    bool            contact() const { return std::isfinite(fem_contact_force.x()); }
    // 100 (|F_chain| - |F_FEM|) / |F_FEM|; NaN where the FEM's finger does
    // not touch or the chain failed.
    double          contact_force_error_percent() const;
  };

  class ChainValidation
  {
  public:
    // Reads the FEM tip pose of every converged sample whose role is listed;
    // the database must have tip nodes (InputError otherwise).
    ChainValidation(const data::ActuationDatabase &database,
                    const std::vector<std::string> &roles, double finger_length);

    // Solves every sample with `model` and records the errors; each sample
    // `timed_solves` times, its solve time the median (1: the first solve,
    // with the caches and allocations of a cold start).
    void compare(const ChainModel &model, const EquilibriumSettings &settings,
                 const FrictionalPathSettings &friction_path = {}, int timed_solves = 1);

    const std::vector<ValidationRecord> &records() const { return records_; }
    int                                  n_failed(const std::string &model) const;
    data::CsvTable                       per_sample_table() const;
    data::CsvTable                       summary_table() const;
    // Per model over the contact samples (chain/grasp_summary.csv): the
    // largest |force error| on blocked-force and on grasp samples, the
    // largest tip errors, the median solve time.
    data::CsvTable                       grasp_summary_table() const;
    // The FEM tip pose of every sample: position [mm] and the tip bending
    // angle about z, atan2(R_yx, R_xx) [deg] (negative: toward -y, the fabric
    // side), plus the total rotation angle [deg].
    data::CsvTable                       fem_tip_table() const;
    // The chain's joints and tip at equilibrium, for pictures over the FEM
    // finger: sample, model, point (joint 1..n, then "tip"), x, y, z [m].
    data::CsvTable                       pose_table() const;

  private:
    struct FemSample
    {
      std::string id, role;
      ChainLoad   load;
      data::TipPose tip;
      Eigen::Vector3d contact_force = Eigen::Vector3d::Constant(NAN); // the FEM's, contact samples
    };

    std::vector<FemSample>        samples_;
    double                        finger_length_;
    std::vector<ValidationRecord> records_;
  };

  // A force error of grasp_summary_table for the terminal: "4.88 %", or for
  // a kind of contact sample the database lacks (NaN in the table) "none
  // (no such sample)".
  std::string error_percent(double percent);
} // namespace softchain::chain
