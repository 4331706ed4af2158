#pragma once
// run_simulate: `softchain simulate FILE.prm [--scene NAME]`. The finger of
// <output>/chain/finger.xml (softchain chain --export-mjcf) in a MuJoCo
// scene (MujocoScene) with the obstacle NAME of subsection Contact (default
// the first, or none if there is none), under a slow pressure ramp
// (PressureRampSimulation) through the pressures of that obstacle's FEM
// contact samples (<output>/contact/contact_forces.csv, softchain reduce;
// without obstacle, to the MJCF's top pressure). The capsules touch with
// the radius that puts their underside on the FEM mesh's palm (its lowest
// y) at rest: the distance from the lowest joint to it. Writes under
// <output>/simulate/ the scene's MJCF, its time series and
// contact_vs_fem.csv (data::SimulateFileSet), and prints the steady contact
// force and tip per pressure against the FEM's. Returns 0; bad input throws
// data::InputError naming the parameter.
//
// simulate_contact_scenes: the same for every obstacle with converged FEM
// contact samples, one scene after the other, and MuJoCo's row in
// <output>/chain/grasp_summary.csv (model "mujoco": the largest absolute
// force error on the plane obstacles' samples, blocked force, and on the
// others', grasp; the largest tip distance in % of L; orientation and
// solve time nan), replacing an earlier mujoco row; contact_vs_fem.csv then
// holds every scene's rows. `softchain run` calls it
// after the chain's validation and MJCF export. Without contact samples it
// removes an earlier run's contact_vs_fem.csv and returns 0 (the scenes' own
// time series stay: `softchain simulate` writes them too).
#include <softchain/data/prm_file.h>

#include <string>

namespace softchain::chain
{
  int run_simulate(const data::PrmFile &prm, const std::string &database_path, const std::string &output_dir,
                   const std::string &scene_name);
  int simulate_contact_scenes(const data::PrmFile &prm, const std::string &database_path,
                              const std::string &output_dir);
} // namespace softchain::chain
