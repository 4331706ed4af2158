// StiffnessExtraction: below-threshold rotations give NaN (never inf) and
// are counted; the value at the largest load and the least-squares fit.
#include <softchain/data/joint_angles.h>
#include <softchain/reduction/joint_layout.h>
#include <softchain/reduction/method_reduction.h>
#include <softchain/reduction/stiffness_tables.h>

#include <catch2/catch.hpp>

#include <cmath>

#include "synthetic_finger.h"

using namespace softchain;
using namespace softchain::reduction;
using namespace softchain::testing;

namespace
{
  constexpr double a         = 10 * mm;
  constexpr double threshold = 0.0017453292519943296; // 0.1 deg, the default

  ReductionParameters parameters()
  {
    ReductionParameters p;
    p.joint_spacing      = a;
    p.rotation_threshold = threshold;
    p.pressure_roles     = {"pressure"};
    p.lateral_roles      = {"lateral"};
    p.torsion_roles      = {"torsion"};
    p.bending_roles      = {"bending"};
    return p;
  }

  // A pressure sample bent onto an arc of radius R (R = inf: undeformed).
  data::SampleRecord bent(const SyntheticFinger &finger, double pressure, double R,
                          const std::string &role = "pressure")
  {
    data::SampleRecord s;
    s.id                 = role + std::to_string(pressure);
    s.actuation.pressure = pressure;
    s.actuation.role     = role;
    s.x = std::isinf(R) ? finger.mesh.X : deform(finger.mesh.X, arc_about_z(R));
    return s;
  }

  MethodReduction reduce(const SyntheticFinger &finger, const std::vector<data::SampleRecord> &s,
                         const ReductionParameters &p = parameters())
  {
    const JointLayout layout(finger.mesh.X, a, 0, "synthetic");
    return MethodReduction(RotationMethod::affine_fit, 0.5, p,
                           JointGeometry(layout, finger.mesh, 0.5 * a), finger.mesh, s);
  }
} // namespace

TEST_CASE("a rotation below the threshold gives NaN stiffness, counted, never inf")
{
  const SyntheticFinger finger = hollow_box(uniform_planes(50 * mm, 50));
  // Undeformed (phi = 0 up to round-off) and bent by half the threshold per
  // joint (a / R = threshold / 2); both carry a nonzero pressure torque.
  const MethodReduction r =
    reduce(finger, {bent(finger, 1e4, INFINITY), bent(finger, 2e4, -a / (threshold / 2))});
  for (const auto &joint : r.stiffness().joints())
    {
      CHECK(std::isnan(joint.at_largest_load(2)));
      CHECK(std::isnan(joint.fit(2)));
      CHECK(joint.n_used[2] == 0);
    }
  CHECK(r.stiffness().n_below_threshold() == 2 * 5);
  CHECK(r.samples()[1].joints()[2].torque(2) != 0);
}

TEST_CASE("a joint that transmits no torque gives NaN stiffness, not 0 or a tiny number")
{
  // Solid base up to x = 1.5 cm: the whole closed cavity is distal to joint 1
  // (x = 0.5 cm), so the pressure's moment about it vanishes (a closed
  // surface's pressure has no net moment); joints 2.. carry torque.
  const SyntheticFinger finger = hollow_box(uniform_planes(50 * mm, 50), 15);
  const MethodReduction r      = reduce(finger, {bent(finger, 2e4, 0.2)});
  const auto           &joints = r.stiffness().joints();
  CHECK(std::abs(r.samples()[0].joints()[0].torque(2)) <
        1e-9 * std::abs(r.samples()[0].joints()[2].torque(2)));
  CHECK(std::isnan(joints[0].at_largest_load(2)));
  CHECK(std::isnan(joints[0].fit(2)));
  for (std::size_t j = 2; j < joints.size(); ++j) // (the arc's sign is arbitrary here)
    CHECK((std::isfinite(joints[j].at_largest_load(2)) && joints[j].at_largest_load(2) != 0));
}

