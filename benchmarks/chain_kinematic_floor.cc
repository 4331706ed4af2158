// The chain's kinematic floor: the tip error of a chain of rigid links that
// is driven by the FEM's own rotations, so that no stiffness is involved.
// For every converged sample of a database and each joint placement
// (the paper's bounding-box centres, joints on the strain-limiting layer),
// the chain tier's KinematicChain through the reference joint centres at
// the relative M2 angles of the slabs (c_1 = J_1,0: the clamped base carries
// joint 1; the last link reaches the tip face's reference centroid), against the FEM tip pose (centroid and
// Kabsch rotation of the deformed tip face). A stiffness-based chain that
// finds the FEM's joint angles lands this far off; other angles may land
// its tip closer only by compensating one error with another.
//
// A further column measures a chain whose joints twist about another axis:
// joint i's psi turns about the proximal link's x axis through
// J_i,0 + (0, t, 0), its theta and phi about J_i,0 as before, t fitted to
// the torsion samples as the reduction does (TwistAxis). The last column is
// that chain on the links the chain tier uses by default: the pressure
// states' link geometry (the reduction's, with the tip face's frame in the
// last link's), interpolated in pressure as the chain interpolates it, on
// which the pressure states are exact by construction; it is the floor of
// the chain as it runs.
//
// Run: chain_kinematic_floor DATABASE.h5 [a = 0.01] [b/a = 0.5] [CSV [LINKS_CSV]]
// CSV (benchmarks/results/chain_kinematic_floor.csv for the demo's
// database): one row per sample and model, the tables of
// docs/chain_fidelity.md. LINKS_CSV (chain_kinematic_floor_links.csv): per
// sample at a pressure of a pressure sample and per link, how its own links
// differ from that state's (the link vector in the link's frame, x along
// it, y towards the finger's top, z sideways) and joint i's in-plane turn
// and twist from it.
#include <softchain/chain/angle_units.h>
#include <softchain/chain/kinematic_chain.h>
#include <softchain/data/tip_pose_fit.h>
#include <softchain/data/actuation_database.h>
#include <softchain/reduction/joint_geometry.h>
#include <softchain/reduction/neutral_layer.h>
#include <softchain/reduction/twist_axis.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

using namespace softchain;

namespace
{
  struct Floor
  {
    double position; // m
    double angle;    // rad
  };

  // The chain tier's forward kinematics (KinematicChain) at the relative
  // angles the reduction measured, against the FEM tip pose.
  // With `moving_base`, the chain starts at the deformed J_1 instead of
  // J_1,0: the share of the floor that the base's deformation (proximal to
  // joint 1) causes.
  Floor floor_of(const reduction::JointGeometry &geometry, const data::SampleRecord &sample,
                 const data::TipPoseFit &tip_fit, const data::MeshRecord &mesh,
                 bool moving_base = false)
  {
    const reduction::JointFrames frames(reduction::RotationMethod::affine_fit, geometry.slabs(),
                                        geometry.reference_points(), geometry.points(sample.x),
                                        sample.id);
    std::vector<Eigen::Vector3d> centres;
    Eigen::VectorXd              q(3 * frames.size());
    for (std::size_t k = 0; k < frames.size(); ++k)
      {
        centres.push_back(geometry.reference_centre(k));
        const data::JointAngles angles = frames.relative_angles(k);
        q.segment<3>(3 * k) << angles.psi, angles.theta, angles.phi;
      }
    const chain::KinematicChain chain(centres, tip_fit.reference_centroid());
    chain::ChainPose            pose = chain.rest_pose();
    chain.update_pose(q, pose);
    const data::TipPose  fem = tip_fit.fit(data::select_nodes(sample.x, mesh.tip_nodes));
    const Eigen::Vector3d base_shift =
      moving_base ? Eigen::Vector3d(geometry.deformed_centre(0, frames, sample.x) - centres[0])
                  : Eigen::Vector3d::Zero();
    return {(pose.tip_position + base_shift - fem.position).norm(),
            data::rotation_angle_between(pose.link_rotations.back(), fem.rotation)};
  }
  // The floor of a chain whose joints twist about an axis t above them
  // (TwistAxis::chain_tip; t = 0 is floor_of's chain).
  Floor twist_axis_floor(const reduction::JointGeometry &geometry, const data::SampleRecord &sample,
                         const data::TipPoseFit &tip_fit, const data::MeshRecord &mesh,
                         const double t)
  {
    const reduction::JointFrames frames(reduction::RotationMethod::affine_fit, geometry.slabs(),
                                        geometry.reference_points(), geometry.points(sample.x),
                                        sample.id);
    const auto tip = reduction::TwistAxis::chain_tip(geometry, frames, tip_fit.reference_centroid(), t);
    const data::TipPose fem = tip_fit.fit(data::select_nodes(sample.x, mesh.tip_nodes));
    return {(tip.position - fem.position).norm(), data::rotation_angle_between(tip.rotation, fem.rotation)};
  }

