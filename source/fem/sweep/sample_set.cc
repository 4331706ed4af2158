#include <softchain/data/content_hash.h>
#include <softchain/data/input_error.h>
#include <softchain/data/text.h>
#include <softchain/fem/sample_set.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>

namespace softchain::fem
{
  namespace
  {
    using data::trim;

    void declare(data::PrmSection &section)
    {
      section.declare("Pressure sweep", "", "Pa, pressure-only samples (role pressure)");
      section.declare("Volume sweep", "",
                      "cavity volume ratios V/V0 > 1: the cavity inflated to each, the pressure "
                      "solved for and stored (role volume); follows the finger past the limit "
                      "point of its pressure");
      section.declare("Lateral tip forces", "", "N along +z at the force point (role lateral)");
      section.declare("Torsion couples", "", "N, two opposite forces along y (role torsion)");
      section.declare("Bending tip forces", "",
                      "N along -y at the force point (role bending): they give k_phi to the "
                      "joints that the pressure does not load (e.g. in the solid base fill)");
      section.declare("Force sample pressures", "0",
                      "Pa: the lateral, torsion and bending samples are made at each of "
                      "these pressures, for k_theta(p), k_psi(p) and k_phi(p)");
      section.declare("Torsion arm", "0", "m, half the z distance of the couple's points; "
                                          "0: a quarter of the tip face width");
      section.declare("Force point", "", "x,y,z; empty: centre of the tip face");
      section.declare("Chord samples", "",
                      "p : point : force ; ... (role chord): a small tip force pulling along the "
                      "base-tip chord of the pressure-only state at p, given as x,y,z or as "
                      "'chord F' (F newtons along that chord, found by the sweep); the reduction "
                      "fits the links' compliance to them (reduction/README.md)");
      section.declare("Skin samples", "",
                      "p : point : palm F [: point : palm F ...] ; ... (role skin): forces of F "
                      "newtons pressing each point (x,y,z on the palm) along the palm's inward "
                      "normal of the pressure-only state at p, found by the sweep; with 'shear F' "
                      "instead, along the palm towards the tip (one keyword per sample); the "
                      "reduction fits the sections' compliance under contact and friction to "
                      "them (reduction/README.md)");
      section.declare("Validation samples", "",
                      "p : point : force [: point : force] ; ...; a point is x,y,z, tip (the "
                      "force point) or tip+arm, tip-arm (the torsion couple's points)");
      section.declare("Contact samples", "",
                      "obstacle : p, p, ... ; ... (role contact): the finger inflated to each "
                      "pressure against the obstacle of subsection Contact named (a blocked "
                      "force on a plane, a grasp of a cylinder); frictionless ones continue "
                      "along the pressure, with friction each from rest");
      section.declare("Sample groups", "0",
                      "MPI sample groups solving samples in parallel; 0: one per rank");
      section.declare("Continuation", "true", "start each sample from its converged neighbour");
    }

    std::vector<std::string> split(const std::string &text, const char separator)
    {
      std::vector<std::string> items;
      std::istringstream       in(text);
      std::string              item;
      while (std::getline(in, item, separator))
        items.push_back(trim(item));
      return items;
    }

    double number(const std::string &text, const std::string &where)
    {
      std::size_t used = 0;
      try
        {
          const double value = std::stod(text, &used);
          if (used == text.size() && std::isfinite(value))
            return value;
        }
      catch (const std::exception &)
        {}
      throw data::InputError(where + ": '" + text + "' is not a number");
    }

    data::Point3 triple(const std::string &text, const std::string &where)
    {
      const auto items = split(text, ',');
      if (items.size() != 3)
        throw data::InputError(where + ": '" + text + "' needs three components x,y,z");
      return {{number(items[0], where), number(items[1], where), number(items[2], where)}};
    }

    std::string label(const std::string &role, const double value, const char *unit,
                      const double pressure = 0)
    {
      std::ostringstream text;
      text << role << ' ' << value << ' ' << unit;
      if (pressure != 0)
        text << " at " << pressure << " Pa";
      return text.str();
    }

    // A chord or validation sample's point: "tip" (the force point), "tip+arm"
    // and "tip-arm" (the torsion couple's points, the force point moved by the
    // torsion arm along +z and -z) or x,y,z.
    data::Point3 listed_point(const std::string &text, const data::Point3 &tip,
                              const double arm, const std::string &where)
    {
      if (text == "tip")
        return tip;
      if (text == "tip+arm" || text == "tip-arm")
        return {{tip[0], tip[1], tip[2] + (text == "tip+arm" ? arm : -arm)}};
      return triple(text, where);
    }

