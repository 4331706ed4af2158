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
    // The search margin's floor and growth, relative to contact_margin_ and
    // to the surface's motion (ChainEquilibrium::contact_direction).
    constexpr double smallest_margin = 1e-3;
    constexpr double margin_per_motion = 4.0;
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
    model_.stiffness().diagonal(load.pressure, stiffness_);
    model_.actuation().torque(load.pressure, pressure_torque_);
    pressure_angles_ = pressure_torque_.cwiseQuotient(stiffness_);
    model_.chain_at(load.pressure, pressure_angles_, chain_);
    force_law_.clear();
    if (const JointForceLaw *law = model_.force_law())
      for (int j = 0; j < law->n_joints(); ++j)
        force_law_.push_back(law->at(load.pressure, j));
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
    contact_margin_ = 0.05 * (chain_.link_tip() - chain_.link_joint(0)).norm();
    search_margin_  = contact_margin_;
    const double              skin_compliance = model_.skin_compliance(load.pressure);
    const std::vector<double> skin(skin_compliance > 0.0 ? chain_.n_joints() : 0, skin_compliance);
    contact_.set(model_.collision_surface(), load.pressure, load.obstacles, settings_.contact_stiffness, skin,
                 model_.skin_shear_compliance(load.pressure), load.path, load.anchors);
  }

  void ChainEquilibrium::set_tolerance(const double tolerance)
  {
    if (!(tolerance > 0.0))
      throw std::invalid_argument("ChainEquilibrium: the tolerance must be positive");
    settings_.tolerance = tolerance;
  }

  void ChainEquilibrium::evaluate(const Eigen::VectorXd &q)
  {
    chain_.update_pose(q, pose_);
    const double contact = contact_.update(pose_);
    accumulate_distal_loads();
    const double strain = evaluate_springs(q);
    const double work   = pressure_torque_.dot(q);
    residual_           = spring_torque_ - pressure_torque_ - generalised_force_;
    residual_scale_     = spring_torque_.lpNorm<Eigen::Infinity>() +
                      pressure_torque_.lpNorm<Eigen::Infinity>() +
                      generalised_force_.lpNorm<Eigen::Infinity>();
    energy_ += strain - work + contact;
    energy_magnitude_ += strain + std::abs(work) + contact;
  }

  // The joints' spring torques, their tangent blocks and energy at q: K_j
  // q_j (energy q_j^T K_j q_j / 2) for a joint with linear springs; J_p,j p +
  // T_j(q_j - q_p,j) (energy J_p,j p . q_j + W_j(q_j - q_p,j)) for a joint
  // with a force law (JointForceLaw), which the same pressure torque holds
  // at q_p.
  double ChainEquilibrium::evaluate_springs(const Eigen::VectorXd &q)
  {
    spring_torque_.resize(q.size());
    spring_tangent_.resize(chain_.n_joints());
    double energy = 0.0;
    for (int j = 0; j < chain_.n_joints(); ++j)
      {
        const auto qj = q.segment<3>(3 * j);
        if (force_law_.empty() || !force_law_[j].lower)
          {
            const auto k = stiffness_.segment<3>(3 * j);
            spring_torque_.segment<3>(3 * j) = k.cwiseProduct(qj);
            spring_tangent_[j]               = k.asDiagonal();
            energy += 0.5 * qj.dot(k.cwiseProduct(qj));
            continue;
          }
        const auto            jp = pressure_torque_.segment<3>(3 * j);
        const Eigen::Vector3d d  = qj - pressure_angles_.segment<3>(3 * j);
        if (force_law_[j].springs) // no fibres here: springs about q_p, without FabricHinge's edges
          {
            const Eigen::Vector3d &k         = *force_law_[j].springs;
            spring_torque_.segment<3>(3 * j) = jp + k.cwiseProduct(d);
            spring_tangent_[j]               = k.asDiagonal();
            energy += jp.dot(qj) + 0.5 * d.dot(k.cwiseProduct(d));
            continue;
          }
        const data::FabricHinge::Value v = force_law_[j].evaluate(d);
        spring_torque_.segment<3>(3 * j) = jp + v.torque;
        spring_tangent_[j]               = v.tangent;
        energy += jp.dot(qj) + v.energy;
      }
    return energy;
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
    auto grip              = contact_.friction().grips().rbegin();
    const auto add_point_force = [&](const Eigen::Vector3d &x, const Eigen::Vector3d &f) {
      force += f;
      moment += x.cross(f);
      dyad += x * f.transpose();
    };
    for (int m = chain_.n_joints() - 1; m >= 0; --m)
      {
        for (; touch != contact_.touches().rend() && touch->link == m; ++touch)
          add_point_force(touch->position, touch->force);
        for (; grip != contact_.friction().grips().rend() && grip->link == m; ++grip)
          add_point_force(grip->position, grip->force);
        for (; load != loads_.rend() && load->link == m; ++load)
          {
            const Eigen::Vector3d x =
              chain_.point_position(pose_, m, load->reference_point);
            add_point_force(x, load->force);
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
          generalised_force_[3 * m] = pose_.joint_axes[m].col(0).dot(moment_about(m, 0));
        if (chain_.has_link_shift()) // phi: the moment about the rolling pivot p_{m,phi}
          generalised_force_[3 * m + 2] = pose_.joint_axes[m].col(2).dot(moment_about(m, 2));
      }
  }

  // M about angle alpha's pivot p = M_m + (c_m - p) x F_m.
  Eigen::Vector3d ChainEquilibrium::moment_about(const int m, const int alpha) const
  {
    return moment_[m] + (pose_.joint_positions[m] - pose_.pivot(m, alpha)).cross(distal_force_[m]);
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
        const Eigen::Vector3d &F = distal_force_[j];
        // About another pivot p: B^p = B_j + d F^T - (d . F) I, M^p = M_j + d x F
        // with d = c_j - p, so the row -(B^p^T a + a x M^p)^T differs from the
        // one about c_j by -(d (a . F) - a (d . F))^T.
        for (const int alpha : {0, 2})
          if (pose_.pivot(j, alpha) != pose_.joint_positions[j])
            {
              const Eigen::Vector3d d = pose_.joint_positions[j] - pose_.pivot(j, alpha);
              const Eigen::Vector3d a = axes.col(alpha);
              tangent_.coupling(j).row(alpha) -= (d * a.dot(F) - a * d.dot(F)).transpose();
            }
        const Eigen::Matrix3d lower = tangent_.coupling(j) * axes;
        Eigen::Matrix3d      &d     = tangent_.diagonal(j);
        d                           = lower.selfadjointView<Eigen::Lower>();
        d += spring_tangent_[j];
        // A rolling pivot turns with phi itself: d p_{j,phi} / d phi_j = -R_j g_j,
        // which adds a_phi . (R_j g_j x F) to dQ_phi / dphi_j (header).
        d(2, 2) -= axes.col(2).dot(pose_.shift_rates[j].cross(F));
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
    if (contact_.empty())
      {
        for (double shift = 0.0; !tangent_.factor(shift); shifted_ = true)
          shift = shift == 0.0 ? 1e-8 * stiffness_.maxCoeff() : 10.0 * shift;
        tangent_.solve(residual_, direction_);
        direction_ *= -1.0;
      }
    else
      {
        contact_direction();
        limit_surface_motion();
      }
    const double big = direction_.lpNorm<Eigen::Infinity>();
    if (big > settings_.max_step_angle)
      direction_ *= settings_.max_step_angle / big;
  }

  // With obstacles, the step minimises the quadratic model of U in which
  // every surface point near an obstacle (closer than 5 % of the chain's
  // length; ChainContact::candidates) keeps its penalty, linearised:
  //   m(d) = r_f^T d + 1/2 d^T (H + C) d + sum_c 1/2 k_c <-(g_c + v_c d)>^2,
  // r_f the residual without the contact's normal forces, H the tangent
  // without the contact's rows, C the touching points' curvature rows and
  // the friction's (CoulombFriction, held at the iterate), v_c = n_c^T J_c
  // (with skins, their displacements' changes are unknowns of m too:
  // add_skin_rows). So a step from outside an obstacle already stops at it,
  // instead of diving in and being cut back by the line search. m is
  // minimised by a semismooth Newton method (settle_active_set). If the
  // curvature rows (negative weights) leave no descent direction, the step
  // is taken without them (the friction's, positive, stay).
  //
  // The model's candidates reach search_margin_. Where the step it gives
  // moves no surface point farther than that, no point outside it could
  // have entered the active set (its linearised gap stays positive along the
  // step), so the step is the one every point within contact_margin_ would
  // give (the model's minimiser is unique where it is convex); otherwise the
  // margin grows to four times the step's motion, up to contact_margin_,
  // and the step is solved again. A load's first step takes every point
  // within contact_margin_ (it starts from a pose whose step is unknown);
  // on P10's contact samples the steps that settle an equilibrium then
  // take a few candidates instead of about 400.
  void ChainEquilibrium::contact_direction()
  {
    for (;;)
      {
        model_direction();
        if (search_margin_ >= contact_margin_)
          return;
        const double motion = surface_motion(direction_);
        if (motion <= search_margin_)
          return;
        search_margin_ = std::min(margin_per_motion * motion, contact_margin_);
      }
  }

  void ChainEquilibrium::model_direction()
  {
    contact_.candidates(pose_, search_margin_, near_, false); // the touches' curvature rows come from update
    const double       k = contact_.stiffness();
    const Eigen::Index m = static_cast<Eigen::Index>(near_.size());
    gaps_.resize(m);
    near_rows_.resize(m);
    link_model_.reset(chain_.n_joints());
    for (Eigen::Index c = 0; c < m; ++c)
      {
        gaps_[c]      = near_[c].gap;
        near_rows_[c] = LinkWrenchStiffness::point_row(near_[c].position, near_[c].normal);
        if (gaps_[c] < 0.0)
          link_model_.add_force(near_[c].link, near_rows_[c], -k * gaps_[c]);
      }
    free_residual_ = residual_;
    link_model_.add_generalised_force(pose_, free_residual_);
    contact_.curvature_rows(curvature_rows_);
    contact_.friction_rows(friction_rows_);
    contact_.skins(pose_, skins_);
    skin_of_link_.assign(chain_.n_joints(), -1);
    for (std::size_t j = 0; j < skins_.size(); ++j)
      skin_of_link_[skins_[j].link] = static_cast<int>(j);
    alignment_.setZero(m);
    for (Eigen::Index c = 0; c < m; ++c)
      if (const int j = skin_of_link_[near_[c].link]; j >= 0 && contact_.gives(near_[c]))
        alignment_[c] = near_[c].normal.dot(skins_[j].direction);
    dense_tangent_ = tangent_.dense();
    std::vector<char> active(m);
    for (const bool curvature : {true, false})
      {
        settle_active_set(curvature, active);
        if (residual_.dot(direction_) < 0.0 || curvature_rows_.empty())
          break;
      }
    if (residual_.dot(direction_) < 0.0)
      return;
    // No descent direction from the model: the step of the touching points alone.
    for (Eigen::Index c = 0; c < m; ++c)
      active[c] = gaps_[c] < 0.0;
    contact_step(active, false);
  }

  // Semismooth Newton on m (with the skins' changes ds_b beside d): from
  // d = 0 and A = {c : g_c < 0}, each pass solves m's quadratic with the
  // points of A held (contact_step) for (d^, ds^), moves to the minimiser
  // of m on the segment towards it (model_step), and takes A as the points
  // predicted inside there, g_c + v_c d + a_c ds_b < 0; until the
  // quadratic's minimiser predicts A itself, at most 10 passes. Without the segment's minimum
  // the passes can cycle between active sets (on P10's grasp and blocked
  // force in a fifth of the Newton steps).
  void ChainEquilibrium::settle_active_set(const bool curvature, std::vector<char> &active)
  {
    const int           n = chain_.n_joints();
    Eigen::VectorXd     d = Eigen::VectorXd::Zero(chain_.n_angles());
    std::vector<double> ds(n, 0.0), full(n), change(n);
    for (std::size_t c = 0; c < active.size(); ++c) // predicted at d = 0: the points inside
      active[c] = gaps_[c] < 0.0;
    std::vector<char> next;
    for (int pass = 0; pass < 10; ++pass)
      {
        contact_step(active, curvature);
        link_twists(direction_, twists_);
        std::fill(full.begin(), full.end(), 0.0);
        for (const SkinPrediction &s : skin_predictions_)
          full[s.link] = -(s.gamma + s.u.dot(twists_[s.link])) / s.D;
        next = active;
        if (!predict_active_set(twists_, full, next))
          return; // A holds at the quadratic's minimiser: it is m's
        const Eigen::VectorXd step = direction_ - d;
        for (int b = 0; b < n; ++b)
          change[b] = full[b] - ds[b];
        const double t = model_step(d, ds, step, change, curvature);
        if (t == 0.0)
          break;
        d += t * step;
        for (int b = 0; b < n; ++b)
          ds[b] += t * change[b];
        if (t == 1.0)
          active.swap(next);
        else
          {
            link_twists(d, twists_);
            predict_active_set(twists_, ds, active);
          }
      }
    direction_ = d;
  }

  // The t in [0, 1] that minimises m(d + t dd, ds + t dds) (contact_direction,
  // add_skin_rows): m' = 2 alpha t + beta + sum_c k_c <h_c(t)>- h1_c with the
  // quadratic part's coefficients alpha, beta from
  //   r_f^T d + 1/2 d^T (H + C) d + sum_b [1/2 k_s (s_b + ds_b)^2 + ds_b t_b d + 1/2 e_b ds_b^2]
  // and each candidate's h_c(t) = h0_c + t h1_c, g_c + v_c d + a_c ds_b along
  // the segment. m' is increasing where m is convex; its root is bracketed
  // and found by Newton's method (exact in a few steps: m' is piecewise
  // linear), bisecting where a step leaves the bracket. 1 if m still falls
  // at the end, 0 if it does not fall at the start.
  double ChainEquilibrium::model_step(const Eigen::VectorXd &d, const std::vector<double> &ds,
                                      const Eigen::VectorXd &dd, const std::vector<double> &dds,
                                      const bool curvature)
  {
    link_twists(d, twists_);
    link_twists(dd, step_twists_);
    const Eigen::VectorXd Hdd   = dense_tangent_ * dd;
    double                alpha = 0.5 * dd.dot(Hdd), beta = free_residual_.dot(dd) + d.dot(Hdd);
    const auto add_rows = [&](const std::vector<ChainContact::LinkRow> &rows) {
      for (const ChainContact::LinkRow &row : rows)
        {
          const double p = row.row.dot(twists_[row.link]), q = row.row.dot(step_twists_[row.link]);
          beta += row.weight * p * q;
          alpha += 0.5 * row.weight * q * q;
        }
    };
    if (curvature)
      add_rows(curvature_rows_);
    add_rows(friction_rows_);
    for (const ChainContact::Skin &skin : skins_)
      {
        const int    b  = skin.link;
        const double y0 = skin.penetration_row.dot(twists_[b]), y1 = skin.penetration_row.dot(step_twists_[b]);
        beta += skin.stiffness * (skin.shift + ds[b]) * dds[b] + ds[b] * y1 + dds[b] * y0 +
                skin.penetration_curvature * ds[b] * dds[b];
        alpha += 0.5 * (skin.stiffness + skin.penetration_curvature) * dds[b] * dds[b] + dds[b] * y1;
      }
    const std::size_t m = near_.size();
    h0_.resize(m);
    h1_.resize(m);
    for (std::size_t c = 0; c < m; ++c)
      {
        const int b = near_[c].link;
        h0_[c]      = gaps_[c] + near_rows_[c].dot(twists_[b]) + alignment_[c] * ds[b];
        h1_[c]      = near_rows_[c].dot(step_twists_[b]) + alignment_[c] * dds[b];
      }
    const double k     = contact_.stiffness();
    const auto   slope = [&](const double t, double &curvature_t) {
      double value = 2.0 * alpha * t + beta;
      curvature_t  = 2.0 * alpha;
      for (std::size_t c = 0; c < m; ++c)
        if (const double h = h0_[c] + t * h1_[c]; h < 0.0)
          {
            value += k * h * h1_[c];
            curvature_t += k * h1_[c] * h1_[c];
          }
      return value;
    };
    double curvature_t = 0.0;
    if (slope(1.0, curvature_t) <= 0.0)
      return 1.0;
    if (slope(0.0, curvature_t) >= 0.0)
      return 0.0;
    double low = 0.0, high = 1.0, t = 1.0;
    for (int iteration = 0; iteration < 60 && high - low > 1e-12; ++iteration)
      {
        const double value = slope(t, curvature_t);
        if (value == 0.0)
          return t;
        (value < 0.0 ? low : high) = t;
        double next = curvature_t > 0.0 ? t - value / curvature_t : low;
        if (!(next > low && next < high))
          next = 0.5 * (low + high);
        if (std::abs(next - t) <= 1e-12)
          return next;
        t = next;
      }
    return low;
  }

  // Each link's twist t_b = (w_b, v_b) (the point velocity is v_b + w_b x x)
  // under the angle rates d, summed joint by joint: a turn d_{i,alpha} about
  // a_{i,alpha} through p_{i,alpha} adds a d to w and p x a d to v.
  void ChainEquilibrium::link_twists(const Eigen::VectorXd &d, std::vector<LinkWrenchStiffness::Vector6d> &twists) const
  {
    LinkWrenchStiffness::Vector6d t = LinkWrenchStiffness::Vector6d::Zero();
    twists.resize(chain_.n_joints());
    for (int i = 0; i < chain_.n_joints(); ++i)
      {
        for (int alpha = 0; alpha < 3; ++alpha)
          {
            const Eigen::Vector3d  turn  = pose_.joint_axes[i].col(alpha) * d[3 * i + alpha];
            const Eigen::Vector3d &pivot = pose_.pivot(i, alpha);
            t.head<3>() += turn;
            t.tail<3>() += pivot.cross(turn);
          }
        twists[i] = t;
      }
  }

  // The candidates predicted inside at (d, ds), g_c + v_c d + a_c ds_b < 0,
  // with the links' twists under d.
  // Returns whether the set changed.
  bool ChainEquilibrium::predict_active_set(const std::vector<LinkWrenchStiffness::Vector6d> &twists,
                                            const std::vector<double> &ds, std::vector<char> &active) const
  {
    bool changed = false;
    for (std::size_t c = 0; c < active.size(); ++c)
      {
        const int  b      = near_[c].link;
        const bool inside = gaps_[c] + near_rows_[c].dot(twists[b]) + alignment_[c] * ds[b] < 0.0;
        if (inside != bool(active[c]))
          {
            active[c] = inside;
            changed   = true;
          }
      }
    return changed;
  }

  // Four times the motion the next step is expected to make: the last
  // step's, scaled by the fall of the residual over it (`fall` < 1; Newton's
  // steps shrink with the residual as it converges). At least a thousandth
  // of contact_margin_ (4.5 um on P10), at most all of it.
  void ChainEquilibrium::next_search_margin(const Eigen::VectorXd &step, const double fall)
  {
    const double scale = std::isfinite(fall) ? std::min(fall, 1.0) : 1.0;
    search_margin_     = std::clamp(margin_per_motion * surface_motion(step) * scale,
                                    smallest_margin * contact_margin_, contact_margin_);
  }

  double ChainEquilibrium::surface_motion(const Eigen::VectorXd &step)
  {
    link_twists(step, twists_);
    const std::vector<CollisionSurface::Node> &nodes = model_.collision_surface()->nodes();
    double                                     motion = 0.0;
    for (std::size_t i = 0; i < nodes.size(); i = nodes[i].skip) // each link's root
      motion = std::max(motion, sphere_motion(static_cast<int>(i)));
    return motion;
  }

  // |v_b + w_b x centre| + |w_b| radius of node i's sphere under twists_.
  double ChainEquilibrium::sphere_motion(const int i) const
  {
    const int                       link   = model_.collision_surface()->nodes()[i].link;
    const CollisionSurface::Sphere &sphere = contact_.spheres()[i];
    const Eigen::Vector3d           w      = twists_[link].head<3>();
    const Eigen::Vector3d           v      = twists_[link].tail<3>();
    const Eigen::Vector3d centre = pose_.link_origins[link] + pose_.link_rotations[link] * sphere.centre;
    return (v + w.cross(centre)).norm() + w.norm() * sphere.radius;
  }

  // With obstacles no surface point may move farther in one step than the
  // active set's reach (search_margin_) or its clearance from every
  // obstacle, whichever is larger: a longer step could carry a point
  // through a thin obstacle without any candidate seeing it (tunnelling),
  // while a point that moves less than its clearance cannot reach one (the
  // signed distance is 1-Lipschitz). Bounded per cluster: motion by
  // |v_b + w_b x centre| + |w_b| radius, clearance by ChainContact::clearance.
  // A node's bound is at least that of every cluster below it (its sphere
  // holds theirs), so a branch whose bound is below the largest ratio so far
  // (or below 1, which needs no cut) is skipped.
  void ChainEquilibrium::limit_surface_motion()
  {
    link_twists(direction_, twists_);
    const CollisionSurface &surface = *model_.collision_surface();
    double ratio = 1.0, bound = 0.0; // the largest motion over what a cluster may move, where above 1
    surface.walk(
      [&](const int i) {
        bound = sphere_motion(i) / std::max(search_margin_, contact_.clearance(i)); // at pose_: model_direction's search
        return bound <= ratio;
      },
      [&](int) {
        ratio = bound; // the cluster's own, just computed
        return false;
      });
    direction_ /= ratio;
  }

  // direction_ = -(H + C + k V_A^T V_A)^-1 (r_f + k V_A^T g_A) (above), with
  // the rows and forces of the pass gathered link by link.
  void ChainEquilibrium::contact_step(const std::vector<char> &active, const bool curvature)
  {
    const double k = contact_.stiffness();
    link_model_.reset(chain_.n_joints());
    for (std::size_t c = 0; c < active.size(); ++c)
      if (active[c]) // the model's force k g_c of a point in A
        {
          link_model_.add_row(near_[c].link, near_rows_[c], k);
          link_model_.add_force(near_[c].link, near_rows_[c], k * gaps_[c]);
        }
    if (curvature)
      for (const ChainContact::LinkRow &row : curvature_rows_)
        link_model_.add_row(row.link, row.row, row.weight);
    for (const ChainContact::LinkRow &row : friction_rows_)
      link_model_.add_row(row.link, row.row, row.weight);
    add_skin_rows(active);
    Eigen::VectorXd b = free_residual_;
    link_model_.add_generalised_force(pose_, b);
    dense_solve(b);
  }

  // The skins in the step's model: with s_b an unknown beside d, link b's
  // points in A add to the quadratic model
  //   1/2 k_s (s_b + ds)^2 + sum_c 1/2 k_c (g_c + v_c d + a_c ds)^2 + ds t_b d + 1/2 e_b ds^2
  // (t_b, e_b: ChainContact::Skin). Its minimum over ds is
  //   -(gamma_b + u_b d)^2 / (2 D_b),   u_b = sum_{c in A} k_c a_c v_c + t_b,
  //   gamma_b = k_s s_b + sum_{c in A} k_c a_c g_c,   D_b = k_s + sum_{c in A} k_c a_c^2 + e_b,
  // one row u_b of link b with weight -1 / D_b whose force -gamma_b u_b / D_b
  // joins the right side (equal to the exact tangent's where A holds the
  // touching points). A skin has a row where a point touches (t_b != 0) or a
  // point of A gives (a_c != 0).
  void ChainEquilibrium::add_skin_rows(const std::vector<char> &active)
  {
    skin_predictions_.clear();
    if (skins_.empty())
      return;
    const double      k = contact_.stiffness();
    std::vector<char> has_row(skins_.size(), 0);
    for (std::size_t j = 0; j < skins_.size(); ++j)
      {
        const ChainContact::Skin &skin = skins_[j];
        skin_predictions_.push_back({skin.link, skin.stiffness * skin.shift,
                                     skin.stiffness + skin.penetration_curvature, skin.penetration_row});
        has_row[j] = !skin.penetration_row.isZero();
      }
    for (std::size_t c = 0; c < active.size(); ++c)
      if (active[c] && alignment_[c] != 0.0)
        {
          const int       j = skin_of_link_[near_[c].link];
          SkinPrediction &s = skin_predictions_[j];
          const double    a = alignment_[c];
          s.u += k * a * near_rows_[c];
          s.gamma += k * a * gaps_[c];
          s.D += k * a * a;
          has_row[j] = 1;
        }
    std::size_t kept = 0;
    for (std::size_t j = 0; j < skins_.size(); ++j)
      if (has_row[j])
        {
          const SkinPrediction &s = skin_predictions_[j];
          link_model_.add_row(s.link, s.u, -1.0 / s.D);
          link_model_.add_force(s.link, s.u, -s.gamma / s.D);
          skin_predictions_[kept++] = s;
        }
    skin_predictions_.resize(kept);
  }

  // H's dense form (built once per Newton step, dense_tangent_) with the
  // pass's rows in its lower triangle, which LLT reads; shifted until
  // positive definite. For the chain's few angles (3 per joint) the
  // factorisation costs about what forming the rows does.
  void ChainEquilibrium::dense_solve(const Eigen::VectorXd &b)
  {
    Eigen::MatrixXd dense = dense_tangent_;
    link_model_.add_to_lower(pose_, dense);
    const double                scale = dense.diagonal().cwiseAbs().maxCoeff();
    Eigen::LLT<Eigen::MatrixXd> factor;
    for (double shift = 0.0; factor.compute(dense).info() != Eigen::Success; shifted_ = true)
      {
        const double more = shift == 0.0 ? 1e-8 * scale : 9.0 * shift;
        dense.diagonal().array() += more;
        shift += more;
      }
    direction_ = -factor.solve(b);
  }

  // Backtracking until U decreases enough (Armijo); `slack` admits the
  // round-off of U itself (a few ulps of its largest term) near convergence.
  // Each rejected step is replaced by the minimiser of the quadratic through
  // U(0), U'(0) and U(step), kept within [step / 10, step / 2] (Nocedal and
  // Wright, Numerical Optimization, Sec. 3.5): a step into an obstacle's
  // stiff penalty is cut to the touch in one or two trials, not in ten
  // halvings.
  bool ChainEquilibrium::line_search(Eigen::VectorXd &q)
  {
    line_start_                  = q; // no allocation after the first solve
    const Eigen::VectorXd &start  = line_start_;
    const double          energy = energy_;
    const double          slope  = residual_.dot(direction_);
    const double          slack  = 64.0 * std::numeric_limits<double>::epsilon() * energy_magnitude_;
    double                step   = 1.0;
    for (int trial = 0; trial < max_halvings; ++trial)
      {
        q = start + step * direction_;
        evaluate(q);
        if (energy_ <= energy + armijo * step * slope + slack)
          return true;
        const double curvature = energy_ - energy - slope * step;
        const double minimiser = curvature > 0.0 ? -slope * step * step / (2.0 * curvature) : 0.5 * step;
        step                   = std::clamp(minimiser, 0.1 * step, 0.5 * step);
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
    if (!touching())
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
    if (contact_.empty())
      return iterate(pressure_angles_);
    return iterate(before_first_contact(pressure_angles_));
  }

  // The free pose may lie deep inside an obstacle, where the nearest surface
  // can push the finger out on the wrong side (through a cylinder it should
  // wrap), or beyond it (a finger curled around it). Newton starts instead
  // from t q_free, the last t of 0, 1/8, 2/8, ... 1 before a surface point
  // penetrates: the pressure's shape from rest stopped short of its first
  // touch, from where the steps' active set brings the contacts in. An
  // obstacle that the finger at rest already penetrates leaves the free
  // start.
  Eigen::VectorXd ChainEquilibrium::before_first_contact(const Eigen::VectorXd &free)
  {
    const auto penetrates = [&](double t) {
      chain_.update_pose(t * free, pose_);
      return contact_.penetrates(pose_);
    };
    if (penetrates(0.0))
      return free;
    for (int eighth = 1; eighth <= 8; ++eighth)
      if (penetrates(eighth / 8.0))
        return (eighth - 1) / 8.0 * free;
    return free;
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
            const double before = relative_residual();
            prepare_tangent();
            newton_direction();
            ++result.iterations;
            if (!line_search(result.angles))
              result.failure = "line search found no decrease of the energy";
            if (!contact_.empty())
              next_search_margin(result.angles - line_start_, relative_residual() / before);
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
    if (!touching())
      return;
    std::vector<ChainContact::LinkRow> rows;
    contact_.tangent_rows(pose_, rows);
    LinkWrenchStiffness links;
    links.reset(chain_.n_joints());
    for (const ChainContact::LinkRow &row : rows)
      links.add_row(row.link, row.row, row.weight);
    links.add_to(pose_, dense);
  }

  bool ChainEquilibrium::touching() const
  {
    return !contact_.touches().empty() || !contact_.friction().grips().empty();
  }
} // namespace softchain::chain
