// A joint whose twist axis passes through S_i above its centre J_i: read
// from the reduction's files as a twist joint at S_i and a bending joint at
// J_i, and its equilibrium under a small tip force against the closed form
// of a straight chain.
#include <softchain/chain/chain_equilibrium.h>
#include <softchain/chain/stiffness_files.h>

#include "../data/scratch_directory.h"
#include "reduction_output.h"

#include <catch2/catch.hpp>

using namespace softchain::chain;
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

TEST_CASE("a joint with its own twist axis becomes a twist joint at S and a bending joint at J")
{
  softchain::testing::ScratchDirectory dir("twist_joint");
  const StiffnessFiles files(dir.path().string(), "M2", 0.5);
  const double         h = 0.004;
  const auto           r = three_joints(h);
  write_reduction(files, r);
  const ChainModel model = files.read_model("M2", tip, "value", true);
  REQUIRE(model.chain().n_joints() == 6);
  for (int i = 0; i < 3; ++i)
    {
      const double x = (i + 0.5) * r.a;
      CHECK(model.is_twist_joint(2 * i));
      CHECK_FALSE(model.is_twist_joint(2 * i + 1));
      CHECK((model.chain().joint_centre(2 * i) - Eigen::Vector3d(x - 1e-9, h, 0)).norm() < 1e-15);
      CHECK((model.chain().joint_centre(2 * i + 1) - Eigen::Vector3d(x, 0, 0)).norm() < 1e-15);
      // The twist joint takes k_psi, the bending joint k_theta and k_phi;
      // the other axes are rigid (1e6 x the axis' largest k).
      CHECK(model.stiffness().joint(2 * i) == Eigen::Vector3d(r.k[0], 1e6 * r.k[1], 1e6 * r.k[2]));
      CHECK(model.stiffness().joint(2 * i + 1) == Eigen::Vector3d(1e6 * r.k[0], r.k[1], r.k[2]));
    }
  // J_p: psi's on the twist joint, theta's and phi's on the bending joint.
  const Eigen::VectorXd jp = model.actuation().rest_torque_per_pascal();
  CHECK(jp.segment<3>(0) == Eigen::Vector3d(r.jp[0], 0, 0));
  CHECK(jp.segment<3>(3) == Eigen::Vector3d(0, r.jp[1], r.jp[2]));

  // Without twist axis columns a joint stays one spherical joint; so does
  // every joint when the twist axes are not asked for.
  write_reduction(files, three_joints(0.0));
  CHECK(files.read_model("M2", tip, "value", true).chain().n_joints() == 3);
  write_reduction(files, r);
  CHECK(files.read_model("M2", tip, "value", true, true, false).chain().n_joints() == 3);
}

TEST_CASE("a small tip force twists the chain about the joints' twist axes, in closed form")
{
  softchain::testing::ScratchDirectory dir("twist_joint_force");
  const StiffnessFiles files(dir.path().string(), "M2", 0.5);
  // F = 1e-5 N turns the joints by <= 1e-5 rad: the first-order closed form
  // holds to that relative size; the rigid axes (1e6 x k) add 1e-6.
  const double F = 1e-5;
  for (const double h : {0.0, 0.004, 0.009})
    {
      INFO("twist axis " << h << " m above the joints");
      const auto r = three_joints(h);
      write_reduction(files, r);
      const double uz = chain_uz(files.read_model("M2", tip, "value", false), F);
      CHECK(uz == Approx(closed_form_uz(r, F)).epsilon(2e-5));
    }
  // The axis matters far beyond that tolerance: raised by 4 of the tip's
  // 6 mm, it cuts the twist's share of u_z by ((6 - 4) / 6)^2 = 1/9, here
  // from 37 % to 6 % of u_z.
  CHECK(closed_form_uz(three_joints(0.004), F) < 0.7 * closed_form_uz(three_joints(0.0), F));
}