TEST_CASE("k at the largest load and the least-squares fit over the usable samples")
{
  const SyntheticFinger finger = hollow_box(uniform_planes(50 * mm, 50));
  // Three pressure samples (the smallest below the threshold) and one
  // validation sample, which feeds no axis.
  const MethodReduction r = reduce(finger, {bent(finger, 3e4, -0.3), bent(finger, 1e4, -0.9),
                                            bent(finger, 5e2, -a / (threshold / 3)),
                                            bent(finger, 9e4, -0.1, "validation")});
  for (std::size_t i = 0; i < 5; ++i)
    {
      const JointStiffness &k = r.stiffness().joints()[i];
      const JointResult    &heavy = r.samples()[0].joints()[i];
      const JointResult    &light = r.samples()[1].joints()[i];
      CHECK(k.n_used[2] == 2);
      // Both are computed from the same doubles in the same order: equal.
      CHECK(k.at_largest_load(2) == heavy.torque(2) / heavy.angles.phi);
      const double fit = (heavy.torque(2) * heavy.angles.phi + light.torque(2) * light.angles.phi) /
                         (heavy.angles.phi * heavy.angles.phi + light.angles.phi * light.angles.phi);
      CHECK(k.fit(2) == Approx(fit).epsilon(1e-14)); // summation order may differ
      CHECK(std::isfinite(k.at_largest_load(2)));
      CHECK(k.at_largest_load(2) > 0); // inflation torque and bend agree in sign
      CHECK(std::isnan(k.at_largest_load(0))); // no torsion samples
    }
  CHECK(r.stiffness().n_below_threshold() == 5);
}

TEST_CASE("pressure tables: one row per joint and distinct nonzero pressure, rest first")
{
  const SyntheticFinger finger = hollow_box(uniform_planes(50 * mm, 50));
  // A pressure sample at p = 0 would repeat the rest rows; the chain tier
  // reads (pressure, joint) as a key.
  const MethodReduction r = reduce(finger, {bent(finger, 2e4, -0.3), bent(finger, 0, INFINITY),
                                            bent(finger, 1e4, -0.6)});
  const StiffnessTables tables(r, parameters());
  const auto            jp = tables.pressure_torque();
  REQUIRE(jp.n_rows() == 3 * 5);
  for (std::size_t row = 0; row < jp.n_rows(); ++row)
    CHECK(jp.number(row, "pressure") == std::vector<double>{0, 1e4, 2e4}[row / 5]);
  const auto kp = tables.kphi_vs_pressure();
  REQUIRE(kp.n_rows() == 2 * 5);
  CHECK(kp.number(0, "pressure") == 1e4);
}

TEST_CASE("a joint that transmits no torque passes its rotation on to the next joint")
{
  // The cavity starts at plane 12 (x = 12 mm): a closed cavity distal to
  // joint 1 (x = 5 mm), whose pressure has no net moment about it, like
  // P10's base fill. Bending onto an arc of radius R turns slab i by m_i / R
  // (m_i its middle): joint 1 reads 0, and joint 2 the whole m_2 / R from
  // the base, so that the chain, which holds joint 1 rigid, keeps it.
  const SyntheticFinger finger = hollow_box(uniform_planes(50 * mm, 50), 12);
  const double          R      = -0.3;
  const MethodReduction r      = reduce(finger, {bent(finger, 2e4, R)});
  const auto           &joints = r.samples().front().joints();
  CHECK(joints[0].torque.norm() <= 1e-6 * joints[1].torque.norm());
  CHECK(joints[0].angles.phi == 0);
  // b = a/2: slab middles at 5, 15 mm (rotations exact, joint_kinematics_test).
  CHECK(joints[1].angles.phi == Approx(15 * mm / R).epsilon(1e-10));
  CHECK(joints[2].angles.phi == Approx(10 * mm / R).epsilon(1e-10));
  CHECK(std::isnan(r.stiffness().joints()[0].at_largest_load(2))); // held rigid by the chain
}

