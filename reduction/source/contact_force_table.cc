#include <softchain/data/tip_pose_fit.h>
#include <softchain/reduction/contact_force_table.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <tuple>

namespace softchain::reduction
{
  namespace
  {
    double norm(const data::Point3 &v) { return std::hypot(v[0], v[1], v[2]); }
  } // namespace

  ContactForceTable::ContactForceTable(const std::vector<data::SampleRecord> &samples,
                                       const data::MeshRecord &mesh, const std::string &source)
    : table_({"sample", "obstacle", "shape", "pressure", "status", "force_x", "force_y", "force_z",
              "force_norm", "moment_x", "moment_y", "moment_z", "tip_x", "tip_y", "tip_z",
              "tip_angle_deg"})
  {
    std::vector<const data::SampleRecord *> contact;
    for (const auto &s : samples)
      if (is_contact(s))
        contact.push_back(&s);
    if (contact.empty())
      return;
    std::sort(contact.begin(), contact.end(), [](const auto *a, const auto *b) {
      return std::make_pair(a->actuation.obstacles.front().name, a->actuation.pressure) <
             std::make_pair(b->actuation.obstacles.front().name, b->actuation.pressure);
    });
    // A mesh without a tip face (a test's node cloud) has no tip pose.
    const auto fit = mesh.tip_nodes.size() >= 3 ? std::optional(data::TipPoseFit::of_mesh(mesh, source)) :
                                                  std::nullopt;
    for (const auto *s : contact)
      {
        data::TipPose tip;
        tip.position = Eigen::Vector3d::Constant(NAN);
        double angle = NAN;
        if (fit)
          {
            tip   = fit->fit(data::select_nodes(s->x, mesh.tip_nodes));
            angle = data::rotation_angle_between(Eigen::Matrix3d::Identity(), tip.rotation);
          }
        for (std::size_t k = 0; k < s->actuation.obstacles.size(); ++k)
          {
            const auto &o = s->actuation.obstacles[k];
            const data::ObstacleWrench w =
              k < s->obstacle_wrenches.size() ? s->obstacle_wrenches[k] :
                                                data::ObstacleWrench{{{NAN, NAN, NAN}}, {{NAN, NAN, NAN}}};
            std::vector<std::string> row = {s->id, o.name, o.shape, data::CsvTable::cell(s->actuation.pressure),
                                            data::status_name(s->status)};
            for (const double v : {w.force[0], w.force[1], w.force[2], norm(w.force), w.moment[0],
                                   w.moment[1], w.moment[2], tip.position[0], tip.position[1],
                                   tip.position[2], angle * 180 / M_PI})
              row.push_back(data::CsvTable::cell(v));
            table_.add_row(row);
          }
      }
  }

  void ContactForceTable::write(const std::string &file) const
  {
    if (empty())
      std::filesystem::remove(file);
    else
      table_.write(file);
  }
} // namespace softchain::reduction
