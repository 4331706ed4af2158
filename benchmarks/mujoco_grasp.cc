// MuJoCo's speed on the grasp of softchain simulate: the exported finger
// (<output>/chain/finger.xml) closing on an obstacle of the .prm's
// subsection Contact (default "cylinder") under the pressure ramp of
// PressureRampSimulation through 10, 20, 30 and 40 kPa (P10's cylinder
// samples), the finger set to the pressure of every step. Per repetition:
// simulated time, wall time of the ramp (scene loading excluded, no time
// series recorded), MuJoCo steps, microseconds per step, the real-time
// factor (simulated / wall time; MuJoCo runs on one core) and the steady
// contact force at the last pressure.
// Run: taskset -c 0 mujoco_grasp FILE.prm [OBSTACLE] [REPETITIONS = 5]
#include <softchain/chain/pressure_ramp_simulation.h>
#include <softchain/data/design_parameters.h>
#include <softchain/data/input_error.h>
#include <softchain/data/output_files.h>
#include <softchain/geometry/contact_scene.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace softchain;

namespace
{
  void time_ramps(const data::PrmFile &prm, const std::string &name, const int repetitions)
  {
    const auto                    design   = data::DesignParameters::read(prm);
    const geometry::ContactScene  contact  = geometry::ContactScene::read(prm);
    const geometry::Obstacle     *obstacle = contact.find(name);
    if (!obstacle)
      throw data::InputError(prm.path() + " has no obstacle '" + name + "' in subsection Contact");
    const std::string finger = data::ChainFileSet(design.output_directory).mjcf;
    const std::string scene_file = data::SimulateFileSet(design.output_directory, name).scene_mjcf;
    const double      radius     = chain::palm_capsule_radius(
      data::ActuationDatabase::open(design.database_path()).mesh(),
      chain::MujocoScene(finger, std::nullopt, 0.0, "").actuation().tables());
    std::printf("%-4s %12s %10s %8s %9s %10s %16s\n", "run", "simulated_s", "wall_s", "steps", "us/step",
                "real-time", "force_last_N");
    for (int r = 1; r <= repetitions; ++r)
      {
        chain::MujocoScene             scene(finger, obstacle->description, radius, scene_file);
        chain::RampSettings            settings;
        settings.record_interval = 0;
        chain::PressureRampSimulation  ramp(scene, settings);
        const auto                     start  = std::chrono::steady_clock::now();
        const auto                     steady = ramp.run({10e3, 20e3, 30e3, 40e3});
        const double wall  = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double steps = ramp.simulated_time() / scene.model()->opt.timestep;
        std::printf("%-4d %12.3f %10.4f %8.0f %9.2f %10.1f %16.6f\n", r, ramp.simulated_time(), wall, steps,
                    1e6 * wall / steps, ramp.simulated_time() / wall, steady.back().force.norm());
      }
  }
} // namespace

int main(int argc, char **argv)
{
  if (argc < 2)
    {
      std::fprintf(stderr, "usage: mujoco_grasp FILE.prm [OBSTACLE = cylinder] [REPETITIONS = 5]\n");
      return 1;
    }
  try
    {
      time_ramps(data::PrmFile::read(argv[1]), argc > 2 ? argv[2] : "cylinder", argc > 3 ? std::atoi(argv[3]) : 5);
      return 0;
    }
  catch (const data::InputError &e)
    {
      std::fprintf(stderr, "mujoco_grasp: error: %s\n", e.what());
      return 1;
    }
}