TEST_CASE("a joint no pressure sample loads takes k_phi from the bending samples' increments")
{
  // Joint 1 (x = 5 mm) in the solid base fill: no pressure torque. The
  // pressure sample at 20 kPa bends the finger onto an arc of radius 0.4 m,
  // a bending sample at the same pressure (a tip force down) onto 0.25 m.
  // Joint 1's slab (paper placement, b = a/2, symmetric about x_1) turns by
  // x_1 / R, so its increment is x_1 (1/0.25 - 1/0.4) whatever the pressure
  // sample passed on to joint 2.
  const SyntheticFinger finger = hollow_box(uniform_planes(50 * mm, 50), 15);
  data::SampleRecord    loaded = bent(finger, 2e4, 0.25, "bending");
  loaded.actuation.point_forces  = {{{50 * mm, 0, 0}, {0, -0.2, 0}}};
  loaded.force_points_deformed   = {loaded.x.back()};
  const MethodReduction r        = reduce(finger, {bent(finger, 2e4, 0.4), loaded});
  const JointResult    &base     = r.samples()[0].joints()[0];
  const JointResult    &bending  = r.samples()[1].joints()[0];
  // The pressure sample: no torque at joint 1, its turn passed on.
  CHECK(base.angles.phi == 0.0);
  CHECK(base.free_angles.phi == Approx(5 * mm / 0.4).epsilon(1e-12));
  const double increment = 5 * mm * (1 / 0.25 - 1 / 0.4);
  CHECK(bending.angles.phi - base.free_angles.phi == Approx(increment).epsilon(1e-12));
  // k_phi of joint 1 from that increment; every other joint from pressure.
  const auto &k = r.stiffness();
  REQUIRE(k.phi_from_bending(0));
  CHECK(k.joints()[0].n_used[2] == 1);
  CHECK(k.joints()[0].at_largest_load(2) == Approx((bending.torque(2) - base.torque(2)) / increment).epsilon(1e-10));
  CHECK(k.joints()[0].fit(2) == Approx(k.joints()[0].at_largest_load(2)).epsilon(1e-14));
  CHECK(bending.torque(2) != 0.0);
  for (std::size_t j = 1; j < k.joints().size(); ++j)
    CHECK_FALSE(k.phi_from_bending(j));
  // The k_phi(p) table gets joint 1's row at the bending samples' pressure.
  const data::CsvTable table = StiffnessTables(r, parameters()).kphi_vs_pressure();
  int                  rows  = 0;
  for (std::size_t row = 0; row < table.n_rows(); ++row)
    if (table.number(row, "joint") == 1 && !std::isnan(table.number(row, "k_phi")))
      {
        ++rows;
        CHECK(table.number(row, "pressure") == 2e4);
        CHECK(table.number(row, "k_phi") == Approx(k.joints()[0].fit(2)).epsilon(1e-14));
      }
  CHECK(rows == 1);
  // Without a pressure-only state at its pressure a bending sample gives nothing.
  data::SampleRecord elsewhere = loaded;
  elsewhere.actuation.pressure = 3e4;
  const MethodReduction alone  = reduce(finger, {bent(finger, 2e4, 0.4), elsewhere});
  CHECK_FALSE(alone.stiffness().phi_from_bending(0));
  CHECK(alone.stiffness().force_increments(2).n_without_base() == 1);
}

