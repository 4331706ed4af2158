#include <softchain/fem/boundary_ids.h>
#include <softchain/data/csv_table.h>
#include <softchain/data/input_error.h>
#include <softchain/data/output_files.h>
#include <softchain/data/base_face_centroid.h>
#include <softchain/data/content_hash.h>
#include <softchain/fem/blas_kernel.h>
#include <softchain/fem/design_hash.h>
#include <softchain/fem/sample_group.h>
#include <softchain/fem/sample_sweep.h>
#include <softchain/fem/sweep_progress.h>

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <Eigen/Core>

#include <boost/serialization/array.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <list>
#include <numeric>
#include <optional>

// A sample's result travels from its group to world rank 0 (the actuation is
// known there by the id; of it only the pressure, which volume control solves for).
namespace boost::serialization
{
  template <class Archive>
  void serialize(Archive &archive, softchain::data::ObstacleWrench &w, const unsigned int)
  {
    archive &w.force &w.moment;
  }

  template <class Archive>
  void serialize(Archive &archive, softchain::data::SampleRecord &s, const unsigned int)
  {
    archive &s.id &s.actuation.pressure &s.status &s.reason &s.load_factor_reached
      &s.newton_iterations &s.load_steps &s.wall_time &s.x &s.force_points_deformed &s.base_force
        &s.base_moment &s.obstacle_wrenches &s.force_limit;
  }
} // namespace boost::serialization

namespace softchain::fem
{
  using namespace dealii;

  namespace
  {
    namespace fs = std::filesystem;

    unsigned int world_rank()
    {
      return Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    }

    // The asked-for actuation on a record that travelled without it; under
    // volume control the record keeps the pressure its solve found.
    void adopt_actuation(data::SampleRecord &record, const data::Actuation &asked)
    {
      const double found = record.actuation.pressure;
      record.actuation   = asked;
      if (asked.cavity_volume_ratio)
        record.actuation.pressure = found;
    }

    // Centre and z extent of the bounding box of the `tip` faces.
    SampleSet::TipFace tip_face(const Triangulation<3> &mesh, const std::string &file)
    {
      const double inf = std::numeric_limits<double>::infinity();
      Point<3>     low(inf, inf, inf), high(-inf, -inf, -inf);
      for (const auto &face : mesh.active_face_iterators())
        if (face->at_boundary() && face->boundary_id() == boundary::tip)
          for (const unsigned int v : face->vertex_indices())
            for (unsigned int c = 0; c < 3; ++c)
              {
                low[c]  = std::min(low[c], face->vertex(v)[c]);
                high[c] = std::max(high[c], face->vertex(v)[c]);
              }
      if (low[0] > high[0])
        throw data::InputError(file + ": the mesh has no face in the physical group 'tip' "
                                      "(needed for the samples' default force point)");
      const Point<3> centre = 0.5 * (low + high);
      return {{{centre[0], centre[1], centre[2]}}, high[2] - low[2]};
    }

    data::DesignRecord design_record(const Parameters &prm, const data::PrmFile &file,
                                     const std::string &hash)
    {
      return {prm.design.name, hash, name(prm.mesh.element_type), "softchain 0.1", file.text()};
    }
  } // namespace

  int SampleSweep::Summary::report(std::ostream &out, std::ostream &err) const
  {
    out << n_samples << " samples: " << n_cached << " cached, " << n_solved << " solved, "
        << failed.size() << " failed; database " << database << std::endl;
    for (const auto &f : failed)
      err << "softchain: sample failed: " << f << '\n';
    return failed.empty() ? 0 : 2;
  }

  SampleSweep::SampleSweep(const data::PrmFile &file)
    : prm(Parameters::read(file))
    , prm_file(file)
    , database_path(prm.design.database_path())
  {
    limit_threads(prm.solver.threads);
    FingerMesh::build(prm, mesh);
    hash = design_hash(prm, mesh);
    set  = SampleSet::read(prm_file, tip_face(mesh.triangulation, file.path()), hash, prm.contact);
    protocol = TipMotionProtocol::read(prm_file, hash);
  }

  void SampleSweep::read_cached(const std::vector<std::size_t> &indices, Records &known) const
  {
    if (!fs::exists(database_path))
      return;
    const auto database = data::ActuationDatabase::open(database_path);
    if (database.design().design_hash != hash)
      return;
    for (const std::size_t i : indices)
      if (database.has_sample(set.samples[i].id))
        known[i] = database.read_sample(set.samples[i].id);
  }

