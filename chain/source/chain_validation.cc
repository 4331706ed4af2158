#include <softchain/chain/chain_validation.h>
#include <softchain/chain/angle_units.h>
#include <softchain/data/statistics.h>
#include <softchain/data/vector_of_point.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <tuple>

namespace softchain::chain
{
  namespace
  {
    using data::CsvTable;

    ChainLoad load_of(const data::Actuation &actuation)
    {
      ChainLoad load{actuation.pressure, {}, actuation.obstacles};
      for (const data::PointForce &f : actuation.point_forces)
        load.point_loads.push_back({data::vector_of(f.point), data::vector_of(f.force)});
      return load;
    }

    // The role a sample is reported under: a contact sample's by its
    // obstacle and whether it has friction.
    std::string reported_role(const data::Actuation &actuation)
    {
      if (actuation.role != "contact" || actuation.obstacles.empty())
        return actuation.role;
      const data::ObstacleRecord &obstacle = actuation.obstacles.front();
      return std::string(obstacle.shape == "plane" ? "blocked force" : "grasp") +
             (obstacle.friction > 0.0 ? " with friction" : "");
    }

    // Sum of the forces the obstacles receive.
    Eigen::Vector3d total_force(const std::vector<data::ObstacleWrench> &wrenches)
    {
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for (const data::ObstacleWrench &w : wrenches)
        sum += data::vector_of(w.force);
      return sum;
    }

    double force_norm(const ChainLoad &load)
    {
      double sum = 0.0;
      for (const PointLoad &p : load.point_loads)
        sum += p.force.norm();
      return sum;
    }

    // Max and mean of the errors of `records` that converged.
    struct ErrorStatistics
    {
      int    n = 0, failed = 0;
      double max_position = 0, mean_position = 0, max_orientation = 0, mean_orientation = 0;
    };

    ErrorStatistics statistics(const std::vector<const ValidationRecord *> &records)
    {
      ErrorStatistics s;
      for (const ValidationRecord *r : records)
        {
          if (!r->converged)
            {
              ++s.failed;
              continue;
            }
          ++s.n;
          s.max_position = std::max(s.max_position, r->position_error);
          s.max_orientation = std::max(s.max_orientation, r->orientation_error);
          s.mean_position += r->position_error;
          s.mean_orientation += r->orientation_error;
        }
      s.mean_position    = s.n ? s.mean_position / s.n : NAN;
      s.mean_orientation = s.n ? s.mean_orientation / s.n : NAN;
      return s;
    }
  } // namespace

  ChainValidation::ChainValidation(const data::ActuationDatabase  &database,
                                   const std::vector<std::string> &roles, double finger_length)
    : finger_length_(finger_length)
  {
    const data::MeshRecord &mesh = database.mesh();
    const data::TipPoseFit  fit  = data::TipPoseFit::of_mesh(mesh, database.path());
    for (const std::string &id : database.sample_ids())
      {
        const data::SampleRecord sample = database.read_sample(id);
        const std::string       &role   = sample.actuation.role;
        if (!sample.converged() || std::find(roles.begin(), roles.end(), role) == roles.end())
          continue;
        FemSample fem{id, reported_role(sample.actuation), load_of(sample.actuation),
                      fit.fit(data::select_nodes(sample.x, mesh.tip_nodes))};
        if (!sample.actuation.obstacles.empty())
          fem.contact_force = total_force(sample.obstacle_wrenches);
        samples_.push_back(fem);
      }
    // Grouped by role, then by increasing load: the order of the table and plot.
    std::stable_sort(samples_.begin(), samples_.end(), [](const FemSample &a, const FemSample &b) {
      return std::make_tuple(a.role, a.load.pressure, force_norm(a.load)) <
             std::make_tuple(b.role, b.load.pressure, force_norm(b.load));
    });
  }

