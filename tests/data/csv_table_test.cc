// CsvTable: round trip with exact doubles and NaN, malformed rows and cells.
#include <softchain/data/csv_table.h>
#include <softchain/data/input_error.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>

#include "scratch_directory.h"

using namespace softchain::data;
using softchain::testing::ScratchDirectory;

TEST_CASE("CSV round trip keeps text, exact doubles and NaN")
{
  ScratchDirectory dir("csv_round_trip");
  CsvTable         table({"name", "value"});
  table.add_row(std::vector<std::string>{"third", "x"});
  table.add_row(std::vector<double>{1.0, 1.0 / 3.0});
  table.add_row(std::vector<double>{2.0, std::nan("")});
  table.write(dir.file("sub/dir/t.csv")); // parent directories are created
  const CsvTable read = CsvTable::read(dir.file("sub/dir/t.csv"));
  REQUIRE(read.n_rows() == 3);
  CHECK(read.columns() == table.columns());
  CHECK(read.text(0, "name") == "third");
  CHECK(read.number(1, "value") == 1.0 / 3.0); // 17 digits round-trip a double exactly
  CHECK(std::isnan(read.number(2, "value")));
  CHECK(read.has_column("value"));
  CHECK_FALSE(read.has_column("other"));
  CHECK_THROWS_AS(read.column("other"), InputError);
  CHECK_THROWS_WITH(read.number(0, "value"), Catch::Contains("'x' is not a number"));
}

TEST_CASE("a CSV row with the wrong number of cells names file and line")
{
  ScratchDirectory dir("csv_malformed");
  std::ofstream(dir.file("bad.csv")) << "a,b\n1,2\n3\n";
  CHECK_THROWS_WITH(CsvTable::read(dir.file("bad.csv")),
                    Catch::Contains(dir.file("bad.csv") + ":3: expected 2 cells, found 1"));
  CHECK_THROWS_WITH(CsvTable::read(dir.file("missing.csv")),
                    Catch::Contains(dir.file("missing.csv")));
}
