// SampleSet: the lateral and torsion samples are repeated at every pressure
// of `Force sample pressures`, each pressure a continuation chain of its own;
// the inflations form one chain per sign of the pressure.
#include <softchain/data/input_error.h>
#include <softchain/fem/sample_set.h>

#include "../data/scratch_directory.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>

using namespace softchain;
using namespace softchain::fem;

namespace
{
  // The sample set of a .prm whose Samples subsection holds `entries`, for
  // a tip face centred at x = 0.08 m and 16 mm wide (default torsion arm 4 mm).
  // `contact`: the entries of a subsection Contact (none if empty).
  SampleSet read_samples(const std::string &name, const std::string &entries,
                         const std::string &contact = "")
  {
    const testing::ScratchDirectory scratch("sample_set_test");
    const std::string               path = scratch.file(name + ".prm");
    std::ofstream(path) << "subsection Samples\n" << entries << "end\n"
                        << (contact.empty() ? "" : "subsection Contact\n" + contact + "end\n");
    const auto file = data::PrmFile::read(path);
    return SampleSet::read(file, {{{0.08, 0, 0}}, 0.016}, "h", geometry::ContactScene::read(file));
  }

  // The first sample of `role` in `set` (end() if none).
  std::vector<Sample>::const_iterator first_of_role(const SampleSet &set, const std::string &role)
  {
    return std::find_if(set.samples.begin(), set.samples.end(),
                        [&](const Sample &s) { return s.actuation.role == role; });
  }
} // namespace

TEST_CASE("force samples are made at each force sample pressure, one chain per role and pressure")
{
  const SampleSet set = read_samples("samples", "  set Pressure sweep = 1e4, 2e4\n"
                                                "  set Lateral tip forces = 0.1, 0.3\n"
                                                "  set Torsion couples = 0.2\n"
                                                "  set Bending tip forces = 0.25\n"
                                                "  set Force sample pressures = 0, 2e4\n");
  // 2 pressures + (2 lateral + 1 torsion + 1 bending) x 2 pressures.
  REQUIRE(set.samples.size() == 10);
  int lateral_at_pressure = 0, bending = 0;
  for (const Sample &s : set.samples)
    if (s.actuation.role == "bending")
      {
        ++bending;
        REQUIRE(s.actuation.point_forces.size() == 1);
        CHECK(s.actuation.point_forces[0].force == data::Point3{{0, -0.25, 0}}); // down, in the bending plane
      }
  CHECK(bending == 2);
  for (const Sample &s : set.samples)
    if (s.actuation.role == "lateral" && s.actuation.pressure == 2e4)
      {
        ++lateral_at_pressure;
        CHECK(s.label.find("at 20000 Pa") != std::string::npos);
        REQUIRE(s.actuation.point_forces.size() == 1);
        CHECK(s.actuation.point_forces[0].force[2] > 0);
      }
  CHECK(lateral_at_pressure == 2);
  // Chains: pressure; lateral, torsion and bending at p = 0 and at 20 kPa.
  CHECK(set.chains.size() == 7);
  for (const auto &chain : set.chains)
    for (const std::size_t k : chain)
      {
        const data::Actuation &a = set.samples[k].actuation;
        CHECK((a.role == "pressure" || a.pressure == set.samples[chain.back()].actuation.pressure));
      }
}

TEST_CASE("the inflations form one chain per sign of the pressure, held-out pressures included")
{
  const SampleSet set = read_samples("inflations", "  set Pressure sweep = 2e4, -1e4, 1e4, -3e4\n"
                                                   "  set Validation samples = 1.5e4 ; -2e4\n");
  REQUIRE(set.samples.size() == 6);
  REQUIRE(set.chains.size() == 2);
  for (const auto &chain : set.chains)
    {
      std::vector<double> pressures;
      for (const std::size_t k : chain)
        pressures.push_back(set.samples[k].actuation.pressure);
      INFO("chain starting at " << pressures.front() << " Pa");
      CHECK(pressures.size() == 3);
      // One sign per chain, in increasing |p| (each sample continues from
      // the nearest smaller pressure of its sign).
      CHECK(std::all_of(pressures.begin(), pressures.end(),
                        [&](double p) { return (p < 0) == (pressures.front() < 0); }));
      CHECK(std::is_sorted(pressures.begin(), pressures.end(),
                           [](double a, double b) { return std::abs(a) < std::abs(b); }));
    }
}

