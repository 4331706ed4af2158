#include <softchain/report/pressure_snapshots.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace softchain::report
{
  namespace
  {
    // A sample is "at" the requested pressure within 1 %: sweeps list round
    // pressures (10e3, 20e3, ...), so this only absorbs how they are written.
    constexpr double same_pressure = 0.01;

    std::string kpa(const double pascal)
    {
      std::ostringstream text;
      text << pascal / 1e3 << " kPa";
      return text.str();
    }

    bool pressure_only(const data::SampleRecord &s) { return s.actuation.point_forces.empty(); }

    // The converged pressure-only sample nearest to `p` (nullptr if none).
    const data::SampleRecord *nearest(const std::vector<data::SampleRecord> &samples, const double p)
    {
      const data::SampleRecord *best = nullptr;
      for (const auto &s : samples)
        if (s.converged() && pressure_only(s) &&
            (!best || std::abs(s.actuation.pressure - p) < std::abs(best->actuation.pressure - p)))
          best = &s;
      return best;
    }

    // "; failed: the samples at 60, 70 kPa; at 60 kPa: <reason>" for the
    // failed pressure-only samples between the shown and the requested
    // pressure, with the reason of the first one the sweep met.
    std::string failures_between(const std::vector<data::SampleRecord> &samples, const double shown,
                                 const double requested)
    {
      std::map<double, std::string> failed; // pressure -> reason
      for (const auto &s : samples)
        if (!s.converged() && pressure_only(s) &&
            (s.actuation.pressure - shown) * (s.actuation.pressure - requested) <= 0)
          failed.emplace(s.actuation.pressure, s.reason);
      if (failed.empty())
        return "";
      std::string text = "; failed: the sample" + std::string(failed.size() > 1 ? "s" : "") + " at ";
      for (auto f = failed.begin(); f != failed.end(); ++f)
        text += (f == failed.begin() ? "" : ", ") + kpa(f->first);
      const auto &first = shown < requested ? *failed.begin() : *failed.rbegin();
      return text + "; at " + kpa(first.first) + ": " + first.second;
    }

    double highest_pressure(const std::vector<data::SampleRecord> &samples)
    {
      double highest = 0;
      for (const auto &s : samples)
        if (s.converged() && pressure_only(s))
          highest = std::max(highest, s.actuation.pressure);
      return highest;
    }

    PressureSnapshot from_sample(const std::vector<data::SampleRecord> &samples,
                                 const data::SampleRecord &s, const double requested)
    {
      PressureSnapshot snapshot{requested, s.actuation.pressure, s.id, s.x, "", true};
      const double     p   = s.actuation.pressure;
      snapshot.at_request = std::abs(p - requested) <= same_pressure * requested;
      if (snapshot.at_request)
        snapshot.caption = kpa(p) + " (sample " + s.id + ")";
      else
        {
          const bool highest = p < requested && p == highest_pressure(samples);
          snapshot.caption = kpa(requested) + " requested: no converged pressure-only sample at " +
                             kpa(requested) + "; shown: the " + (highest ? "highest" : "nearest") +
                             " converged pressure, " + kpa(p) + " (sample " + s.id + ")" +
                             failures_between(samples, p, requested);
        }
      return snapshot;
    }
  } // namespace

  std::vector<PressureSnapshot> pressure_snapshots(const std::vector<data::Point3>     &reference,
                                                   const std::vector<data::SampleRecord> &samples,
                                                   const std::vector<double> &requested)
  {
    std::vector<PressureSnapshot> snapshots;
    for (const double p : requested)
      {
        const data::SampleRecord *s = p > 0 ? nearest(samples, p) : nullptr;
        if (s)
          snapshots.push_back(from_sample(samples, *s, p));
        else
          snapshots.push_back({p, 0.0, "", reference,
                               p > 0 ? kpa(p) + " requested: no converged pressure-only sample; "
                                                "shown: the reference mesh (0 kPa)" :
                                       "0 kPa: the reference mesh (rest shape)",
                               p == 0});
      }
    return snapshots;
  }
} // namespace softchain::report
