// run_reduction end to end on a synthetic database: pressure samples bent
// onto arcs, torsion samples twisted and loaded by a couple, a lateral
// sample bent about y and loaded by a couple, a validation sample and a
// failed one. The CSV files are checked against closed-form k = tau / angle.
//
// Tolerance: 1e-10 relative. The angles are exact to ~1e-13 rad
// (joint_kinematics_test.cc) on angles >= 0.01 rad, the torques are sums of
// a few hundred products (~1e-13 relative), and the CSV keeps 17 digits.
#include <softchain/data/actuation_database.h>
#include <softchain/data/csv_table.h>
#include <softchain/data/input_error.h>
#include <softchain/reduction/reduction_run.h>

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <sys/wait.h>
#include <unistd.h>

#include "../data/scratch_directory.h"
#include "synthetic_finger.h"

using namespace softchain;
using namespace softchain::testing;
using data::CsvTable;

namespace
{
  constexpr double a         = 10 * mm;
  constexpr double L         = 50 * mm;
  constexpr double d         = 4 * mm; // half distance of the couples' points
  constexpr double relative  = 1e-10;  // see the header comment
  const std::string hash     = "synthetic";

  // Pressure p bends onto an arc of radius R(p) = -5e3 Pa m / p (curvature
  // proportional to p, towards -y).
  double radius_at(double p) { return -5e3 / p; }

  // Two opposite forces +-f at the tip points (L, y_c, +-d).
  std::vector<data::PointForce> couple(double y_c, const Eigen::Vector3d &f)
  {
    return {{{L, y_c, d}, {f(0), f(1), f(2)}}, {{L, y_c, -d}, {-f(0), -f(1), -f(2)}}};
  }

  data::SampleRecord sample(const SyntheticFinger &finger, const std::string &role, double p,
                            const std::vector<data::PointForce> &forces, const Map &map)
  {
    data::SampleRecord s;
    s.actuation.pressure     = p;
    s.actuation.role         = role;
    s.actuation.point_forces = forces;
    s.id                     = data::sample_id(hash, s.actuation);
    s.x                      = deform(finger.mesh.X, map);
    for (const auto &f : forces)
      {
        const Eigen::Vector3d q = map(Eigen::Vector3d(f.point.data()));
        s.force_points_deformed.push_back({q(0), q(1), q(2)});
      }
    return s;
  }

  // Moment about the origin of the deformed couple (independent of the
  // reference point because the forces sum to zero).
  Eigen::Vector3d couple_moment(const std::vector<data::PointForce> &forces, const Map &map)
  {
    Eigen::Vector3d m = Eigen::Vector3d::Zero();
    for (const auto &f : forces)
      m += map(Eigen::Vector3d(f.point.data())).cross(Eigen::Vector3d(f.force.data()));
    return m;
  }

  // The nodes of the face x = L as the tip face (for the contact table's tip pose).
  SyntheticFinger with_tip_face(SyntheticFinger finger)
  {
    for (std::size_t n = 0; n < finger.mesh.X.size(); ++n)
      if (std::abs(finger.mesh.X[n][0] - L) < 1e-12)
        finger.mesh.tip_nodes.push_back(n);
    return finger;
  }

  struct Scenario
  {
    SyntheticFinger finger = with_tip_face(hollow_box(uniform_planes(L, 100)));
    double          y_c    = finger.node_centroid_y();
    // torsion: (force, twist rate); lateral: force and radius.
    std::vector<std::pair<double, double>> torsion = {{0.1, 2.0}, {0.2, 4.0}};
    double lateral_force = 0.3, lateral_radius = 0.3;
    std::vector<double> pressures = {1e4, 2e4};

    std::vector<data::PointForce> twist_couple(double F) const
    {
      return couple(y_c, {0, -F, 0});
    }
    std::vector<data::PointForce> lateral_couple() const
    {
      return couple(y_c, {-lateral_force, 0, 0});
    }

