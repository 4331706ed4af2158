// ProtocolTorques on synthetic databases of a straight box finger: the trace
// order, a twist against the closed form of springs in series, the mirror
// symmetry of the lateral motions, the error statistics, the listing.
#include <softchain/chain/protocol_torques.h>

#include "../data/scratch_directory.h"
#include "box_mesh.h"
#include "uniform_finger.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace softchain;
using namespace softchain::chain;
using chain::testing::box_mesh;
using chain::testing::BoxMeshSpec;
using chain::testing::uniform_finger;

namespace
{
  // The inflated state and one protocol sample per motion, with the given
  // FEM base moments, and their listing (protocol_samples.csv).
  struct SyntheticProtocol
  {
    softchain::testing::ScratchDirectory dir;
    data::MeshRecord                     mesh = box_mesh(BoxMeshSpec{});
    data::ActuationDatabase              database;
    data::CsvTable                       listing{{"sample", "motion", "amount", "unit"}};

    double pressure;

    SyntheticProtocol(const std::string &name, const double p = 0.0)
      : dir(name)
      , database(data::ActuationDatabase::open_or_create(dir.file("db.h5"),
                                                         {"box", "h", "Q1", "test", ""}, mesh))
      , pressure(p)
    {
      data::SampleRecord rest;
      rest.actuation.pressure = pressure;
      rest.actuation.role = "protocol inflation";
      rest.id             = data::sample_id("h", rest.actuation);
      rest.x              = mesh.X;
      rest.base_force = rest.base_moment = {0.0, 0.0, 0.0};
      database.store_sample(rest);
      listing.add_row(std::vector<std::string>{rest.id, "inflation", "90", "deg"});
    }

    void add(const std::string &kind, double amount, const data::TipMotion &motion,
             const data::Point3 &fem_moment)
    {
      data::SampleRecord s;
      s.actuation.pressure   = pressure;
      s.actuation.role       = "protocol";
      s.actuation.tip_motion = motion;
      s.id                   = data::sample_id("h", s.actuation);
      s.x                    = mesh.X;
      s.base_force           = {0.0, 0.0, 0.0};
      s.base_moment          = fem_moment;
      database.store_sample(s);
      listing.add_row(std::vector<std::string>{s.id, kind, data::CsvTable::cell(amount),
                                               kind == "twist" ? "deg" : "mm"});
    }

    ProtocolTorques torques()
    {
      listing.write(dir.file("protocol_samples.csv"));
      return ProtocolTorques(database, dir.file("protocol_samples.csv"));
    }
  };

  constexpr double degree = M_PI / 180.0;
} // namespace

TEST_CASE("the protocol's twist: the trace 0, +, ++, +, 0, -, --, -, 0 and the base torque of "
          "springs in series")
{
  // Three joints with twist stiffness k: a tip frame turned by beta about
  // the finger's axis (which holds the tip point, on the axis) twists them
  // in series, T_x = (k / 3) beta, no force; the synthetic FEM gives exactly
  // that, so the chain's error is the solver's (relative 1e-10 residual).
  const double      k = 0.004;
  SyntheticProtocol protocol("protocol_twist");
  for (const double beta : {10.0, 20.0, -10.0, -20.0})
    protocol.add("twist", beta, {{0, 0, 0}, {beta * degree, 0, 0}}, {k / 3 * beta * degree, 0, 0});

  ProtocolTorques torques = protocol.torques();
  REQUIRE_FALSE(torques.empty());
  const ChainModel model = uniform_finger(3, 0.03, Eigen::Vector3d(k, 1, 1));
  torques.compare(model, {});
  CHECK(torques.failures().empty());

  const data::CsvTable trace = torques.trace_table();
  const std::vector<double> expected{0, 10, 20, 10, 0, -10, -20, -10, 0};
  REQUIRE(trace.n_rows() == expected.size());
  for (std::size_t r = 0; r < expected.size(); ++r)
    {
      INFO("step " << r);
      CHECK(trace.text(r, "motion") == "twist");
      CHECK(trace.number(r, "amount") == Approx(expected[r]).margin(1e-12));
      const double Tx = k / 3 * expected[r] * degree;
      CHECK(std::abs(trace.number(r, "uniform_Tx") - Tx) <= 1e-8 * k);
      CHECK(std::abs(trace.number(r, "uniform_Ty")) <= 1e-8 * k);
      CHECK(std::abs(trace.number(r, "uniform_Tz")) <= 1e-8 * k);
    }
  const data::CsvTable summary = torques.summary_table();
  REQUIRE(summary.n_rows() == 3);
  CHECK(summary.number(0, "fem_range_Nm") == Approx(2 * k / 3 * 20 * degree));
  CHECK(summary.number(0, "rms_error_percent_range") < 1e-6);
  CHECK(summary.text(0, "n_failed_points") == "0");
}

TEST_CASE("the protocol's lateral motions: a straight chain's base torques mirror in z")
{
  // The finger, bent in its x-y plane by the pressure (0.2 rad per joint), is
  // symmetric about z = 0: moving its tip by -t_z gives T_x and T_y of the
  // opposite sign and the same T_z as +t_z (moments are pseudovectors). (A
  // straight chain of rigid links could not move its tip sideways with the
  // tip frame held: that needs slack along its axis.) The FEM moments here
  // are placeholders (zero).
  SyntheticProtocol protocol("protocol_lateral", 2e4);
  for (const double dz : {0.004, 0.008, -0.004, -0.008})
    protocol.add("lateral", 1e3 * dz, {{0, 0, dz}, {0, 0, 0}}, {0, 0, 0});
  ProtocolTorques torques = protocol.torques();
  const ChainModel model = uniform_finger(6, 0.015, Eigen::Vector3d(0.01, 0.02, 0.03),
                                          Eigen::Vector3d(0, 0, 3e-7));
  torques.compare(model, {});
  REQUIRE(torques.failures().empty());
  const data::CsvTable trace = torques.trace_table();
  // Rows 2 (+8 mm) and 6 (-8 mm); the moment itself is ~1e-2 N m.
  REQUIRE(trace.number(2, "amount") == Approx(8.0));
  REQUIRE(trace.number(6, "amount") == Approx(-8.0));
  const double Ty = trace.number(2, "uniform_Ty");
  CHECK(std::abs(Ty) > 1e-3); // it does bend sideways
  CHECK(trace.number(6, "uniform_Tx") == Approx(-trace.number(2, "uniform_Tx")).margin(1e-10));
  CHECK(trace.number(6, "uniform_Ty") == Approx(-Ty).margin(1e-10));
  CHECK(trace.number(6, "uniform_Tz") == Approx(trace.number(2, "uniform_Tz")).margin(1e-10));
}

TEST_CASE("no listing, no protocol, and a listed sample missing from the database is an error naming it")
{
  SyntheticProtocol protocol("protocol_listing");
  CHECK(ProtocolTorques(protocol.database, protocol.dir.file("none.csv")).empty());
  protocol.listing.add_row(std::vector<std::string>{"0123456789abcdef", "lateral", "1", "mm"});
  CHECK_THROWS_WITH(protocol.torques(), Catch::Contains("sample 0123456789abcdef is not in the database"));
}
