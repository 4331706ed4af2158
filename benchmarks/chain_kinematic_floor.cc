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
// that chain on the links the chain tier uses by default: those of the
// pressure state at the sample's pressure (the reduction's link geometry,
// with the tip face's frame in the last link's), where the pressure states
// are exact by construction; it is the floor of the chain as it runs.
//
// Run: chain_kinematic_floor DATABASE.h5 [a = 0.01] [b/a = 0.5]
#include <softchain/chain/angle_units.h>
#include <softchain/chain/kinematic_chain.h>
#include <softchain/data/tip_pose_fit.h>
#include <softchain/data/actuation_database.h>
#include <softchain/reduction/joint_geometry.h>
#include <softchain/reduction/neutral_layer.h>
#include <softchain/reduction/twist_axis.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
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

  // The same chain on the links of the pressure state at the sample's
  // pressure (the chain tier's default link geometry), the joints twisting
  // about the axis t above them; NaN where no pressure state was solved at
  // that pressure.
  Floor pressure_links_floor(const reduction::JointGeometry &geometry, const data::SampleRecord &sample,
                             const std::vector<data::SampleRecord> &samples, const data::TipPoseFit &tip_fit,
                             const data::MeshRecord &mesh, const double t)
  {
    const auto frames_of = [&](const data::SampleRecord &s) {
      return reduction::JointFrames(reduction::RotationMethod::affine_fit, geometry.slabs(),
                                    geometry.reference_points(), geometry.points(s.x), s.id);
    };
    const data::SampleRecord *state = nullptr;
    for (const auto &s : samples)
      if (s.actuation.role == "pressure" && s.actuation.pressure == sample.actuation.pressure)
        state = &s;
    if (sample.actuation.pressure == 0.0 || state == nullptr)
      return sample.actuation.pressure == 0.0 ? twist_axis_floor(geometry, sample, tip_fit, mesh, t)
                                              : Floor{NAN, NAN};
    const reduction::JointFrames state_frames = frames_of(*state);
    const data::TipPose          state_tip    = tip_fit.fit(data::select_nodes(state->x, mesh.tip_nodes));
    const auto links = reduction::TwistAxis::links_of(geometry, state_frames, state->x, state_tip.position);
    // The tip face's frame in the last link's, Q_T = R_n^T R_T, as the chain carries it.
    const Eigen::Matrix3d Q_T = state_frames[state_frames.size() - 1].rotation.transpose() * state_tip.rotation;
    const auto            tip = reduction::TwistAxis::chain_tip(frames_of(sample), links, t);
    const data::TipPose   fem = tip_fit.fit(data::select_nodes(sample.x, mesh.tip_nodes));
    return {(tip.position - fem.position).norm(), data::rotation_angle_between(tip.rotation * Q_T, fem.rotation)};
  }
} // namespace

int main(int argc, char **argv)
{
  if (argc < 2)
    {
      std::fprintf(stderr, "usage: %s DATABASE.h5 [joint spacing a = 0.01] [b/a = 0.5]\n", argv[0]);
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

      struct Placement
      {
        std::string              name;
        reduction::JointGeometry geometry;
      };
      std::vector<Placement> placements;
      placements.push_back({"paper: bounding-box centres", {layout, mesh, fraction * a}});
      placements.push_back({"bottom face", {layout, body, bottom + 1e-6, fraction * a}});
      placements.push_back({"strain-limiting layer", {layout, body, layer.height(), fraction * a}});
      const std::size_t layer_index = placements.size() - 1;

      const data::TipPoseFit tip_fit = data::TipPoseFit::of_mesh(mesh, argv[1]);
      std::vector<const data::SampleRecord *> torsion;
      for (const auto &s : samples)
        if (s.actuation.role == "torsion")
          torsion.push_back(&s);
      const reduction::TwistAxis axis(placements[layer_index].geometry, mesh, torsion,
                                      body->reference_box().max()(1) - layer.height(), argv[1]);
      const double twist_offset = axis.offset();
      std::printf("%s\n", axis.description().c_str());
      std::printf("\ntip error of the chain driven by the FEM's M2 rotations (b = %.2f a), "
                  "%% of L = %.1f mm / deg\n\n",
                  fraction, 1e3 * length);
      std::printf("| sample | role | p [kPa] | |f| [N] |");
      for (const auto &p : placements)
        std::printf(" %s |", p.name.c_str());
      std::printf(" layer, chain from the deformed J_1 | layer, twist axis %.2f mm higher |"
                  " the same on the pressure state's links |",
                  1e3 * twist_offset);
      std::printf("\n| --- | --- | ---: | ---: |");
      for (std::size_t k = 0; k <= placements.size() + 2; ++k)
        std::printf(" ---: |");
      std::printf("\n");
      std::vector<Floor> worst(placements.size() + 3, {0, 0});
      for (const auto &s : samples)
        {
          double force = 0;
          for (const auto &f : s.actuation.point_forces)
            force += Eigen::Vector3d(f.force[0], f.force[1], f.force[2]).norm();
          std::printf("| %s | %s | %.0f | %.2f |", s.id.substr(0, 8).c_str(),
                      s.actuation.role.c_str(), 1e-3 * s.actuation.pressure, force);
          for (std::size_t k = 0; k <= placements.size(); ++k)
            {
              const bool  moving_base = k == placements.size();
              const Floor f = floor_of(placements[moving_base ? layer_index : k].geometry, s, tip_fit,
                                       mesh, moving_base);
              worst[k]      = {std::max(worst[k].position, f.position), std::max(worst[k].angle, f.angle)};
              std::printf(" %.2f %% / %.1f |", 100 * f.position / length, chain::degrees(f.angle));
            }
          const Floor f = twist_axis_floor(placements[layer_index].geometry, s, tip_fit, mesh, twist_offset);
          Floor &twisted = worst[placements.size() + 1];
          twisted        = {std::max(twisted.position, f.position), std::max(twisted.angle, f.angle)};
          std::printf(" %.2f %% / %.1f |", 100 * f.position / length, chain::degrees(f.angle));
          const Floor g = pressure_links_floor(placements[layer_index].geometry, s, samples, tip_fit, mesh,
                                               twist_offset);
          if (std::isfinite(g.position))
            worst.back() = {std::max(worst.back().position, g.position), std::max(worst.back().angle, g.angle)};
          std::printf(" %.2f %% / %.1f |", 100 * g.position / length, chain::degrees(g.angle));
          std::printf("\n");
        }
      std::printf("| max | | | |");
      for (const Floor &f : worst)
        std::printf(" %.2f %% / %.1f |", 100 * f.position / length, chain::degrees(f.angle));
      std::printf("\n");
    }
  catch (const std::exception &e)
    {
      std::fprintf(stderr, "chain_kinematic_floor: %s\n", e.what());
      return 1;
    }
  return 0;
}