    // A finger bent like the pressure samples onto an obstacle, which
    // receives (0, -p / 1e5, 0) N: a contact sample, which the extraction
    // must leave out (its torques would need the contact forces).
    data::SampleRecord contact_sample(double p, const std::string &obstacle) const
    {
      data::SampleRecord s = sample(finger, "contact", p, {}, arc_about_z(radius_at(p)));
      s.actuation.obstacles   = {{obstacle, "plane", {0, -0.01, 0}, {0, 1, 0}, 0, {}, 0, {}}};
      s.actuation.contact_law = "synthetic";
      s.id                    = data::sample_id(hash, s.actuation);
      s.obstacle_wrenches     = {{{0, -p / 1e5, 0}, {0, 0, -L * p / 1e5}}};
      return s;
    }

    // Stores the samples not yet in the database at `path`, like a sweep.
    void write_database(const std::string &path) const
    {
      data::DesignRecord design{"synthetic box", hash, "Q1", "test", ""};
      auto db    = data::ActuationDatabase::open_or_create(path, design, finger.mesh);
      auto store = [&db](const data::SampleRecord &s) {
        if (!db.has_sample(s.id))
          db.store_sample(s);
      };
      for (const double p : pressures)
        store(sample(finger, "pressure", p, {}, arc_about_z(radius_at(p))));
      for (const auto &[F, kappa] : torsion)
        store(sample(finger, "torsion", 0, twist_couple(F), twist_about_x(kappa, y_c)));
      store(sample(finger, "lateral", 0, lateral_couple(), arc_about_y(lateral_radius)));
      store(sample(finger, "validation", 3e4, {}, arc_about_z(0.2)));
      for (const double p : {2e4, 1e4}) // against the alphabet and the pressure: sorted on output
        for (const auto &obstacle : {"wall", "table"})
          store(contact_sample(p, obstacle));
      data::SampleRecord failed = sample(finger, "pressure", 9e4, {}, arc_about_z(0.05));
      failed.status             = data::SampleStatus::failed;
      failed.reason             = "synthetic failure";
      store(failed);
    }
  };

  std::string write_prm(const ScratchDirectory &dir, const std::string &reduction_body)
  {
    std::ofstream(dir.file("finger.prm"))
      << "subsection Finger design\n  set Length = 0.05\nend\n"
      << "subsection Reduction\n" << reduction_body << "end\n";
    return dir.file("finger.prm");
  }

  // The paper's placement: its closed forms below are the bounding-box
  // centres' (the synthetic finger is a node cloud without cells).
  // Every force sample in the per-pressure fits, so that at p = 0 they equal
  // the main table's least squares (the _fit columns).
  const std::string good_prm = "  set Joint placement = paper\n"
                               "  set Force samples per fit = 0\n"
                               "  set Joint spacing = 0.01\n"
                               "  set Slab half-widths = 1, 0.5\n"
                               "  set Methods = M1, M2\n"
                               "  set Plots = true\n";

  // Middle m_i of joint i's slab along x (= J_i,0,x): the planes lie every
  // half millimetre and x_i +- b falls on planes, so the slab spans
  // [max(0, x_i - b), min(L, x_i + b)]; m_0 = 0. The middles fall on planes
  // too (7.5 mm for joint 1 with b = a), so the section through J_i meets
  // the deformed cavity at mapped nodes, where its polyhedral wall has no
  // chord error.
  double middle(int i, double b)
  {
    const double x_i = (i - 0.5) * a;
    return i == 0 ? 0.0 : 0.5 * (std::max(0.0, x_i - b) + std::min(L, x_i + b));
  }

  // The relative rotation of joint i is (m_i - m_{i-1}) times the curvature
  // or twist rate (joint_kinematics_test.cc): a for inner slabs, less for the
  // slabs cut by the base or the tip face.
  double step(int i, double b)
  {
    return middle(i, b) - middle(i - 1, b);
  }