  // The chain tier's link geometry at one pressure state: the links U and
  // the tip face's frame in the last link's, Q_T = R_n^T R_T, as a rotation
  // vector (the chain interpolates both in pressure, chain/link_geometry.h).
  struct Links
  {
    std::vector<Eigen::Vector3d> points;
    Eigen::Vector3d              tip_frame = Eigen::Vector3d::Zero();
    std::vector<double>          phi; // the state's relative in-plane angles
    std::vector<double>          psi; // and twists
  };

  Links links_at_state(const reduction::JointGeometry &geometry, const data::SampleRecord &state,
                       const data::TipPoseFit &tip_fit, const data::MeshRecord &mesh)
  {
    const reduction::JointFrames frames(reduction::RotationMethod::affine_fit, geometry.slabs(),
                                        geometry.reference_points(), geometry.points(state.x), state.id);
    const data::TipPose     tip = tip_fit.fit(data::select_nodes(state.x, mesh.tip_nodes));
    const Eigen::AngleAxisd Q_T(frames[frames.size() - 1].rotation.transpose() * tip.rotation);
    std::vector<double>     phi, psi;
    for (std::size_t i = 0; i < frames.size(); ++i)
      {
        phi.push_back(frames.relative_angles(i).phi);
        psi.push_back(frames.relative_angles(i).psi);
      }
    return {reduction::TwistAxis::links_of(geometry, frames, state.x, tip.position), Q_T.angle() * Q_T.axis(), phi,
            psi};
  }

  // Each link's change from the pressure state at the sample's pressure
  // (solved there; none otherwise): the link vector U_i+1 - U_i of the
  // sample's own links against the state's, in the link's frame [m], and
  // joint i's in-plane turn and twist from the state [rad].
  struct LinkChange
  {
    int             link;
    double          turn, twist;
    Eigen::Vector3d change;
  };
  std::vector<LinkChange> link_changes(const reduction::JointGeometry &geometry, const data::SampleRecord &sample,
                                       const std::map<double, Links> &states, const data::TipPoseFit &tip_fit,
                                       const data::MeshRecord &mesh)
  {
    const auto state = states.find(sample.actuation.pressure);
    if (state == states.end())
      return {};
    const Links             own = links_at_state(geometry, sample, tip_fit, mesh);
    const Links            &at  = state->second;
    std::vector<LinkChange> changes;
    for (std::size_t i = 0; i + 1 < own.points.size(); ++i)
      changes.push_back({static_cast<int>(i) + 1, own.phi[i] - at.phi[i], own.psi[i] - at.psi[i],
                         (own.points[i + 1] - own.points[i]) - (at.points[i + 1] - at.points[i])});
    return changes;
  }

  // The links at rest (the reference) and at every pressure sample.
  std::map<double, Links> link_states(const reduction::JointGeometry &geometry,
                                      const std::vector<data::SampleRecord> &samples,
                                      const data::TipPoseFit &tip_fit, const data::MeshRecord &mesh)
  {
    std::map<double, Links> states{{0.0,
                                    {reduction::TwistAxis::reference_links(geometry, tip_fit.reference_centroid()),
                                     Eigen::Vector3d::Zero(), std::vector<double>(geometry.n_joints(), 0.0),
                                     std::vector<double>(geometry.n_joints(), 0.0)}}};
    for (const auto &s : samples)
      if (s.actuation.role == "pressure" && s.actuation.pressure > 0)
        states[s.actuation.pressure] = links_at_state(geometry, s, tip_fit, mesh);
    return states;
  }

