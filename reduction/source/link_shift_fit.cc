#include <softchain/reduction/link_shift_fit.h>

#include <cmath>
#include <map>

namespace softchain::reduction
{
  namespace
  {
    // dphi_i of every link from the pressure state.
    double turn(const SampleReduction &sample, const SampleReduction &state, const std::size_t link)
    {
      return sample.joints()[link].angles.phi - state.joints()[link].angles.phi;
    }

    // dU_i = (U_i+1 - U_i) - (U_i+1 - U_i)(p), link frame, x and y.
    Eigen::Vector2d change(const SampleReduction &sample, const SampleReduction &state, const std::size_t link)
    {
      const auto &U = sample.link_geometry(), &U_p = state.link_geometry();
      return ((U[link + 1] - U[link]) - (U_p[link + 1] - U_p[link])).head<2>();
    }
  } // namespace

  Eigen::Vector2d LinkShiftFit::shift_per_turn(const std::vector<Observation> &observations)
  {
    Eigen::Vector2d turn_change = Eigen::Vector2d::Zero();
    double          turn_squared = turn_resolution * turn_resolution;
    for (const Observation &o : observations)
      {
        turn_change += o.turn * o.change;
        turn_squared += o.turn * o.turn;
      }
    return turn_change / turn_squared;
  }

  LinkShiftFit::LinkShiftFit(const MethodReduction &reduction, const ReductionParameters &parameters)
  {
    if (reduction.rest().link_geometry().empty())
      return; // no tip face, no links to measure
    const std::size_t n_links = reduction.rest().link_geometry().size() - 1; // points U_1..U_n, U_T
    const auto states = reduction.pressure_states(parameters.pressure_roles);
    std::map<double, std::vector<std::vector<Observation>>> observations; // per pressure, per link
    std::map<double, int>                                   samples;      // per pressure
    for (const SampleReduction &s : reduction.samples())
      {
        if (!s.has_role(parameters.bending_roles) && !s.has_role(parameters.chord_roles))
          continue;
        const SampleReduction *state =
          MethodReduction::state_of(s, states, "in-plane", "the links' shift per turn", warnings_);
        if (!state)
          continue;
        auto &links = observations[s.pressure()];
        links.resize(n_links);
        ++samples[s.pressure()];
        for (std::size_t i = 0; i < n_links; ++i)
          if (state->joints()[i].angles.phi != 0.0) // turned by the pressure (header)
            links[i].push_back({turn(s, *state, i), change(s, *state, i)});
      }
    for (const auto &[pressure, links] : observations)
      {
        LinkShiftAtPressure v{pressure, {}, {}, samples[pressure]};
        for (const auto &link : links)
          {
            double squared = 0.0;
            for (const Observation &o : link)
              squared += o.turn * o.turn;
            v.shift.push_back(shift_per_turn(link));
            v.turn_rms.push_back(link.empty() ? 0.0 : std::sqrt(squared / link.size()));
          }
        values_.push_back(std::move(v));
      }
  }

  data::CsvTable LinkShiftFit::table() const
  {
    data::CsvTable table({"pressure", "link", "shift_x", "shift_y", "turn_rms", "samples"});
    for (const LinkShiftAtPressure &v : values_)
      for (std::size_t i = 0; i < v.shift.size(); ++i)
        table.add_row(std::vector<double>{v.pressure, double(i + 1), v.shift[i].x(), v.shift[i].y(), v.turn_rms[i],
                                          double(v.samples)});
    return table;
  }
} // namespace softchain::reduction