  // k_phi of joint i (1-based) at pressure p, from the closed forms: the
  // joint frame is Rz(m_i / R) for both methods; the section through the
  // deformed centre J_i cuts the cavity where its cross-section is the
  // reference one (area A, centroid 1 mm above the axis in the joint frame);
  // J_i sits at height R (1 - mean_j cos((X_j - m_i) / R)) above the axis in
  // that frame (the affine fit of y' = Y cos(s/R) + R (1 - cos(s/R)) over the
  // slab's product node set); hence J_p,z = -A (1 mm - that height) and
  // k_phi = p J_p,z / phi with phi = (m_i - m_{i-1}) / R.
  double closed_form_kphi(const Scenario &s, int i, double b, double p)
  {
    const double R   = radius_at(p);
    const double m_i = middle(i, b);
    double       sum = 0;
    int          n   = 0;
    for (const auto &X : s.finger.mesh.X)
      if (std::abs(X[0] - (i - 0.5) * a) <= b * (1 + 1e-9))
        {
          sum += std::cos((X[0] - m_i) / R);
          ++n;
        }
    const double centre_height = R * (1 - sum / n);
    const double jp_z          = -cavity_area * (cavity_centroid_y - centre_height);
    return p * jp_z / (step(i, b) / R);
  }

  void check_relative(const CsvTable &table, std::size_t row, const std::string &column,
                      double want)
  {
    INFO("row " << row + 1 << ", column " << column);
    CHECK(table.number(row, column) == Approx(want).epsilon(relative));
  }
} // namespace

