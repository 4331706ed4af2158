// HtmlReport on a hand-made output directory: every section, the images as
// data: URIs, the stage times, the captions of missing pressures, the
// protocol's base torque errors, bad input.
#include <softchain/data/input_error.h>
#include <softchain/report/base64.h>
#include <softchain/report/html_report.h>

#include <catch2/catch.hpp>

#include "../data/occurrences.h"
#include "synthetic_outputs.h"

#include <filesystem>

using namespace softchain::report;
using softchain::report::testing::SyntheticOutputs;

TEST_CASE("Base64 of the RFC 4648 test vectors")
{
  const std::pair<const char *, const char *> vectors[] = {
    {"", ""}, {"f", "Zg=="}, {"fo", "Zm8="}, {"foo", "Zm9v"}, {"foob", "Zm9vYg=="}, {"foobar", "Zm9vYmFy"}};
  for (const auto &[text, encoded] : vectors)
    CHECK(base64(text) == encoded);
  CHECK(base64(std::string("\xff\x00", 2)) == "/wA=");
}

TEST_CASE("The report holds every section, its pictures and its tables")
{
  const SyntheticOutputs outputs("report_sections");
  std::ofstream(outputs.file("stiffness/kpsi.png")) << "not really a PNG";
  const std::string html = HtmlReport(softchain::data::PrmFile::read(outputs.prm()), outputs.database(), outputs.directory()).html();
  for (const char *section : {"Summary", "1. The design", "2. The deformed finger", "3. Stiffness profiles",
                              "4. Chain against FEM", "Baseline comparison", "5. Prescribed tip motion",
                              "6. Contact", "7. Run times", "8. The paper's claims"})
    CHECK(html.find(section) != std::string::npos);
  CHECK(html.find("set Name = a&lt;b") != std::string::npos); // the .prm, escaped
  CHECK(softchain::testing::occurrences(html, "<img src=\"data:image/svg+xml;base64,") == 3); // 0, 40, 80 kPa
  CHECK(html.find(data_uri("image/png", "not really a PNG")) != std::string::npos);
  CHECK(html.find("ktheta.png is missing") != std::string::npos); // said, not broken
  // 80 kPa is beyond the converged 40 kPa; the failed 60 kPa sample is named.
  CHECK(html.find("shown: the highest converged pressure, 40 kPa") != std::string::npos);
  CHECK(html.find("at 60 kPa: limit point at p = 55000 Pa") != std::string::npos);
  // Baseline 40 % against the chain's 4 %: 10 times more accurate.
  CHECK(html.find("<td>40</td><td>10</td>") != std::string::npos);
  CHECK(html.find("not measured in this run") != std::string::npos);
  CHECK(softchain::testing::occurrences(html, "<td>1.25</td>") == 2); // both samples' wall times
  // The summary comes first: the chain's and the baseline's errors before the design.
  CHECK(html.find("Summary") < html.find("1. The design"));
  CHECK(html.find("median 1.25 s of wall time per sample") != std::string::npos);
  CHECK(html.find("chain/chain_poses.csv is missing") != std::string::npos);
}

TEST_CASE("The chain of every validation sample is drawn over its FEM finger")
{
  const SyntheticOutputs outputs("report_chain_pictures");
  // The synthetic database's converged sample, relabelled as a validation
  // sample (the id stays: the role is not part of it).
  auto database = softchain::data::ActuationDatabase::open(outputs.database());
  softchain::data::SampleRecord validation = database.read_sample(database.sample_ids().front());
  if (!validation.converged())
    validation = database.read_sample(database.sample_ids().back());
  REQUIRE(validation.converged());
  validation.actuation.role = "validation";
  database.store_sample(validation);
  softchain::data::CsvTable poses({"sample", "model", "point", "x", "y", "z"});
  poses.add_row({validation.id, "M2", "1", "0", "0", "0"});
  poses.add_row({validation.id, "M2", "tip", "0.02", "-0.001", "0"});
  poses.add_row({validation.id, "baseline", "1", "0", "0", "0"});
  poses.write(outputs.file("chain/chain_poses.csv"));
  const std::string html = HtmlReport(softchain::data::PrmFile::read(outputs.prm()), outputs.database(), outputs.directory()).html();
  CHECK(html.find("The chain over the FEM finger") != std::string::npos);
  // Three finger pictures and one with the chain (the M2 points only).
  CHECK(softchain::testing::occurrences(html, "<img src=\"data:image/svg+xml;base64,") == 4);
  CHECK(html.find("sample " + validation.id + "<") != std::string::npos); // with its chain
}

TEST_CASE("The stage times of softchain run replace the 'not measured' line")
{
  const SyntheticOutputs outputs("report_stage_times");
  HtmlReport             report(softchain::data::PrmFile::read(outputs.prm()), outputs.database(), outputs.directory());
  report.set_stage_times({{"FEM sample sweep", 12.5}, {"reduction", 0.25}});
  const std::string html = report.html();
  CHECK(html.find("<td>FEM sample sweep</td><td>12.5</td>") != std::string::npos);
  CHECK(html.find("not measured in this run") == std::string::npos);
}

