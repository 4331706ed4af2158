#pragma once
// CoulombFriction: the friction of the chain's surface points on obstacles
// with a coefficient mu > 0, regularised like the FEM's (docs/contact.md,
// "The method": a tangential penalty up to Coulomb's cone, then sliding).
//
// Along a load path (FrictionalLoadPath) each point k that touches obstacle
// o keeps a stick anchor a_k on it (StickAnchor), with the obstacle's normal
// n_k there and the point's normal force N_k. Within one load step the
// point's tangential slip from its anchor,
//     delta_k = P_k (x_k - a_k),   P_k = I - n_k n_k^T,
// costs the potential
//     D(delta) = 1/2 k_t delta^2               for delta = |delta_k| <= delta_s = mu N_k / k_t,
//                mu N_k (delta - delta_s / 2)  beyond,
// whose force on the finger is f_k = -D'(delta) t, t = delta_k / delta:
// -k_t delta_k while the point sticks, mu N_k against its slip once it
// slides. Its Hessian in x is
//     D''(delta) t t^T + D'(delta) / delta (P_k - t t^T)
// (k_t P_k in stick, mu N_k / delta (P_k - t t^T) in slip): two rows of the
// chain's low-rank contact tangent per anchor, along t and n_k x t.
//
// N_k and n_k are held fixed within a solve, so that the problem stays
// conservative (the current N_k would make the friction force depend on the
// normal penetration, a non-symmetric coupling); FrictionalLoadPath solves
// each step again with the normal forces it found until they settle, which
// is Coulomb's law with the current N_k. x_k is the point on its link's
// rigid section: a section that gives (ChainContact's skin) moves it along
// the palm's normal, nearly the obstacle's, which the slip does not see.
// k_t is the normal penalty k_c, in series with the section's shear: a
// section sheared by its sticking points gives along the palm by c_t(p)
// times their force (SkinComplianceFit's c_t; the silicone between the palm
// and the fabric layer shears). The link's shear spring 1 / c_t is shared
// among its anchors in proportion to their normal forces N_k (of sum N_b):
//     k_t = 1 / (1 / k_c + c_t N_b / N_k),
// so that points sticking alike carry 1 / (c_t + 1 / (m_b k_c)) together
// where their normal forces are equal, all reach the cone at the same slip
// mu c_t N_b (plus mu N_k / k_c), and a point that grazes the obstacle
// takes a share that vanishes with its force (an equal share would halve
// its neighbours' stiffness as it touches, and the normal forces of a
// grasp's path then cycle). Where some of them slide, the others keep their
// share. Without c_t a sticking point slips elastically by |f_t| / k_c,
// 10 um per newton.
#include <softchain/chain/chain_load.h>
#include <softchain/chain/kinematic_chain.h>

#include <Eigen/Core>

#include <array>
#include <utility>
#include <vector>

namespace softchain::chain
{
  class CoulombFriction
  {
  public:
    // The friction at one anchored point at the last update.
    struct Grip
    {
      int             link = 0, point = 0, obstacle = 0;
      Eigen::Vector3d position = Eigen::Vector3d::Zero(); // x_k, m, world (the rigid section's point)
      Eigen::Vector3d force    = Eigen::Vector3d::Zero(); // f_k on the finger, N
      double          slip     = 0.0;                     // |delta_k|, m
      Eigen::Vector3d direction = Eigen::Vector3d::Zero(); // t, along delta_k (any tangent at delta_k = 0)
      bool            sliding  = false;                   // on the cone: |f_k| = mu N_k
      // The Hessian's rows: directions (world) and weights, N/m.
      std::array<std::pair<Eigen::Vector3d, double>, 2> rows;
    };

    // `coefficients`: mu per obstacle (>= 0); `stiffness`: k_c [N/m];
    // `shear_compliance`: c_t [m/N] (0: rigid sections); `anchors`: those of
    // obstacles with mu > 0 and N > 0 act (sorted by link here). Throws
    // std::invalid_argument on a negative or non-finite coefficient or
    // compliance, or an anchor naming no obstacle.
    void set(const std::vector<double> &coefficients, double stiffness, double shear_compliance,
             std::vector<StickAnchor> anchors);
    bool any() const { return any_; } // some obstacle has friction
    double coefficient(int obstacle) const { return coefficients_[obstacle]; }
    // k_t of anchor i (in anchors()' order).
    double stiffness(std::size_t anchor) const { return anchor_stiffness_[anchor]; }
    const std::vector<StickAnchor> &anchors() const { return anchors_; }

    // The grips at `pose`, point k of link b at c_b + R_b offsets[k];
    // returns sum D.
    double update(const ChainPose &pose, const std::vector<Eigen::Vector3d> &offsets);
    const std::vector<Grip> &grips() const { return grips_; }

    // The anchors after the step that ends at the last update: a sliding
    // point's anchor follows it to the cone's edge, a_k = x_k - delta_s t
    // (the return mapping); a sticking one stays.
    std::vector<StickAnchor> slid_anchors() const;

  private:
    std::vector<double>      coefficients_;
    bool                     any_ = false;
    std::vector<StickAnchor> anchors_;
    std::vector<double>      anchor_stiffness_; // k_t per anchor, N/m
    std::vector<Grip>        grips_;
  };
} // namespace softchain::chain
