#include <softchain/fem/tip_motion_protocol.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace softchain::fem
{
  namespace
  {
    constexpr double degree = M_PI / 180.0;

    void declare(data::PrmSection &section)
    {
      section.declare("Tip angle", "0", "deg the inflation turns the tip frame; 0: no protocol");
      section.declare("Angle tolerance", "0.5", "deg, how close the inflation gets to the tip angle");
      section.declare("First pressure", "2e4",
                      "Pa, the first trial when no pressure-only sample is solved");
      section.declare("Lateral amplitude", "0.01", "m, tip moved along +-z of the tip frame");
      section.declare("Bending amplitude", "0.01", "m, tip moved along +-y of the tip frame");
      section.declare("Twist amplitude", "20", "deg, tip turned about +-x of the tip frame");
      section.declare("Steps", "4", "samples from 0 to each amplitude");
      section.declare("Tip contact", "point",
                      "point: the lateral and bending motions move the tip face's centre, the "
                      "face free to turn (a chopstick); face: they move the whole face rigidly");
    }

    // p to four significant digits: the ids of the inflation samples then do
    // not depend on the round-off of the angles they were interpolated from.
    double rounded(const double p)
    {
      if (!(p > 0))
        return p;
      const double unit = std::pow(10.0, std::floor(std::log10(p)) - 3);
      return std::round(p / unit) * unit;
    }

    std::string millimetres(const double metres)
    {
      std::ostringstream text;
      text << std::showpos << 1e3 * metres << " mm";
      return text.str();
    }

    std::string degrees(const double radians)
    {
      std::ostringstream text;
      text << std::showpos << radians / degree << " deg";
      return text.str();
    }
  } // namespace

  TipMotionProtocol TipMotionProtocol::read(const data::PrmFile &prm, const std::string &design_hash)
  {
    data::PrmSection section;
    declare(section);
    prm.parse_section("Protocol", section);
    const auto positive = [&](const std::string &name) {
      const double value = section.get_double(name);
      section.require(value > 0, name, "must be > 0");
      return value;
    };
    TipMotionProtocol protocol;
    protocol.design_hash = design_hash;
    const double angle   = section.get_double("Tip angle");
    section.require(angle >= 0 && angle < 180, "Tip angle", "must be in [0, 180) degrees");
    protocol.tip_angle       = angle * degree;
    protocol.angle_tolerance = positive("Angle tolerance") * degree;
    protocol.first_pressure  = positive("First pressure");
    protocol.lateral         = positive("Lateral amplitude");
    protocol.bending         = positive("Bending amplitude");
    protocol.twist           = positive("Twist amplitude") * degree;
    // Each step is six FEM samples (both signs of three motions): 100 are 600.
    protocol.steps           = section.get_integer("Steps", 1, 100);
    protocol.point_contact   = section.get_selection("Tip contact", {"point", "face"}) == "point";
    return protocol;
  }

  double TipMotionProtocol::tip_angle_of(const data::TipPose &tip)
  {
    return data::rotation_angle_between(Eigen::Matrix3d::Identity(), tip.rotation);
  }

  std::string TipMotionProtocol::target_text() const
  {
    std::ostringstream text;
    text << "tip angle " << tip_angle / degree << " +- " << angle_tolerance / degree << " deg";
    return text.str();
  }

  std::optional<TipMotionProtocol::Trial>
  TipMotionProtocol::reached(const std::vector<Trial> &trials) const
  {
    std::optional<Trial> best;
    for (const Trial &t : trials)
      if (std::abs(t.angle - tip_angle) <= angle_tolerance &&
          (!best || std::abs(t.angle - tip_angle) < std::abs(best->angle - tip_angle)))
        best = t;
    return best;
  }

  // Secant through the two equilibria nearest the tip angle, kept inside the
  // bracket [largest pressure below the angle, smallest pressure above it or
  // without equilibrium]; bisection where the secant leaves the bracket or
  // the bracket ends at a pressure without equilibrium (beyond a limit point
  // the angle curve gives no secant to trust).
  double TipMotionProtocol::next_pressure(const std::vector<Trial> &trials) const
  {
    std::vector<Trial> solved;
    double             low = 0.0, high = INFINITY;
    bool               high_failed = false;
    for (const Trial &t : trials)
      if (std::isfinite(t.angle))
        {
          solved.push_back(t);
          if (t.angle < tip_angle)
            low = std::max(low, t.pressure);
          else if (t.pressure < high)
            {
              high        = t.pressure;
              high_failed = false;
            }
        }
      else if (t.pressure < high)
        {
          high        = t.pressure;
          high_failed = true;
        }
    std::sort(solved.begin(), solved.end(), [&](const Trial &a, const Trial &b) {
      return std::abs(a.angle - tip_angle) < std::abs(b.angle - tip_angle);
    });
    double p = NAN;
    if (solved.size() >= 2 && solved[0].angle != solved[1].angle)
      p = solved[0].pressure + (tip_angle - solved[0].angle) * (solved[1].pressure - solved[0].pressure) /
                                 (solved[1].angle - solved[0].angle);
    else if (solved.size() == 1 && solved[0].pressure > 0) // angle ~ p from rest
      p = solved[0].pressure * tip_angle / solved[0].angle;
    if (high_failed || !(p > low && p < high))
      p = std::isfinite(high) ? 0.5 * (low + high) : (low > 0 ? 2 * low : first_pressure);
    return rounded(p);
  }

  Sample TipMotionProtocol::inflation(const double pressure) const
  {
    Sample sample;
    sample.actuation.pressure = pressure;
    sample.actuation.role     = "protocol inflation";
    std::ostringstream label;
    label << "protocol inflation " << pressure << " Pa";
    sample.label = label.str();
    sample.id    = data::sample_id(design_hash, sample.actuation);
    return sample;
  }

  std::vector<std::vector<TipMotionProtocol::Motion>>
  TipMotionProtocol::motions(const data::Actuation &inflated,
                                                              const data::TipPose   &tip) const
  {
    struct Direction
    {
      const char     *name;
      Eigen::Vector3d axis; // tip frame
      double          amplitude;
      bool            turn; // rotation (else translation)
    };
    const Direction directions[] = {{"lateral", Eigen::Vector3d::UnitZ(), lateral, false},
                                    {"bending", Eigen::Vector3d::UnitY(), bending, false},
                                    {"twist", Eigen::Vector3d::UnitX(), twist, true}};
    std::vector<std::vector<Motion>> chains;
    for (const Direction &d : directions)
      for (const double sign : {1.0, -1.0})
        {
          chains.emplace_back();
          for (int k = 1; k <= steps; ++k)
            {
              const double          amount = sign * d.amplitude * k / steps;
              const Eigen::Vector3d world  = tip.rotation * (amount * d.axis);
              data::TipMotion       motion;
              (d.turn ? motion.rotation : motion.translation) = {{world.x(), world.y(), world.z()}};
              motion.point_contact = point_contact && !d.turn; // a twist needs the face held
              Sample sample;
              sample.actuation            = inflated;
              sample.actuation.role       = "protocol";
              sample.actuation.tip_motion = motion;
              sample.label = std::string("protocol ") + d.name + " " +
                             (d.turn ? degrees(amount) : millimetres(amount));
              sample.id    = data::sample_id(design_hash, sample.actuation);
              chains.back().push_back({sample, d.name, d.turn ? amount / degree : 1e3 * amount,
                                       d.turn ? "deg" : "mm"});
            }
        }
    return chains;
  }
} // namespace softchain::fem