TEST_CASE("k_theta(p) is fitted to the lightest lateral increments over the pressure-only state")
{
  // At 20 kPa the pressure-only sample bends the finger sideways onto an arc
  // about y of radius 1 m (as P10's helical threads turn its joints a little
  // about theta); lateral tip forces of 0.1, 0.2, 0.4 N onto 0.5, 0.25 and
  // 0.125 m. A joint past the first turns by a / R relative to its
  // neighbour, so the increments are a (1/R - 1/1) = a, 3 a, 7 a while the
  // forces double: each sample has another secant, and the fits differ.
  const SyntheticFinger finger = hollow_box(uniform_planes(50 * mm, 50), 15);
  data::SampleRecord base;
  base.id = "pressure";
  base.actuation.pressure = 2e4;
  base.actuation.role     = "pressure";
  base.x = deform(finger.mesh.X, arc_about_y(1.0));
  std::vector<data::SampleRecord> samples = {base};
  const double forces[] = {0.1, 0.2, 0.4}, radii[] = {0.5, 0.25, 0.125};
  for (int k = 0; k < 3; ++k)
    {
      data::SampleRecord s = base;
      s.id = "lateral" + std::to_string(k);
      s.actuation.role         = "lateral";
      s.actuation.point_forces = {{{50 * mm, 0, 0}, {0, 0, forces[k]}}};
      s.x = deform(finger.mesh.X, arc_about_y(radii[k]));
      s.force_points_deformed = {s.x.back()};
      samples.push_back(s);
    }
  ReductionParameters two = parameters(), all = parameters();
  two.force_samples_per_fit = 2;
  all.force_samples_per_fit = 0;
  const MethodReduction lightest = reduce(finger, samples); // the default: the lightest one
  const MethodReduction pair     = reduce(finger, samples, two);
  const MethodReduction every    = reduce(finger, samples, all);
  const std::size_t     joint    = 2;
  const JointResult    &b        = lightest.samples()[0].joints()[joint];
  // The least-squares fit sum(d tau d theta) / sum(d theta^2) over samples 1..n.
  const auto fit_of_first = [&](int n) {
    double sum_tau_angle = 0, sum_angle_squared = 0;
    for (int k = 1; k <= n; ++k)
      {
        const JointResult &r = lightest.samples()[k].joints()[joint];
        const double d_angle = r.angles.theta - b.free_angles.theta;
        sum_tau_angle += (r.torque(1) - b.torque(1)) * d_angle;
        sum_angle_squared += d_angle * d_angle;
      }
    return sum_tau_angle / sum_angle_squared;
  };
  // The increments are the arcs' (exact for the affine fit), not the totals.
  CHECK(lightest.samples()[1].joints()[joint].angles.theta - b.angles.theta ==
        Approx(a * (1 / 0.5 - 1 / 1.0)).epsilon(1e-10));
  CHECK(b.angles.theta == Approx(a / 1.0).epsilon(1e-10)); // the pressure's share, not charged to the force
  const auto k_at = [&](const MethodReduction &r) -> double {
    const data::CsvTable table = StiffnessTables(r, parameters()).k_vs_pressure(1);
    for (std::size_t row = 0; row < table.n_rows(); ++row)
      if (table.number(row, "joint") == joint + 1 && table.number(row, "pressure") == 2e4)
        return table.number(row, "k_theta");
    return NAN;
  };
  CHECK(k_at(lightest) == Approx(fit_of_first(1)).epsilon(1e-12));
  CHECK(k_at(pair) == Approx(fit_of_first(2)).epsilon(1e-12));
  CHECK(k_at(every) == Approx(fit_of_first(3)).epsilon(1e-12));
  // The choice matters here: each fit differs from the next by over 10 %.
  CHECK(std::abs(fit_of_first(1) / fit_of_first(2) - 1) > 0.1);
  CHECK(std::abs(fit_of_first(2) / fit_of_first(3) - 1) > 0.1);
}

TEST_CASE("k_psi(p) leaves out joints whose torque lies mostly about another axis")
{
  // At rest (the pressure-only state at p = 0), a torsion sample twisted at
  // 2 rad/m about the centroid axis and loaded by one force along z at the
  // tip's top, 5 mm above that axis: joint i carries tau = r_i x f with
  // r_i = (x_tip - x_i, 5 mm, 0), so tau_x / |tau| = 5 mm / |r_i| falls
  // from the tip to the base. Joints where it is below a quarter turn
  // about psi by their coupling, not their torque (ForceIncrementStiffness).
  const SyntheticFinger finger = hollow_box(uniform_planes(50 * mm, 50));
  const double          y_c    = finger.node_centroid_y();
  data::SampleRecord    s;
  s.id                     = "torsion";
  s.actuation.role         = "torsion";
  s.actuation.point_forces = {{{50 * mm, y_c + 5 * mm, 0}, {0, 0, 0.1}}};
  s.x                      = deform(finger.mesh.X, twist_about_x(2.0, y_c));
  const Eigen::Vector3d q  = twist_about_x(2.0, y_c)(Eigen::Vector3d(50 * mm, y_c + 5 * mm, 0));
  s.force_points_deformed  = {{q(0), q(1), q(2)}};
  const MethodReduction reduction = reduce(finger, {s});
  const data::CsvTable  table     = StiffnessTables(reduction, parameters()).k_vs_pressure(0);
  int                   with_k = 0, without_k = 0;
  for (std::size_t row = 0; row < table.n_rows(); ++row)
    {
      const std::size_t  joint = static_cast<std::size_t>(table.number(row, "joint")) - 1;
      const JointResult &r     = reduction.samples()[0].joints()[joint];
      const double share = std::abs(r.torque(0)) / std::hypot(r.torque(0), r.torque(1), r.torque(2));
      const double k     = table.number(row, "k_psi");
      CAPTURE(joint, share, k);
      if (share >= 0.25 && std::abs(r.angles.psi) >= threshold)
        {
          CHECK(k == Approx(r.torque(0) / r.angles.psi).epsilon(1e-12));
          ++with_k;
        }
      else
        {
          CHECK(std::isnan(k));
          ++without_k;
        }
    }
  // Both kinds occur: joints within 5 mm / 0.25 of the tip's force keep a k.
  CHECK(with_k > 0);
  CHECK(without_k > 0);
}
