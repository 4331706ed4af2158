#include <softchain/chain/base_wrench.h>
#include <softchain/chain/protocol_torques.h>
#include <softchain/chain/tip_constrained_equilibrium.h>
#include <softchain/data/base_face_centroid.h>
#include <softchain/data/input_error.h>
#include <softchain/data/tip_pose_fit.h>
#include <softchain/data/vector_of_point.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

namespace softchain::chain
{
  ProtocolTorques::ProtocolTorques(const data::ActuationDatabase &database,
                                   const std::string             &listing)
  {
    if (!std::filesystem::exists(listing))
      return;
    const data::CsvTable rows = data::CsvTable::read(listing);
    if (rows.n_rows() == 0 || rows.text(0, "motion") != "inflation")
      throw data::InputError(listing + ": the first row must be the inflated state (motion 'inflation')");
    const auto read = [&](std::size_t r) {
      const std::string &id = rows.text(r, "sample");
      if (!database.has_sample(id))
        throw data::InputError(listing + ", row " + std::to_string(r + 1) + ": sample " + id +
                               " is not in the database " + database.path() +
                               " (rerun the sweep)");
      return database.read_sample(id);
    };
    const data::SampleRecord inflated = read(0);
    if (!inflated.converged())
      throw data::InputError(listing + ": the inflated state " + inflated.id + " did not converge");
    pressure_                    = inflated.actuation.pressure;
    const data::MeshRecord &mesh = database.mesh();
    base_centroid_               = data::base_face_centroid(mesh);

    // Each motion by kind and signed amount; an FEM sample that failed leaves its state out.
    std::map<std::string, std::map<double, TracePoint>> by_kind;
    for (std::size_t r = 1; r < rows.n_rows(); ++r)
      {
        const data::SampleRecord s = read(r);
        if (!s.converged() || !s.actuation.tip_motion)
          continue;
        const auto &m = *s.actuation.tip_motion;
        by_kind[rows.text(r, "motion")][rows.number(r, "amount")] =
          TracePoint{rows.text(r, "motion"), rows.number(r, "amount"), s.id,
                     data::vector_of(m.translation), data::vector_of(m.rotation), m.point_contact,
                     data::vector_of(s.base_moment), data::vector_of(s.base_force)};
      }
    const TracePoint rest{"", 0.0, inflated.id, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                          false, data::vector_of(inflated.base_moment),
                          data::vector_of(inflated.base_force)};
    // 0 -> +a -> 0 -> -a -> 0 per kind, in the paper's order.
    for (const std::string kind : {"lateral", "bending", "twist"})
      {
        if (by_kind.count(kind) == 0)
          continue;
        const auto          &amounts = by_kind[kind];
        std::vector<double> up, down;
        for (const auto &[amount, p] : amounts)
          (amount > 0 ? up : down).push_back(amount);
        std::reverse(down.begin(), down.end()); // -1, -2, ...
        for (const auto *side : {&up, &down})
          {
            points_.push_back(rest);
            points_.back().motion = kind;
            for (std::size_t k = 0; k < side->size(); ++k)
              points_.push_back(amounts.at((*side)[k]));
            for (std::size_t k = side->size(); k-- > 1;)
              points_.push_back(amounts.at((*side)[k - 1]));
          }
      }
    if (points_.empty())
      return;
    points_.push_back(rest);
    points_.back().motion = points_[points_.size() - 2].motion;
  }

