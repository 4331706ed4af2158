// PaperClaims on synthetic CSV files: for each claim tested, a case where it
// holds, one where it does not, and where it cannot be measured.
#include <softchain/report/paper_claims.h>

#include <catch2/catch.hpp>

#include <filesystem>

#include "synthetic_outputs.h"

using namespace softchain::report;
using softchain::data::CsvTable;
using softchain::report::testing::stiffness_table;
using softchain::report::testing::validation_summary;

namespace
{
  // An output directory "finger" (and siblings) under a scratch directory.
  struct Outputs
  {
    softchain::testing::ScratchDirectory root{"paper_claims"};
    std::string stiffness(const std::string &design = "finger") const
    {
      return root.file(design + "/stiffness/M2_b0.50a");
    }
    Claim claim(const std::string &number, const int samples = 20) const
    {
      const PaperClaims claims({"finger", root.file("finger"), "M2", 0.5, samples});
      for (const auto &c : claims.claims())
        if (c.number == number)
          return c;
      FAIL("no claim " << number);
      return {};
    }
  };

  const std::vector<double> level = {0.01, 0.01, 0.01, 0.01, 0.01};
} // namespace

TEST_CASE("Claim 5: k_psi higher near the base")
{
  Outputs outputs;
  CHECK(outputs.claim("5").verdict == Verdict::not_measurable); // no table yet
  stiffness_table({0.4, 0.3, 0.2, 0.1, 0.05}, level, level).write(outputs.stiffness() + ".csv");
  const Claim decreasing = outputs.claim("5");
  CHECK(decreasing.verdict == Verdict::holds);
  CHECK(decreasing.measured.find("ratio 8") != std::string::npos); // first 0.4, last 0.05
  stiffness_table({0.05, 0.1, 0.2, 0.3, 0.4}, level, level).write(outputs.stiffness() + ".csv");
  CHECK(outputs.claim("5").verdict == Verdict::does_not_hold);
}

TEST_CASE("Claim 2b: k_phi decreases with pressure")
{
  Outputs outputs;
  const auto table = [](const double low_pressure_k, const double high_pressure_k) {
    CsvTable t({"pressure", "joint", "k_phi"});
    for (const auto &[p, k] : {std::pair{10e3, low_pressure_k}, std::pair{50e3, high_pressure_k}})
      for (int joint = 1; joint <= 3; ++joint)
        t.add_row(std::vector<double>{p, double(joint), joint == 1 ? NAN : k});
    return t;
  };
  table(0.02, 0.01).write(outputs.stiffness() + "_kphi_vs_pressure.csv");
  CHECK(outputs.claim("2b").verdict == Verdict::holds);
  table(0.01, 0.02).write(outputs.stiffness() + "_kphi_vs_pressure.csv");
  const Claim rising = outputs.claim("2b");
  CHECK(rising.verdict == Verdict::does_not_hold);
  CHECK(rising.measured.find("0.01 → 0.02 N m/rad from 10 to 50 kPa") != std::string::npos);
}

TEST_CASE("Claim 1a: k_phi constant along the parallelepiped, read beside this design")
{
  Outputs outputs;
  const Claim absent = outputs.claim("1a");
  CHECK(absent.verdict == Verdict::not_measurable);
  CHECK(absent.measured.find("run parameter_files/parallelepiped.prm") != std::string::npos);
  // Joints next to the base and at the tip are left out: 0.05 and 0.04
  // there do not matter, the inside within +-10 % does.
  const std::string file = outputs.stiffness("parallelepiped") + ".csv";
  stiffness_table(level, {0.05, 0.029, 0.03, 0.032, 0.04}, level).write(file);
  CHECK(outputs.claim("1a").verdict == Verdict::holds);
  stiffness_table(level, {0.05, 0.02, 0.03, 0.04, 0.04}, level).write(file); // +-33 %
  CHECK(outputs.claim("1a").verdict == Verdict::does_not_hold);
}

TEST_CASE("Claim 2a: k_phi along a tapered finger, not measurable on an untapered one")
{
  Outputs                   outputs;
  const std::vector<double> falling = {0.05, 0.03, 0.025, 0.02, 0.015};
  // The finger's height at base and tip comes from its database's mesh: a
  // box, then the same box 40 % lower at the tip than at the base.
  const auto write_mesh = [&](double tip_scale) {
    softchain::chain::testing::BoxMeshSpec spec;
    softchain::data::MeshRecord mesh = softchain::chain::testing::box_mesh(spec);
    for (auto &X : mesh.X)
      X[1] *= 1 - (1 - tip_scale) * X[0] / spec.length;
    std::filesystem::remove(outputs.root.file("finger/database.h5"));
    softchain::data::ActuationDatabase::open_or_create(outputs.root.file("finger/database.h5"),
                                            {"finger", "hash", "Q1", "test", ""}, mesh);
  };
  stiffness_table(level, falling, level).write(outputs.stiffness() + ".csv");
  CHECK(outputs.claim("2a").verdict == Verdict::not_measurable); // no database
  write_mesh(1.0);
  CHECK(outputs.claim("2a").verdict == Verdict::not_measurable);
  write_mesh(0.6);
  CHECK(outputs.claim("2a").verdict == Verdict::holds);
  stiffness_table(level, {0.05, 0.015, 0.02, 0.025, 0.03}, level).write(outputs.stiffness() + ".csv");
  CHECK(outputs.claim("2a").verdict == Verdict::does_not_hold);
}

TEST_CASE("Claim 6: fewer than 30 samples give a chain within 5 % of L")
{
  Outputs outputs;
  validation_summary(3).write(outputs.root.file("finger/chain/validation_summary.csv"));
  CHECK(outputs.claim("6", 25).verdict == Verdict::holds);
  CHECK(outputs.claim("6", 30).verdict == Verdict::not_measurable); // not "fewer than 30"
  validation_summary(17).write(outputs.root.file("finger/chain/validation_summary.csv"));
  const Claim poor = outputs.claim("6", 25);
  CHECK(poor.verdict == Verdict::does_not_hold);
  CHECK(poor.measured.find("mean tip error 17 % of L") != std::string::npos);
}