TEST_CASE("Without a chain validation the report says so instead of failing")
{
  // E.g. P13 reduced from pressure samples only: every k_phi is negative,
  // the chain stage cannot build a chain, and the rest is still reported.
  const SyntheticOutputs outputs("report_no_chain");
  std::filesystem::remove(outputs.file("chain/validation_summary.csv"));
  const std::string html = HtmlReport(softchain::data::PrmFile::read(outputs.prm()), outputs.database(), outputs.directory()).html();
  CHECK(html.find("No chain validation: chain/validation_summary.csv is missing") != std::string::npos);
  CHECK(html.find("3. Stiffness") != std::string::npos);
}

TEST_CASE("The contact section plots the force per obstacle and draws the finger on it, or says there is none")
{
  const SyntheticOutputs outputs("report_contact");
  const auto report = [&] {
    return HtmlReport(softchain::data::PrmFile::read(outputs.prm()), outputs.database(), outputs.directory()).html();
  };
  std::string html = report();
  CHECK(html.find("No contact samples") != std::string::npos);
  const std::size_t pictures = softchain::testing::occurrences(html, "<img src=\"data:image/svg+xml;base64,");

  // The converged 40 kPa sample again, pressed on a cylinder.
  auto database = softchain::data::ActuationDatabase::open(outputs.database());
  softchain::data::SampleRecord pressed = database.read_sample(database.sample_ids().front());
  REQUIRE(pressed.converged());
  pressed.actuation.role      = "contact";
  pressed.actuation.obstacles = {{"can", "cylinder", {0.5, -0.5, 0}, {0, 0, 1}, 0.2, {}, 0, {}}};
  pressed.id                  = softchain::data::sample_id("hash", pressed.actuation);
  pressed.obstacle_wrenches   = {{{0, -0.75, 0}, {0, 0, 0}}};
  database.store_sample(pressed);
  softchain::data::CsvTable forces({"sample", "obstacle", "shape", "pressure", "status", "force_x", "force_y",
                                    "force_z", "force_norm", "tip_angle_deg"});
  forces.add_row({pressed.id, "can", "cylinder", "40000", "converged", "0", "-0.75", "0", "0.75", "30"});
  forces.write(outputs.file("contact/contact_forces.csv"));
  html = report();
  CHECK(html.find("No contact samples") == std::string::npos);
  CHECK(html.find("6. Contact") < html.find("7. Run times"));
  CHECK(html.find("<tr><td>can</td><td>cylinder</td><td>40</td><td>0</td><td>-0.75</td><td>0</td><td>0.75</td><td>30</td><td>converged</td></tr>") !=
        std::string::npos);
  // The force plot and the finger on the can: two more pictures.
  CHECK(softchain::testing::occurrences(html, "<img src=\"data:image/svg+xml;base64,") == pictures + 2);
  CHECK(html.find("the finger on the obstacle 'can'") != std::string::npos);
  CHECK(html.find("No chain in contact") != std::string::npos);

  // The chains in contact: the summary per model, and per sample each
  // model's force and error beside the FEM's.
  softchain::data::CsvTable summary({"model", "n_samples", "n_failed", "blocked_force_error_percent",
                                     "grasp_force_error_percent", "tip_error_percent_L", "orientation_error_deg",
                                     "median_solve_time_us"});
  summary.add_row({"M2", "1", "0", "nan", "4", "1.5", "2", "900"});
  summary.add_row({"baseline", "1", "0", "nan", "60", "15", "30", "700"});
  summary.write(outputs.file("chain/grasp_summary.csv"));
  softchain::data::CsvTable validation({"sample", "role", "pressure", "model", "fem_contact_force_N",
                                        "contact_force_N", "contact_force_error_percent", "solve_time_us"});
  validation.add_row({"free", "pressure", "40000", "M2", "nan", "nan", "nan", "9"});
  validation.add_row({pressed.id, "grasp with friction", "40000", "M2", "0.75", "0.78", "4", "900"});
  validation.add_row({pressed.id, "grasp with friction", "40000", "baseline", "0.75", "1.2", "60", "700"});
  validation.write(outputs.file("chain/validation.csv"));
  html = report();
  CHECK(html.find("No chain in contact") == std::string::npos);
  CHECK(html.find("<td>M2</td><td>1</td><td>0</td><td>nan</td><td>4</td><td>1.5</td><td>2</td><td>900</td>") !=
        std::string::npos);
  CHECK(html.find("<th>M2 |F| [N]</th><th>M2 error [%]</th><th>baseline |F| [N]</th><th>baseline error [%]</th>") !=
        std::string::npos);
  CHECK(html.find("<tr><td>grasp with friction</td><td>40</td><td>0.75</td><td>0.78</td><td>4</td><td>1.2</td>"
                  "<td>60</td></tr>") != std::string::npos);
  CHECK(html.find("<td>pressure</td><td>40</td><td>nan</td>") == std::string::npos); // a free sample has no row
}