  void ChainValidation::compare(const ChainModel &model, const EquilibriumSettings &settings,
                                const FrictionalPathSettings &friction_path, const int timed_solves)
  {
    ChainEquilibrium   solver(model, settings);
    FrictionalLoadPath path(solver, friction_path);
    for (const FemSample &s : samples_)
      {
        Equilibrium         e;
        std::vector<double> times;
        for (int solve = 0; solve < std::max(timed_solves, 1); ++solve)
          {
            const auto start = std::chrono::steady_clock::now();
            e                = path.solve(s.load);
            times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
          }
        std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
        ValidationRecord  r;
        r.sample     = s.id;
        r.role       = s.role;
        r.model      = model.name();
        r.pressure   = s.load.pressure;
        r.force_norm = force_norm(s.load);
        r.position_error    = NAN;
        r.orientation_error = NAN;
        r.iterations = e.iterations;
        r.converged  = e.converged;
        r.failure    = e.failure;
        r.solve_time = times[times.size() / 2];
        r.fem_contact_force = s.contact_force;
        if (e.converged)
          {
            const ChainPose &pose = solver.pose();
            const Eigen::Vector3d tip = pose.tip_position + model.link_deflection(s.load);
            r.position_error      = (tip - s.tip.position).norm();
            r.orientation_error =
              data::rotation_angle_between(pose.tip_rotation, s.tip.rotation);
            r.tip_position       = tip;
            r.joint_positions = pose.joint_positions;
            r.tip_rotation_angle =
              data::rotation_angle_between(Eigen::Matrix3d::Identity(), pose.tip_rotation);
            if (r.contact())
              r.contact_force = total_force(solver.contact().obstacle_wrenches());
          }
        records_.push_back(r);
      }
  }

  int ChainValidation::n_failed(const std::string &model) const
  {
    return static_cast<int>(std::count_if(records_.begin(), records_.end(), [&](const auto &r) {
      return r.model == model && !r.converged;
    }));
  }

  CsvTable ChainValidation::per_sample_table() const
  {
    CsvTable table({"sample_index", "sample", "role", "pressure", "force_norm", "model",
                    "tip_error_mm", "tip_error_percent_L", "orientation_error_deg",
                    "chain_iterations", "chain_status", "chain_tip_x_mm", "chain_tip_y_mm",
                    "chain_tip_z_mm", "chain_tip_rotation_angle_deg", "solve_time_us",
                    "contact_force_N", "fem_contact_force_N", "contact_force_error_percent"});
    for (std::size_t i = 0; i < records_.size(); ++i)
      {
        const ValidationRecord &r = records_[i];
        table.add_row({CsvTable::cell(double(i % samples_.size() + 1)), r.sample, r.role,
                       CsvTable::cell(r.pressure), CsvTable::cell(r.force_norm), r.model,
                       CsvTable::cell(1e3 * r.position_error),
                       CsvTable::cell(100.0 * r.position_error / finger_length_),
                       CsvTable::cell(degrees(r.orientation_error)),
                       CsvTable::cell(double(r.iterations)),
                       r.converged ? std::string("converged") : r.failure,
                       CsvTable::cell(1e3 * r.tip_position.x()),
                       CsvTable::cell(1e3 * r.tip_position.y()),
                       CsvTable::cell(1e3 * r.tip_position.z()),
                       CsvTable::cell(degrees(r.tip_rotation_angle)),
                       CsvTable::cell(1e6 * r.solve_time), CsvTable::cell(r.contact_force.norm()),
                       CsvTable::cell(r.fem_contact_force.norm()),
                       CsvTable::cell(r.contact_force_error_percent())});
      }
    return table;
  }

  double ValidationRecord::contact_force_error_percent() const
  {
    const double fem = fem_contact_force.norm();
    return fem > 0.0 ? 100.0 * (contact_force.norm() - fem) / fem : NAN;
  }

