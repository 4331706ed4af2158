// A joint whose twist axis passes through S_i above its centre J_i: read
// from the reduction's files as a joint that twists about S_i and bends
// about J_i, its equilibrium under a small tip force against the closed form
// of a straight chain, and its exact tangent against finite differences.
#include <softchain/chain/chain_equilibrium.h>
#include <softchain/chain/stiffness_files.h>

#include "../data/scratch_directory.h"
#include "central_differences.h"
#include "reduction_output.h"

#include <catch2/catch.hpp>

using namespace softchain::chain;
namespace data = softchain::data;
using softchain::chain::testing::UniformReduction;

namespace
{
  // Three joints at x = 5, 15, 25 mm on the axis; the tip point 6 mm above
  // the axis at x = 30 mm.
  UniformReduction three_joints(const double twist_height)
  {
    UniformReduction r;
    r.n            = 3;
    r.twist_height = twist_height;
    r.k            = {0.01, 0.05, 0.05}; // soft in torsion, as a hollow finger is
    return r;
  }
  const Eigen::Vector3d tip(0.03, 0.006, 0.0);

  // z displacement of the tip under the lateral tip force F e_z, to first
  // order in F: every twist joint turns by psi = (y_T - h) F / k_psi about
  // its axis at height h, every bending joint by
  // theta_i = -(x_T - x_i) F / k_theta about its y axis, and
  //   u_z = sum_i psi_i (y_T - h) - theta_i (x_T - x_i).
  double closed_form_uz(const UniformReduction &r, const double F)
  {
    double u = 0.0;
    for (int i = 0; i < r.n; ++i)
      {
        const double lever = tip.x() - (i + 0.5) * r.a;
        u += std::pow(tip.y() - r.twist_height, 2) * F / r.k[0] + lever * lever * F / r.k[1];
      }
    return u;
  }

  double chain_uz(const ChainModel &model, const double F)
  {
    ChainEquilibrium solver(model, EquilibriumSettings{});
    const Equilibrium e = solver.solve(ChainLoad{0.0, {{tip, Eigen::Vector3d(0, 0, F)}}});
    REQUIRE(e.converged);
    return solver.pose().tip_position.z() - tip.z();
  }
} // namespace

TEST_CASE("a joint with its own twist axis twists about S and bends about J")
{
  softchain::testing::ScratchDirectory dir("twist_joint");
  const StiffnessFiles files(dir.path().string(), data::RotationMethod::affine_fit, 0.5);
  const double         h = 0.004;
  const auto           r = three_joints(h);
  write_reduction(files, r);
  const ChainModel model = files.read_model("M2", tip, StiffnessColumn::value, true);
  REQUIRE(model.chain().n_joints() == 3);
  REQUIRE(model.chain().has_twist_offsets());
  for (int i = 0; i < 3; ++i)
    {
      CHECK(model.chain().joint_centre(i) == Eigen::Vector3d((i + 0.5) * r.a, 0, 0));
      CHECK(model.chain().twist_offset(i) == Eigen::Vector3d(0, h, 0));
      CHECK(model.stiffness().joint(i) == r.k);
    }
  // Turned by psi alone the joint's centre swings about its twist pivot S,
  // h above it: c = S + R_x(psi) (0, -h, 0) = J + (0, h (1 - cos psi), -h sin psi).
  ChainPose       pose = model.chain().rest_pose();
  Eigen::VectorXd q    = Eigen::VectorXd::Zero(9);
  q[0]                 = 0.3;
  model.chain().update_pose(q, pose);
  CHECK((pose.twist_pivots[0] - Eigen::Vector3d(0.5 * r.a, h, 0)).norm() < 1e-17);
  CHECK((pose.joint_positions[0] - Eigen::Vector3d(0.5 * r.a, h * (1 - std::cos(0.3)), -h * std::sin(0.3)))
          .norm() < 1e-17);

  // Without twist axis columns every joint twists about its centre; so does
  // every joint when the twist axes are not asked for.
  write_reduction(files, three_joints(0.0));
  CHECK_FALSE(files.read_model("M2", tip, StiffnessColumn::value, true).chain().has_twist_offsets());
  write_reduction(files, r);
  CHECK_FALSE(files.read_model("M2", tip, StiffnessColumn::value, true, true, false).chain().has_twist_offsets());
}