  SampleSweep::Summary SampleSweep::run()
  {
    Records                  known;
    Summary                  summary{0, 0, 0, {}, database_path};
    std::vector<std::size_t> listed(set.samples.size());
    std::iota(listed.begin(), listed.end(), 0);
    solve_missing(listed, known, summary, set.continuation);
    if (!set.measured_requests.empty())
      solve_measured_samples(known, summary);
    if (world_rank() == 0) // a listing of an earlier protocol must not outlive it
      fs::remove(protocol_listing());
    if (protocol.enabled())
      if (const auto failure = run_protocol(known, summary); !failure.empty())
        summary.failed.push_back(failure);
    if (world_rank() == 0)
      for (const auto &[i, record] : known)
        if (!record.converged())
          summary.failed.push_back(set.samples[i].label + " (" + record.id + "): " + record.reason);
    summary.failed = Utilities::MPI::broadcast(MPI_COMM_WORLD, summary.failed, 0);
    if (world_rank() == 0)
      write_plan(known);
    if (prm.output.write_vtu && world_rank() == 0) // also when all were cached: the set may have shrunk
      write_series();
    return summary;
  }

  // The database's plan: this sweep's samples, so that the reduction and the
  // chain leave out samples an earlier .prm asked for (data::SamplePlan).
  void SampleSweep::write_plan(const Records &known) const
  {
    if (!fs::exists(database_path))
      return;
    std::vector<std::string> ids;
    for (const auto &[i, record] : known)
      ids.push_back(record.id);
    data::ActuationDatabase::open(database_path).set_plan(ids);
  }

  // The samples `indices` (increasing) from the database, or solved. With
  // `inflations_first`, the pressure-only samples are solved first, and then
  // every other chain starts from one of them (start_chains_from_inflations).
  void SampleSweep::solve_missing(const std::vector<std::size_t> &indices, Records &known,
                                  Summary &summary, const bool inflations_first)
  {
    read_cached(indices, known);
    MPI_Barrier(MPI_COMM_WORLD); // all have read before rank 0 may replace the file
    std::vector<std::size_t> pending;
    for (const std::size_t i : indices)
      if (known.count(i) == 0)
        pending.push_back(i);
    const unsigned int n_ranks  = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    const unsigned int n_groups = set.sample_groups == 0 ? n_ranks : std::min(set.sample_groups, n_ranks);
    std::ostream  silent(nullptr);
    SweepProgress progress(world_rank() == 0 ? std::cout : silent, indices.size(), pending.size(),
                           n_groups);
    for (const std::size_t i : indices)
      if (known.count(i) > 0)
        progress.cached(set.samples[i], known.at(i));
    if (inflations_first)
      {
        // The chains that cannot start from an inflation are solved beside
        // the inflations, the others after them.
        std::vector<bool> waits(set.samples.size(), false);
        for (const auto &chain : set.chains)
          if (may_start_inflated(set.samples[chain.front()].actuation))
            for (const std::size_t i : chain)
              waits[i] = true;
        std::vector<std::size_t> first, others;
        for (const std::size_t i : pending)
          (pressure_only(set.samples[i].actuation) || !waits[i] ? first : others).push_back(i);
        if (!first.empty())
          solve_pending(first, known, progress, n_groups);
        start_chains_from_inflations(indices, known);
        if (!others.empty())
          solve_pending(others, known, progress, n_groups);
      }
    else if (!pending.empty())
      solve_pending(pending, known, progress, n_groups);
    summary.n_samples += indices.size();
    summary.n_cached += indices.size() - pending.size();
    summary.n_solved += pending.size();
  }

  // A chain of forces at a pressure p would start from rest, and its first
  // load path would inflate the finger again before the forces act. It
  // starts instead from the converged pressure-only sample at the highest
  // pressure p_0 <= p, put at the head of the chain (pressure control only:
  // a volume-controlled sample may lie past the limit point, on another
  // branch of equilibria than a load path from rest); the path from there
  // ramps the pressure from p_0 to p and the forces from zero. The
  // equilibrium is the same; the demo's sweep took 827 Newton iterations
  // instead of 1341 (docs/history.md, "Force chains start inflated"). Rank 0
  // holds every record and chooses; every rank gets the choice and the records.
  void SampleSweep::start_chains_from_inflations(const std::vector<std::size_t> &indices,
                                                 Records                        &known)
  {
    constexpr std::size_t    none = std::numeric_limits<std::size_t>::max();
    std::vector<std::size_t> head(set.chains.size(), none);
    if (world_rank() == 0)
      for (std::size_t c = 0; c < set.chains.size(); ++c)
        head[c] = inflated_start(set.chains[c], indices, known).value_or(none);
    head = Utilities::MPI::broadcast(MPI_COMM_WORLD, head, 0);
    for (std::size_t c = 0; c < set.chains.size(); ++c)
      if (head[c] != none)
        {
          share_record(head[c], known);
          set.chains[c].insert(set.chains[c].begin(), head[c]);
        }
  }