  // The same chain on the links the chain tier takes at the sample's
  // pressure (its default link geometry): the reference at rest, the
  // pressure states' interpolated linearly between the two around it
  // (held beyond the last), the joints twisting about the axis t above them.
  Floor pressure_links_floor(const reduction::JointGeometry &geometry, const data::SampleRecord &sample,
                             const std::map<double, Links> &states, const data::TipPoseFit &tip_fit,
                             const data::MeshRecord &mesh, const double t)
  {
    const double p     = sample.actuation.pressure;
    auto         upper = states.lower_bound(p);
    Links        links = upper == states.end() ? std::prev(upper)->second : upper->second;
    if (upper != states.end() && upper->first != p && upper != states.begin())
      {
        const auto   lower = std::prev(upper);
        const double w     = (p - lower->first) / (upper->first - lower->first);
        for (std::size_t k = 0; k < links.points.size(); ++k)
          links.points[k] = (1 - w) * lower->second.points[k] + w * upper->second.points[k];
        links.tip_frame = (1 - w) * lower->second.tip_frame + w * upper->second.tip_frame;
      }
    const reduction::JointFrames frames(reduction::RotationMethod::affine_fit, geometry.slabs(),
                                        geometry.reference_points(), geometry.points(sample.x), sample.id);
    const auto            tip = reduction::TwistAxis::chain_tip(frames, links.points, t);
    const double          angle = links.tip_frame.norm();
    const Eigen::Matrix3d Q_T =
      angle > 0 ? Eigen::AngleAxisd(angle, links.tip_frame / angle).toRotationMatrix() : Eigen::Matrix3d::Identity();
    const data::TipPose fem = tip_fit.fit(data::select_nodes(sample.x, mesh.tip_nodes));
    return {(tip.position - fem.position).norm(), data::rotation_angle_between(tip.rotation * Q_T, fem.rotation)};
  }

  // The sample's kind in the tables: its role, a contact sample's by its
  // obstacle (a plane: blocked force; else grasp) and friction.
  std::string kind_of(const data::SampleRecord &sample)
  {
    const data::Actuation &a = sample.actuation;
    if (a.role != "contact" || a.obstacles.empty())
      return a.role;
    return std::string(a.obstacles.front().shape == "plane" ? "blocked force" : "grasp") +
           (a.obstacles.front().friction > 0.0 ? " with friction" : "");
  }

  // One sample's floors, one per model (column).
  struct Row
  {
    const data::SampleRecord *record;
    std::string               sample, kind;
    double                    pressure_kPa = 0, force_N = 0;
    std::vector<Floor>        floors;
  };

  // The tables' order: by kind (the order below, others after), pressure, force.
  bool before(const Row &a, const Row &b)
  {
    static const std::vector<std::string> kinds = {"pressure", "validation", "lateral", "torsion", "bending",
                                                   "chord", "blocked force", "blocked force with friction",
                                                   "grasp", "grasp with friction"};
    const auto rank = [&](const std::string &k) { return std::find(kinds.begin(), kinds.end(), k) - kinds.begin(); };
    return std::make_tuple(rank(a.kind), a.kind, a.pressure_kPa, a.force_N) <
           std::make_tuple(rank(b.kind), b.kind, b.pressure_kPa, b.force_N);
  }
} // namespace

