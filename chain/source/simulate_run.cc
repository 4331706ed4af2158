#include <softchain/chain/chain_validation.h>
#include <softchain/chain/pressure_ramp_simulation.h>
#include <softchain/chain/simulate_run.h>
#include <softchain/data/input_error.h>
#include <softchain/data/output_files.h>
#include <softchain/geometry/contact_scene.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>

namespace softchain::chain
{
  namespace
  {
    // The obstacle `name` of subsection Contact, the first if `name` is
    // empty, none if the subsection has none.
    std::optional<data::ObstacleRecord> chosen_obstacle(const data::PrmFile &prm, const std::string &name)
    {
      const geometry::ContactScene contact = geometry::ContactScene::read(prm);
      if (name.empty())
        return contact.empty() ? std::nullopt : std::optional(contact.obstacles.front().description);
      if (const geometry::Obstacle *o = contact.find(name))
        return o->description;
      std::string known;
      for (const auto &o : contact.obstacles)
        known += (known.empty() ? "" : ", ") + o.name();
      throw data::InputError("--scene " + name + ": " + prm.path() + " has no obstacle '" + name +
                             "' in subsection Contact (its obstacles: " + (known.empty() ? "none" : known) +
                             ")");
    }

    // The rows of the FEM's converged contact samples on `obstacle`, by pressure.
    data::CsvTable fem_contact_forces(const std::string &output_dir, const std::string &obstacle)
    {
      const std::string file = data::contact_forces_file(output_dir);
      if (!std::filesystem::exists(file))
        throw data::InputError("softchain simulate needs the FEM's contact forces " + file +
                               " (softchain sweep and reduce with Samples/Contact samples on '" + obstacle + "')");
      const data::CsvTable all = data::CsvTable::read(file);
      data::CsvTable       rows(all.columns());
      for (std::size_t r = 0; r < all.n_rows(); ++r)
        if (all.text(r, "obstacle") == obstacle && all.text(r, "status") == "converged")
          {
            std::vector<std::string> cells;
            for (const std::string &c : all.columns())
              cells.push_back(all.text(r, c));
            rows.add_row(cells);
          }
      if (rows.n_rows() == 0)
        throw data::InputError(file + " holds no converged contact sample on '" + obstacle + "'");
      return rows;
    }

    // The steady forces and tips against the FEM's, printed and as a table;
    // L the finger's length, for the tip distance.
    data::CsvTable compare(const std::string &obstacle, const std::vector<SteadyContact> &mujoco,
                           const data::CsvTable &fem, const double L)
    {
      data::CsvTable table({"obstacle", "pressure", "mujoco_force_x", "mujoco_force_y", "mujoco_force_z",
                            "mujoco_force_norm", "fem_force_x", "fem_force_y", "fem_force_z", "fem_force_norm",
                            "difference_percent", "tip_distance_percent_L"});
      for (std::size_t r = 0; r < mujoco.size(); ++r)
        {
          const Eigen::Vector3d m = mujoco[r].force;
          const Eigen::Vector3d f(fem.number(r, "force_x"), fem.number(r, "force_y"), fem.number(r, "force_z"));
          // Relative to the FEM's force; a sample without contact in the FEM has none.
          const double difference = f.norm() > 0 ? 100 * (m.norm() - f.norm()) / f.norm()
                                                 : std::numeric_limits<double>::quiet_NaN();
          const Eigen::Vector3d fem_tip(fem.number(r, "tip_x"), fem.number(r, "tip_y"), fem.number(r, "tip_z"));
          const double          tip = 100 * (mujoco[r].tip - fem_tip).norm() / L;
          table.add_row({obstacle, data::CsvTable::cell(mujoco[r].pressure), data::CsvTable::cell(m.x()),
                         data::CsvTable::cell(m.y()), data::CsvTable::cell(m.z()), data::CsvTable::cell(m.norm()),
                         data::CsvTable::cell(f.x()), data::CsvTable::cell(f.y()), data::CsvTable::cell(f.z()),
                         data::CsvTable::cell(f.norm()), data::CsvTable::cell(difference), data::CsvTable::cell(tip)});
          std::cout << "simulate: " << obstacle << " at " << mujoco[r].pressure / 1e3 << " kPa: MuJoCo "
                    << m.norm() << " N, FEM " << f.norm() << " N (" << difference << " %), tip "
                    << tip << " % of L from the FEM's\n";
        }
      return table;
    }

    void write_time_series(const PressureRampSimulation &run, const data::SimulateFileSet &files)
    {
      run.joint_angles().write(files.joint_angles);
      run.tip_pose().write(files.tip_pose);
      run.contact_force().write(files.contact_force);
      std::cout << "simulate: " << run.simulated_time() << " s simulated; time series " << files.joint_angles
                << ", " << files.tip_pose << ", " << files.contact_force << "\n";
    }
  } // namespace

