#include <softchain/chain/base_wrench.h>
#include <softchain/chain/protocol_torques.h>
#include <softchain/chain/tip_constrained_equilibrium.h>
#include <softchain/data/input_error.h>
#include <softchain/data/tip_pose_fit.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>

namespace softchain::chain
{
  namespace
  {
    constexpr double degree = M_PI / 180.0;

    Eigen::Vector3d vector_of(const data::Point3 &p)
    {
      return {p[0], p[1], p[2]};
    }

    struct MotionSample
    {
      std::string     id;
      Eigen::Vector3d translation, rotation, fem_torque;
    };

    // The protocol's samples at the inflation pressure with the most of them.
    std::vector<MotionSample> motion_samples(const std::vector<data::SampleRecord> &records,
                                             double                               &pressure)
    {
      std::map<double, std::vector<MotionSample>> by_pressure;
      for (const auto &r : records)
        if (r.actuation.role == "protocol" && r.converged() && r.actuation.tip_motion)
          by_pressure[r.actuation.pressure].push_back({r.id,
                                                       vector_of(r.actuation.tip_motion->translation),
                                                       vector_of(r.actuation.tip_motion->rotation),
                                                       vector_of(r.base_moment)});
      std::vector<MotionSample> most;
      for (auto &[p, samples] : by_pressure)
        if (samples.size() > most.size())
          {
            pressure = p;
            most     = std::move(samples);
          }
      return most;
    }
  } // namespace

  ProtocolTorques::ProtocolTorques(const data::ActuationDatabase &database)
  {
    std::vector<data::SampleRecord> records;
    for (const std::string &id : database.sample_ids())
      records.push_back(database.read_sample(id));
    const auto samples = motion_samples(records, pressure_);
    if (samples.empty())
      return;
    // The inflated state: a converged sample at that pressure with a free tip and no force.
    const auto inflated = std::find_if(records.begin(), records.end(), [&](const auto &r) {
      return r.converged() && r.actuation.pressure == pressure_ &&
             r.actuation.point_forces.empty() && !r.actuation.tip_motion;
    });
    if (inflated == records.end())
      throw data::InputError(database.path() + ": protocol samples at " + std::to_string(pressure_) +
                             " Pa but no converged sample of the inflated finger they start from");
    const data::MeshRecord &mesh = database.mesh();
    base_centroid_               = base_face_centroid(mesh);
    const Eigen::Matrix3d R =
      data::TipPoseFit::of_mesh(mesh, database.path()).fit(data::select_nodes(inflated->x, mesh.tip_nodes)).rotation;

    // Each sample's motion in the inflated tip frame: its kind and amount.
    std::map<std::string, std::map<double, const MotionSample *>> by_kind;
    for (const MotionSample &s : samples)
      {
        const Eigen::Vector3d t = R.transpose() * s.translation, theta = R.transpose() * s.rotation;
        if (theta.norm() > 0)
          by_kind["twist"][theta.x() / degree] = &s;
        else if (std::abs(t.z()) >= std::abs(t.y()))
          by_kind["lateral"][1e3 * t.z()] = &s;
        else
          by_kind["bending"][1e3 * t.y()] = &s;
      }
    const TracePoint rest{"", 0.0, inflated->id, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                          vector_of(inflated->base_moment)};
    const auto point = [](const std::string &kind, double amount, const MotionSample &s) {
      return TracePoint{kind, amount, s.id, s.translation, s.rotation, s.fem_torque};
    };
    // 0 -> +a -> 0 -> -a -> 0 per kind, in the paper's order.
    for (const std::string kind : {"lateral", "bending", "twist"})
      {
        if (by_kind.count(kind) == 0)
          continue;
        const auto          &amounts = by_kind[kind];
        std::vector<double> up, down;
        for (const auto &[amount, s] : amounts)
          (amount > 0 ? up : down).push_back(amount);
        std::reverse(down.begin(), down.end()); // -1, -2, ...
        for (const auto *side : {&up, &down})
          {
            points_.push_back(rest);
            points_.back().motion = kind;
            for (std::size_t k = 0; k < side->size(); ++k)
              points_.push_back(point(kind, (*side)[k], *amounts.at((*side)[k])));
            for (std::size_t k = side->size(); k-- > 1;)
              points_.push_back(point(kind, (*side)[k - 1], *amounts.at((*side)[k - 1])));
          }
      }
    points_.push_back(rest);
    points_.back().motion = points_[points_.size() - 2].motion;
  }

  void ProtocolTorques::compare(const ChainModel &model, const EquilibriumSettings &settings)
  {
    ModelTrace       trace{model.name(), {}};
    const ChainLoad  load{pressure_, {}};
    ChainEquilibrium free(model, settings);
    const auto       inflated = free.solve(load);
    if (!inflated.converged)
      {
        failures_.push_back(model.name() + " at the inflation pressure: " + inflated.failure);
        trace.torque.assign(points_.size(), Eigen::Vector3d::Constant(NAN));
        traces_.push_back(trace);
        return;
      }
    const Eigen::Vector3d tip0 = free.pose().tip_position;
    const Eigen::Matrix3d R0   = free.pose().link_rotations.back();

    // Each state is solved once, from the angles of the trace's previous
    // state (the motion is continuous along the trace).
    TipConstrainedEquilibrium              held(model, settings);
    std::map<std::string, Eigen::Vector3d> torque_of;
    std::map<std::string, Eigen::VectorXd> angles_of{{points_.front().sample, inflated.angles}};
    torque_of[points_.front().sample] = Eigen::Vector3d::Zero(); // pressure alone: no wrench
    Eigen::VectorXd start = inflated.angles;
    for (const TracePoint &p : points_)
      {
        if (torque_of.count(p.sample) == 0)
          {
            const Eigen::Vector3d axis = p.rotation.norm() > 0 ? p.rotation.normalized() : Eigen::Vector3d::UnitX();
            const TipTarget target{tip0 + p.translation,
                                   Eigen::Matrix3d(Eigen::AngleAxisd(p.rotation.norm(), axis)) * R0};
            const auto result = held.solve(load, target, start);
            if (result.converged)
              {
                angles_of[p.sample] = result.angles;
                torque_of[p.sample] =
                  base_wrench(model.chain(), held.pose(), held.with_contact(load, result.contact_force),
                              base_centroid_).moment + result.contact_moment;
              }
            else
              {
                torque_of[p.sample] = Eigen::Vector3d::Constant(NAN);
                failures_.push_back(model.name() + " on sample " + p.sample + " (" + p.motion + " " +
                                    data::CsvTable::cell(p.amount) + "): " + result.failure);
              }
          }
        if (angles_of.count(p.sample) > 0)
          start = angles_of[p.sample];
        trace.torque.push_back(torque_of[p.sample]);
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