int main(int argc, char **argv)
{
  if (argc < 2)
    {
      std::fprintf(stderr, "usage: %s DATABASE.h5 [joint spacing a = 0.01] [b/a = 0.5] [CSV [LINKS_CSV]]\n",
                   argv[0]);
      return 1;
    }
  const double a        = argc > 2 ? std::atof(argv[2]) : 0.01;
  const double fraction = argc > 3 ? std::atof(argv[3]) : 0.5;
  try
    {
      const auto  database = data::ActuationDatabase::open(argv[1]);
      const auto &mesh     = database.mesh();
      std::vector<data::SampleRecord>         samples;
      std::vector<const data::SampleRecord *> bending;
      for (const auto &id : database.sample_ids())
        if (auto s = database.read_sample(id); s.converged())
          samples.push_back(std::move(s));
      for (const auto &s : samples)
        if (s.actuation.role == "pressure" && s.actuation.pressure != 0)
          bending.push_back(&s);

      const reduction::JointLayout layout(mesh.X, a, 0, argv[1]);
      const auto body = std::make_shared<const reduction::BodySamples>(
        mesh, a / reduction::lattice_points_per_spacing, argv[1]);
      const reduction::NeutralLayer layer(body, layout, mesh, bending);
      const double                  bottom = body->reference_box().min()(1);
      const double                  length = body->reference_box().sizes()(0);
      std::printf("%s: %s\n", argv[1], layer.description().c_str());

      const reduction::JointGeometry paper(layout, mesh, fraction * a);
      const reduction::JointGeometry bottom_face(layout, body, bottom + 1e-6, fraction * a);
      const reduction::JointGeometry on_layer(layout, body, layer.height(), fraction * a);

      const data::TipPoseFit tip_fit = data::TipPoseFit::of_mesh(mesh, argv[1]);
      std::vector<const data::SampleRecord *> torsion;
      for (const auto &s : samples)
        if (s.actuation.role == "torsion")
          torsion.push_back(&s);
      // t on the reference links (no pressure states), as the reduction fits it.
      const reduction::TwistAxis axis(on_layer, mesh, torsion, body->reference_box().max()(1) - layer.height(),
                                      argv[1]);
      const double t = axis.offset();
      std::printf("%s\n", axis.description().c_str());

      // The models (columns): the CSV's name and the printed header.
      const std::vector<std::pair<std::string, std::string>> models = {
        {"paper", "paper: bounding-box centres"},
        {"bottom face", "bottom face"},
        {"layer", "strain-limiting layer"},
        {"moving base", "layer, chain from the deformed J_1"},
        {"twist axis", "layer, twist axis " + std::to_string(1e3 * t).substr(0, 4) + " mm higher"},
        {"chain links", "the same on the chain's links (pressure states)"}};
      const std::map<double, Links> states = link_states(on_layer, samples, tip_fit, mesh);
      std::vector<Row> rows;
      for (const auto &s : samples)
        {
          Row row{&s, s.id.substr(0, 8), kind_of(s), 1e-3 * s.actuation.pressure, 0, {}};
          for (const auto &f : s.actuation.point_forces)
            row.force_N += Eigen::Vector3d(f.force[0], f.force[1], f.force[2]).norm();
          row.floors = {floor_of(paper, s, tip_fit, mesh), floor_of(bottom_face, s, tip_fit, mesh),
                        floor_of(on_layer, s, tip_fit, mesh), floor_of(on_layer, s, tip_fit, mesh, true),
                        twist_axis_floor(on_layer, s, tip_fit, mesh, t),
                        pressure_links_floor(on_layer, s, states, tip_fit, mesh, t)};
          rows.push_back(row);
        }
      std::stable_sort(rows.begin(), rows.end(), before);

      std::printf("\ntip error of the chain driven by the FEM's M2 rotations (b = %.2f a), "
                  "%% of L = %.1f mm / deg\n\n| sample | kind | p [kPa] | |f| [N] |",
                  fraction, 1e3 * length);
      for (const auto &m : models)
        std::printf(" %s |", m.second.c_str());
      std::printf("\n| --- | --- | ---: | ---: |");
      for (std::size_t k = 0; k < models.size(); ++k)
        std::printf(" ---: |");
      std::printf("\n");
      for (const Row &r : rows)
        {
          std::printf("| %s | %s | %.0f | %.2f |", r.sample.c_str(), r.kind.c_str(), r.pressure_kPa, r.force_N);
          for (const Floor &f : r.floors)
            std::printf(" %.2f %% / %.1f |", 100 * f.position / length, chain::degrees(f.angle));
          std::printf("\n");
        }

      if (argc > 4)
        {
          std::ofstream csv(argv[4]);
          csv << "sample,kind,pressure_kPa,force_N,model,tip_percent_L,angle_deg\n";
          for (const Row &r : rows)
            for (std::size_t k = 0; k < models.size(); ++k)
              {
                char line[256];
                std::snprintf(line, sizeof line, "%s,%s,%.0f,%.2f,%s,%.2f,%.2f\n", r.sample.c_str(),
                              r.kind.c_str(), r.pressure_kPa, r.force_N, models[k].first.c_str(),
                              100 * r.floors[k].position / length, chain::degrees(r.floors[k].angle));
                csv << line;
              }
          if (!csv)
            throw std::runtime_error(std::string("cannot write ") + argv[4]);
          std::printf("\ntable written to %s\n", argv[4]);
        }
      if (argc > 5)
        {
          std::ofstream csv(argv[5]);
          csv << "sample,kind,pressure_kPa,force_N,link,turn_rad,dx_mm,dy_mm,dz_mm,twist_rad\n";
          for (const Row &r : rows)
            for (const LinkChange &c : link_changes(on_layer, *r.record, states, tip_fit, mesh))
              {
                char line[256];
                std::snprintf(line, sizeof line, "%s,%s,%.0f,%.2f,%d,%.3f,%.2f,%.2f,%.2f,%.3f\n", r.sample.c_str(),
                              r.kind.c_str(), r.pressure_kPa, r.force_N, c.link, c.turn, 1e3 * c.change.x(),
                              1e3 * c.change.y(), 1e3 * c.change.z(), c.twist);
                csv << line;
              }
          if (!csv)
            throw std::runtime_error(std::string("cannot write ") + argv[5]);
          std::printf("table written to %s\n", argv[5]);
        }
    }
  catch (const std::exception &e)
    {
      std::fprintf(stderr, "chain_kinematic_floor: %s\n", e.what());
      return 1;
    }
  return 0;
}