    // One chord or validation entry "p : point : force [: point : force ...]",
    // a sample of `role`.
    data::Actuation listed_actuation(const std::string &role, const std::string &entry,
                                     const data::Point3 &tip, const double arm,
                                     const std::string &where)
    {
      const auto fields = split(entry, ':');
      if (fields.size() % 2 == 0)
        throw data::InputError(where + ": '" + entry + "' needs 'p' followed by "
                                       "'point : force' pairs");
      data::Actuation a;
      a.role     = role;
      a.pressure = number(fields[0], where);
      for (std::size_t k = 1; k < fields.size(); k += 2)
        a.point_forces.push_back({listed_point(fields[k], tip, arm, where),
                                  triple(fields[k + 1], where)});
      return a;
    }

    // The chain key: role, force points and, for samples with forces, the
    // pressure (a chain of forces grows at one pressure). The inflations
    // under pressure control share one chain per sign of the pressure,
    // whatever their role (the pressure sweep and the held-out pressures):
    // a held-out pressure then continues from the nearest lower swept one,
    // not from rest. Split by sign, each chain loads proportionally, so a
    // sample past a limit point of its chain has no equilibrium on that path
    // (a vacuum that collapses the finger says nothing of inflation).
    std::string chain_key(const data::Actuation &a)
    {
      // A contact chain ramps the pressure against its obstacles. Friction
      // makes the state depend on the path, and a chain continued from a
      // cached sample would lose its stick history: each such sample is a
      // chain of its own, solved from rest.
      if (!a.obstacles.empty())
        {
          std::string key = "contact " + a.contact_law;
          for (const auto &o : a.obstacles)
            key += " " + o.canonical_text();
          const bool friction = std::any_of(a.obstacles.begin(), a.obstacles.end(),
                                            [](const auto &o) { return o.friction > 0; });
          return friction ? key + " p " + data::canonical(a.pressure) : key;
        }
      if (pressure_only(a) && !a.cavity_volume_ratio)
        return a.pressure < 0 ? "deflation" : "inflation";
      std::string key = a.role;
      if (!a.point_forces.empty())
        key += " p " + data::canonical(a.pressure);
      for (const auto &f : a.point_forces)
        for (const double v : f.point)
          key += ' ' + data::canonical(v);
      return key;
    }

    // A sample of `role` at `pressure` with `forces` (no tip motion, pressure control).
    Sample sample_of(const std::string &role, const double pressure,
                     std::vector<data::PointForce> forces, const std::string &label)
    {
      Sample sample;
      sample.actuation.role         = role;
      sample.actuation.pressure     = pressure;
      sample.actuation.point_forces = std::move(forces);
      sample.label                  = label;
      return sample;
    }

    // "obstacle : p, p, ... ; ..." of Contact samples: one sample per
    // obstacle and pressure, the obstacle of `contact` by that name.
    std::vector<Sample> contact_samples(const data::PrmSection &s, const geometry::ContactScene &contact)
    {
      std::vector<Sample> samples;
      for (const auto &entry : split(s.get("Contact samples"), ';'))
        {
          if (entry.empty())
            continue;
          const auto        fields = split(entry, ':');
          const std::string where  = s.describe("Contact samples") + ", entry '" + entry + "'";
          if (fields.size() != 2)
            throw data::InputError(where + ": needs 'obstacle : pressures'");
          const geometry::Obstacle *obstacle = contact.find(fields[0]);
          if (!obstacle)
            throw data::InputError(where + ": '" + fields[0] + "' is no obstacle of subsection "
                                           "'Contact'");
          for (const auto &text : split(fields[1], ','))
            {
              const double p = number(text, where);
              Sample sample = sample_of("contact", p, {}, label("contact " + fields[0], p, "Pa"));
              sample.actuation.obstacles   = {obstacle->description};
              sample.actuation.contact_law = contact.law_text();
              samples.push_back(sample);
            }
        }
      return samples;
    }

    // "chord F", "palm F" or "shear F" (`keyword` F): F, else nothing.
    std::optional<double> measured_force(const std::string &text, const std::string &keyword,
                                         const std::string &where)
    {
      std::istringstream in(text);
      std::string        word, rest;
      double             force = 0;
      if (!(in >> word) || word != keyword)
        return std::nullopt;
      if (!(in >> force) || (in >> rest) || !(force > 0))
        throw data::InputError(where + ": '" + text + "' is not '" + keyword +
                               " F' with a force F > 0 in N");
      return force;
    }