  namespace
  {
    // One scene of `obstacle` (none: the free finger) run and written;
    // the comparison with the FEM's contact samples, if it has an obstacle.
    std::optional<data::CsvTable> simulate_scene(const std::optional<data::ObstacleRecord> &obstacle,
                                                 const std::string &database_path, const std::string &output_dir)
    {
      const data::SimulateFileSet   files(output_dir, obstacle ? obstacle->name : "free");
      const std::string             finger = data::ChainFileSet(output_dir).mjcf;
      const data::ActuationDatabase database = data::ActuationDatabase::open(database_path);
      const double radius = palm_capsule_radius(database.mesh(),
                                                MujocoScene(finger, std::nullopt, 0.0, "").actuation().tables());
      MujocoScene scene(finger, obstacle, radius, files.scene_mjcf);
      std::cout << "simulate: scene " << (obstacle ? obstacle->name + " (" + obstacle->shape + ")" : "free")
                << ", capsules of radius " << 1e3 * radius << " mm\n";
      PressureRampSimulation run(scene);
      if (!obstacle)
        {
          run.run({scene.actuation().tables().pressures().back()});
          write_time_series(run, files);
          return std::nullopt;
        }
      const data::CsvTable fem = fem_contact_forces(output_dir, obstacle->name);
      std::vector<double>  pressures;
      for (std::size_t r = 0; r < fem.n_rows(); ++r)
        pressures.push_back(fem.number(r, "pressure"));
      const std::vector<SteadyContact> steady = run.run(pressures);
      write_time_series(run, files);
      double low = INFINITY, high = -INFINITY;
      for (const data::Point3 &X : database.mesh().X)
        {
          low  = std::min(low, X[0]);
          high = std::max(high, X[0]);
        }
      data::CsvTable table = compare(obstacle->name, steady, fem, high - low);
      table.write(files.contact_vs_fem);
      std::cout << "simulate: " << files.contact_vs_fem << "\n";
      return table;
    }

    bool has_converged_contact(const std::string &output_dir, const std::string &obstacle)
    {
      const std::string file = data::contact_forces_file(output_dir);
      if (!std::filesystem::exists(file))
        return false;
      const data::CsvTable all = data::CsvTable::read(file);
      for (std::size_t r = 0; r < all.n_rows(); ++r)
        if (all.text(r, "obstacle") == obstacle && all.text(r, "status") == "converged")
          return true;
      return false;
    }

    // grasp_summary.csv with the row `row` for model "mujoco" (replacing
    // an earlier one; a new file if there is none).
    void write_mujoco_row(const std::string &file, const std::vector<std::string> &row)
    {
      const std::vector<std::string> columns{"model", "n_samples", "n_failed", "blocked_force_error_percent",
                                             "grasp_force_error_percent", "tip_error_percent_L",
                                             "orientation_error_deg", "median_solve_time_us"};
      data::CsvTable table(columns);
      if (std::filesystem::exists(file))
        {
          const data::CsvTable old = data::CsvTable::read(file);
          for (std::size_t r = 0; r < old.n_rows(); ++r)
            if (old.text(r, "model") != "mujoco")
              {
                std::vector<std::string> cells;
                for (const std::string &c : columns)
                  cells.push_back(old.text(r, c));
                table.add_row(cells);
              }
        }
      table.add_row(row);
      std::filesystem::create_directories(std::filesystem::path(file).parent_path());
      table.write(file);
    }
  } // namespace

  int run_simulate(const data::PrmFile &prm, const std::string &database_path, const std::string &output_dir,
                   const std::string &scene_name)
  {
    simulate_scene(chosen_obstacle(prm, scene_name), database_path, output_dir);
    return 0;
  }

  int simulate_contact_scenes(const data::PrmFile &prm, const std::string &database_path,
                              const std::string &output_dir)
  {
    int    n = 0;
    double blocked = NAN, grasp = NAN, tip = NAN;
    const auto larger = [](double &max, const double value) {
      if (std::isfinite(value))
        max = std::isfinite(max) ? std::max(max, value) : value;
    };
    std::optional<data::CsvTable> all; // every scene's rows
    for (const geometry::Obstacle &o : geometry::ContactScene::read(prm).obstacles)
      {
        if (!has_converged_contact(output_dir, o.name()))
          continue;
        const data::CsvTable table = *simulate_scene(o.description, database_path, output_dir);
        if (!all)
          all.emplace(table.columns());
        for (std::size_t r = 0; r < table.n_rows(); ++r, ++n)
          {
            larger(o.description.shape == "plane" ? blocked : grasp, std::abs(table.number(r, "difference_percent")));
            larger(tip, table.number(r, "tip_distance_percent_L"));
            std::vector<std::string> cells;
            for (const std::string &c : table.columns())
              cells.push_back(table.text(r, c));
            all->add_row(cells);
          }
      }
    const std::string comparison = data::SimulateFileSet(output_dir, "free").contact_vs_fem;
    if (n == 0) // no contact sample: an earlier run's comparison goes
      {
        std::filesystem::remove(comparison);
        return 0;
      }
    all->write(comparison);
    const std::string file = data::ChainFileSet(output_dir).grasp_summary;
    write_mujoco_row(file, {"mujoco", data::CsvTable::cell(n), "0", data::CsvTable::cell(blocked),
                            data::CsvTable::cell(grasp), data::CsvTable::cell(tip), "nan", "nan"});
    std::cout << "simulate: MuJoCo in contact: blocked force error " << error_percent(blocked)
              << ", grasp force error " << error_percent(grasp) << ", tip " << tip << " % of L (max over " << n
              << " samples); " << file << "\n";
    return 0;
  }
} // namespace softchain::chain
