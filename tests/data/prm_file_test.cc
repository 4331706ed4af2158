// PrmFile / PrmSection: nested subsections, unknown entries with file:line,
// continuation lines, unknown subsections, typed getters, enums and the
// canonical values that key the design hash.
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
                              "subsection Mesh\n"                   // 2
                              "  set Bender length = 0.09\n"        // 3
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

TEST_CASE("prm: an integer within bounds, also one beyond an int, names file, line and range")
{
  ScratchDirectory dir("prm_bounded");
  for (const auto &[value, ok] : std::vector<std::pair<std::string, bool>>{
         {"7", true}, {"0", true}, {"8", false}, {"-1", false}, {"4294967297", false}, {"3.5", false}})
    {
      INFO(value);
      PrmSection section = reduction_section();
      PrmFile::read(write(dir, "subsection Reduction\n  set Number of joints = " + value + "\nend\n"))
        .parse_section("Reduction", section);
      if (ok)
        CHECK(section.get_integer("Number of joints", 0, 7) == std::stoi(value));
      else
        CHECK_THROWS_WITH(section.get_integer("Number of joints", 0, 7),
                          Catch::Contains(dir.file("p.prm") + ":2: parameter 'Number of joints'"));
    }
  PrmSection section = reduction_section();
  PrmFile::read(write(dir, "subsection Reduction\n  set Number of joints = 9\nend\n"))
    .parse_section("Reduction", section);
  CHECK_THROWS_WITH(section.get_integer("Number of joints", 0, 7), Catch::Contains("must lie in [0, 7]"));
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
  CHECK_THROWS_WITH(PrmFile::read(write(dir, "subsection Chain\n  set x 1\nend\n")),
                    Catch::Contains(dir.file("p.prm") + ":2:"));
  CHECK_THROWS_WITH(PrmFile::read(write(dir, "end\n")), Catch::Contains(":1: 'end' without"));
  CHECK_THROWS_WITH(PrmFile::read(write(dir, "\nsubsection Chain\n")),
                    Catch::Contains(":2: subsection is never closed"));
  CHECK_THROWS_WITH(PrmFile::read(dir.file("none.prm")), Catch::Contains(dir.file("none.prm")));
  // A "\" on the last line continues into nothing: the statement still counts.
  CHECK_NOTHROW(PrmFile::read(write(dir, "subsection Chain\nend \\")));
  CHECK_THROWS_WITH(PrmFile::read(write(dir, "subsection Chain \\")),
                    Catch::Contains(":1: subsection is never closed"));
}

TEST_CASE("prm: a top-level subsection SoftChain does not know names file and line")
{
  // A misspelled title would leave all its entries at their defaults.
  ScratchDirectory dir("prm_unknown_subsection");
  CHECK_THROWS_WITH(PrmFile::read(write(dir, "subsection Mesh\nend\nsubsection Reduktion\nend\n")),
                    Catch::StartsWith(dir.file("p.prm") + ":3: unknown subsection 'Reduktion'") &&
                      Catch::Contains("Reduction"));
  CHECK_THROWS_WITH(PrmFile::read(write(dir, "set Pressure = 1\n")),
                    Catch::Contains(":1: parameter 'Pressure' outside every subsection"));
  // Nested subsections are the tiers' business (material regions).
  CHECK_NOTHROW(PrmFile::read(write(dir, "subsection Materials\n subsection rubber\n end\nend\n")));
}

TEST_CASE("prm: subsection_names lists the nested subsections in file order")
{
  ScratchDirectory dir("prm_subsection_names");
  const PrmFile    file = PrmFile::read(write(dir, "subsection Materials\n"
                                                    "  set Density = 1000\n"
                                                    "  subsection silicone\n  end\n"
                                                    "  subsection fabric\n"
                                                    "    subsection inner\n    end\n"
                                                    "  end\n"
                                                    "end\n"));
  CHECK(file.subsection_names("Materials") == std::vector<std::string>{"silicone", "fabric"});
  CHECK(file.subsection_names("Mesh").empty());
}

TEST_CASE("prm: selections and enums accept their names only")
{
  enum class Shape
  {
    box,
    tube
  };
  PrmSection section;
  section.file  = "f.prm";
  section.title = "T";
  section.declare("Shape", "tube");
  section.declare("Other", "sphere");
  CHECK(section.get_enum<Shape>("Shape", {{"box", Shape::box}, {"tube", Shape::tube}}) ==
        Shape::tube);
  CHECK_THROWS_WITH(section.get_enum<Shape>("Other", {{"box", Shape::box}, {"tube", Shape::tube}}),
                    Catch::Equals("f.prm: parameter 'Other' in subsection 'T': 'sphere' is not "
                                  "one of: box, tube"));
  CHECK(section.get_selection("Shape", {"tube"}) == "tube");
}

TEST_CASE("prm: canonical values do not depend on how a number is written")
{
  ScratchDirectory dir("prm_canonical");
  const auto values = [&](const std::string &set_lines) {
    PrmSection section;
    section.declare("E", "2.6e5");
    section.declare("Rigidity", "fabric: 2000, thread: 500");
    section.declare("Name", "p10");
    section.declare("Stepping", "1e-2", "not part of the design", false);
    PrmFile::read(write(dir, "subsection Materials\n" + set_lines + "end\n"))
      .parse_section("Materials", section);
    return section.canonical_values();
  };
  const std::string defaults = values("");
  CHECK(values("  set E = 260000\n") == defaults);
  CHECK(values("  set E = 2.60e+05 # same\n  set Rigidity = fabric:2e3,thread : 500.0\n") ==
        defaults);
  CHECK(values("  set E = 2.6e5\n  set Name = p10\n") == defaults);
  CHECK(values("  set E = 2.7e5\n") != defaults);
  CHECK(values("  set Rigidity = fabric: 2000, thread: 501\n") != defaults);
  CHECK(values("  set Name = p13\n") != defaults);
  // An entry declared as not part of the design is left out, whatever its value.
  CHECK(values("  set Stepping = 0.5\n") == defaults);
  CHECK(defaults.find("Stepping") == std::string::npos);
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