TEST_CASE("a validation sample can load the torsion couple's points by name")
{
  const SampleSet set =
    read_samples("validation", "  set Torsion couples = 0.2\n"
                               "  set Validation samples = 2e4 : tip+arm : 0,0.3,0 : tip-arm : 0,-0.3,0\n");
  const auto validation = first_of_role(set, "validation");
  const auto torsion    = first_of_role(set, "torsion");
  REQUIRE(validation != set.samples.end());
  REQUIRE(torsion != set.samples.end());
  REQUIRE(validation->actuation.point_forces.size() == 2);
  for (int k = 0; k < 2; ++k)
    CHECK(validation->actuation.point_forces[k].point == torsion->actuation.point_forces[k].point);
  CHECK(validation->actuation.point_forces[0].point == data::Point3{{0.08, 0, 0.004}});
  CHECK(validation->actuation.point_forces[1].force == data::Point3{{0, -0.3, 0}});
}

TEST_CASE("a chord sample is a tip force of role chord, listed before the validation samples")
{
  const SampleSet set =
    read_samples("chord", "  set Pressure sweep = 2e4\n"
                          "  set Chord samples = 2e4 : tip : 0.477,-0.1505,0\n"
                          "  set Validation samples = 2e4 : tip : 0,0,0.2\n");
  REQUIRE(set.samples.size() == 3);
  const auto chord      = first_of_role(set, "chord");
  const auto validation = first_of_role(set, "validation");
  REQUIRE(chord != set.samples.end());
  REQUIRE(validation != set.samples.end());
  CHECK(chord < validation);
  CHECK(chord->label == "chord 1");
  CHECK(chord->actuation.pressure == 2e4);
  REQUIRE(chord->actuation.point_forces.size() == 1);
  CHECK(chord->actuation.point_forces[0].point == data::Point3{{0.08, 0, 0}}); // the force point
  CHECK(chord->actuation.point_forces[0].force == data::Point3{{0.477, -0.1505, 0}});
  // A chain of its own (role chord at 20 kPa), like a validation sample.
  CHECK(set.chains.size() == 3);

  CHECK_THROWS_WITH(read_samples("bad_chord", "  set Chord samples = 4e4 : tip\n"),
                    Catch::Contains("parameter 'Chord samples'") &&
                      Catch::Contains("sample 'chord 1': '4e4 : tip' needs 'p'"));
}

TEST_CASE("'chord F' leaves the chord sample to the sweep, which needs the pressure sample at its pressure")
{
  const SampleSet set = read_samples("chord_keyword", "  set Pressure sweep = 2e4\n"
                                                      "  set Chord samples = 2e4 : tip : chord 0.5 ; "
                                                      "0 : tip : chord 0.25 ; 2e4 : tip : 0.3,0,0\n");
  // The listed force is a sample now; the two 'chord F' wait for their chord.
  REQUIRE(set.samples.size() == 2);
  REQUIRE(set.measured_requests.size() == 2);
  const auto &request = set.measured_requests[0];
  CHECK(request.pressure == 2e4);
  CHECK(request.forces == std::vector<double>{0.5});
  CHECK(request.points == std::vector<data::Point3>{{{0.08, 0, 0}}});
  CHECK(request.label == "chord 1");
  CHECK(request.role() == "chord");
  CHECK(set.measured_requests[1].pressure == 0); // the finger at rest: no pressure sample needed
  REQUIRE(set.inflation_at(2e4));
  CHECK(set.samples[*set.inflation_at(2e4)].actuation.role == "pressure");
  CHECK_FALSE(set.inflation_at(3e4));

  // The sample made from a chord: F along it, its id from the force.
  const Sample sample = SampleSet::measured_sample(request, {{{0.6, -0.8, 0}}}, "h");
  CHECK(sample.actuation.role == "chord");
  CHECK(sample.label == "chord 1");
  REQUIRE(sample.actuation.point_forces.size() == 1);
  CHECK(sample.actuation.point_forces[0].force[0] == Approx(0.3));
  CHECK(sample.actuation.point_forces[0].force[1] == Approx(-0.4));
  CHECK(sample.id == data::sample_id("h", sample.actuation));
  CHECK(sample.id != SampleSet::measured_sample(request, {{{0.8, -0.6, 0}}}, "h").id);
  // A chord measured on a state that another solver ordering or rank count
  // computed differs at round-off (1e-13): the same sample, still cached.
  CHECK(sample.id == SampleSet::measured_sample(request, {{{0.6 + 3e-13, -0.8 - 2e-13, 1e-13}}}, "h").id);

  CHECK_THROWS_WITH(read_samples("chord_without_inflation", "  set Pressure sweep = 1e4\n"
                                                            "  set Chord samples = 2e4 : tip : chord 0.5\n"),
                    Catch::Contains("sample 'chord 1'") && Catch::Contains("'chord' at 20000 Pa") &&
                      Catch::Contains("'Pressure sweep'"));
  CHECK_THROWS_WITH(read_samples("chord_bad_force", "  set Pressure sweep = 2e4\n"
                                                    "  set Chord samples = 2e4 : tip : chord -1\n"),
                    Catch::Contains("'chord -1' is not 'chord F'"));
  CHECK_THROWS_WITH(read_samples("chord_in_validation", "  set Pressure sweep = 2e4\n"
                                                        "  set Validation samples = 2e4 : tip : chord 0.5\n"),
                    Catch::Contains("Chord samples only"));
}

