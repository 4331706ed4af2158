#include <softchain/chain/tip_constrained_equilibrium.h>

#include <Eigen/Dense>

#include <stdexcept>

namespace softchain::chain
{
  TipConstrainedEquilibrium::TipConstrainedEquilibrium(const ChainModel         &model,
                                                       const EquilibriumSettings settings)
    : model_(model)
    , settings_(settings)
    , equilibrium_(model, settings)
  {}

  ChainLoad TipConstrainedEquilibrium::with_contact(const ChainLoad       &load,
                                                    const Eigen::Vector3d &contact_force) const
  {
    ChainLoad total = load;
    total.point_loads.push_back({model_.chain().tip(), contact_force});
    return total;
  }

  Eigen::MatrixXd TipConstrainedEquilibrium::tip_jacobian() const
  {
    const ChainPose &p = pose();
    Eigen::MatrixXd  J(3, model_.chain().n_angles());
    for (int i = 0; i < model_.chain().n_joints(); ++i)
      for (int alpha = 0; alpha < 3; ++alpha)
        J.col(3 * i + alpha) =
          p.joint_axes[i].col(alpha).cross(p.tip_position - p.joint_positions[i]);
    return J;
  }

  double TipConstrainedEquilibrium::residual_scale(const ChainLoad       &load,
                                                   const Eigen::VectorXd &q,
                                                   const Eigen::VectorXd &contact_torque) const
  {
    return model_.stiffness().diagonal(load.pressure).cwiseProduct(q).lpNorm<Eigen::Infinity>() +
           model_.actuation().torque(load.pressure).lpNorm<Eigen::Infinity>() +
           contact_torque.lpNorm<Eigen::Infinity>();
  }

  ConstrainedEquilibrium TipConstrainedEquilibrium::solve(const ChainLoad       &load,
                                                          const Eigen::Vector3d &tip_target,
                                                          const Eigen::VectorXd &start)
  {
    const int n = model_.chain().n_angles();
    if (start.size() != n || !start.allFinite() || !tip_target.allFinite())
      throw std::invalid_argument(
        "TipConstrainedEquilibrium: start needs 3 finite angles per joint, the target 3 finite "
        "coordinates");
    const double length = (model_.chain().tip() - model_.chain().joint_centre(0)).norm();
    ConstrainedEquilibrium result;
    result.angles = start;
    for (;; ++result.iterations)
      {
        equilibrium_.set_load(with_contact(load, result.contact_force));
        const Eigen::VectorXd r = equilibrium_.residual(result.angles);
        const Eigen::Vector3d c = pose().tip_position - tip_target;
        const Eigen::MatrixXd J = tip_jacobian();
        const double          scale =
          residual_scale(load, result.angles, J.transpose() * result.contact_force);
        if (r.lpNorm<Eigen::Infinity>() <= settings_.tolerance * scale &&
            c.lpNorm<Eigen::Infinity>() <= settings_.tolerance * length)
          break;
        if (result.iterations == settings_.max_iterations)
          {
            result.failure = "no constrained equilibrium within " +
                             std::to_string(settings_.max_iterations) + " Newton iterations";
            break;
          }
        Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(n + 3, n + 3);
        kkt.topLeftCorner(n, n)     = equilibrium_.tangent(result.angles);
        kkt.topRightCorner(n, 3)    = -J.transpose();
        kkt.bottomLeftCorner(3, n)  = J;
        Eigen::VectorXd right(n + 3);
        right << -r, -c;
        Eigen::VectorXd step = kkt.completeOrthogonalDecomposition().solve(right);
        // The same cap as the free equilibrium: no angle moves by more than
        // max_step_angle in one step (the whole step is scaled).
        const double largest = step.head(n).lpNorm<Eigen::Infinity>();
        if (largest > settings_.max_step_angle)
          step *= settings_.max_step_angle / largest;
        result.angles += step.head(n);
        result.contact_force += step.tail<3>();
      }
    result.converged = result.failure.empty();
    return result;
  }
} // namespace softchain::chain
