// `softchain run` end to end on a tiny bender with its fabric springs (so
// that pressure bends it): the stiffness CSVs and the chain validation CSV.
#include <softchain/data/csv_table.h>

#include "tiny_design.h"

#include <catch2/catch.hpp>

#include <filesystem>

using softchain::testing::TinyDesign;

TEST_CASE("softchain run goes from the .prm to the stiffness and validation tables")
{
  // Joints 2 cm apart and b = a, so that every slab holds several node
  // planes of the 4-cell mesh (planes 19 mm apart). The small loads keep the
  // solves fast; their rotations (~1e-4 rad) are above a lowered threshold.
  TinyDesign design("run_pipeline",
                    "set Pressure sweep = 1e3, 2e3, 3e3\n"
                    "set Lateral tip forces = 0.005, 0.01\n"
                    "set Torsion couples = 0.005, 0.01\n"
                    "set Validation samples = 2e3 : tip : 0,0,0.005",
                    "subsection Springs\n  set Generate for bender = true\n"
                    "  set Axial rigidity = fabric: 2000, thread: 500\nend\n"
                    "subsection Reduction\n  set Joint spacing = 0.02\n"
                    "  set Slab half-widths = 1\n  set Rotation threshold = 1e-6\n"
                    "  set Plots = false\nend\n"
                    "subsection Chain\n  set Slab half-width = 1\nend\n");
  const auto outcome = design.run("run");
  INFO(outcome.output);
  CHECK(outcome.status == 0);
  for (const char *stage : {"stage 1/4", "stage 2/4", "stage 3/4", "stage 4/4"})
    CHECK(outcome.output.find(std::string(stage) + ": ") != std::string::npos);
  const std::string stiffness  = design.output() + "/stiffness/M2_b1.00a.csv";
  const std::string validation = design.output() + "/chain/validation.csv";
  REQUIRE(std::filesystem::exists(stiffness));
  REQUIRE(std::filesystem::exists(validation));
  CHECK(outcome.output.find(validation) != std::string::npos); // listed at the end
  CHECK(outcome.output.find("outputs:") != std::string::npos);
}