TEST_CASE("a small tip force twists the chain about the joints' twist axes, in closed form")
{
  softchain::testing::ScratchDirectory dir("twist_joint_force");
  const StiffnessFiles files(dir.path().string(), data::RotationMethod::affine_fit, 0.5);
  // F = 1e-5 N turns the joints by <= 1e-5 rad: the first-order closed form
  // holds to that relative size.
  const double F = 1e-5;
  for (const double h : {0.0, 0.004, 0.009})
    {
      INFO("twist axis " << h << " m above the joints");
      const auto r = three_joints(h);
      write_reduction(files, r);
      const double uz = chain_uz(files.read_model("M2", tip, StiffnessColumn::value, false), F);
      CHECK(uz == Approx(closed_form_uz(r, F)).epsilon(2e-5));
    }
  // The axis matters far beyond that tolerance: raised by 4 of the tip's
  // 6 mm, it cuts the twist's share of u_z by ((6 - 4) / 6)^2 = 1/9, here
  // from 37 % to 6 % of u_z.
  CHECK(closed_form_uz(three_joints(0.004), F) < 0.7 * closed_form_uz(three_joints(0.0), F));
}

TEST_CASE("with twist pivots the tangent is exact and the residual is the energy's gradient")
{
  // The chain_equilibrium_test.cc cases (soft joints, 1 N forces at and
  // between the joints, angles up to 0.4 rad) with twist axes 3-9 mm above
  // the joints and below them, and links shaped by the pressure: central
  // differences with h = 1e-5 err by 1e-8 of |H| (tangent) and of |r|
  // (gradient).
  const int                    n = 5;
  std::vector<Eigen::Vector3d> centres, offsets;
  for (int i = 0; i < n; ++i)
    {
      centres.emplace_back((i + 0.5) * 0.01, 0.0, 0.0);
      offsets.emplace_back(0.0, (i % 2 ? -1.0 : 1.0) * (0.003 + 0.0015 * i), 0.001 * i);
    }
  ChainModel model("twist pivots", KinematicChain(centres, {0.05, 0.004, 0}).with_twist_offsets(offsets),
                   JointStiffness(std::vector<Eigen::Vector3d>(n, {0.03, 0.01, 0.02})),
                   PressureActuation(Eigen::Vector3d(0.01, -0.02, 0.05).replicate(n, 1)));
  ChainEquilibrium solver(model);
  solver.set_load({0.5,
                   {{{0.022, 0.002, -0.001}, {0.2, -1.0, 0.3}},
                    {{0.05, 0.004, 0.0}, {-0.5, 0.1, 0.8}},
                    {{0.037, -0.003, 0.002}, {0.0, 0.7, -0.6}}}});
  Eigen::VectorXd q(3 * n);
  for (int j = 0; j < q.size(); ++j)
    q[j] = 0.4 * std::sin(2.3 * j + 1.0);
  const Eigen::MatrixXd tangent = solver.tangent(q);
  const auto            errors  = testing::derivative_errors(solver, q, 1e-5);
  CHECK(errors.tangent < 1e-8);
  CHECK(errors.gradient < 1e-8);
  // The pivots matter: the same chain about its joint centres has another tangent.
  ChainModel       centred("centred", KinematicChain(centres, {0.05, 0.004, 0}), model.stiffness(),
                           model.actuation());
  ChainEquilibrium plain(centred);
  plain.set_load({0.5, {{{0.05, 0.004, 0.0}, {-0.5, 0.1, 0.8}}}});
  solver.set_load({0.5, {{{0.05, 0.004, 0.0}, {-0.5, 0.1, 0.8}}}});
  CHECK((plain.tangent(q) - solver.tangent(q)).cwiseAbs().maxCoeff() > 1e-3 * tangent.cwiseAbs().maxCoeff());
}