TEST_CASE("run_reduction end to end on a synthetic database")
{
  ScratchDirectory dir("reduction_run");
  const Scenario   s;
  s.write_database(dir.file("database.h5"));
  const std::string prm = write_prm(dir, good_prm);
  const auto summary = reduction::ReductionRun(data::PrmFile::read(prm), dir.file("database.h5"), dir.file("out")).run();
  CHECK(summary.n_samples_used == 6); // not the contact samples
  CHECK(summary.n_failed_skipped == 1);
  // The contact samples' table: by obstacle, then pressure; the tip turned
  // by L / |R| about z (an arc of radius R), the wrench as stored.
  const CsvTable contact = CsvTable::read(dir.file("out/contact/contact_forces.csv"));
  REQUIRE(contact.n_rows() == 4);
  for (std::size_t r = 0; r < 4; ++r)
    {
      const double p = r % 2 ? 2e4 : 1e4;
      CHECK(contact.text(r, "obstacle") == (r < 2 ? "table" : "wall"));
      CHECK(contact.number(r, "pressure") == p);
      CHECK(contact.number(r, "force_y") == -p / 1e5);
      CHECK(contact.number(r, "force_norm") == Approx(p / 1e5).epsilon(1e-15));
      CHECK(contact.number(r, "moment_z") == -L * p / 1e5);
      CHECK(contact.text(r, "status") == "converged");
      // Kabsch's rotation of the exactly rotated tip face: to ~1e-12 rad.
      CHECK(contact.number(r, "tip_angle_deg") == Approx(L / std::abs(radius_at(p)) * 180 / M_PI).epsilon(1e-9));
    }
  CHECK(summary.n_below_threshold == 0);
  CHECK(reduction::run_reduction(data::PrmFile::read(prm), dir.file("database.h5"), dir.file("out")) == 0);

  for (const std::string method : {"M1", "M2"})
    for (const auto &[b, f] : {std::pair{a, "1.00"}, std::pair{a / 2, "0.50"}})
      {
        const std::string stem = dir.file("out/stiffness/" + method + "_b" + f + "a");
        const CsvTable    k    = CsvTable::read(stem + ".csv");
        CHECK(k.columns() == std::vector<std::string>{"joint", "x_ref", "Jx", "Jy", "Jz", "Sx", "Sy",
                                                       "Sz", "k_psi", "k_theta", "k_phi", "k_psi_fit",
                                                       "k_theta_fit", "k_phi_fit", "n_psi",
                                                       "n_theta", "n_phi"});
        REQUIRE(k.n_rows() == 5);
        for (int i = 1; i <= 5; ++i)
          {
            const std::size_t row     = i - 1;
            const double      x_i     = (i - 0.5) * a;
            CHECK(k.number(row, "joint") == i);
            check_relative(k, row, "x_ref", x_i);
            check_relative(k, row, "Jx", middle(i, b));
            check_relative(k, row, "k_phi", closed_form_kphi(s, i, b, 2e4));
            // Fit over p = 1e4, 2e4 with the closed-form tau and phi.
            double tau_phi = 0, phi_phi = 0;
            for (const double p : s.pressures)
              {
                const double phi = step(i, b) / radius_at(p);
                tau_phi += closed_form_kphi(s, i, b, p) * phi * phi;
                phi_phi += phi * phi;
              }
            check_relative(k, row, "k_phi_fit", tau_phi / phi_phi);
            // Torsion: a couple of moment 2 d F cos(kappa L) about x, twist
            // psi = kappa step; at the largest load F = 0.2 N, kappa = 4 /m.
            const auto [F, kappa] = s.torsion.back();
            check_relative(k, row, "k_psi",
                           2 * d * F * std::cos(kappa * L) / (kappa * step(i, b)));
            // Lateral: the couple's moment in the joint frame Ry(m_i / R).
            const Map             arc = arc_about_y(s.lateral_radius);
            const double          R   = s.lateral_radius;
            const Eigen::Vector3d tau =
              Eigen::AngleAxisd(middle(i, b) / R, Eigen::Vector3d::UnitY()).inverse() *
              couple_moment(s.lateral_couple(), arc);
            check_relative(k, row, "k_theta", tau(1) / (step(i, b) / R));
            CHECK(k.number(row, "n_phi") == 2);
            CHECK(k.number(row, "n_psi") == 2);
            CHECK(k.number(row, "n_theta") == 1);
          }

        const CsvTable samples = CsvTable::read(stem + "_samples.csv");
        CHECK(samples.columns() ==
              std::vector<std::string>{"sample", "role", "pressure", "force_norm", "joint", "psi",
                                       "theta", "phi", "tau_x", "tau_y", "tau_z", "stretch_1",
                                       "stretch_2", "stretch_3"});
        REQUIRE(samples.n_rows() == 6 * 5);
        for (std::size_t r = 0; r < samples.n_rows(); ++r)
          CHECK(std::isnan(samples.number(r, "stretch_1")) == (method == "M1"));

        const CsvTable kp = CsvTable::read(stem + "_kphi_vs_pressure.csv");
        CHECK(kp.columns() == std::vector<std::string>{"pressure", "joint", "k_phi"});
        REQUIRE(kp.n_rows() == 2 * 5);
        for (std::size_t r = 0; r < kp.n_rows(); ++r)
          check_relative(kp, r, "k_phi",
                         closed_form_kphi(s, int(kp.number(r, "joint")), b, kp.number(r, "pressure")));

        // The lateral and torsion samples all lie at p = 0: one row per
        // joint, their least-squares k over all of them (Force samples per
        // fit = 0), the fit columns above.
        for (const auto &[file, column] : {std::pair{"_ktheta_vs_pressure.csv", "k_theta"},
                                           std::pair{"_kpsi_vs_pressure.csv", "k_psi"}})
          {
            const CsvTable kp_force = CsvTable::read(stem + file);
            CHECK(kp_force.columns() == std::vector<std::string>{"pressure", "joint", column});
            REQUIRE(kp_force.n_rows() == 5);
            for (std::size_t r = 0; r < kp_force.n_rows(); ++r)
              {
                CHECK(kp_force.number(r, "pressure") == 0);
                check_relative(kp_force, r, column, k.number(r, std::string(column) + "_fit"));
              }
          }

        const CsvTable jp = CsvTable::read(stem + "_pressure_torque.csv");
        CHECK(jp.columns() == std::vector<std::string>{"pressure", "joint", "jp_x", "jp_y", "jp_z"});
        REQUIRE(jp.n_rows() == 3 * 5);
        for (std::size_t r = 0; r < 5; ++r) // the rest configuration comes first
          {
            CHECK(jp.number(r, "pressure") == 0);
            check_relative(jp, r, "jp_z", -cavity_area * cavity_centroid_y);
          }
      }
  if (summary.plots_drawn)
    CHECK(std::filesystem::file_size(dir.file("out/stiffness/kphi_methods_and_b.png")) > 0);
  CHECK(std::filesystem::exists(dir.file("out/stiffness/plots.gp")));
}

namespace
{
  // Writes the scenario's database in a child process that the data layer's
  // test hook (actuation_database.h) kills while it stores sample k.
  bool writer_killed_in_store(const Scenario &s, const std::string &path, int k)
  {
    const pid_t child = ::fork();
    if (child == 0)
      {
        ::setenv("SOFTCHAIN_TEST_KILL_IN_STORE", std::to_string(k).c_str(), 1);
        try
          {
            s.write_database(path);
          }
        catch (...)
          {
          }
        ::_exit(0);
      }
    int status = 0;
    ::waitpid(child, &status, 0);
    return WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL;
  }