    // One entry "p : point : chord F" of Chord samples or "p : point : palm F
    // [: point : palm F ...]" of Skin samples ('shear F' instead of 'palm F'
    // throughout: along the palm): its request, checked.
    SampleSet::MeasuredForceRequest measured_request(const std::vector<std::string> &fields,
                                                     const SampleSet::MeasuredForceRequest::Direction direction,
                                                     const data::Point3 &tip, const double arm,
                                                     const std::string &name, const std::string &where)
    {
      SampleSet::MeasuredForceRequest r;
      r.direction               = direction;
      const std::string keyword = r.keyword();
      if (direction == SampleSet::MeasuredForceRequest::Direction::chord && fields.size() != 3)
        throw data::InputError(where + ": a force 'chord F' takes one point: 'p : point : chord F'");
      if (fields.size() < 3 || fields.size() % 2 == 0)
        throw data::InputError(where + ": needs 'p' followed by 'point : " + keyword + " F' pairs");
      r.pressure = number(fields[0], where);
      r.label    = name;
      r.where    = where;
      for (std::size_t k = 1; k < fields.size(); k += 2)
        {
          const auto force = measured_force(fields[k + 1], keyword, where);
          if (!force)
            throw data::InputError(where + ": '" + fields[k + 1] + "' is not '" + keyword + " F'");
          r.points.push_back(listed_point(fields[k], tip, arm, where));
          r.forces.push_back(*force);
        }
      return r;
    }

    std::vector<Sample> listed_samples(const data::PrmSection &s, const SampleSet::TipFace &tip,
                                       const geometry::ContactScene        &contact,
                                       std::vector<SampleSet::MeasuredForceRequest> &measured_requests)
    {
      const data::Point3 at =
        s.get("Force point").empty() ? tip.centre : triple(s.get("Force point"), s.describe("Force point"));
      const double arm = s.get_double("Torsion arm") > 0 ? s.get_double("Torsion arm") : tip.width / 4;
      std::vector<Sample> samples;
      for (const double p : s.get_double_list("Pressure sweep"))
        samples.push_back(sample_of("pressure", p, {}, label("pressure", p, "Pa")));
      for (const double ratio : s.get_double_list("Volume sweep"))
        {
          std::ostringstream value;
          value << ratio;
          if (!(ratio > 1 && ratio <= 100))
            throw data::InputError(s.describe("Volume sweep") + ": " + value.str() +
                                   " is not a volume ratio in (1, 100]");
          Sample sample = sample_of("volume", 0, {}, "volume ratio " + value.str());
          sample.actuation.cavity_volume_ratio = ratio;
          samples.push_back(sample);
        }
      for (const double p : s.get_double_list("Force sample pressures"))
        {
          for (const double f : s.get_double_list("Lateral tip forces"))
            samples.push_back(
              sample_of("lateral", p, {{at, {{0, 0, f}}}}, label("lateral", f, "N", p)));
          for (const double f : s.get_double_list("Torsion couples"))
            samples.push_back(sample_of("torsion", p,
                                        {{{{at[0], at[1], at[2] + arm}}, {{0, f, 0}}},
                                         {{{at[0], at[1], at[2] - arm}}, {{0, -f, 0}}}},
                                        label("torsion", f, "N", p)));
          for (const double f : s.get_double_list("Bending tip forces"))
            samples.push_back(
              sample_of("bending", p, {{at, {{0, -f, 0}}}}, label("bending", f, "N", p)));
        }
      // Chord samples (the reduction's, for the links' compliance), skin
      // samples (for the sections' compliance), then the validation samples
      // (held out): the same syntax, each of its role.
      const std::pair<std::string, std::string> listed[] = {{"chord", "Chord samples"},
                                                            {"skin", "Skin samples"},
                                                            {"validation", "Validation samples"}};
      using Direction = SampleSet::MeasuredForceRequest::Direction;
      for (const auto &[role, parameter] : listed)
        {
          const auto entries = split(s.get(parameter), ';');
          for (std::size_t k = 0; k < entries.size(); ++k)
            if (!entries[k].empty())
              {
                const std::string name = role + ' ' + std::to_string(k + 1);
                const std::string where = s.describe(parameter) + ", sample '" + name + "'";
                const auto        fields = split(entries[k], ':');
                const auto chord = fields.size() > 2 ? measured_force(fields[2], "chord", where) : std::nullopt;
                if (chord && role != "chord")
                  throw data::InputError(where + ": 'chord F' is a force of Chord samples only");
                if (role == "skin")
                  measured_requests.push_back(measured_request(
                    fields,
                    fields.size() > 2 && measured_force(fields[2], "shear", where) ? Direction::palm_shear
                                                                                 : Direction::palm_normal,
                    at, arm, name, where));
                else if (chord)
                  measured_requests.push_back(measured_request(fields, Direction::chord, at, arm, name, where));
                else
                  samples.push_back({listed_actuation(role, entries[k], at, arm, where), name, ""});
              }
        }
      for (auto &sample : contact_samples(s, contact))
        samples.push_back(sample);
      return samples;
    }
  } // namespace

