// `softchain solve` with Write VTU = true on a small pressurised bender with
// springs: the files are read back. The body (.pvtu record and its .vtu
// pieces, deal.II's DataOut: zlib-compressed base64 "binary" arrays) must
// carry displacement (3 components per point), the Cauchy stress, von_mises,
// J and material_id with sane values; the springs' ASCII VTU one tension per
// line cell, never negative (tension-only springs) and positive somewhere
// (the pressure stretches the threads).
#include "fem_test_tools.h"

#include <softchain/app/commands.h>

#include <zlib.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>

using namespace dealii;
using namespace softchain;
using namespace softchain::fem;

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

  std::string base64_decode(const std::string &text)
  {
    const std::string alphabet =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string  bytes;
    unsigned int buffer = 0, bits = 0;
    for (const char c : text)
      {
        const auto value = alphabet.find(c);
        if (value == std::string::npos)
          continue; // padding
        buffer = (buffer << 6) | value;
        bits += 6;
        if (bits >= 8)
          {
            bits -= 8;
            bytes.push_back(char((buffer >> bits) & 0xff));
          }
      }
    return bytes;
  }

  // A DataOut "binary" Float32 array: base64 of a header of four uint32
  // (one block, block size, last block size, compressed size), then base64
  // of the zlib-compressed little-endian floats.
  std::vector<float> binary_array(const std::string &xml, const std::string &name)
  {
    const std::string tag = data_array_tag(xml, name);
    REQUIRE(!tag.empty());
    const auto        begin = xml.find(tag) + tag.size();
    std::istringstream in(xml.substr(begin, xml.find("</DataArray>", begin) - begin));
    std::string        text;
    in >> text;
    std::uint32_t header[4];
    const auto    header_bytes = base64_decode(text.substr(0, 24));
    std::memcpy(header, header_bytes.data(), sizeof(header));
    REQUIRE(header[0] == 1);
    const auto   compressed = base64_decode(text.substr(24));
    std::vector<float> values(header[1] / sizeof(float));
    uLongf             size = header[1];
    REQUIRE(uncompress(reinterpret_cast<Bytef *>(values.data()), &size,
                       reinterpret_cast<const Bytef *>(compressed.data()),
                       compressed.size()) == Z_OK);
    REQUIRE(size == header[1]);
    return values;
  }

  // Largest |u| over the points of a displacement array (x, y, z per point).
  double largest_displacement(const std::vector<float> &u)
  {
    double largest = 0;
    for (std::size_t k = 0; k + 2 < u.size(); k += 3)
      largest = std::max(largest, std::hypot(double(u[k]), double(u[k + 1]), double(u[k + 2])));
    return largest;
  }

  // The data row of solve_summary.csv: 15 columns and 6 per obstacle
  // (docs/conventions.md, "CSV files").
  std::vector<double> summary_row(const std::string &file, const unsigned int obstacles)
  {
    std::istringstream in(file_text(file));
    std::string        header, row;
    std::getline(in, header);
    std::getline(in, row);
    std::vector<double> columns;
    std::istringstream  cells(row);
    for (std::string cell; std::getline(cells, cell, ',');)
      columns.push_back(std::stod(cell));
    REQUIRE(columns.size() == 15 + 6 * obstacles);
    return columns;
  }

  // The body's fields: all present, with one value per point (three for
  // the displacement), J > 0, von Mises >= 0, material id 0 (one region).
  // Returns the largest |u|.
  double check_body_piece(const std::string &xml)
  {
    const auto n_points = std::stoul(attribute_values(xml, "NumberOfPoints").at(0));
    REQUIRE(n_points > 0);
    const auto u = binary_array(xml, "displacement");
    CHECK(u.size() == 3 * n_points);
    for (const std::string name : {"cauchy_xx", "cauchy_yz", "von_mises", "J", "material_id"})
      {
        INFO(name);
        CHECK(binary_array(xml, name).size() == n_points);
      }
    const auto J = binary_array(xml, "J"), von_mises = binary_array(xml, "von_mises"),
               material = binary_array(xml, "material_id");
    CHECK(*std::min_element(J.begin(), J.end()) > 0);
    CHECK(*std::min_element(von_mises.begin(), von_mises.end()) >= 0);
    CHECK(std::all_of(material.begin(), material.end(), [](float m) { return m == 0; }));
    return largest_displacement(u);
  }
} // namespace