  // Whether a chain whose first sample has the actuation `first` may start
  // from an inflation: at a pressure p > 0, without tip motion, volume
  // control or obstacles (a free inflated finger may lie inside the
  // obstacle).
  bool SampleSweep::may_start_inflated(const data::Actuation &first)
  {
    return !first.tip_motion && !first.cavity_volume_ratio && first.pressure > 0 && first.obstacles.empty();
  }

  // Of `indices`, the converged pressure-controlled sample without forces,
  // outside `chain`, at the highest pressure not above the chain's first
  // sample's; none for a chain at p <= 0, of tip motions, under volume control
  // or of contact (a free inflated finger may lie inside the obstacle).
  std::optional<std::size_t> SampleSweep::inflated_start(const std::vector<std::size_t> &chain,
                                                         const std::vector<std::size_t> &indices,
                                                         const Records &known) const
  {
    const data::Actuation &first = set.samples[chain.front()].actuation;
    if (!may_start_inflated(first))
      return std::nullopt;
    std::optional<std::size_t> best;
    double                     best_pressure = 0;
    for (const std::size_t i : indices)
      {
        const auto record = known.find(i);
        if (record == known.end() || !record->second.converged())
          continue;
        const data::Actuation &a = record->second.actuation;
        if (pressure_only(a) && !set.samples[i].actuation.cavity_volume_ratio &&
            a.pressure <= first.pressure &&
            a.pressure > best_pressure && std::find(chain.begin(), chain.end(), i) == chain.end())
          {
            best          = i;
            best_pressure = a.pressure;
          }
      }
    return best;
  }

  // The samples whose forces' directions the pressure-only state gives
  // (SampleSet::MeasuredForceRequest): 'chord F' along the chord from the
  // base face's centroid to the tip's position (chord_direction), 'palm F'
  // along the palm's inward normal at the force's point (palm_normal),
  // 'shear F' along the palm towards the tip there (palm_tangent), in the
  // converged pressure sample at its pressure, or in the finger at rest at
  // p = 0. The samples at one pressure and points form a chain by increasing
  // force, from the pressure sample (whose state they share: only the forces
  // ramp). A sample whose pressure sample failed is reported failed, not
  // solved.
  void SampleSweep::solve_measured_samples(Records &known, Summary &summary)
  {
    MeasuredChains           chains;
    std::vector<std::size_t> added;
    for (const auto &request : set.measured_requests)
      {
        const auto inflation  = set.inflation_at(request.pressure);
        const auto directions = measured_directions(request, inflation, known);
        if (!directions)
          {
            summary.failed.push_back(request.label + ": not solved: the pressure sample at " +
                                     data::canonical(request.pressure) +
                                     " Pa, which gives the forces' directions, did not converge");
            continue;
          }
        if (world_rank() == 0)
          {
            using Direction = SampleSet::MeasuredForceRequest::Direction;
            std::cout << request.label << ": along the "
                      << (request.direction == Direction::chord         ? "base-tip chord"
                          : request.direction == Direction::palm_normal ? "palm's inward normal"
                                                                        : "palm towards the tip")
                      << " at "
                      << request.pressure << " Pa:";
            for (std::size_t k = 0; k < directions->size(); ++k)
              std::cout << (k > 0 ? "," : "") << ' ' << request.forces[k] << " N (" << (*directions)[k][0]
                        << ", " << (*directions)[k][1] << ", " << (*directions)[k][2] << ')';
            std::cout << std::endl;
          }
        added.push_back(set.samples.size());
        set.samples.push_back(SampleSet::measured_sample(request, *directions, hash));
        chain_measured_sample(added.back(), request, inflation, known, chains);
      }
    solve_missing(added, known, summary);
  }