  // NaN for no value: a model without samples of a kind.
  CsvTable ChainValidation::grasp_summary_table() const
  {
    CsvTable table({"model", "n_samples", "n_failed", "blocked_force_error_percent",
                    "grasp_force_error_percent", "tip_error_percent_L", "orientation_error_deg",
                    "median_solve_time_us"});
    std::vector<std::string> models;
    for (const ValidationRecord &r : records_)
      if (r.contact() && std::find(models.begin(), models.end(), r.model) == models.end())
        models.push_back(r.model);
    for (const std::string &model : models)
      {
        int                 n = 0, failed = 0;
        double              blocked = NAN, grasp = NAN, tip = NAN, angle = NAN;
        std::vector<double> times;
        const auto larger = [](double &max, double value) {
          if (std::isfinite(value))
            max = std::isfinite(max) ? std::max(max, value) : value;
        };
        for (const ValidationRecord &r : records_)
          if (r.model == model && r.contact())
            {
              ++n;
              failed += r.converged ? 0 : 1;
              times.push_back(1e6 * r.solve_time);
              larger(r.role.rfind("blocked force", 0) == 0 ? blocked : grasp,
                     std::abs(r.contact_force_error_percent()));
              larger(tip, 100.0 * r.position_error / finger_length_);
              larger(angle, degrees(r.orientation_error));
            }
        table.add_row({model, CsvTable::cell(n), CsvTable::cell(failed), CsvTable::cell(blocked),
                       CsvTable::cell(grasp), CsvTable::cell(tip), CsvTable::cell(angle),
                       CsvTable::cell(data::median(times))});
      }
    return table;
  }

  CsvTable ChainValidation::fem_tip_table() const
  {
    CsvTable table({"sample", "role", "pressure", "force_norm", "tip_x_mm", "tip_y_mm",
                    "tip_z_mm", "tip_bending_angle_deg", "tip_rotation_angle_deg"});
    for (const FemSample &s : samples_)
      {
        const Eigen::Matrix3d &R = s.tip.rotation;
        table.add_row({s.id, s.role, CsvTable::cell(s.load.pressure),
                       CsvTable::cell(force_norm(s.load)), CsvTable::cell(1e3 * s.tip.position.x()),
                       CsvTable::cell(1e3 * s.tip.position.y()),
                       CsvTable::cell(1e3 * s.tip.position.z()),
                       CsvTable::cell(degrees(std::atan2(R(1, 0), R(0, 0)))),
                       CsvTable::cell(degrees(data::rotation_angle_between(Eigen::Matrix3d::Identity(), R)))});
      }
    return table;
  }

  CsvTable ChainValidation::pose_table() const
  {
    CsvTable table({"sample", "model", "point", "x", "y", "z"});
    for (const ValidationRecord &r : records_)
      {
        std::vector<Eigen::Vector3d> points = r.joint_positions;
        if (!points.empty())
          points.push_back(r.tip_position);
        for (std::size_t k = 0; k < points.size(); ++k)
          table.add_row({r.sample, r.model,
                         k + 1 < points.size() ? std::to_string(k + 1) : std::string("tip"),
                         CsvTable::cell(points[k].x()), CsvTable::cell(points[k].y()),
                         CsvTable::cell(points[k].z())});
      }
    return table;
  }

  CsvTable ChainValidation::summary_table() const
  {
    CsvTable table({"model", "roles", "n_samples", "n_failed", "max_tip_error_mm",
                    "mean_tip_error_mm", "max_tip_error_percent_L", "mean_tip_error_percent_L",
                    "max_orientation_error_deg", "mean_orientation_error_deg"});
    std::vector<std::pair<std::string, std::string>> groups; // (model, role or "all")
    for (const ValidationRecord &r : records_)
      for (const std::string &role : {r.role, std::string("all")})
        if (std::find(groups.begin(), groups.end(), std::make_pair(r.model, role)) == groups.end())
          groups.emplace_back(r.model, role);
    for (const auto &[model, role] : groups)
      {
        std::vector<const ValidationRecord *> members;
        for (const ValidationRecord &r : records_)
          if (r.model == model && (role == "all" || r.role == role))
            members.push_back(&r);
        const ErrorStatistics s = statistics(members);
        table.add_row({model, role, CsvTable::cell(s.n), CsvTable::cell(s.failed),
                       CsvTable::cell(1e3 * s.max_position), CsvTable::cell(1e3 * s.mean_position),
                       CsvTable::cell(100 * s.max_position / finger_length_),
                       CsvTable::cell(100 * s.mean_position / finger_length_),
                       CsvTable::cell(degrees(s.max_orientation)),
                       CsvTable::cell(degrees(s.mean_orientation))});
      }
    return table;
  }

  std::string error_percent(const double percent)
  {
    if (std::isnan(percent))
      return "none (no such sample)";
    std::ostringstream text;
    text.precision(3);
    text << percent << " %";
    return text.str();
  }
} // namespace softchain::chain
