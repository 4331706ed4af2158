// CsvTable: round trip with exact doubles and NaN, RFC 4180 quoting checked
// against Python's csv module, malformed rows and cells.
#include <softchain/data/csv_table.h>
#include <softchain/data/input_error.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "scratch_directory.h"

using namespace softchain::data;
using softchain::testing::ScratchDirectory;

namespace
{
  using Records = std::vector<std::vector<std::string>>;

  // Cells that RFC 4180 must quote (comma, double quote, LF, CRLF, lone CR, a
  // chain status as validation.csv holds it) next to cells that it must not.
  CsvTable awkward_table()
  {
    CsvTable table({"label", "note, with comma", "value"});
    table.add_row({"plain",
                   "joint 4: phi = -504.108 deg at equilibrium, outside the chain's range "
                   "(|theta| < 90 deg, |psi|, |phi| <= 180 deg)",
                   CsvTable::cell(1.0 / 3.0)});
    table.add_row({"say \"hi\"", "\"", "nan"});
    table.add_row({"two\nlines", "crlf\r\nend", ""});
    table.add_row({"", " spaced ", "lone\rcr"});
    table.add_row({"ends with quote\"", ",", "\xc3\xbcnicode"});
    return table;
  }

  // Header and rows as one list of records.
  Records records(const CsvTable &table)
  {
    Records all{table.columns()};
    for (std::size_t r = 0; r < table.n_rows(); ++r)
      {
        all.emplace_back();
        for (const auto &column : table.columns())
          all.back().push_back(table.text(r, column));
      }
    return all;
  }

  std::string file_text(const std::string &path)
  {
    std::ostringstream text;
    text << std::ifstream(path).rdbuf();
    return text.str();
  }

  // Records of the CELLS file of csv_module_check.py: one line per record,
  // each cell as x<hex of its bytes>.
  Records hex_records(const std::string &path)
  {
    Records       all;
    std::ifstream in(path);
    for (std::string line; std::getline(in, line);)
      {
        all.emplace_back();
        std::istringstream tokens(line);
        for (std::string token; tokens >> token;)
          {
            std::string cell;
            for (std::size_t i = 1; i + 1 < token.size(); i += 2)
              cell += char(std::stoi(token.substr(i, 2), nullptr, 16));
            all.back().push_back(cell);
          }
      }
    return all;
  }

  // The message of the InputError that reading `path` throws.
  std::string error_of(const std::string &path)
  {
    try
      {
        CsvTable::read(path);
      }
    catch (const InputError &e)
      {
        return e.what();
      }
    return "no InputError";
  }
} // namespace

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

TEST_CASE("CSV round trip keeps cells with commas, quotes and line breaks")
{
  ScratchDirectory dir("csv_quoted_round_trip");
  const CsvTable   table = awkward_table();
  table.write(dir.file("t.csv"));
  CHECK(records(CsvTable::read(dir.file("t.csv"))) == records(table));

  // Only the cells that need it are quoted, inner quotes doubled; numbers,
  // words and nan stay as they were.
  const std::string text = file_text(dir.file("t.csv"));
  CHECK(text.find("label,\"note, with comma\",value\n") == 0);
  CHECK(text.find("\nplain,\"joint 4: phi = -504.108 deg at equilibrium, outside the chain's "
                  "range (|theta| < 90 deg, |psi|, |phi| <= 180 deg)\",0.33333333333333331\n") !=
        std::string::npos);
  CHECK(text.find("\n\"say \"\"hi\"\"\",\"\"\"\",nan\n") != std::string::npos);

  // A one-column row with an empty cell is not lost as a blank line.
  CsvTable single({"only"});
  single.add_row(std::vector<std::string>{""});
  single.add_row(std::vector<std::string>{"x"});
  single.write(dir.file("single.csv"));
  CHECK(records(CsvTable::read(dir.file("single.csv"))) == records(single));
}

TEST_CASE("malformed quoting names file and line")
{
  ScratchDirectory  dir("csv_bad_quotes");
  const std::string file = dir.file("bad.csv");
  std::ofstream(file) << "a,b\n1,\"open\n2,3\n";
  CHECK_THAT(error_of(file), Catch::Contains(file + ":2: quoted cell not closed"));
  std::ofstream(file) << "a,b\n\"x\"y,1\n";
  CHECK_THAT(error_of(file), Catch::Contains(file + ":2: text after the closing quote"));
  std::ofstream(file) << "a,b\nx\"y,1\n";
  CHECK_THAT(error_of(file), Catch::Contains(file + ":2: double quote inside an unquoted cell"));
  // Lines inside a quoted cell count: the short row is on line 4.
  std::ofstream(file) << "a,b\n\"x\ny\",1\n3\n";
  CHECK_THAT(error_of(file), Catch::Contains(file + ":4: expected 2 cells, found 1"));
}

// Python's csv module, an RFC 4180 reader and writer independent of CsvTable,
// must parse what CsvTable writes into the same cells; CsvTable must read the
// copy Python writes (every cell quoted, CRLF line ends) into the same cells.
TEST_CASE("Python's csv module reads what CsvTable writes and the other way round")
{
  INFO("Python 3 found when configuring: '" SOFTCHAIN_PYTHON3 "' (scripts/setup installs it)");
  REQUIRE(std::string(SOFTCHAIN_PYTHON3) != "");
  ScratchDirectory dir("csv_python");
  const CsvTable   table = awkward_table();
  table.write(dir.file("t.csv"));
  const std::string command = "'" SOFTCHAIN_PYTHON3 "' '" SOFTCHAIN_SOURCE_DIR
                              "/tests/data/csv_module_check.py' '" +
                              dir.file("t.csv") + "' '" + dir.file("cells.txt") + "' '" +
                              dir.file("copy.csv") + "'";
  REQUIRE(std::system(command.c_str()) == 0);
  CHECK(hex_records(dir.file("cells.txt")) == records(table));
  CHECK(file_text(dir.file("copy.csv")).find("\r\n") != std::string::npos);
  CHECK(records(CsvTable::read(dir.file("copy.csv"))) == records(table));
}