  std::string content(const std::filesystem::path &file)
  {
    std::ostringstream text;
    text << std::ifstream(file).rdbuf();
    return text.str();
  }
} // namespace

TEST_CASE("run_reduction on a database built by killed and resumed writers equals the uninterrupted")
{
  ScratchDirectory dir("reduction_interrupted");
  const Scenario   s;
  s.write_database(dir.file("whole.h5"));
  for (int k = 1; k <= 3; ++k) // each writer stores one sample, then is killed
    REQUIRE(writer_killed_in_store(s, dir.file("resumed.h5"), k));
  REQUIRE(data::ActuationDatabase::open(dir.file("resumed.h5")).sample_ids().size() == 3);
  s.write_database(dir.file("resumed.h5"));

  const std::string prm = write_prm(dir, "  set Joint placement = paper\n"
                                         "  set Joint spacing = 0.01\n"
                                         "  set Methods = M1, M2\n");
  reduction::ReductionRun(data::PrmFile::read(prm), dir.file("whole.h5"), dir.file("whole")).run();
  reduction::ReductionRun(data::PrmFile::read(prm), dir.file("resumed.h5"), dir.file("resumed")).run();
  // The same samples give the same stiffness tables, to the last digit.
  std::size_t n_tables = 0;
  for (const auto &entry : std::filesystem::directory_iterator(dir.file("whole/stiffness")))
    if (entry.path().extension() == ".csv")
      {
        INFO(entry.path().filename());
        CHECK(content(entry.path()) ==
              content(dir.file("resumed/stiffness/") + entry.path().filename().string()));
        ++n_tables;
      }
  CHECK(n_tables >= 2); // at least one table per method
}

TEST_CASE("run_reduction: bad input is an InputError naming file or parameter")
{
  ScratchDirectory dir("reduction_bad");
  Scenario().write_database(dir.file("database.h5"));
  CHECK_THROWS_WITH(reduction::run_reduction(data::PrmFile::read(write_prm(dir, "  set Methods = M1, M3\n")),
                                             dir.file("database.h5"), dir.file("out")),
                    Catch::Contains("finger.prm:5: parameter 'Methods'") &&
                      Catch::Contains("M3"));
  CHECK_THROWS_WITH(reduction::run_reduction(data::PrmFile::read(write_prm(dir, "  set Color = red\n")),
                                             dir.file("database.h5"), dir.file("out")),
                    Catch::Contains("finger.prm:5: unknown parameter 'Color'"));
  CHECK_THROWS_WITH(reduction::run_reduction(data::PrmFile::read(write_prm(dir, good_prm)), dir.file("none.h5"),
                                             dir.file("out")),
                    Catch::Contains(dir.file("none.h5")));
  CHECK_THROWS_WITH(reduction::run_reduction(data::PrmFile::read(write_prm(dir, "  set Joint placement = middle\n")),
                                             dir.file("database.h5"), dir.file("out")),
                    Catch::Contains("parameter 'Joint placement'") && Catch::Contains("middle"));
  CHECK_THROWS_WITH(reduction::run_reduction(data::PrmFile::read(write_prm(dir, "  set Joint height = low\n")),
                                             dir.file("database.h5"), dir.file("out")),
                    Catch::Contains("parameter 'Joint height'"));
  // The default placement samples the body through its cells: a database
  // without cells is refused with the reason.
  CHECK_THROWS_WITH(reduction::run_reduction(data::PrmFile::read(write_prm(dir, "  set Joint spacing = 0.01\n")),
                                             dir.file("database.h5"), dir.file("out")),
                    Catch::Contains("database.h5") && Catch::Contains("/mesh/cells is empty"));
  CHECK_THROWS_AS(reduction::run_reduction(data::PrmFile::read(write_prm(dir, "  set Joint spacing = 1\n")),
                                           dir.file("database.h5"), dir.file("out")),
                  data::InputError);
}