  // Rank 0 measures the directions of `request` on the pressure sample
  // `inflation` (none: the finger at rest) if it converged, and tells every
  // rank.
  std::optional<std::vector<data::Point3>>
  SampleSweep::measured_directions(const SampleSet::MeasuredForceRequest &request,
                                   const std::optional<std::size_t> &inflation, const Records &known)
  {
    std::vector<double> values(1 + 3 * request.points.size(), 0.0); // measured (1 or 0), then the directions
    if (world_rank() == 0 &&
        (!inflation || (known.count(*inflation) > 0 && known.at(*inflation).converged())))
      {
        const data::SampleRecord *record = inflation ? &known.at(*inflation) : nullptr;
        values[0]                        = 1.0;
        for (std::size_t k = 0; k < request.points.size(); ++k)
          {
            using Direction      = SampleSet::MeasuredForceRequest::Direction;
            const data::Point3 d = request.direction == Direction::chord       ? chord_direction(record)
                                   : request.direction == Direction::palm_normal ? palm_normal(record, request.points[k])
                                                                                 : palm_tangent(record, request.points[k]);
            std::copy(d.begin(), d.end(), values.begin() + 1 + 3 * k);
          }
      }
    values = Utilities::MPI::broadcast(MPI_COMM_WORLD, values, 0);
    if (values[0] == 0.0)
      return std::nullopt;
    std::vector<data::Point3> directions(request.points.size());
    for (std::size_t k = 0; k < directions.size(); ++k)
      directions[k] = {{values[1 + 3 * k], values[2 + 3 * k], values[3 + 3 * k]}};
    return directions;
  }

  // Puts the sample `index` into the chain of its role, pressure and points
  // (a new one starts at the pressure sample `inflation`), by increasing force.
  void SampleSweep::chain_measured_sample(const std::size_t index,
                                          const SampleSet::MeasuredForceRequest &request,
                                          const std::optional<std::size_t> &inflation, Records &known,
                                          MeasuredChains &chains)
  {
    std::ostringstream key;
    key << request.keyword() << ' ' << request.pressure;
    for (const auto &point : request.points)
      key << ' ' << point[0] << ' ' << point[1] << ' ' << point[2];
    if (!chains.count(key.str()))
      {
        chains[key.str()] = set.chains.size();
        set.chains.emplace_back();
        if (inflation)
          {
            share_record(*inflation, known);
            set.chains.back().push_back(*inflation);
          }
      }
    auto      &chain = set.chains[chains.at(key.str())];
    const auto place = std::upper_bound(chain.begin() + (inflation ? 1 : 0), chain.end(), index,
                                        [&](const std::size_t a, const std::size_t b) {
                                          return load_size(set.samples[a].actuation) <
                                                 load_size(set.samples[b].actuation);
                                        });
    chain.insert(place, index);
  }

  // The unit vector from the base face's centroid to the tip's position
  // (TipPoseFit: the centroid of the tip nodes) deformed as in `record`
  // (none: the finger at rest).
  data::Point3 SampleSweep::chord_direction(const data::SampleRecord *record)
  {
    const data::MeshRecord &mesh = database_mesh();
    const Eigen::Vector3d   tip  = record ? tip_pose(*record).position
                                          : tip_fit->fit(data::select_nodes(mesh.X, mesh.tip_nodes)).position;
    const Eigen::Vector3d chord = (tip - data::base_face_centroid(mesh)).normalized();
    return {{chord[0], chord[1], chord[2]}};
  }

  // The palm's inward normal (+y at rest, docs/conventions.md) at reference
  // point X deformed as in `record` (none: the finger at rest): the normal
  // F^-T e_y of the deformation gradient F there (palm_deformation).
  data::Point3 SampleSweep::palm_normal(const data::SampleRecord *record, const data::Point3 &X)
  {
    if (!record)
      return {{0.0, 1.0, 0.0}};
    const Eigen::Vector3d normal = palm_deformation(*record, X).inverse().transpose().col(1).normalized();
    return {{normal[0], normal[1], normal[2]}};
  }

  // The palm's tangent towards the tip (+x at rest) at reference point X
  // deformed as in `record` (none: the finger at rest): the image F e_x of
  // the finger's axis, which lies in the deformed palm.
  data::Point3 SampleSweep::palm_tangent(const data::SampleRecord *record, const data::Point3 &X)
  {
    if (!record)
      return {{1.0, 0.0, 0.0}};
    const Eigen::Vector3d tangent = palm_deformation(*record, X).col(0).normalized();
    return {{tangent[0], tangent[1], tangent[2]}};
  }