TEST_CASE("solve writes VTU files that read back with all fields", "[fem][output]")
{
  const std::string directory = "vtu_output_test";
  std::filesystem::remove_all(directory);
  const std::string prm = test::write_prm(
    "vtu_output", test::bender_prm("Q1", 4,
                                   "subsection Output\n  set Write VTU = true\nend\n"
                                   "subsection Loads\n  set Pressure = 5000\nend\n"
                                   "subsection Contact\n  subsection table\n    set Shape = plane\n"
                                   "    set Position = 0, -0.0005, 0\n    set Friction coefficient = 0.5\n"
                                   "  end\nend\n"
                                   "subsection Design\n  set Output directory = " +
                                     directory + "\nend\n"));
  REQUIRE(softchain::app::solve_command(data::PrmFile::read(prm)) == 0);
  MPI_Barrier(MPI_COMM_WORLD); // every rank's piece written

  const std::string vtu    = directory + "/vtu/";
  const auto        pieces = attribute_values(file_text(vtu + "solution_0000.pvtu"), "Source");
  REQUIRE(!pieces.empty());
  double largest = 0;
  for (const auto &piece : pieces)
    largest = std::max(largest, check_body_piece(file_text(vtu + piece)));
  // The mean of u over the tip face is a convex combination of nodal values
  // (Q1), so it cannot exceed the largest nodal |u| (up to the float32
  // rounding of the VTU, 6e-8 relative).
  const auto   summary = summary_row(directory + "/solve_summary.csv", 1);
  const double tip     = std::hypot(summary[4], summary[5], summary[6]);
  // The body's balance: the support's and the table's reactions cancel (a
  // closed cavity's pressure has no resultant), to the solve's tolerance.
  for (unsigned int i = 0; i < 3; ++i)
    CHECK(summary[8 + i] + summary[15 + i] == Approx(0).margin(1e-6 * std::hypot(summary[8], summary[9])));
  CHECK(tip > 0);
  CHECK(largest >= tip * (1 - 1e-6));

  const std::string springs  = file_text(vtu + "solution_springs_0000.vtu");
  const auto        tensions = ascii_array(springs, "tension");
  CHECK(tensions.size() == std::stoul(attribute_values(springs, "NumberOfCells").at(0)));
  CHECK(*std::min_element(tensions.begin(), tensions.end()) >= 0);
  CHECK(*std::max_element(tensions.begin(), tensions.end()) > 0);

  // The contact points: a pressure >= 0, somewhere > 0 (the bent tip on the
  // table 0.5 mm below it), a 3-vector of tangential traction each, a
  // status among open (0), stick (1) and slip (2).
  const std::string  contact  = file_text(vtu + "solution_contact_0000.vtu");
  const unsigned int points   = std::stoul(attribute_values(contact, "NumberOfCells").at(0));
  const auto         pressure = ascii_array(contact, "contact_pressure");
  const auto         status   = ascii_array(contact, "contact_status");
  CHECK(points > 0);
  CHECK(pressure.size() == points);
  CHECK(ascii_array(contact, "tangential_traction").size() == 3 * points);
  CHECK(ascii_array(contact, "gap").size() == points);
  CHECK(*std::min_element(pressure.begin(), pressure.end()) >= 0);
  CHECK(*std::max_element(pressure.begin(), pressure.end()) > 0);
  CHECK(std::all_of(status.begin(), status.end(), [](double s) { return s == 0 || s == 1 || s == 2; }));
  CHECK(std::count(status.begin(), status.end(), 0.0) < static_cast<long>(points));
}
