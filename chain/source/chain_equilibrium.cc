#include <softchain/chain/chain_equilibrium.h>
#include <softchain/chain/angle_units.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace softchain::chain
{
  namespace
  {
    Eigen::Matrix3d cross_matrix(const Eigen::Vector3d &v)
    {
      Eigen::Matrix3d m;
      m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
      return m;
    }

    // Armijo constant of the backtracking line search (sufficient decrease).
    constexpr double armijo = 1e-4;
    constexpr int    max_halvings = 40;
  } // namespace

  ChainEquilibrium::ChainEquilibrium(const ChainModel &model, EquilibriumSettings settings)
    : model_(model)
    , settings_(settings)
    , chain_(model.chain())
    , pose_(model.chain().rest_pose())
    , moment_(model.chain().n_joints())
    , moment_gradient_(model.chain().n_joints())
    , distal_force_(model.chain().n_joints())
    , generalised_force_(model.chain().n_angles())
    , residual_(model.chain().n_angles())
    , tangent_(model.chain().n_joints())
    , direction_(model.chain().n_angles())
  {
    if (!(settings_.tolerance > 0.0) || settings_.max_iterations < 1 ||
        !(settings_.max_step_angle > 0.0))
      throw std::invalid_argument("ChainEquilibrium: tolerance, iterations and step must be positive");
  }

  void ChainEquilibrium::set_load(const ChainLoad &load)
  {
    if (!std::isfinite(load.pressure))
      throw std::invalid_argument("ChainEquilibrium: pressure is not finite");
    model_.chain_at(load.pressure, chain_);
    model_.stiffness().diagonal(load.pressure, stiffness_);
    model_.actuation().torque(load.pressure, pressure_torque_);
    loads_.clear();
    for (const PointLoad &p : load.point_loads)
      {
        if (!p.reference_point.allFinite() || !p.force.allFinite())
          throw std::invalid_argument("ChainEquilibrium: point load is not finite");
        const int link = chain_.link_of(p.reference_point);
        if (link >= 0) // loads on the clamped base do no work
          loads_.push_back({link, p.reference_point, p.force});
      }
    std::stable_sort(loads_.begin(), loads_.end(),
                     [](const AttachedLoad &a, const AttachedLoad &b) { return a.link < b.link; });
    contact_.set(model_.collision_surface(), load.pressure, load.obstacles, settings_.contact_stiffness);
  }

  void ChainEquilibrium::evaluate(const Eigen::VectorXd &q)
  {
    chain_.update_pose(q, pose_);
    const double contact = contact_.update(pose_);
    accumulate_distal_loads();
    const double strain = 0.5 * q.dot(stiffness_.cwiseProduct(q));
    const double work   = pressure_torque_.dot(q);
    residual_           = stiffness_.cwiseProduct(q) - pressure_torque_ - generalised_force_;
    residual_scale_     = stiffness_.cwiseProduct(q).lpNorm<Eigen::Infinity>() +
                      pressure_torque_.lpNorm<Eigen::Infinity>() +
                      generalised_force_.lpNorm<Eigen::Infinity>();
    energy_ += strain - work + contact;
    energy_magnitude_ += strain + std::abs(work) + contact;
  }

  // Backward pass from the tip: M_m, B_m (header) and Q_m = A_m^T M_m, with
  // the potential of the dead loads, -sum f.x, left in energy_. The contact
  // forces enter M and B like dead loads at their points (their potential
  // is the contact's energy).
  void ChainEquilibrium::accumulate_distal_loads()
  {
    Eigen::Vector3d force  = Eigen::Vector3d::Zero(); // sum f_k
    Eigen::Vector3d moment = Eigen::Vector3d::Zero(); // sum x_k x f_k
    Eigen::Matrix3d dyad   = Eigen::Matrix3d::Zero(); // sum x_k f_k^T
    energy_                = 0.0;
    energy_magnitude_      = 0.0;
    auto load              = loads_.rbegin();
    auto touch             = contact_.touches().rbegin();
    for (int m = chain_.n_joints() - 1; m >= 0; --m)
      {
        for (; touch != contact_.touches().rend() && touch->link == m; ++touch)
          {
            force += touch->force;
            moment += touch->position.cross(touch->force);
            dyad += touch->position * touch->force.transpose();
          }
        for (; load != loads_.rend() && load->link == m; ++load)
          {
            const Eigen::Vector3d x =
              chain_.point_position(pose_, m, load->reference_point);
            force += load->force;
            moment += x.cross(load->force);
            dyad += x * load->force.transpose();
            energy_ -= load->force.dot(x);
            energy_magnitude_ += std::abs(load->force.dot(x));
          }
        const Eigen::Vector3d &c = pose_.joint_positions[m];
        moment_[m]               = moment - c.cross(force);
        const Eigen::Matrix3d a  = dyad - c * force.transpose();
        moment_gradient_[m]      = a - a.trace() * Eigen::Matrix3d::Identity();
        distal_force_[m]         = force;
        generalised_force_.segment<3>(3 * m) = pose_.joint_axes[m].transpose() * moment_[m];
        if (chain_.has_twist_offsets()) // psi: the moment about the twist pivot s_m
          generalised_force_[3 * m] = pose_.joint_axes[m].col(0).dot(twist_moment(m));
      }
  }

  // M about s_m = M_m + (c_m - s_m) x F_m.
  Eigen::Vector3d ChainEquilibrium::twist_moment(const int m) const
  {
    return moment_[m] + (pose_.joint_positions[m] - pose_.twist_pivots[m]).cross(distal_force_[m]);
  }

  // H = K - dQ/dq in ChainTangent's form (header): U_j = -A_j^T (B_j + [M_j]x)
  // for every (l, beta) before (j, alpha), also within joint j, so the lower
  // triangle of D_j - K_j is that of U_j A_j. (Directly: the lower triangle of
  // -A_j^T B_j A_j - strictly lower part of A_j^T [M_j]x A_j, the same since
  // A^T [M]x A is antisymmetric.) D_j is mirrored from it. With a twist
  // pivot s_j the psi row takes M and B about s_j (header).
  void ChainEquilibrium::prepare_tangent()
  {
    for (int j = 0; j < chain_.n_joints(); ++j)
      {
        const Eigen::Matrix3d &axes = pose_.joint_axes[j];
        tangent_.axes(j)            = axes;
        tangent_.coupling(j) = -axes.transpose() * (moment_gradient_[j] + cross_matrix(moment_[j]));
        if (chain_.has_twist_offsets())
          {
            // About s_j: B^s = B_j + d F^T - (d . F) I, M^s = M_j + d x F with
            // d = c_j - s_j, so the psi row -(B^s^T a + a x M^s)^T differs
            // from the one about c_j by -(d (a . F) - a (d . F))^T.
            const Eigen::Vector3d  d = pose_.joint_positions[j] - pose_.twist_pivots[j];
            const Eigen::Vector3d &F = distal_force_[j];
            const Eigen::Vector3d  a = axes.col(0);
            tangent_.coupling(j).row(0) -= (d * a.dot(F) - a * d.dot(F)).transpose();
          }
        const Eigen::Matrix3d lower = tangent_.coupling(j) * axes;
        Eigen::Matrix3d      &d     = tangent_.diagonal(j);
        d                           = lower.selfadjointView<Eigen::Lower>();
        d.diagonal() += stiffness_.segment<3>(3 * j);
      }
  }

  bool ChainEquilibrium::converged() const
  {
    return residual_.lpNorm<Eigen::Infinity>() <= settings_.tolerance * residual_scale_;
  }

  double ChainEquilibrium::relative_residual() const
  {
    const double r = residual_.lpNorm<Eigen::Infinity>();
    return residual_scale_ > 0.0 ? r / residual_scale_ : r;
  }

  // direction_ = -H^-1 r, with H shifted by mu I until positive definite (the
  // shifted step is a descent direction of U), capped at max_step_angle.
  void ChainEquilibrium::newton_direction()
  {
    shifted_ = false;
    if (contact_.touches().empty())
      {
        for (double shift = 0.0; !tangent_.factor(shift); shifted_ = true)
          shift = shift == 0.0 ? 1e-8 * stiffness_.maxCoeff() : 10.0 * shift;
        tangent_.solve(residual_, direction_);
        direction_ *= -1.0;
      }
    else
      contact_direction();
    const double big = direction_.lpNorm<Eigen::Infinity>();
    if (big > settings_.max_step_angle)
      direction_ *= settings_.max_step_angle / big;
  }

  // With touching points, the tangent is H + V^T W V. Where H is positive
  // definite (the usual case), by Woodbury around its O(n) factor; if the
  // round obstacles' curvature rows (negative weights) make the step no
  // descent direction, again without them (then H + V^T W V is positive
  // definite). Where H alone is not (a contact force that would buckle the
  // free finger, or the deep penetrations of the first iterates), the dense
  // tangent: whole, without the curvature rows, or shifted until positive
  // definite.
  void ChainEquilibrium::contact_direction()
  {
    contact_.tangent_rows(pose_, chain_.n_angles(), contact_rows_, contact_weights_);
    if (tangent_.factor(0.0))
      {
        woodbury_direction();
        if (residual_.dot(direction_) < 0.0 || contact_weights_.minCoeff() >= 0.0)
          return;
        without_curvature_rows();
        woodbury_direction();
        return;
      }
    Eigen::MatrixXd dense = tangent_.dense();
    Eigen::LLT<Eigen::MatrixXd> factor(dense + contact_rows_.transpose() * contact_weights_.asDiagonal() * contact_rows_);
    if (factor.info() != Eigen::Success)
      {
        without_curvature_rows();
        dense += contact_rows_.transpose() * contact_weights_.asDiagonal() * contact_rows_;
        const double scale = dense.diagonal().cwiseAbs().maxCoeff();
        for (double shift = 0.0; factor.compute(dense).info() != Eigen::Success; shifted_ = true)
          {
            const double more = shift == 0.0 ? 1e-8 * scale : 9.0 * shift;
            dense.diagonal().array() += more;
            shift += more;
          }
      }
    direction_ = -factor.solve(residual_);
  }

  // direction_ = -(H + V^T W V)^-1 r from H's factor (header).
  void ChainEquilibrium::woodbury_direction()
  {
    tangent_.solve(residual_, direction_);
    direction_ *= -1.0;
    const Eigen::Index r = contact_rows_.rows();
    Eigen::MatrixXd    Y(chain_.n_angles(), r);
    Eigen::VectorXd    column(chain_.n_angles());
    for (Eigen::Index i = 0; i < r; ++i)
      {
        tangent_.solve(contact_rows_.row(i).transpose(), column);
        Y.col(i) = column;
      }
    const Eigen::MatrixXd WV = contact_weights_.asDiagonal() * contact_rows_;
    const Eigen::MatrixXd S  = Eigen::MatrixXd::Identity(r, r) + WV * Y;
    direction_ -= Y * S.partialPivLu().solve(WV * direction_);
  }

  // Keeps the rows of non-negative weight (the normals).
  void ChainEquilibrium::without_curvature_rows()
  {
    Eigen::Index kept = 0;
    for (Eigen::Index i = 0; i < contact_rows_.rows(); ++i)
      if (contact_weights_[i] >= 0.0)
        {
          contact_rows_.row(kept)  = contact_rows_.row(i);
          contact_weights_[kept++] = contact_weights_[i];
        }
    contact_rows_.conservativeResize(kept, Eigen::NoChange);
    contact_weights_.conservativeResize(kept);
  }

  // Backtracking until U decreases enough (Armijo); `slack` admits the
  // round-off of U itself (a few ulps of its largest term) near convergence.
  bool ChainEquilibrium::line_search(Eigen::VectorXd &q)
  {
    line_start_                  = q; // no allocation after the first solve
    const Eigen::VectorXd &start  = line_start_;
    const double          energy = energy_;
    const double          slope  = residual_.dot(direction_);
    const double          slack  = 64.0 * std::numeric_limits<double>::epsilon() * energy_magnitude_;
    double                step   = 1.0;
    for (int halving = 0; halving < max_halvings; ++halving, step *= 0.5)
      {
        q = start + step * direction_;
        evaluate(q);
        if (energy_ <= energy + armijo * step * slope + slack)
          return true;
      }
    q = start;
    evaluate(q);
    return false;
  }

  std::string ChainEquilibrium::range_violation(const Eigen::VectorXd &q) const
  {
    static const char *names[3] = {"psi", "theta", "phi"};
    for (Eigen::Index j = 0; j < q.size(); ++j)
      {
        const bool outside =
          j % 3 == 1 ? std::abs(q[j]) >= 0.5 * M_PI : std::abs(q[j]) > M_PI;
        if (outside)
          {
            std::ostringstream message;
            message << "joint " << j / 3 + 1 << ": " << names[j % 3] << " = " << degrees(q[j])
                    << " deg at equilibrium, outside the chain's range (|theta| < 90 deg, "
                       "|psi|, |phi| <= 180 deg)";
            return message.str();
          }
      }
    return {};
  }

  // An equilibrium reached without a Newton step (the start was one, e.g. a
  // straight finger under an axial load) or through a shifted tangent may be
  // unstable: then H is not positive definite there and no finger rests in it.
  std::string ChainEquilibrium::instability()
  {
    prepare_tangent();
    bool stable = false;
    if (contact_.touches().empty())
      stable = tangent_.factor(0.0);
    else
      {
        Eigen::MatrixXd dense = tangent_.dense();
        add_contact_tangent(dense);
        stable = dense.llt().info() == Eigen::Success;
      }
    if (stable)
      return {};
    return "unstable equilibrium: the tangent stiffness is not positive definite (buckling)";
  }

  // From the pressure's own equilibrium: without forces K q = J_p p is
  // linear (diagonal K), q = K^-1 J_p p, which is where the forces then
  // bend the finger from.
  Equilibrium ChainEquilibrium::solve(const ChainLoad &load)
  {
    set_load(load);
    const Eigen::VectorXd free = pressure_torque_.cwiseQuotient(stiffness_);
    if (contact_.empty())
      return iterate(free);
    // A stiff penalty met from outside makes the line search halve many
    // steps (the first Newton steps know no contact yet); with one 100
    // times softer the finger finds its contacts in a few, then the stiff
    // one starts within 1 % of the answer's penetrations.
    const Eigen::VectorXd start = before_first_contact(free);
    contact_.set_stiffness(1e-2 * settings_.contact_stiffness);
    const Equilibrium soft = iterate(start);
    contact_.set_stiffness(settings_.contact_stiffness);
    Equilibrium stiff = iterate(soft.converged ? soft.angles : start);
    stiff.iterations += soft.iterations;
    return stiff;
  }

  // The free pose may lie deep inside an obstacle, where the nearest surface
  // can push the finger out on the wrong side (through a cylinder it should
  // wrap), or beyond it (a finger curled around it). Newton starts instead
  // from t q_free with the smallest t in [0, 1] at which a surface point
  // penetrates, less 2^-11: the path of the pressure's shape from rest,
  // scanned in eighths and then bisected, stopped at the first touch; the
  // line search lets the contact build up from there. An obstacle that the
  // finger at rest already penetrates leaves the free start.
  Eigen::VectorXd ChainEquilibrium::before_first_contact(const Eigen::VectorXd &free)
  {
    const auto penetrates = [&](double t) {
      chain_.update_pose(t * free, pose_);
      contact_.update(pose_);
      return !contact_.touches().empty();
    };
    if (penetrates(0.0))
      return free;
    double outside = 0.0, inside = 0.125;
    while (inside <= 1.0 && !penetrates(inside))
      {
        outside = inside;
        inside += 0.125;
      }
    if (inside > 1.0)
      return free;
    for (int i = 0; i < 8; ++i)
      (penetrates(0.5 * (outside + inside)) ? inside : outside) = 0.5 * (outside + inside);
    return outside * free;
  }

  Equilibrium ChainEquilibrium::solve(const ChainLoad &load, const Eigen::VectorXd &start)
  {
    if (start.size() != model_.chain().n_angles() || !start.allFinite())
      throw std::invalid_argument("ChainEquilibrium: start needs 3 finite angles per joint");
    set_load(load);
    return iterate(start);
  }

  // Newton from `start` under the load of the last set_load.
  Equilibrium ChainEquilibrium::iterate(const Eigen::VectorXd &start)
  {
    Equilibrium result;
    result.angles = start;
    evaluate(result.angles);
    while (!converged() && result.failure.empty())
      {
        if (result.iterations == settings_.max_iterations)
          result.failure = "no equilibrium within " + std::to_string(settings_.max_iterations) +
                           " Newton iterations";
        else
          {
            prepare_tangent();
            newton_direction();
            ++result.iterations;
            if (getenv("DBG")) fprintf(stderr, "it %d res %.3e touches %zu energy %.6e shifted %d slope %.3e |d| %.3e\n", result.iterations, relative_residual(), contact_.touches().size(), energy_, (int)shifted_, residual_.dot(direction_), direction_.lpNorm<Eigen::Infinity>());
            if (!line_search(result.angles))
              result.failure = "line search found no decrease of the energy";
          }
      }
    if (result.failure.empty())
      result.failure = range_violation(result.angles);
    if (result.failure.empty() && (result.iterations == 0 || shifted_))
      result.failure = instability();
    result.converged = result.failure.empty();
    result.residual  = relative_residual();
    return result;
  }

  double ChainEquilibrium::energy(const Eigen::VectorXd &q)
  {
    evaluate(q);
    return energy_;
  }

  Eigen::VectorXd ChainEquilibrium::residual(const Eigen::VectorXd &q)
  {
    evaluate(q);
    return residual_;
  }

  Eigen::VectorXd ChainEquilibrium::newton_step(const Eigen::VectorXd &q)
  {
    evaluate(q);
    prepare_tangent();
    newton_direction();
    return direction_;
  }

  Eigen::MatrixXd ChainEquilibrium::tangent(const Eigen::VectorXd &q)
  {
    evaluate(q);
    prepare_tangent();
    Eigen::MatrixXd dense = tangent_.dense();
    add_contact_tangent(dense);
    return dense;
  }

  // + V^T diag(w) V of the contact (ChainContact).
  void ChainEquilibrium::add_contact_tangent(Eigen::MatrixXd &dense) const
  {
    if (contact_.touches().empty())
      return;
    Eigen::MatrixXd rows;
    Eigen::VectorXd weights;
    contact_.tangent_rows(pose_, chain_.n_angles(), rows, weights);
    dense += rows.transpose() * weights.asDiagonal() * rows;
  }
} // namespace softchain::chain