  // The affine map F that fits the deformation of the mesh nodes nearest to
  // reference point X in `record` (least squares over 20 of them, enough to
  // span 3D on a surface of hexahedra or tetrahedra).
  Eigen::Matrix3d SampleSweep::palm_deformation(const data::SampleRecord &record, const data::Point3 &X)
  {
    const data::MeshRecord        &mesh = database_mesh();
    const Eigen::Vector3d          point(X[0], X[1], X[2]);
    std::vector<std::pair<double, std::size_t>> nearest;
    for (std::size_t i = 0; i < mesh.X.size(); ++i)
      nearest.emplace_back((Eigen::Vector3d(mesh.X[i][0], mesh.X[i][1], mesh.X[i][2]) - point).squaredNorm(), i);
    const std::size_t n = std::min<std::size_t>(20, nearest.size());
    std::partial_sort(nearest.begin(), nearest.begin() + n, nearest.end());
    Eigen::Vector3d mean_X = Eigen::Vector3d::Zero(), mean_x = Eigen::Vector3d::Zero();
    const auto      at = [](const data::Point3 &p) { return Eigen::Vector3d(p[0], p[1], p[2]); };
    for (std::size_t k = 0; k < n; ++k)
      {
        mean_X += at(mesh.X[nearest[k].second]) / double(n);
        mean_x += at(record.x[nearest[k].second]) / double(n);
      }
    Eigen::Matrix3d XX = Eigen::Matrix3d::Zero(), xX = Eigen::Matrix3d::Zero();
    for (std::size_t k = 0; k < n; ++k)
      {
        const Eigen::Vector3d dX = at(mesh.X[nearest[k].second]) - mean_X;
        XX += dX * dX.transpose();
        xX += (at(record.x[nearest[k].second]) - mean_x) * dX.transpose();
      }
    return xX * XX.inverse();
  }

  // The paper's validation protocol (TipMotionProtocol): the inflation to the
  // tip angle, then the tip motions from there. Returns why it could not be
  // run (empty if it ran; its samples' failures are reported as any other).
  std::string SampleSweep::run_protocol(Records &known, Summary &summary)
  {
    const bool root = world_rank() == 0;
    const auto inflated = inflate_to_tip_angle(known, summary);
    if (!inflated.second.empty())
      return inflated.second;
    share_record(inflated.first, known); // every motion chain starts from it
    // The tip frame of the inflated finger, from rank 0 to all.
    std::vector<double> frame(9);
    if (root)
      {
        const auto tip = tip_pose(known.at(inflated.first));
        std::copy(tip.rotation.data(), tip.rotation.data() + 9, frame.begin());
      }
    frame = Utilities::MPI::broadcast(MPI_COMM_WORLD, frame, 0);
    data::TipPose tip;
    tip.rotation = Eigen::Map<const Eigen::Matrix3d>(frame.data());
    std::vector<std::size_t> added;
    data::CsvTable           listing({"sample", "motion", "amount", "unit"});
    listing.add_row(std::vector<std::string>{set.samples[inflated.first].id, "inflation",
                                             data::CsvTable::cell(protocol.tip_angle_degrees()),
                                             "deg"});
    for (const auto &chain : protocol.motions(known.at(inflated.first).actuation, tip))
      {
        set.chains.push_back({inflated.first});
        for (const auto &motion : chain)
          {
            set.chains.back().push_back(set.samples.size());
            added.push_back(set.samples.size());
            set.samples.push_back(motion.sample);
            listing.add_row(std::vector<std::string>{motion.sample.id, motion.kind,
                                                     data::CsvTable::cell(motion.amount), motion.unit});
          }
      }
    if (root)
      std::cout << "protocol: " << added.size() << " tip motions from sample "
                << set.samples[inflated.first].label << std::endl;
    solve_missing(added, known, summary);
    if (root)
      listing.write(protocol_listing());
    return "";
  }

  // <output>/protocol_samples.csv: the protocol's samples, for the chain tier.
  std::string SampleSweep::protocol_listing() const
  {
    return prm.design.output_directory + "/protocol_samples.csv";
  }

