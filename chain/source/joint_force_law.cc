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
      }
    if (blend.lower->kappa == 0.0 && (blend.weight == 0.0 || blend.upper->kappa == 0.0))
      blend.springs = (1 - blend.weight) * blend.lower->k + blend.weight * blend.upper->k;
    return blend;
  }

  data::FabricHinge::Value JointForceLaw::Blend::evaluate(const Eigen::Vector3d &increment) const
  {
    data::FabricHinge::Value a = lower->evaluate(increment);
    if (weight == 0.0)
      return a;
    const data::FabricHinge::Value b = upper->evaluate(increment);
    const double                   w = weight;
    a.energy  = (1 - w) * a.energy + w * b.energy;
    a.torque  = (1 - w) * a.torque + w * b.torque;
    a.tangent = (1 - w) * a.tangent + w * b.tangent;
    return a;
  }
} // namespace softchain::chain