  void ProtocolTorques::compare(const ChainModel &model, const EquilibriumSettings &settings)
  {
    ModelTrace       trace{model.name(), {}, {}};
    const ChainLoad  load{pressure_, {}};
    ChainEquilibrium free(model, settings);
    const auto       inflated = free.solve(load);
    if (!inflated.converged)
      {
        failures_.push_back(model.name() + " at the inflation pressure: " + inflated.failure);
        trace.torque.assign(points_.size(), Eigen::Vector3d::Constant(NAN));
        trace.force.assign(points_.size(), Eigen::Vector3d::Constant(NAN));
        traces_.push_back(trace);
        return;
      }
    const Eigen::Vector3d tip0 = free.pose().tip_position;
    const Eigen::Matrix3d R0   = free.pose().tip_rotation;

    // Each state is solved once, from the angles of the trace's previous
    // state (the motion is continuous along the trace).
    TipConstrainedEquilibrium              held(model, settings);
    std::map<std::string, Wrench>          wrench_of;
    std::map<std::string, Eigen::VectorXd> angles_of{{points_.front().sample, inflated.angles}};
    wrench_of[points_.front().sample] = Wrench{}; // pressure alone: no wrench
    Eigen::VectorXd start = inflated.angles;
    for (const TracePoint &p : points_)
      {
        if (wrench_of.count(p.sample) == 0)
          {
            const Eigen::Vector3d axis = p.rotation.norm() > 0 ? p.rotation.normalized() : Eigen::Vector3d::UnitX();
            TipTarget target{tip0 + p.translation,
                             Eigen::Matrix3d(Eigen::AngleAxisd(p.rotation.norm(), axis)) * R0};
            if (p.point_contact) // the tip point only, its frame free
              target.rotation.reset();
            const auto result = held.solve(load, target, start);
            if (result.converged)
              {
                angles_of[p.sample] = result.angles;
                Wrench wrench = base_wrench(held.chain(), held.pose(),
                                            held.with_contact(load, result.contact_force), base_centroid_);
                wrench.moment += result.contact_moment;
                wrench_of[p.sample] = wrench;
              }
            else
              {
                wrench_of[p.sample] = Wrench{Eigen::Vector3d::Constant(NAN), Eigen::Vector3d::Constant(NAN)};
                failures_.push_back(model.name() + " on sample " + p.sample + " (" + p.motion + " " +
                                    data::CsvTable::cell(p.amount) + "): " + result.failure);
              }
          }
        if (angles_of.count(p.sample) > 0)
          start = angles_of[p.sample];
        trace.torque.push_back(wrench_of[p.sample].moment);
        trace.force.push_back(wrench_of[p.sample].force);
      }
    traces_.push_back(trace);
  }

  std::vector<std::string> ProtocolTorques::models() const
  {
    std::vector<std::string> names;
    for (const auto &t : traces_)
      names.push_back(t.name);
    return names;
  }

  data::CsvTable ProtocolTorques::trace_table() const
  {
    std::vector<std::string> columns{"step", "motion", "amount", "unit", "sample",
                                     "fem_Tx", "fem_Ty", "fem_Tz"};
    for (const auto &t : traces_)
      for (const char *c : {"_Tx", "_Ty", "_Tz"})
        columns.push_back(t.name + c);
    for (const char *c : {"fem_Fx", "fem_Fy", "fem_Fz"})
      columns.push_back(c);
    for (const auto &t : traces_)
      for (const char *c : {"_Fx", "_Fy", "_Fz"})
        columns.push_back(t.name + c);
    data::CsvTable table(columns);
    for (std::size_t k = 0; k < points_.size(); ++k)
      {
        const TracePoint        &p = points_[k];
        std::vector<std::string> row{std::to_string(k), p.motion, data::CsvTable::cell(p.amount),
                                     p.motion == "twist" ? "deg" : "mm", p.sample};
        for (int c = 0; c < 3; ++c)
          row.push_back(data::CsvTable::cell(p.fem_torque[c]));
        for (const auto &t : traces_)
          for (int c = 0; c < 3; ++c)
            row.push_back(data::CsvTable::cell(t.torque[k][c]));
        for (int c = 0; c < 3; ++c)
          row.push_back(data::CsvTable::cell(p.fem_force[c]));
        for (const auto &t : traces_)
          for (int c = 0; c < 3; ++c)
            row.push_back(data::CsvTable::cell(t.force[k][c]));
        table.add_row(row);
      }
    return table;
  }

  data::CsvTable ProtocolTorques::summary_table() const
  {
    data::CsvTable table({"model", "torque", "fem_range_Nm", "rms_error_Nm",
                          "rms_error_percent_range", "max_error_percent_range", "n_failed_points"});
    for (const auto &t : traces_)
      for (int c = 0; c < 3; ++c)
        {
          double low = INFINITY, high = -INFINITY, sum = 0.0, largest = 0.0;
          int    n = 0, failed = 0;
          for (std::size_t k = 0; k < points_.size(); ++k)
            {
              low  = std::min(low, points_[k].fem_torque[c]);
              high = std::max(high, points_[k].fem_torque[c]);
              const double error = t.torque[k][c] - points_[k].fem_torque[c];
              if (!std::isfinite(error))
                {
                  ++failed;
                  continue;
                }
              sum += error * error;
              largest = std::max(largest, std::abs(error));
              ++n;
            }
          const double range = high - low, rms = n > 0 ? std::sqrt(sum / n) : NAN;
          table.add_row(std::vector<std::string>{
            t.name, std::string("T") + "xyz"[c], data::CsvTable::cell(range),
            data::CsvTable::cell(rms), data::CsvTable::cell(100 * rms / range),
            data::CsvTable::cell(n > 0 ? 100 * largest / range : NAN), std::to_string(failed)});
        }
    return table;
  }
} // namespace softchain::chain