  // Secant steps on the tip angle over the pressure (TipMotionProtocol),
  // each trial a sample continued from the nearest lower pressure-only
  // equilibrium. Returns the index of the sample that reached the angle, or
  // why none did. Rank 0, which holds every record, decides; the others
  // follow its broadcasts and receive the records their solves start from.
  std::pair<std::size_t, std::string> SampleSweep::inflate_to_tip_angle(Records &known,
                                                                        Summary &summary)
  {
    constexpr std::size_t none = std::numeric_limits<std::size_t>::max();
    const bool            root = world_rank() == 0;
    std::vector<TipMotionProtocol::Trial> trials{{0.0, 0.0}}; // rank 0
    std::map<double, std::size_t>         sample_at;          // rank 0: pressure-only samples
    const auto                            add_trial = [&](const std::size_t i) {
      const auto &record = known.at(i);
      sample_at[record.actuation.pressure] = i;
      trials.push_back({record.actuation.pressure,
                        record.converged() ? TipMotionProtocol::tip_angle_of(tip_pose(record)) : NAN});
    };
    if (root)
      for (const auto &[i, record] : known)
        if (pressure_only(record.actuation))
          add_trial(i);
    for (unsigned int n = 0;; ++n)
      {
        // Rank 0: the sample that reached the angle, or the next pressure
        // and the equilibrium to start from (none: rest).
        std::size_t hit = none, start = none;
        double      next = NAN;
        if (root)
          {
            if (const auto reached = protocol.reached(trials))
              hit = sample_at.at(reached->pressure);
            else if (n < protocol.max_trials())
              {
                next = protocol.next_pressure(trials);
                if (sample_at.count(next) > 0) // the search cannot refine further
                  next = NAN;
                for (const auto &[p, i] : sample_at)
                  if (p < next && known.at(i).converged())
                    start = i;
              }
          }
        hit   = Utilities::MPI::broadcast(MPI_COMM_WORLD, hit, 0);
        next  = Utilities::MPI::broadcast(MPI_COMM_WORLD, next, 0);
        start = Utilities::MPI::broadcast(MPI_COMM_WORLD, start, 0);
        if (hit != none)
          return {hit, ""};
        if (!std::isfinite(next))
          return {0, "protocol: the inflation did not reach the " + protocol.target_text() +
                       " in " + std::to_string(n) + " trials (see the protocol inflation samples)"};
        const std::size_t index = set.samples.size();
        set.samples.push_back(protocol.inflation(next));
        set.chains.emplace_back();
        if (start != none)
          {
            share_record(start, known);
            set.chains.back().push_back(start);
          }
        set.chains.back().push_back(index);
        solve_missing({index}, known, summary);
        if (root)
          add_trial(index);
      }
  }

  // Rank 0's record of sample i to every rank (a chain that continues from
  // it may be solved by another sample group).
  void SampleSweep::share_record(const std::size_t i, Records &known) const
  {
    data::SampleRecord record;
    if (world_rank() == 0)
      record = known.at(i);
    record           = Utilities::MPI::broadcast(MPI_COMM_WORLD, record, 0);
    adopt_actuation(record, set.samples[i].actuation); // known from the id
    known[i] = std::move(record);
  }

  // The tip pose of a sample (rank 0: the database's mesh).
  const data::MeshRecord &SampleSweep::database_mesh()
  {
    if (!tip_fit)
      {
        tip_mesh = data::ActuationDatabase::open(database_path).mesh();
        tip_fit  = data::TipPoseFit::of_mesh(tip_mesh, database_path);
      }
    return tip_mesh;
  }

  data::TipPose SampleSweep::tip_pose(const data::SampleRecord &record)
  {
    const auto &nodes = database_mesh().tip_nodes;
    return tip_fit->fit(data::select_nodes(record.x, nodes));
  }

