#include <softchain/chain/tip_constrained_equilibrium.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <stdexcept>

namespace softchain::chain
{
  Eigen::MatrixXd angular_jacobian(const ChainPose &pose)
  {
    const int       n_joints = static_cast<int>(pose.joint_axes.size());
    Eigen::MatrixXd W(3, 3 * n_joints);
    for (int i = 0; i < n_joints; ++i)
      W.middleCols(3 * i, 3) = pose.joint_axes[i];
    return W;
  }

  Eigen::MatrixXd dead_couple_stiffness(const ChainPose &pose, const Eigen::Vector3d &m)
  {
    const Eigen::MatrixXd W = angular_jacobian(pose);
    const int             n = static_cast<int>(W.cols());
    Eigen::MatrixXd       G = Eigen::MatrixXd::Zero(n, n);
    for (int j = 0; j < n; ++j)
      for (int l = 0; l < j; ++l) // (l, beta) before (j, alpha) in q's order
        G(j, l) = Eigen::Vector3d(W.col(l)).cross(Eigen::Vector3d(W.col(j))).dot(m);
    return G;
  }

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
      for (int alpha = 0; alpha < 3; ++alpha) // each angle about its pivot
        J.col(3 * i + alpha) = p.joint_axes[i].col(alpha).cross(p.tip_position - p.pivot(i, alpha));
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
    return solve(load, TipTarget{tip_target, std::nullopt}, start);
  }

  ConstrainedEquilibrium TipConstrainedEquilibrium::solve(const ChainLoad       &load,
                                                          const TipTarget       &target,
                                                          const Eigen::VectorXd &start)
  {
    const int n = model_.chain().n_angles();
    const int m = target.rotation ? 6 : 3; // constraints
    if (start.size() != n || !start.allFinite() || !target.position.allFinite() ||
        (target.rotation && !target.rotation->allFinite()))
      throw std::invalid_argument(
        "TipConstrainedEquilibrium: start needs 3 finite angles per joint, the target finite "
        "coordinates");
    const double length = (model_.chain().tip() - model_.chain().joint_centre(0)).norm();
    // The links in series: compliance c to the contact force, the other
    // loads' deflection d (LinkCompliance).
    const double          compliance = model_.link_compliance(load.pressure);
    const Eigen::Vector3d deflection = model_.link_deflection(load);
    ConstrainedEquilibrium result;
    result.angles = start;
    for (;; ++result.iterations)
      {
        equilibrium_.set_load(with_contact(load, result.contact_force));
        Eigen::VectorXd       r = equilibrium_.residual(result.angles);
        Eigen::VectorXd       c(m);
        Eigen::MatrixXd       C(m, n); // the constraints' Jacobian [J; W]
        c.head<3>() = pose().tip_position + compliance * result.contact_force + deflection - target.position;
        C.topRows(3)     = tip_jacobian();
        Eigen::VectorXd contact_torque = C.topRows(3).transpose() * result.contact_force;
        if (target.rotation)
          {
            const Eigen::AngleAxisd error(pose().tip_rotation * target.rotation->transpose());
            c.tail<3>()      = error.angle() * error.axis();
            C.bottomRows(3)  = angular_jacobian(pose());
            const Eigen::VectorXd couple_torque = C.bottomRows(3).transpose() * result.contact_moment;
            r -= couple_torque;
            contact_torque += couple_torque;
          }
        const double scale = residual_scale(load, result.angles, contact_torque);
        if (r.lpNorm<Eigen::Infinity>() <= settings_.tolerance * scale &&
            c.head<3>().lpNorm<Eigen::Infinity>() <= settings_.tolerance * length &&
            c.tail(m - 3).lpNorm<Eigen::Infinity>() <= settings_.tolerance)
          break;
        if (result.iterations == settings_.max_iterations)
          {
            result.failure = "no constrained equilibrium within " +
                             std::to_string(settings_.max_iterations) + " Newton iterations";
            break;
          }
        Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(n + m, n + m);
        kkt.topLeftCorner(n, n) = equilibrium_.tangent(result.angles);
        if (target.rotation)
          kkt.topLeftCorner(n, n) -= dead_couple_stiffness(pose(), result.contact_moment);
        kkt.topRightCorner(n, m)   = -C.transpose();
        kkt.bottomLeftCorner(m, n) = C;
        kkt.block(n, n, 3, 3)      = compliance * Eigen::Matrix3d::Identity();
        Eigen::VectorXd right(n + m);
        right << -r, -c;
        Eigen::VectorXd step = kkt.completeOrthogonalDecomposition().solve(right);
        // The same cap as the free equilibrium: no angle moves by more than
        // max_step_angle in one step (the whole step is scaled).
        const double largest = step.head(n).lpNorm<Eigen::Infinity>();
        if (largest > settings_.max_step_angle)
          step *= settings_.max_step_angle / largest;
        result.angles += step.head(n);
        result.contact_force += step.segment<3>(n);
        if (target.rotation)
          result.contact_moment += step.tail<3>();
      }
    result.converged = result.failure.empty();
    return result;
  }
} // namespace softchain::chain