TEST_CASE("'palm F' leaves a skin sample to the sweep: one force per point along the palm's normal")
{
  const SampleSet set =
    read_samples("palm_keyword", "  set Pressure sweep = 2e4\n"
                                 "  set Skin samples = 2e4 : 0.05,0,-0.004 : palm 0.1 : 0.05,0,0.004 : palm 0.2\n");
  REQUIRE(set.samples.size() == 1); // the pressure sample; the skin sample waits for its normals
  REQUIRE(set.measured_requests.size() == 1);
  const auto &request = set.measured_requests[0];
  CHECK(request.role() == "skin");
  CHECK(request.label == "skin 1");
  CHECK(request.pressure == 2e4);
  CHECK(request.points == std::vector<data::Point3>{{{0.05, 0, -0.004}}, {{0.05, 0, 0.004}}});
  CHECK(request.forces == std::vector<double>{0.1, 0.2});
  // Each force along its own measured normal.
  const Sample sample = SampleSet::measured_sample(request, {{{0, 1, 0}}, {{0.6, 0.8, 0}}}, "h");
  CHECK(sample.actuation.role == "skin");
  REQUIRE(sample.actuation.point_forces.size() == 2);
  CHECK(sample.actuation.point_forces[0].force == data::Point3{{0, 0.1, 0}});
  CHECK(sample.actuation.point_forces[1].force[0] == Approx(0.12));
  CHECK(sample.actuation.point_forces[1].force[1] == Approx(0.16));

  CHECK_THROWS_WITH(read_samples("palm_not_a_force", "  set Pressure sweep = 2e4\n"
                                                     "  set Skin samples = 2e4 : 0.05,0,0 : 0,0.1,0\n"),
                    Catch::Contains("sample 'skin 1'") && Catch::Contains("is not 'palm F'"));
  CHECK_THROWS_WITH(read_samples("palm_without_inflation", "  set Pressure sweep = 1e4\n"
                                                           "  set Skin samples = 2e4 : 0.05,0,0 : palm 0.1\n"),
                    Catch::Contains("'palm' at 20000 Pa") && Catch::Contains("'Pressure sweep'"));
}

