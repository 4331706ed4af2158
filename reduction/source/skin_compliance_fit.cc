#include <softchain/data/vector_of_point.h>
#include <softchain/reduction/compliance_sums.h>
#include <softchain/reduction/skin_compliance_fit.h>

#include <algorithm>
#include <map>

namespace softchain::reduction
{
  namespace
  {
    bool has_role(const std::string &role, const std::vector<std::string> &roles)
    {
      return std::find(roles.begin(), roles.end(), role) != roles.end();
    }

    // The link that carries reference point X: the last joint at or before
    // its x, or -1 before the first joint.
    int link_of(const JointGeometry &geometry, const double x)
    {
      int link = -1;
      for (std::size_t i = 0; i < geometry.n_joints(); ++i)
        if (geometry.x_joint(i) <= x)
          link = static_cast<int>(i);
      return link;
    }

    // The point of the joints' layer above palm point X (its x and z, the
    // height of the joint centre of `link`).
    Eigen::Vector3d layer_point(const JointGeometry &geometry, const int link, const Eigen::Vector3d &X)
    {
      return {X.x(), geometry.reference_centre(link).y(), X.z()};
    }
  } // namespace

  SkinComplianceFit::SkinComplianceFit(const std::vector<data::SampleRecord> &records,
                                       const std::vector<SampleReduction> &reduced,
                                       const SampleReduction &rest, const JointGeometry &geometry,
                                       const data::MeshRecord &mesh, const ReductionParameters &parameters,
                                       const SkinDirection direction)
    : axis_(direction == SkinDirection::normal ? 1 : 0)
  {
    // The pressure states: the first pressure sample at each pressure, the
    // rest configuration at 0.
    std::map<double, State> states{{0.0, {&mesh.X, &rest}}};
    for (std::size_t i = 0; i < records.size(); ++i)
      if (has_role(records[i].actuation.role, parameters.pressure_roles) &&
          records[i].actuation.point_forces.empty())
        states.emplace(records[i].actuation.pressure, State{&records[i].x, &reduced[i]});
    std::map<double, ComplianceSums> sums;
    std::optional<BodySamples>       body; // locates the palm points; its lattice is not used
    for (std::size_t i = 0; i < records.size(); ++i)
      {
        const data::SampleRecord &s = records[i];
        if (!has_role(s.actuation.role, parameters.skin_roles) || s.actuation.point_forces.empty() ||
            !along_direction(s, reduced[i], geometry))
          continue;
        const auto state = states.find(s.actuation.pressure);
        if (state == states.end())
          warnings_.push_back("skin sample '" + s.id + "' at " + data::CsvTable::cell(s.actuation.pressure) +
                              " Pa skipped: no pressure sample at that pressure");
        else
          {
            if (!body)
              body.emplace(mesh, 1.0, "the database's mesh");
            if (const auto give = measured_give(s, reduced[i], state->second, geometry, *body))
              sums[s.actuation.pressure].add(give->first * give->second, give->second * give->second);
          }
      }
    for (const auto &[pressure, sum] : sums)
      if (const auto c = sum.compliance(name() + " at " + data::CsvTable::cell(pressure) +
                                          " Pa set to 0: the palm moved against the skin samples' force",
                                        warnings_))
        values_.push_back({pressure, *c, sum.samples});
  }

  bool SkinComplianceFit::along_direction(const data::SampleRecord &s, const SampleReduction &reduced,
                                          const JointGeometry &geometry) const
  {
    double along = 0, magnitude = 0;
    for (const data::PointForce &f : s.actuation.point_forces)
      {
        const Eigen::Vector3d force = data::vector_of(f.force);
        const int             link  = std::max(link_of(geometry, f.point[0]), 0);
        along += force.dot(reduced.link_rotation(link).col(axis_));
        magnitude += force.norm();
      }
    return std::abs(along) >= 0.5 * magnitude;
  }

  // (delta, F) of skin sample `s`: the mean give of its points along their
  // link's palm normal (or axis), and the sum of its forces along it (header).
  std::optional<std::pair<double, double>>
  SkinComplianceFit::measured_give(const data::SampleRecord &s, const SampleReduction &reduced,
                                   const State &state, const JointGeometry &geometry,
                                   const BodySamples &body)
  {
    double delta = 0, F = 0;
    int    n     = 0;
    for (const data::PointForce &f : s.actuation.point_forces)
      {
        const auto located = body.locate(data::vector_of(f.point));
        const int  link    = link_of(geometry, f.point[0]);
        if (!located || link < 0)
          {
            warnings_.push_back("skin sample '" + s.id + "': a force point lies outside the body or "
                                "before the first joint; skipped");
            continue;
          }
        const Eigen::Vector3d d = reduced.link_rotation(link).col(axis_);
        if (axis_ == 1)
          {
            const Eigen::Vector3d carried =
              reduced.carried_from(*state.reduced, link, body.deformed(*located, *state.x));
            delta += d.dot(body.deformed(*located, s.x) - carried);
          }
        else
          {
            const auto layer = body.locate(layer_point(geometry, link, data::vector_of(f.point)));
            if (!layer)
              {
                warnings_.push_back("skin sample '" + s.id + "': the layer above a force point lies outside "
                                    "the body; skipped");
                continue;
              }
            const Eigen::Matrix3d turn = reduced.link_rotation(link) * state.reduced->link_rotation(link).transpose();
            const Eigen::Vector3d before = body.deformed(*located, *state.x) - body.deformed(*layer, *state.x);
            const Eigen::Vector3d after  = body.deformed(*located, s.x) - body.deformed(*layer, s.x);
            delta += d.dot(after - turn * before);
          }
        F += data::vector_of(f.force).dot(d);
        ++n;
      }
    if (n == 0)
      return std::nullopt;
    return std::make_pair(delta / n, F);
  }

  data::CsvTable SkinComplianceFit::table() const
  {
    data::CsvTable table({"pressure", "compliance", "samples"});
    for (const SkinComplianceAtPressure &v : values_)
      table.add_row(std::vector<double>{v.pressure, v.compliance, double(v.samples)});
    return table;
  }
} // namespace softchain::reduction
