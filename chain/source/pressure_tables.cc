#include <softchain/chain/pressure_tables.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace softchain::chain
{
  namespace
  {
    // The numeric field `name` holding `size` values, at 17 digits (the
    // doubles read back exactly).
    std::string numeric(const std::string &indent, const char *name, const double *data, Eigen::Index size)
    {
      std::ostringstream s;
      s.precision(17);
      s << indent << "  <numeric name=\"" << name << "\" data=\"";
      for (Eigen::Index j = 0; j < size; ++j)
        s << (j > 0 ? " " : "") << data[j];
      s << "\"/>\n";
      return s.str();
    }

    // The model's table pressures within (0, top), with 0 and top.
    std::vector<double> grid(const ChainModel &model, const double top)
    {
      std::vector<double> pressures{0.0};
      for (const double p : model.table_pressures())
        if (p > 0.0 && p < top)
          pressures.push_back(p);
      if (top > 0.0)
        pressures.push_back(top);
      return pressures;
    }
  } // namespace

  PressureTables::PressureTables(std::vector<double> pressures, Rows stiffness, Rows torque_per_pascal,
                                 Rows link_points, std::vector<double> skin_compliance)
    : pressures_(std::move(pressures))
    , stiffness_(std::move(stiffness))
    , torque_per_pascal_(std::move(torque_per_pascal))
    , link_points_(std::move(link_points))
    , skin_compliance_(std::move(skin_compliance))
  {
    if (!skin_compliance_.empty() &&
        (skin_compliance_.size() != pressures_.size() ||
         std::any_of(skin_compliance_.begin(), skin_compliance_.end(),
                     [](double c) { return !(c > 0.0) || !std::isfinite(c); })))
      throw std::invalid_argument("PressureTables: the skin compliance needs one positive, finite value "
                                  "per pressure");
    if (pressures_.empty() || pressures_.front() != 0.0)
      throw std::invalid_argument("PressureTables: the pressures must start at 0");
    for (std::size_t r = 1; r < pressures_.size(); ++r)
      if (!(pressures_[r] > pressures_[r - 1]) || !std::isfinite(pressures_[r]))
        throw std::invalid_argument("PressureTables: the pressures must be finite and increase strictly");
    const Eigen::Index m = static_cast<Eigen::Index>(pressures_.size()), hinges = stiffness_.cols();
    if (hinges == 0 || hinges % 3 != 0 || stiffness_.rows() != m || torque_per_pascal_.rows() != m ||
        torque_per_pascal_.cols() != hinges || link_points_.rows() != m || link_points_.cols() != hinges + 3)
      throw std::invalid_argument("PressureTables: need one row per pressure, 3 values per joint for "
                                  "stiffness and J_p, 3 per joint and tip for the link points");
    if (!stiffness_.allFinite() || !torque_per_pascal_.allFinite() || !link_points_.allFinite())
      throw std::invalid_argument("PressureTables: a value is not finite");
  }

  PressureTables PressureTables::of_model(const ChainModel &model, const double top_pressure)
  {
    const std::vector<double> pressures = grid(model, top_pressure);
    const Eigen::Index        m = static_cast<Eigen::Index>(pressures.size()), n = model.chain().n_joints();
    Rows                      k(m, 3 * n), jp(m, 3 * n), points(m, 3 * (n + 1));
    for (Eigen::Index r = 0; r < m; ++r)
      {
        k.row(r)                     = model.stiffness().diagonal(pressures[r]).transpose();
        jp.row(r)                    = model.actuation().torque_per_pascal(pressures[r]).transpose();
        const KinematicChain links   = model.chain_at(pressures[r]);
        for (int i = 0; i < n; ++i)
          points.row(r).segment<3>(3 * i) = links.link_joint(i).transpose();
        points.row(r).tail<3>() = links.link_tip().transpose();
      }
    // A skin only where it gives at every pressure (MuJoCo's slide joint
    // needs a finite stiffness 1 / c_s).
    std::vector<double> skin;
    for (const double p : pressures)
      if (model.has_skin_compliance() && model.skin_compliance(p) > 0.0)
        skin.push_back(model.skin_compliance(p));
    if (skin.size() != pressures.size())
      skin.clear();
    return PressureTables(pressures, k, jp, points, skin);
  }

  Eigen::VectorXd PressureTables::stiffness(const double pressure) const { return row_at(stiffness_, pressure); }

  Eigen::VectorXd PressureTables::torque_per_pascal(const double pressure) const
  {
    return row_at(torque_per_pascal_, pressure);
  }

  Eigen::VectorXd PressureTables::link_points(const double pressure) const
  {
    return row_at(link_points_, pressure);
  }

  double PressureTables::skin_compliance(const double pressure) const
  {
    if (skin_compliance_.empty())
      return 0.0;
    const Eigen::Map<const Rows> rows(skin_compliance_.data(), static_cast<Eigen::Index>(skin_compliance_.size()), 1);
    return row_at(rows, pressure)[0];
  }

  // Linear between the two grid pressures around `pressure`.
  Eigen::VectorXd PressureTables::row_at(const Eigen::Ref<const Rows> &rows, const double pressure) const
  {
    if (!(pressure >= 0.0 && pressure <= pressures_.back()))
      {
        std::ostringstream s;
        s << "pressure " << pressure << " Pa is outside the pressure table of the MJCF, 0 to "
          << pressures_.back() << " Pa (the chain is exact only where it was tabulated)";
        throw std::out_of_range(s.str());
      }
    if (rows.rows() == 1)
      return rows.row(0).transpose();
    // The first grid pressure above `pressure` (the last one at the top).
    const Eigen::Index r = std::min<Eigen::Index>(
      std::upper_bound(pressures_.begin(), pressures_.end(), pressure) - pressures_.begin(), rows.rows() - 1);
    const double t = (pressure - pressures_[r - 1]) / (pressures_[r] - pressures_[r - 1]);
    return ((1.0 - t) * rows.row(r - 1) + t * rows.row(r)).transpose();
  }

  std::string PressureTables::mjcf(const std::string &indent) const
  {
    return indent + "<custom>\n" +
           numeric(indent, pressure_name, pressures_.data(), static_cast<Eigen::Index>(pressures_.size())) +
           numeric(indent, stiffness_name, stiffness_.data(), stiffness_.size()) +
           numeric(indent, torque_per_pascal_name, torque_per_pascal_.data(), torque_per_pascal_.size()) +
           numeric(indent, link_points_name, link_points_.data(), link_points_.size()) +
           (skin_compliance_.empty()
              ? std::string()
              : numeric(indent, skin_compliance_name, skin_compliance_.data(),
                        static_cast<Eigen::Index>(skin_compliance_.size()))) +
           indent + "</custom>\n";
  }
} // namespace softchain::chain
