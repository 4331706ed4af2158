#include <softchain/chain/joint_force_law.h>
#include <softchain/chain/piecewise_linear.h>

#include <algorithm>
#include <stdexcept>

namespace softchain::chain
{
  JointForceLaw::JointForceLaw(std::vector<Table> per_joint)
    : per_joint_(std::move(per_joint))
  {
    for (const Table &table : per_joint_)
      {
        if (table.pressures.size() != table.hinges.size())
          throw std::invalid_argument("JointForceLaw: one law per pressure");
        for (std::size_t j = 1; j < table.pressures.size(); ++j)
          if (!(table.pressures[j] > table.pressures[j - 1]))
            throw std::invalid_argument("JointForceLaw: pressures must increase strictly");
      }
  }

  JointForceLaw JointForceLaw::completed_with(const JointStiffness &springs) const
  {
    std::vector<double> pressures = springs.table_pressures();
    for (const Table &table : per_joint_)
      merge_abscissae(table.pressures, pressures);
    std::vector<double> forced = springs.table_pressures(0); // where force samples were made
    merge_abscissae(springs.table_pressures(1), forced);
    std::vector<Table> complete(per_joint_.size());
    for (std::size_t i = 0; i < per_joint_.size(); ++i)
      for (const double p : pressures)
        {
          const Table &fitted = per_joint_[i];
          // Between two laws of this joint, at a pressure without force
          // samples (a pressure sample's k_phi), the laws blend.
          const bool between = !fitted.pressures.empty() && fitted.pressures.front() < p &&
                               p < fitted.pressures.back();
          if (between && !std::binary_search(forced.begin(), forced.end(), p) &&
              !std::binary_search(fitted.pressures.begin(), fitted.pressures.end(), p))
            continue;
          const auto   at     = std::find(fitted.pressures.begin(), fitted.pressures.end(), p);
          data::FabricHinge hinge;
          if (at != fitted.pressures.end())
            hinge = fitted.hinges[at - fitted.pressures.begin()];
          else
            hinge.k = springs.diagonal(p).segment<3>(3 * i);
          complete[i].pressures.push_back(p);
          complete[i].hinges.push_back(hinge);
        }
    return JointForceLaw(std::move(complete));
  }

  JointForceLaw::Blend JointForceLaw::at(const double pressure, const int joint) const
  {
    const Table &table = per_joint_[joint];
    Blend        blend;
    if (table.pressures.empty())
      return blend;
    const auto upper = std::upper_bound(table.pressures.begin(), table.pressures.end(), pressure);
    if (upper == table.pressures.begin() || upper == table.pressures.end())
      blend.lower = blend.upper =
        upper == table.pressures.begin() ? &table.hinges.front() : &table.hinges.back();
    else
      {
        const std::size_t j = static_cast<std::size_t>(upper - table.pressures.begin());
        blend.lower         = &table.hinges[j - 1];
        blend.upper         = &table.hinges[j];
        blend.weight = (pressure - table.pressures[j - 1]) / (table.pressures[j] - table.pressures[j - 1]);
        blend.theta_in_series = table.pressures[j - 1] == 0.0;
      }
    if (blend.lower->kappa == 0.0 && (blend.weight == 0.0 || blend.upper->kappa == 0.0))
      {
        const double w = blend.weight;
        blend.springs  = (1 - w) * blend.lower->k + w * blend.upper->k;
        if (blend.theta_in_series)
          (*blend.springs)(1) = 1.0 / ((1 - w) / blend.lower->k(1) + w / blend.upper->k(1));
      }
    return blend;
  }

  data::FabricHinge::Value JointForceLaw::Blend::evaluate(const Eigen::Vector3d &increment) const
  {
    if (weight == 0.0)
      return lower->evaluate(increment);
    if (theta_in_series)
      return in_series(increment);
    data::FabricHinge::Value       a = lower->evaluate(increment);
    const data::FabricHinge::Value b = upper->evaluate(increment);
    const double                   w = weight;
    a.energy  = (1 - w) * a.energy + w * b.energy;
    a.torque  = (1 - w) * a.torque + w * b.torque;
    a.tangent = (1 - w) * a.tangent + w * b.tangent;
    return a;
  }

  // The infimal convolution in theta (header): Newton on the convex
  // F(x) = (1 - w) W_lo(x) + w W_hi(y), y = (d_theta - (1 - w) x) / w (theta
  // components; psi and phi at d), F' = (1 - w) (T_lo - T_hi)_theta, with
  // backtracking on F. Both laws are piecewise quadratic, so Newton lands
  // on the minimiser in a few steps from x = d_theta (exact if the laws
  // agree); it stops when the step falls to round-off (1e-14 |d|) or F no
  // longer decreases.
  data::FabricHinge::Value JointForceLaw::Blend::in_series(const Eigen::Vector3d &d) const
  {
    const double             w = weight;
    Eigen::Vector3d          at_lo = d, at_hi = d;
    data::FabricHinge::Value lo, hi;
    const auto F = [&](const double x) {
      at_lo(1) = x;
      at_hi(1) = (d(1) - (1 - w) * x) / w;
      lo       = lower->evaluate(at_lo);
      hi       = upper->evaluate(at_hi);
      return (1 - w) * lo.energy + w * hi.energy;
    };
    // F_xx at the last evaluation: Newton's curvature, and the Schur pivot below.
    const auto curvature = [&] { return (1 - w) * lo.tangent(1, 1) + (1 - w) * (1 - w) / w * hi.tangent(1, 1); };
    double x = d(1), value = F(x);
    const double resolution = 1e-14 * d.lpNorm<Eigen::Infinity>();
    for (int iteration = 0; iteration < max_series_iterations; ++iteration)
      {
        const double slope = (1 - w) * (lo.torque(1) - hi.torque(1));
        const double step  = -slope / curvature();
        if (!(std::abs(step) > resolution)) // the minimiser to round-off
          break;
        double t = 1.0, trial = F(x + step);
        while (trial > value + 1e-4 * t * slope * step && t > 1e-6)
          trial = F(x + (t *= 0.5) * step);
        if (trial > value) // no decrease left above round-off
          {
            F(x); // lo, hi back at x
            break;
          }
        x += t * step;
        value = trial;
      }
    data::FabricHinge::Value out;
    out.energy    = value;
    out.torque    = (1 - w) * lo.torque + w * hi.torque;
    out.torque(1) = hi.torque(1); // = lo's at the minimiser
    // d^2W/dd^2 = F_dd - F_dx F_xd / F_xx (the Schur complement of x).
    const Eigen::Matrix3d &L = lo.tangent, &H = hi.tangent;
    Eigen::Matrix3d        F_dd = (1 - w) * L + w * H;
    F_dd.row(1)                 = H.row(1);
    F_dd.col(1)                 = H.col(1);
    F_dd(1, 1)                  = H(1, 1) / w;
    Eigen::RowVector3d F_xd     = (1 - w) * (L.row(1) - H.row(1));
    F_xd(1)                     = -(1 - w) / w * H(1, 1);
    const double F_xx           = curvature();
    out.tangent                 = F_dd;
    if (F_xx > 0.0) // else both laws are free in theta, and F_xd, their theta rows, is 0
      out.tangent -= F_xd.transpose() * F_xd / F_xx;
    return out;
  }
} // namespace softchain::chain
