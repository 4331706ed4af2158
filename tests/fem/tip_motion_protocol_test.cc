// TipMotionProtocol: the search for the inflation pressure on model angle
// curves (a reachable tip angle, one beyond a limit point, no pressure
// sample to start from) and the motion samples along the tip frame.
#include <softchain/fem/tip_motion_protocol.h>

#include "../data/scratch_directory.h"

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <set>

using namespace softchain;
using namespace softchain::fem;

// Its own namespace, so that the unity batch that compiles this file with
// others holds each file's constants once.
namespace tip_motion_protocol_test
{

  namespace
  {
    constexpr double degree = M_PI / 180.0;

    TipMotionProtocol read(const std::string &entries)
    {
      // A directory of this process's own: test cases run in parallel.
      const testing::ScratchDirectory scratch("protocol_test");
      const std::string               path = scratch.file("protocol.prm");
      std::ofstream(path) << "subsection Protocol\n" << entries << "end\n";
      return TipMotionProtocol::read(data::PrmFile::read(path), "h");
    }

    // The sweep's loop: trials until the angle is reached, a pressure repeats
    // or the trials run out; returns the trials.
    std::vector<TipMotionProtocol::Trial> search(const TipMotionProtocol           &protocol,
                                                 const std::function<double(double)> &angle,
                                                 const std::vector<double>         &pressure_samples)
    {
      std::vector<TipMotionProtocol::Trial> trials{{0.0, 0.0}};
      for (const double p : pressure_samples)
        trials.push_back({p, angle(p)});
      for (unsigned int n = 0; n < protocol.max_trials() && !protocol.reached(trials); ++n)
        {
          const double p = protocol.next_pressure(trials);
          if (std::any_of(trials.begin(), trials.end(), [&](const auto &t) { return t.pressure == p; }))
            break;
          trials.push_back({p, angle(p)});
        }
      return trials;
    }

    // A stiffening finger: the tip angle saturates at 2 rad.
    double saturating(const double p)
    {
      return 2.0 * (1.0 - std::exp(-p / 3e4));
    }
  } // namespace

  TEST_CASE("the inflation search reaches the tip angle in a few trials from the pressure samples")
  {
    const auto protocol = read("  set Tip angle = 90\n  set Angle tolerance = 0.5\n");
    const auto trials   = search(protocol, saturating, {1e4, 2e4, 3e4, 4e4, 5e4});
    const auto reached  = protocol.reached(trials);
    REQUIRE(reached);
    CHECK(std::abs(reached->angle - 90 * degree) <= 0.5 * degree);
    // Secant steps on a smooth curve: two trials suffice here (measured), four
    // leave room for a less smooth one.
    CHECK(trials.size() - 6 <= 4);
    // Pressures to four significant digits (stable sample ids).
    for (const auto &t : trials)
      CHECK(t.pressure == std::round(t.pressure / 10) * 10);
  }

  TEST_CASE("without pressure samples the search starts at the first pressure")
  {
    const auto protocol = read("  set Tip angle = 60\n  set First pressure = 1.5e4\n");
    CHECK(protocol.next_pressure({{0.0, 0.0}}) == 1.5e4);
    const auto trials = search(protocol, saturating, {});
    REQUIRE(protocol.reached(trials));
    CHECK(std::abs(protocol.reached(trials)->angle - 60 * degree) <= 0.5 * degree);
  }

  TEST_CASE("a tip angle beyond the limit point is not reached, the trials close in on the limit")
  {
    // No equilibrium past 42 kPa (a limit point), where the angle is 86.3 deg.
    const auto limited = [](double p) { return p <= 4.2e4 ? saturating(p) : NAN; };
    const auto protocol = read("  set Tip angle = 90\n");
    const auto trials   = search(protocol, limited, {1e4, 2e4, 3e4, 4e4, 5e4});
    CHECK_FALSE(protocol.reached(trials));
    // Bisection between the last equilibrium and the first failure.
    double below = 0, above = INFINITY;
    for (const auto &t : trials)
      if (std::isfinite(t.angle))
        below = std::max(below, t.pressure);
      else
        above = std::min(above, t.pressure);
    CHECK(below <= 4.2e4);
    CHECK(above > 4.2e4);
    CHECK(above - below < 500); // 10 trials halve the 8 kPa bracket 6+ times
  }

  TEST_CASE("the motion samples: six chains along the inflated tip frame's axes")
  {
    const auto protocol = read("  set Tip angle = 90\n  set Lateral amplitude = 0.01\n"
                               "  set Bending amplitude = 0.004\n  set Twist amplitude = 20\n"
                               "  set Steps = 3\n");
    data::Actuation inflated;
    inflated.pressure = 3e4;
    inflated.role     = "protocol inflation";
    data::TipPose tip;
    tip.rotation = Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const auto chains = protocol.motions(inflated, tip);
    REQUIRE(chains.size() == 6);
    std::set<std::string> ids;
    for (const auto &chain : chains)
      {
        REQUIRE(chain.size() == 3);
        for (const auto &[s, kind, amount, unit] : chain)
          {
            CHECK(s.actuation.role == "protocol");
            CHECK(s.actuation.pressure == 3e4);
            REQUIRE(s.actuation.tip_motion);
            ids.insert(s.id);
          }
      }
    CHECK(ids.size() == 18);
    // Lateral: along the tip frame's z, which a bend about z leaves world z.
    const auto &lateral = chains[0].back().sample.actuation.tip_motion->translation;
    CHECK(lateral[2] == Approx(0.01));
    CHECK(std::abs(lateral[0]) + std::abs(lateral[1]) < 1e-15);
    // Bending, negative side, first step: -4/3 mm along the tip frame's y =
    // R e_y = +x world for a tip turned -90 deg about z.
    const auto &bending = chains[3].front().sample.actuation.tip_motion->translation;
    CHECK(bending[0] == Approx(-0.004 / 3));
    CHECK(std::abs(bending[1]) < 1e-15);
    // Twist: about the tip frame's x = R e_x = -y world.
    const auto &twist = chains[4].back().sample.actuation.tip_motion->rotation;
    CHECK(twist[1] == Approx(-20 * degree));
    CHECK(chains[4].back().sample.label == "protocol twist +20 deg");
    CHECK(chains[4].back().kind == "twist");
    CHECK(chains[4].back().amount == Approx(20));
    CHECK(chains[3].front().amount == Approx(-4.0 / 3));
    CHECK(chains[3].front().unit == "mm");
  }

  TEST_CASE("protocol parameters out of range are refused, naming the parameter")
  {
    CHECK_THROWS_WITH(read("  set Tip angle = 200\n"), Catch::Contains("'Tip angle'"));
    CHECK_THROWS_WITH(read("  set Tip angle = 90\n  set Twist amplitude = 0\n"),
                      Catch::Contains("'Twist amplitude'"));
    CHECK_THROWS_WITH(read("  set Steps = 0\n"), Catch::Contains("'Steps'"));
    CHECK_THROWS_WITH(read("  set Steps = 40000\n"), Catch::Contains("'Steps'") && Catch::Contains("[1, 100]"));
  }
} // namespace tip_motion_protocol_test