TEST_CASE("'shear F' leaves a skin sample to the sweep: one force per point along the palm towards the tip")
{
  const SampleSet set = read_samples("shear_keyword", "  set Pressure sweep = 2e4\n"
                                                      "  set Skin samples = 2e4 : 0.05,0,0 : palm 0.1 ; "
                                                      "2e4 : 0.05,0,0 : shear 0.1 : 0.05,0,0.004 : shear 0.2\n");
  REQUIRE(set.measured_requests.size() == 2);
  const auto &palm = set.measured_requests[0], &shear = set.measured_requests[1];
  CHECK(palm.keyword() == "palm");
  CHECK(shear.keyword() == "shear");
  CHECK(shear.role() == "skin"); // the reduction tells them apart by the forces' directions
  CHECK(shear.label == "skin 2");
  CHECK(shear.forces == std::vector<double>{0.1, 0.2});
  // The same point pressed and sheared: two samples, two ids.
  const Sample pressed = SampleSet::measured_sample(palm, {{{0, 1, 0}}}, "h");
  const Sample sheared = SampleSet::measured_sample(shear, {{{1, 0, 0}}, {{0.8, 0.6, 0}}}, "h");
  CHECK(sheared.actuation.point_forces[0].force == data::Point3{{0.1, 0, 0}});
  CHECK(sheared.actuation.point_forces[1].force[1] == Approx(0.12));
  CHECK(sheared.id != pressed.id);

  // One keyword per sample: its first force decides, the others must follow.
  CHECK_THROWS_WITH(read_samples("shear_mixed", "  set Pressure sweep = 2e4\n"
                                                "  set Skin samples = 2e4 : 0.05,0,0 : shear 0.1 : 0.05,0,0.004 : palm 0.1\n"),
                    Catch::Contains("sample 'skin 1'") && Catch::Contains("'palm 0.1' is not 'shear F'"));
  CHECK_THROWS_WITH(read_samples("shear_bad_force", "  set Pressure sweep = 2e4\n"
                                                    "  set Skin samples = 2e4 : 0.05,0,0 : shear 0\n"),
                    Catch::Contains("'shear 0' is not 'shear F'"));
}

TEST_CASE("contact samples carry their obstacle: frictionless ones form one chain and with friction one each")
{
  const std::string contact = "  subsection table\n    set Shape = plane\n    set Position = 0, -0.005, 0\n  end\n"
                              "  subsection can\n    set Shape = cylinder\n    set Friction coefficient = 0.3\n  end\n";
  const SampleSet set = read_samples("contact", "  set Pressure sweep = 1e4, 2e4\n"
                                                "  set Contact samples = table : 3e4, 1e4 ; can : 1e4, 2e4\n",
                                     contact);
  REQUIRE(set.samples.size() == 6);
  // Chains: the inflations; the table at 10 and 30 kPa, ordered by pressure;
  // the can at 10 kPa; the can at 20 kPa.
  REQUIRE(set.chains.size() == 4);
  const auto table = first_of_role(set, "contact");
  REQUIRE(table != set.samples.end());
  CHECK(table->label == "contact table 10000 Pa");
  REQUIRE(table->actuation.obstacles.size() == 1);
  CHECK(table->actuation.obstacles[0].name == "table");
  CHECK(table->actuation.obstacles[0].position[1] == -0.005);
  CHECK_FALSE(table->actuation.contact_law.empty());
  CHECK_FALSE(pressure_only(table->actuation)); // not an inflation: it never heads a force chain
  for (const auto &chain : set.chains)
    {
      const auto &first = set.samples[chain.front()].actuation;
      if (first.obstacles.empty())
        continue;
      const bool friction = first.obstacles[0].friction > 0;
      CHECK(chain.size() == (friction ? 1u : 2u));
      if (!friction)
        CHECK(set.samples[chain.back()].actuation.pressure == 3e4);
    }
  // The contact law is part of the samples' ids: a stiffer penalty solves them anew.
  const SampleSet stiffer = read_samples("stiffer", "  set Contact samples = table : 1e4\n",
                                         contact + "  set Penalty factor = 20\n");
  CHECK(stiffer.samples[0].id != table->id);
}

TEST_CASE("a contact sample naming no obstacle of subsection Contact is an InputError naming it")
{
  try
    {
      read_samples("no_obstacle", "  set Contact samples = wall : 1e4\n",
                   "  subsection table\n    set Shape = plane\n  end\n");
      FAIL("no error");
    }
  catch (const data::InputError &e)
    {
      const std::string what = e.what();
      CHECK(what.find("Contact samples") != std::string::npos);
      CHECK(what.find("'wall' is no obstacle") != std::string::npos);
    }
}

TEST_CASE("sample groups default to one per MPI rank, and a negative count is an InputError naming it")
{
  CHECK(read_samples("groups_default", "  set Pressure sweep = 1e4\n").sample_groups == 0);
  CHECK(read_samples("groups_two", "  set Pressure sweep = 1e4\n  set Sample groups = 2\n").sample_groups == 2);
  CHECK_THROWS_WITH(read_samples("groups_negative", "  set Pressure sweep = 1e4\n  set Sample groups = -1\n"),
                    Catch::Contains("Sample groups") && Catch::Contains("0 (one per rank) or more"));
}