  double load_size(const data::Actuation &actuation)
  {
    if (actuation.cavity_volume_ratio)
      return *actuation.cavity_volume_ratio - 1;
    double size = std::abs(actuation.pressure);
    for (const auto &f : actuation.point_forces)
      size += std::hypot(f.force[0], f.force[1], f.force[2]);
    return size;
  }

  bool pressure_only(const data::Actuation &actuation)
  {
    return actuation.point_forces.empty() && !actuation.tip_motion && actuation.obstacles.empty();
  }

  SampleSet SampleSet::read(const data::PrmFile &prm, const TipFace &tip,
                            const std::string &design_hash, const geometry::ContactScene &contact)
  {
    data::PrmSection section;
    declare(section);
    prm.parse_section("Samples", section);
    SampleSet set;
    set.continuation  = section.get_bool("Continuation");
    const int groups  = section.get_integer("Sample groups");
    if (groups < 0)
      throw data::InputError(section.describe("Sample groups") + ": must be 0 (one per rank) or more");
    set.sample_groups = groups;

    // Chains in order of first appearance, each by increasing load.
    std::map<std::string, std::size_t>    chain_of;
    std::vector<std::vector<Sample>>      chains;
    std::map<std::string, std::string>    label_of_id;
    for (auto &sample : listed_samples(section, tip, contact, set.measured_requests))
      {
        sample.id = data::sample_id(design_hash, sample.actuation);
        if (!label_of_id.emplace(sample.id, sample.label).second)
          throw data::InputError(prm.path() + ": subsection 'Samples': sample '" + sample.label +
                                 "' repeats the actuation of sample '" +
                                 label_of_id[sample.id] + "'");
        const std::string key = set.continuation ? chain_key(sample.actuation) : sample.id;
        if (chain_of.emplace(key, chains.size()).second)
          chains.emplace_back();
        chains[chain_of[key]].push_back(sample);
      }
    for (auto &chain : chains)
      {
        std::stable_sort(chain.begin(), chain.end(), [](const Sample &a, const Sample &b) {
          return load_size(a.actuation) < load_size(b.actuation);
        });
        set.chains.emplace_back();
        for (auto &sample : chain)
          {
            set.chains.back().push_back(set.samples.size());
            set.samples.push_back(sample);
          }
      }
    if (set.samples.empty())
      throw data::InputError(prm.path() + ": subsection 'Samples' lists no sample");
    for (const auto &request : set.measured_requests)
      if (request.pressure != 0 && !set.inflation_at(request.pressure))
        throw data::InputError(request.where + ": '" + request.keyword() + "' at " +
                               data::canonical(request.pressure) +
                               " Pa needs the finger inflated to that pressure alone: add it to "
                               "'Pressure sweep'");
    return set;
  }

  std::optional<std::size_t> SampleSet::inflation_at(const double pressure) const
  {
    for (std::size_t i = 0; i < samples.size(); ++i)
      {
        const data::Actuation &a = samples[i].actuation;
        if (pressure_only(a) && !a.cavity_volume_ratio && a.pressure == pressure)
          return i;
      }
    return std::nullopt;
  }

  Sample SampleSet::measured_sample(const MeasuredForceRequest &request,
                                    const std::vector<data::Point3> &directions,
                                    const std::string &design_hash)
  {
    // A direction measured on a computed state carries that state's
    // round-off (1e-13 between solver orderings or rank counts); rounded to
    // 1e-9 it gives the same forces, and so the same sample id (cached),
    // however the state was computed.
    const auto                    rounded = [](const double c) { return std::round(c * 1e9) / 1e9; };
    std::vector<data::PointForce> forces;
    for (std::size_t k = 0; k < request.points.size(); ++k)
      forces.push_back({request.points[k],
                        {{request.forces[k] * rounded(directions[k][0]), request.forces[k] * rounded(directions[k][1]),
                          request.forces[k] * rounded(directions[k][2])}}});
    Sample sample = sample_of(request.role(), request.pressure, std::move(forces), request.label);
    sample.id     = data::sample_id(design_hash, sample.actuation);
    return sample;
  }
} // namespace softchain::fem
