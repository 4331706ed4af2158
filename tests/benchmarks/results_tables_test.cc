// ResultsTable and ResultsPage: the documentation's result tables rendered
// from CSV files, on small files whose tables are written out here by hand.
#include "../data/scratch_directory.h"

#include <softchain/data/input_error.h>

#include <catch2/catch.hpp>
#include <results_page.h>
#include <results_table.h>

#include <fstream>

using softchain::benchmarks::ResultsPage;
using softchain::benchmarks::ResultsTable;
using softchain::data::InputError;
using Catch::Contains;

namespace
{
  // The tip angle of two designs at three pressures; P13's 30 kPa failed.
  const std::string angles_csv = "design,pressure_kPa,status,angle_deg,tip_x_mm\n"
                                 "p10,10,converged,-14.663,90.34\n"
                                 "p10,20,converged,-33.479,87.913\n"
                                 "p10,30,converged,-57.648,80.051\n"
                                 "p13,10,converged,-3.4123,100.1\n"
                                 "p13,20,converged,-8.0456,99.8\n"
                                 "p13,30,failed,nan,nan\n";

  std::vector<std::string> render(const softchain::testing::ScratchDirectory &dir, const std::string &spec)
  {
    std::ofstream(dir.file("angles.csv")) << angles_csv;
    return ResultsTable(spec, dir.path().string()).render();
  }
} // namespace

TEST_CASE("a plain table holds the chosen columns of the kept rows, numbers right-aligned")
{
  softchain::testing::ScratchDirectory dir("results_table_plain");
  CHECK(render(dir, "angles.csv; where status = converged; where design = p13; columns design, angle_deg") ==
        std::vector<std::string>{"| design | angle_deg |", "| --- | ---: |", "| p13 | -3.4123 |",
                                 "| p13 | -8.0456 |"});
  CHECK(render(dir, "angles.csv; where pressure_kPa = 30").back() == "| p13 | 30 | failed | nan | nan |");
  CHECK(render(dir, "angles.csv; where pressure_kPa = 30")[2] == "| p10 | 30 | converged | -57.648 | 80.051 |");
}

TEST_CASE("joined columns, headers and a text for values that are all nan")
{
  softchain::testing::ScratchDirectory dir("results_table_joined");
  CHECK(render(dir, "angles.csv; where design = p13; columns pressure_kPa, angle_deg / tip_x_mm; "
                    "headers p [kPa], angle [deg] / x [mm]; nan not reached") ==
        std::vector<std::string>{"| p [kPa] | angle [deg] / x [mm] |", "| ---: | --- |",
                                 "| 10 | -3.4123 / 100.1 |", "| 20 | -8.0456 / 99.8 |", "| 30 | not reached |"});
  CHECK_THROWS_WITH(render(dir, "angles.csv; columns design; headers a, b"), Contains("2 headers for 1 columns"));
}

TEST_CASE("a pivot has a row per key and a column per value across, in file order")
{
  softchain::testing::ScratchDirectory dir("results_table_pivot");
  CHECK(render(dir, "angles.csv; where status = converged; rows design; across pressure_kPa; "
                    "values angle_deg; decimals 1") ==
        std::vector<std::string>{"| design | pressure_kPa = 10 | pressure_kPa = 20 | pressure_kPa = 30 |",
                                 "| --- | ---: | ---: | ---: |", "| p10 | -14.7 | -33.5 | -57.6 |",
                                 "| p13 | -3.4 | -8.0 | – |"});
  CHECK(render(dir, "angles.csv; where design = p10; where pressure_kPa = 10; rows design; across status; "
                    "values angle_deg, tip_x_mm") ==
        std::vector<std::string>{"| design | status = converged: angle_deg / tip_x_mm |", "| --- | --- |",
                                 "| p10 | -14.663 / 90.34 |"});
}

TEST_CASE("bad table specs and CSV files are input errors naming the clause or column")
{
  softchain::testing::ScratchDirectory dir("results_table_errors");
  CHECK_THROWS_WITH(render(dir, "angles.csv; columns design, speed"), Contains("speed") && Contains("angles.csv"));
  CHECK_THROWS_WITH(render(dir, "angles.csv; where colour = red"), Contains("colour"));
  CHECK_THROWS_WITH(render(dir, "angles.csv; sort design"), Contains("'sort design'") && Contains("unknown clause"));
  CHECK_THROWS_WITH(render(dir, "angles.csv; rows design; values angle_deg"), Contains("a pivot needs"));
  CHECK_THROWS_WITH(render(dir, "angles.csv; rows design; across status; values angle_deg; decimals two"),
                    Contains("expected 0 to 17 decimals"));
  CHECK_THROWS_WITH(render(dir, "angles.csv; decimals 1"), Contains("decimals round a pivot's values"));
  CHECK_THROWS_AS(render(dir, "missing.csv"), InputError);
}

TEST_CASE("a page's tables are regenerated between their comments, and a stale one is named")
{
  softchain::testing::ScratchDirectory dir("results_page");
  std::ofstream(dir.file("angles.csv")) << angles_csv;
  const std::string spec    = "<!-- table: angles.csv; where design = p13; columns pressure_kPa, angle_deg -->";
  const std::string current = "| pressure_kPa | angle_deg |\n| ---: | ---: |\n| 10 | -3.4123 |\n"
                              "| 20 | -8.0456 |\n| 30 | nan |\n";
  const std::string before = "# Results\n\nSome text.\n\n" + spec + "\n";
  const std::string after  = "<!-- end table -->\n\nMore text.\n";

  std::ofstream(dir.file("page.txt")) << before << current << after;
  const ResultsPage page = ResultsPage::read(dir.file("page.txt"));
  CHECK(page.regenerated() == page.text());
  REQUIRE(page.tables().size() == 1);
  CHECK(page.tables()[0].current);
  CHECK(page.tables()[0].line == 6);

  // A number typed by hand (-3.41 for -3.4123) makes the table stale; the
  // regenerated page restores the CSV's.
  std::string edited = current;
  edited.replace(edited.find("-3.4123"), 7, "-3.41");
  std::ofstream(dir.file("page.txt")) << before << edited << after;
  const ResultsPage stale = ResultsPage::read(dir.file("page.txt"));
  CHECK_FALSE(stale.tables()[0].current);
  CHECK(stale.regenerated() == before + current + after);

  std::ofstream(dir.file("page.txt")) << before << current;
  CHECK_THROWS_WITH(ResultsPage::read(dir.file("page.txt")).regenerated(),
                    Contains("page.txt:5") && Contains("without '<!-- end table -->'"));
}