  void SampleSweep::solve_pending(const std::vector<std::size_t> &pending, Records &known,
                                  SweepProgress &progress, const unsigned int n_groups) const
  {
    const unsigned int rank  = world_rank();
    const unsigned int color = rank * n_groups / Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    MPI_Comm           group_comm;
    MPI_Comm_split(MPI_COMM_WORLD, color, rank, &group_comm);
    std::ostream log(prm.output.verbose && rank == 0 ? std::cout.rdbuf() : nullptr);
    {
      SampleGroup group(prm, mesh, group_comm, log);
      group.check_samples(set.samples);
      std::optional<data::ActuationDatabase> database;
      std::string                            open_error;
      if (rank == 0)
        try
          {
            fs::create_directories(prm.design.output_directory);
            database = data::ActuationDatabase::open_or_create(database_path,
                                                               design_record(prm, prm_file, hash),
                                                               group.mesh());
          }
        catch (const data::InputError &e)
          {
            open_error = e.what();
          }
      // Only rank 0 writes; every rank learns whether it could open the
      // database (e.g. another sweep is writing it), so that all stop
      // together instead of waiting for rank 0 in the first round.
      open_error = Utilities::MPI::broadcast(MPI_COMM_WORLD, open_error, 0);
      if (!open_error.empty())
        throw data::InputError(open_error);
      const auto  share     = shares(pending, n_groups);
      std::size_t n_records = 0; // the records rank 0 stores: every group's share
      for (const auto &s : share)
        n_records += s.size();
      solve_share(group, share[color], n_records, database, known, progress);
      group.print_timing();
    }
    MPI_Comm_free(&group_comm);
  }

  // Each group solves its share on its own, and the records reach rank 0,
  // which writes them, as they come: the group leaders send each record as
  // it is solved, and rank 0 takes the records that have arrived after each
  // of its own samples and waits for the rest at the end. No group waits for
  // another's sample. (Rounds of one sample per group, gathered after each,
  // took as long as each round's slowest sample: on P10 with fibre sheets,
  // 4 mm across and 8 mm along, the sweep took 560 s on two groups against
  // 714 s on one rank, where the samples' solves added up to 783 s.)
  void SampleSweep::solve_share(SampleGroup &group, const std::vector<std::size_t> &mine,
                                const std::size_t n_records,
                                std::optional<data::ActuationDatabase> &database, Records &known,
                                SweepProgress &progress) const
  {
    std::map<std::string, std::size_t> index_of;
    for (std::size_t i = 0; i < set.samples.size(); ++i)
      index_of[set.samples[i].id] = i;
    std::size_t n_stored = 0;
    const auto  store    = [&](data::SampleRecord record) {
      const std::size_t i = index_of.at(record.id);
      adopt_actuation(record, set.samples[i].actuation);
      database->store_sample(record);
      progress.solved(set.samples[i], record, database->mesh());
      known[i] = std::move(record);
      ++n_stored;
    };
    std::list<std::vector<char>> sent; // kept until their sends complete
    std::vector<MPI_Request>     requests;
    for (const std::size_t i : mine)
      {
        const auto *stop = stopped_before(i, known);
        known[i] = stop ? beyond_limit_point(i, *stop) :
                          group.solve(set.samples[i], start_of(i, known), anchor_of(i, known), i);
        if (world_rank() == 0)
          {
            store(known[i]);
            while (const auto record = receive_record(false))
              store(*record);
          }
        else if (group.leader())
          {
            sent.push_back(Utilities::pack(known[i], false));
            requests.emplace_back();
            MPI_Isend(sent.back().data(), sent.back().size(), MPI_CHAR, 0, record_tag, MPI_COMM_WORLD,
                      &requests.back());
          }
      }
    if (world_rank() == 0)
      while (n_stored < n_records)
        store(*receive_record(true));
    MPI_Waitall(requests.size(), requests.data(), MPI_STATUSES_IGNORE);
  }

  // Rank 0: a record another group sent, if one has arrived (or, with
  // `wait`, once one has).
  std::optional<data::SampleRecord> SampleSweep::receive_record(const bool wait) const
  {
    MPI_Status status;
    int        arrived = 1;
    if (wait)
      MPI_Probe(MPI_ANY_SOURCE, record_tag, MPI_COMM_WORLD, &status);
    else
      MPI_Iprobe(MPI_ANY_SOURCE, record_tag, MPI_COMM_WORLD, &arrived, &status);
    if (!arrived)
      return std::nullopt;
    int size = 0;
    MPI_Get_count(&status, MPI_CHAR, &size);
    std::vector<char> buffer(size);
    MPI_Recv(buffer.data(), size, MPI_CHAR, status.MPI_SOURCE, record_tag, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    return Utilities::unpack<data::SampleRecord>(buffer, false);
  }

  // Whole chains per group (so that every sample continues from the same
  // neighbour whatever the grouping), the largest first to the least loaded.
  std::vector<std::vector<std::size_t>> SampleSweep::shares(const std::vector<std::size_t> &pending,
                                                             const unsigned int n_groups) const
  {
    std::vector<std::vector<std::size_t>> work;
    for (const auto &chain : set.chains)
      {
        work.emplace_back();
        for (const auto i : chain)
          if (std::binary_search(pending.begin(), pending.end(), i))
            work.back().push_back(i);
      }
    std::vector<std::size_t> order(work.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return work[a].size() > work[b].size(); });
    std::vector<std::size_t>              load(n_groups, 0);
    std::vector<std::vector<std::size_t>> chains_of(n_groups);
    for (const auto c : order)
      {
        const auto g = std::min_element(load.begin(), load.end()) - load.begin();
        load[g] += work[c].size();
        chains_of[g].push_back(c);
      }
    std::vector<std::vector<std::size_t>> share(n_groups);
    for (unsigned int g = 0; g < n_groups; ++g)
      {
        std::sort(chains_of[g].begin(), chains_of[g].end());
        for (const auto c : chains_of[g])
          share[g].insert(share[g].end(), work[c].begin(), work[c].end());
      }
    return share;
  }