TEST_CASE("The protocol's base torque errors, or a line saying the design has none")
{
  const SyntheticOutputs outputs("report_protocol");
  const auto report = [&] {
    return HtmlReport(softchain::data::PrmFile::read(outputs.prm()), outputs.database(), outputs.directory()).html();
  };
  // Without chain/protocol_summary.csv: the paragraph, and no table.
  std::string html = report();
  CHECK(html.find("No tip-motion protocol: the design has none (subsection Protocol, Tip angle = 0)") !=
        std::string::npos);
  CHECK(html.find("RMS error [% of range]") == std::string::npos);

  softchain::report::testing::protocol_summary().write(outputs.file("chain/protocol_summary.csv"));
  // A two-step trace whose first sample is the database's 40 kPa one.
  const auto database = softchain::data::ActuationDatabase::open(outputs.database());
  const std::string first = database.sample_ids().front();
  REQUIRE(database.read_sample(first).actuation.pressure == 40e3);
  softchain::data::CsvTable torques({"step", "motion", "amount", "unit", "sample", "fem_Tx", "fem_Ty",
                                     "fem_Tz", "M2_Tx", "M2_Ty", "M2_Tz"});
  torques.add_row({"0", "lateral", "0", "mm", first, "0", "0", "0", "0", "0", "0"});
  torques.add_row({"1", "lateral", "2.5", "mm", first, "0.001", "0", "0", "0.001", "0", "nan"});
  torques.write(outputs.file("chain/protocol_torques.csv"));
  html = report();
  CHECK(html.find("No tip-motion protocol") == std::string::npos);
  // Between the validation and the run times.
  CHECK(html.find("4. Chain against FEM") < html.find("5. Prescribed tip motion"));
  CHECK(html.find("5. Prescribed tip motion") < html.find("7. Run times"));
  // Cells with 3 significant digits, as the report's other tables: torques
  // in mN m (0.0125 N m -> 12.5), percentages as written (12.3456 -> 12.3),
  // failed points as the CSV counts them.
  CHECK(html.find("<tr><td>M2</td><td>Tx</td><td>12.5</td><td>0.5</td><td>4</td><td>9.5</td><td>0</td></tr>") !=
        std::string::npos);
  CHECK(html.find("<tr><td>M2</td><td>Ty</td><td>20</td><td>2.47</td><td>12.3</td><td>30.4</td><td>0</td></tr>") !=
        std::string::npos);
  // Every baseline Tz equilibrium failed: no error, said as nan.
  CHECK(html.find("<tr><td>baseline</td><td>Tz</td><td>4</td><td>nan</td><td>nan</td><td>nan</td><td>13</td></tr>") !=
        std::string::npos);
  CHECK(html.find("protocol_torques.png is missing") != std::string::npos); // no gnuplot: said
  CHECK(html.find("chain/protocol_torques.csv holds the trace step by step (2 steps, inflated at 40 kPa)") !=
        std::string::npos);
}

TEST_CASE("A missing input is an error naming the file")
{
  const SyntheticOutputs outputs("report_missing");
  for (const std::string missing : {"stiffness/M2_b0.50a.csv", "database.h5"})
    {
      std::filesystem::remove(outputs.file(missing));
      CHECK_THROWS_WITH(HtmlReport(softchain::data::PrmFile::read(outputs.prm()), outputs.database(), outputs.directory()),
                        Catch::Contains(outputs.file(missing)));
    }
}

// The summary gives the FEM's own error beside the chain's when `softchain
// accuracy` has written fem_accuracy.csv (its first row the design's
// distance to the converged estimate, its last that estimate's
// uncertainty) for this database's design, and says how to get it when not.
TEST_CASE("The summary shows the FEM's discretisation error, or how to estimate it")
{
  const SyntheticOutputs outputs("report_fem_accuracy");
  const auto html = [&] {
    return HtmlReport(softchain::data::PrmFile::read(outputs.prm()), outputs.database(), outputs.directory()).html();
  };
  CHECK(html().find("run `softchain accuracy` on its .prm") != std::string::npos);
  // The table of this database's design (its hash, "hash" in SyntheticOutputs).
  const auto write_table = [&](const std::string &design_hash) {
    softchain::data::CsvTable table({"run", "distance_to_converged_percent_L", "design_hash"});
    using Row = std::vector<std::string>;
    table.add_row(Row{"design", "2.07", design_hash});
    table.add_row(Row{"sheets", "0.5", "0123456789abcdef"});
    table.add_row(Row{"converged (Richardson)", "0.313", ""});
    table.write(outputs.file("fem_accuracy.csv"));
  };
  write_table("hash");
  const std::string with = html();
  CHECK(with.find("mesh lies 2.07 % of L from the mesh-converged answer, which is uncertain to 0.313 % of L") !=
        std::string::npos);
  CHECK(with.find("FEM discretisation error") < with.find("1. The design"));
  // Made for another design (the .prm's walls changed since): not shown as this one's.
  write_table("fedcba9876543210");
  const std::string stale = html();
  CHECK(stale.find("2.07 %") == std::string::npos);
  CHECK(stale.find("is of another design") != std::string::npos);
}
