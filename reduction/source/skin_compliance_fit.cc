#include <softchain/data/vector_of_point.h>
#include <softchain/reduction/body_samples.h>
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

    Eigen::Vector3d vector(const data::Point3 &p) { return {p[0], p[1], p[2]}; }
  } // namespace

  SkinComplianceFit::SkinComplianceFit(const std::vector<data::SampleRecord> &records,
                                       const std::vector<SampleReduction> &reduced,
                                       const SampleReduction &rest, const JointGeometry &geometry,
                                       const data::MeshRecord &mesh, const ReductionParameters &parameters)
  {
    // The pressure states: the first pressure sample at each pressure, the
    // rest configuration at 0.
    std::map<double, std::pair<const std::vector<data::Point3> *, const SampleReduction *>> states{
      {0.0, {&mesh.X, &rest}}};
    for (std::size_t i = 0; i < records.size(); ++i)
      if (has_role(records[i].actuation.role, parameters.pressure_roles) &&
          records[i].actuation.point_forces.empty())
        states.emplace(records[i].actuation.pressure, std::make_pair(&records[i].x, &reduced[i]));
    // The cells locate the palm points; the lattice is not used (one point).
    std::optional<BodySamples> body;
    struct Sums
    {
      double dF = 0, FF = 0;
      int    n  = 0;
    };
    std::map<double, Sums> sums;
    for (std::size_t i = 0; i < records.size(); ++i)
      {
        const data::SampleRecord &s = records[i];
        if (!has_role(s.actuation.role, parameters.skin_roles) || s.actuation.point_forces.empty())
          continue;
        const auto state = states.find(s.actuation.pressure);
        if (state == states.end())
          {
            warnings_.push_back("skin sample '" + s.id + "' at " + data::CsvTable::cell(s.actuation.pressure) +
                                " Pa skipped: no pressure sample at that pressure");
            continue;
          }
        if (!body)
          body.emplace(mesh, 1.0, "the database's mesh");
        double delta = 0, F = 0;
        int    n     = 0;
        for (const data::PointForce &f : s.actuation.point_forces)
          {
            const auto located = body->locate(vector(f.point));
            const int  link    = link_of(geometry, f.point[0]);
            if (!located || link < 0)
              {
                warnings_.push_back("skin sample '" + s.id + "': a force point lies outside the body "
                                    "or before the first joint; skipped");
                continue;
              }
            const Eigen::Vector3d d       = reduced[i].link_rotation(link).col(1);
            const Eigen::Vector3d carried = reduced[i].carried_from(
              *state->second.second, link, body->deformed(*located, *state->second.first));
            delta += d.dot(body->deformed(*located, s.x) - carried);
            F += data::vector_of(f.force).dot(d);
            ++n;
          }
        if (n == 0)
          continue;
        Sums &sum = sums[s.actuation.pressure];
        sum.dF += delta / n * F;
        sum.FF += F * F;
        ++sum.n;
      }
    for (const auto &[pressure, sum] : sums)
      {
        if (!(sum.FF > 0))
          continue;
        const double c = sum.dF / sum.FF;
        if (c < 0)
          warnings_.push_back("skin compliance at " + data::CsvTable::cell(pressure) +
                              " Pa set to 0: the palm moved against the skin samples' force "
                              "(least squares c_s = " + data::CsvTable::cell(c) + " m/N)");
        values_.push_back({pressure, std::max(c, 0.0), sum.n});
      }
  }

  data::CsvTable SkinComplianceFit::table() const
  {
    data::CsvTable table({"pressure", "compliance", "samples"});
    for (const SkinComplianceAtPressure &v : values_)
      table.add_row(std::vector<double>{v.pressure, v.compliance, double(v.samples)});
    return table;
  }
} // namespace softchain::reduction
