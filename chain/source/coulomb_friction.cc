#include <softchain/chain/coulomb_friction.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace softchain::chain
{
  namespace
  {
    // A unit vector perpendicular to n.
    Eigen::Vector3d tangent_of(const Eigen::Vector3d &n)
    {
      const Eigen::Vector3d e = std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
      return (e - e.dot(n) * n).normalized();
    }
  } // namespace

  void CoulombFriction::set(const std::vector<double> &coefficients, const double stiffness,
                            const double shear_compliance, std::vector<StickAnchor> anchors)
  {
    for (const double mu : coefficients)
      if (!(mu >= 0.0) || !std::isfinite(mu))
        throw std::invalid_argument("chain contact: a friction coefficient is negative or not finite");
    if (!(shear_compliance >= 0.0) || !std::isfinite(shear_compliance))
      throw std::invalid_argument("chain contact: the sections' shear compliance is negative or not finite");
    coefficients_ = coefficients;
    any_          = std::any_of(coefficients.begin(), coefficients.end(), [](double mu) { return mu > 0.0; });
    anchors_.clear();
    for (const StickAnchor &a : anchors)
      {
        if (a.obstacle < 0 || a.obstacle >= static_cast<int>(coefficients.size()))
          throw std::invalid_argument("chain contact: a stick anchor names obstacle " +
                                      std::to_string(a.obstacle) + " of " +
                                      std::to_string(coefficients.size()));
        if (coefficients[a.obstacle] > 0.0 && a.normal_force > 0.0)
          anchors_.push_back(a);
      }
    std::stable_sort(anchors_.begin(), anchors_.end(),
                     [](const StickAnchor &a, const StickAnchor &b) { return a.link < b.link; });
    anchor_stiffness_.resize(anchors_.size());
    for (std::size_t begin = 0, end = 0; begin < anchors_.size(); begin = end)
      {
        while (end < anchors_.size() && anchors_[end].link == anchors_[begin].link)
          ++end;
        double N_b = 0.0;
        for (std::size_t i = begin; i < end; ++i)
          N_b += anchors_[i].normal_force;
        for (std::size_t i = begin; i < end; ++i)
          anchor_stiffness_[i] = 1.0 / (1.0 / stiffness + shear_compliance * N_b / anchors_[i].normal_force);
      }
    grips_.clear();
  }

  double CoulombFriction::update(const ChainPose &pose, const std::vector<Eigen::Vector3d> &offsets)
  {
    grips_.resize(anchors_.size());
    double energy = 0.0;
    for (std::size_t i = 0; i < anchors_.size(); ++i)
      {
        const StickAnchor &a = anchors_[i];
        Grip              &g = grips_[i];
        g.link     = a.link;
        g.point    = a.point;
        g.obstacle = a.obstacle;
        g.position = pose.link_origins[a.link] + pose.link_rotations[a.link] * offsets[a.point];
        Eigen::Vector3d delta = g.position - a.position;
        delta -= a.normal.dot(delta) * a.normal;
        g.slip = delta.norm();
        const double k_t     = anchor_stiffness_[i];
        const double limit   = coefficient(a.obstacle) * a.normal_force; // mu N
        const double elastic = limit / k_t;                              // delta_s
        const Eigen::Vector3d t = g.slip > 0.0 ? Eigen::Vector3d(delta / g.slip) : tangent_of(a.normal);
        g.direction = t;
        g.sliding   = g.slip > elastic;
        if (!g.sliding)
          {
            g.force = -k_t * delta;
            g.rows  = {{{t, k_t}, {a.normal.cross(t), k_t}}};
            energy += 0.5 * k_t * g.slip * g.slip;
          }
        else
          {
            g.force = -limit * t;
            g.rows  = {{{t, 0.0}, {a.normal.cross(t), limit / g.slip}}};
            energy += limit * (g.slip - 0.5 * elastic);
          }
      }
    return energy;
  }

  std::vector<StickAnchor> CoulombFriction::slid_anchors() const
  {
    std::vector<StickAnchor> anchors = anchors_;
    for (std::size_t i = 0; i < grips_.size(); ++i)
      if (grips_[i].sliding)
        {
          const StickAnchor &a       = anchors_[i];
          const double       elastic = coefficient(a.obstacle) * a.normal_force / anchor_stiffness_[i];
          anchors[i].position        = grips_[i].position - elastic * grips_[i].direction;
        }
    return anchors;
  }
} // namespace softchain::chain
