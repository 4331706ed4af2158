// PrmFile / PrmSection: nested subsections, unknown entries with file:line,
// continuation lines, text_without, typed getters.
#include <softchain/data/input_error.h>
#include <softchain/data/prm_file.h>

#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

#include "scratch_directory.h"

using namespace softchain::data;
using softchain::testing::ScratchDirectory;

namespace
{
  const char *const example = "# a design\n"                        // 1
                              "subsection Geometry\n"               // 2
                              "  set Length = 0.09\n"               // 3
                              "end\n"                               // 4
                              "subsection Reduction\n"              // 5
                              "  set Joint spacing = 0.01 # [m]\n"  // 6
                              "  set Methods = M1, \\\n"            // 7
                              "                M2\n"                // 8
                              "  subsection Plot\n"                 // 9
                              "    set Enabled = false\n"           // 10
                              "  end\n"                             // 11
                              "end\n"                               // 12
                              "subsection Solver\n"                 // 13
                              "  set Tolerance = 1e-8\n"            // 14
                              "end\n";                              // 15

  PrmSection reduction_section()
  {
    PrmSection section;
    section.declare("Joint spacing", "0.02");
    section.declare("Methods", "M1");
    section.declare("Number of joints", "0");
    section.declare("Plot/Enabled", "true");
    return section;
  }

  std::string write(const ScratchDirectory &dir, const std::string &text)
  {
    std::ofstream(dir.file("p.prm")) << text;
    return dir.file("p.prm");
  }
} // namespace

TEST_CASE("prm: nested subsections, continuation lines and defaults")
{
  ScratchDirectory dir("prm_nested");
  const PrmFile    file    = PrmFile::read(write(dir, example));
  PrmSection       section = reduction_section();
  file.parse_section("Reduction", section);
  CHECK(section.get_double("Joint spacing") == 0.01);
  CHECK(section.get_list("Methods") == std::vector<std::string>{"M1", "M2"});
  CHECK(section.entries.at("Methods").line == 7);
  CHECK_FALSE(section.get_bool("Plot/Enabled"));
  CHECK(section.get_integer("Number of joints") == 0); // default kept
  CHECK(section.entries.at("Number of joints").line == 0);
  CHECK_THROWS_WITH(section.get_integer("Joint spacing"),
                    Catch::Contains(dir.file("p.prm") + ":6: parameter 'Joint spacing'"));
}

TEST_CASE("prm: an unknown parameter names file and line")
{
  ScratchDirectory dir("prm_unknown");
  const PrmFile    file    = PrmFile::read(write(dir, example));
  PrmSection       section = reduction_section();
  section.entries.erase("Plot/Enabled");
  CHECK_THROWS_WITH(file.parse_section("Reduction", section),
                    Catch::Equals(dir.file("p.prm") +
                                  ":10: unknown parameter 'Plot/Enabled' in subsection 'Reduction'"));
}

TEST_CASE("prm: malformed structure names file and line")
{
  ScratchDirectory dir("prm_malformed");
  CHECK_THROWS_WITH(PrmFile::read(write(dir, "subsection A\n  set x 1\nend\n")),
                    Catch::Contains(dir.file("p.prm") + ":2:"));
  CHECK_THROWS_WITH(PrmFile::read(write(dir, "end\n")), Catch::Contains(":1: 'end' without"));
  CHECK_THROWS_WITH(PrmFile::read(write(dir, "\nsubsection A\n")),
                    Catch::Contains(":2: subsection is never closed"));
  CHECK_THROWS_WITH(PrmFile::read(dir.file("none.prm")), Catch::Contains(dir.file("none.prm")));
  // A "\" on the last line continues into nothing: the statement still counts.
  CHECK_NOTHROW(PrmFile::read(write(dir, "subsection A\nend \\")));
  CHECK_THROWS_WITH(PrmFile::read(write(dir, "subsection A \\")),
                    Catch::Contains(":1: subsection is never closed"));
}

TEST_CASE("prm: text_without blanks the named subsections and keeps line numbers")
{
  ScratchDirectory  dir("prm_without");
  const PrmFile     file = PrmFile::read(write(dir, example));
  const std::string rest = file.text_without({"Reduction"});
  std::istringstream original(example), stripped(rest);
  std::string        a, b;
  for (int line = 1; std::getline(original, a); ++line)
    {
      REQUIRE(std::getline(stripped, b));
      CHECK(b == (line >= 5 && line <= 12 ? "" : a));
    }
  CHECK_FALSE(std::getline(stripped, b));
}

TEST_CASE("prm: typed getters reject malformed values")
{
  PrmSection section;
  section.file  = "f.prm";
  section.title = "T";
  section.declare("Flag", "maybe");
  section.declare("List", "1, x");
  section.declare("Empty", "");
  CHECK_THROWS_WITH(section.get_bool("Flag"), Catch::Contains("f.prm: parameter 'Flag'"));
  CHECK_THROWS_AS(section.get_double_list("List"), InputError);
  CHECK(section.get_double_list("Empty").empty());
}
