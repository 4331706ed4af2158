// `softchain solve` with Write VTU = true on a small pressurised bender with
// springs: the files are read back. The body (.pvtu record and its .vtu
// pieces, deal.II's DataOut) must carry displacement (3 components), the
// Cauchy stress, von_mises, J and material_id; the springs' ASCII VTU one
// tension per line cell, never negative (tension-only springs) and positive
// somewhere (the pressure stretches the threads).
#include "fem_test_tools.h"

#include <softchain/commands.h>

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <algorithm>
#include <iterator>
#include <regex>

using namespace softchain;

namespace
{
  std::string file_text(const std::string &file)
  {
    std::ifstream      in(file);
    std::ostringstream text;
    text << in.rdbuf();
    REQUIRE(in);
    return text.str();
  }

  // All values of attribute `name` in `xml`, in order.
  std::vector<std::string> attribute_values(const std::string &xml, const std::string &name)
  {
    std::vector<std::string> values;
    const std::regex         pattern("\\b" + name + "=\"([^\"]*)\"");
    for (std::sregex_iterator m(xml.begin(), xml.end(), pattern), end; m != end; ++m)
      values.push_back((*m)[1]);
    return values;
  }

  // The opening tag of the DataArray named `name` ("" if none).
  std::string data_array_tag(const std::string &xml, const std::string &name)
  {
    std::smatch m;
    std::regex_search(xml, m, std::regex("<DataArray[^>]*Name=\"" + name + "\"[^>]*>"));
    return m.empty() ? "" : m.str();
  }

  // The numbers of an ASCII DataArray.
  std::vector<double> ascii_array(const std::string &xml, const std::string &name)
  {
    const std::string tag   = data_array_tag(xml, name);
    REQUIRE(!tag.empty());
    const auto        begin = xml.find(tag) + tag.size();
    std::istringstream in(xml.substr(begin, xml.find("</DataArray>", begin) - begin));
    return std::vector<double>(std::istream_iterator<double>(in), std::istream_iterator<double>());
  }

  void check_body_piece(const std::string &xml)
  {
    REQUIRE(std::stoul(attribute_values(xml, "NumberOfPoints").at(0)) > 0);
    const std::string displacement = data_array_tag(xml, "displacement");
    REQUIRE(!displacement.empty());
    CHECK(attribute_values(displacement, "NumberOfComponents").at(0) == "3");
    for (const std::string name : {"cauchy_xx", "cauchy_yz", "von_mises", "J", "material_id"})
      {
        INFO(name);
        CHECK(!data_array_tag(xml, name).empty());
      }
  }
} // namespace

TEST_CASE("solve writes VTU files that read back with all fields", "[fem][output]")
{
  const std::string directory = "vtu_output_test";
  std::filesystem::remove_all(directory);
  const std::string prm = "vtu_output.prm";
  std::ofstream(prm) << test::bender_prm("Q1", 4,
                                         "subsection Output\n  set Write VTU = true\nend\n"
                                         "subsection Loads\n  set Pressure = 5000\nend\n"
                                         "subsection Design\n  set Output directory = " +
                                           directory + "\nend\n");
  REQUIRE(solve_command(prm) == 0);

  const std::string vtu    = directory + "/vtu/";
  const auto        pieces = attribute_values(file_text(vtu + "solution_0000.pvtu"), "Source");
  REQUIRE(!pieces.empty());
  for (const auto &piece : pieces)
    check_body_piece(file_text(vtu + piece));

  const std::string springs  = file_text(vtu + "solution_springs_0000.vtu");
  const auto        tensions = ascii_array(springs, "tension");
  CHECK(tensions.size() == std::stoul(attribute_values(springs, "NumberOfCells").at(0)));
  CHECK(*std::min_element(tensions.begin(), tensions.end()) >= 0);
  CHECK(*std::max_element(tensions.begin(), tensions.end()) > 0);
}