  // The records of the samples before `sample` in its chain, nearest first.
  std::vector<const data::SampleRecord *> SampleSweep::known_before(const std::size_t sample,
                                                                    const Records    &known) const
  {
    std::vector<const data::SampleRecord *> before;
    for (const auto &chain : set.chains)
      {
        const auto at = std::find(chain.begin(), chain.end(), sample);
        if (at == chain.end())
          continue;
        for (auto k = std::make_reverse_iterator(at); k != chain.rend(); ++k)
          if (const auto record = known.find(*k); record != known.end())
            before.push_back(&record->second);
      }
    return before;
  }

  // The nearest converged sample before `sample` in its chain, or nullptr
  // (start from rest).
  const data::SampleRecord *SampleSweep::start_of(const std::size_t sample,
                                                  const Records    &known) const
  {
    for (const auto *record : known_before(sample, known))
      if (record->converged())
        return record;
    return nullptr;
  }

  // The equilibrium a sample's tip motion is relative to: the nearest
  // converged sample before it in its chain without one (nullptr for a
  // sample without tip motion).
  const data::SampleRecord *SampleSweep::anchor_of(const std::size_t sample,
                                                   const Records    &known) const
  {
    if (!set.samples[sample].actuation.tip_motion)
      return nullptr;
    for (const auto *record : known_before(sample, known))
      if (record->converged() && !record->actuation.tip_motion)
        return record;
    return nullptr;
  }

  // The nearest sample before `sample` in its chain with a result, if that
  // result is a stop at a limit point (or a sample beyond one), else nullptr.
  const data::SampleRecord *SampleSweep::stopped_before(const std::size_t sample,
                                                        const Records    &known) const
  {
    const auto before = known_before(sample, known);
    return !before.empty() && before.front()->status == data::SampleStatus::limit_point ?
             before.front() :
             nullptr;
  }

  // A chain loads proportionally, so a sample further along it than a limit
  // point has no equilibrium on that load path either (pressure control cannot
  // pass a limit point): it is stored as failed without a solve, holding the
  // state at the limit.
  data::SampleRecord SampleSweep::beyond_limit_point(const std::size_t         sample,
                                                     const data::SampleRecord &stop) const
  {
    data::SampleRecord record = stop;
    record.id                 = set.samples[sample].id;
    record.actuation          = set.samples[sample].actuation;
    record.reason             = stop.reason.rfind("not solved", 0) == 0 ?
                                  stop.reason :
                                  "not solved: beyond the limit point of sample " + stop.id + " (" +
                                    stop.reason + ")";
    record.load_factor_reached = 0.0;
    record.newton_iterations   = 0;
    record.load_steps          = 0;
    record.wall_time           = 0.0;
    return record;
  }

  // vtu/samples.pvd: the samples' VTU files in sample order (time = index).
  void SampleSweep::write_series() const
  {
    const std::string directory = prm.design.output_directory + "/" + data::folder::vtu + "/";
    std::vector<std::pair<double, std::string>> series;
    for (std::size_t i = 0; i < set.samples.size(); ++i)
      for (const char *extension : {".pvtu", ".vtu"})
        {
          const std::string file = "sample_" + set.samples[i].id + "_0000" + extension;
          if (fs::exists(directory + file))
            {
              series.emplace_back(i, file);
              break;
            }
        }
    if (series.empty())
      return;
    std::ofstream out(directory + "samples.pvd");
    DataOutBase::write_pvd_record(out, series);
  }
} // namespace softchain::fem
