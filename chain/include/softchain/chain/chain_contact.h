#pragma once
// ChainContact: the chain's collision surface (CollisionSurface) against
// rigid obstacles (geometry::Obstacle, the FEM's analytic signed distances),
// frictionless and unilateral, by a penalty on the penetration. For each
// surface point x_k and obstacle with signed distance g (n = grad g, H_g =
// grad grad g, rigid_obstacle.h) the contact energy and the force on the
// finger are
//     U_c = sum_k 1/2 k_c <-g(x_k)>^2,     f_k = k_c <-g(x_k)> n(x_k),
// <.> the positive part: only penetrating points push, along the outward
// normal. f_k acts at the material point x_k of its link, so the chain's
// generalised force is J_k^T f_k and its energy gradient that of U_c. The
// consistent tangent of U_c adds to ChainEquilibrium's (which already holds
// f_k's part as a point load at x_k, the change of the lever J_k)
//     J_k^T k_c (n n^T + g H_g) J_k,
// the normal stiffness and the curvature of a round obstacle (negative:
// g < 0 where it acts): one row n^T J_k per touching point and one per
// non-zero curvature e^T J_k, each of one link, which ChainEquilibrium
// gathers into each link's 6 x 6 stiffness (LinkWrenchStiffness).
//
// The penalty k_c [N/m] per point makes the penetration k_c^-1 |f_k|: with
// the default 1e5 N/m, 10 um under a force of 1 N on one point, and the
// force's error relative to an exact constraint ~ k_joint / (k_c l^2), the
// joints' stiffness against the penalty's at the lever l. A moving obstacle
// stands where its motion has brought it at the load's path parameter.
//
// Friction (CoulombFriction): on obstacles with a coefficient, each stick
// anchor of the load adds its regularised Coulomb potential D to U_c, its
// force f_k at the point of the link's rigid section, and its two Hessian
// rows J_k^T e (e along and across the slip) to the low-rank tangent. An
// equilibrium with friction depends on the load's path; FrictionalLoadPath
// follows it and hands each step's anchors to the next.
//
// The section's compliance (optional, per link): a soft finger pressed on
// its palm gives locally -- the palm plate bends into the cavity -- before
// its joints turn. Link b's surface then carries a skin displacement s_b
// along d_b = R_b e_y (the palm's inward normal, +y in the link frame,
// docs/conventions.md), x_k = c_b + R_b (L_k + s_b e_y), held by a spring
// of stiffness k_s = 1 / c_b:
//     U_c(q) = min_s sum_b [1/2 k_s s_b^2 + sum_{k in b} 1/2 k_c <-g(x_k)>^2].
// Only the points on sections that give move with the skin
// (CollisionSurface::gives: over the cavity, not the solid base and tip);
// for the others a_k = 0. Each s_b is found exactly (a convex problem in one unknown) at every
// update, so U_c stays a function of the angles, its gradient is that of
// the touching points' forces at the displaced points (envelope theorem),
// and its tangent is the rigid skin's minus one rank-one term per touching
// link (the Schur complement of s_b):
//     - u_b^T u_b / D_b,   u_b = sum_k k_c (a_k n_k^T J_k + g_k d^T H_g J_k + g_k (d x n_k)^T W_k),
//     D_b = k_s + sum_k k_c (a_k^2 + g_k d^T H_g d),   a_k = n_k . d,
// W_k the rows a_{i,alpha} of the joints up to link b (d turns with the link).
#include <softchain/chain/collision_surface.h>
#include <softchain/chain/coulomb_friction.h>
#include <softchain/chain/kinematic_chain.h>
#include <softchain/chain/link_wrench_stiffness.h>
#include <softchain/geometry/contact_scene.h>

#include <Eigen/Core>

#include <vector>

namespace softchain::chain
{
  class ChainContact
  {
  public:
    // A surface point inside an obstacle.
    struct Touch
    {
      int             link = 0, point = 0, obstacle = 0;
      Eigen::Vector3d position = Eigen::Vector3d::Zero(); // x_k, m, world
      Eigen::Vector3d normal   = Eigen::Vector3d::Zero(); // n, the obstacle's outward normal
      Eigen::Vector3d force    = Eigen::Vector3d::Zero(); // f_k on the finger, N
      double          gap      = 0.0;                     // g < 0, m
      Eigen::Matrix3d curvature = Eigen::Matrix3d::Zero(); // H_g, 1/m
    };

    // The obstacles of one load at path parameter `path` and the surface at
    // its pressure (`surface` must outlive the contact; none: no contact),
    // with the stick anchors of its friction. Throws std::invalid_argument
    // if there are obstacles but no surface, a friction coefficient is
    // negative, or the stiffness is not positive. `skin_compliance` [m/N]
    // per link (empty or 0: a rigid section); `shear_compliance` [m/N] the
    // sections' give along the palm under friction (CoulombFriction).
    void set(const CollisionSurface *surface, double pressure,
             const std::vector<data::ObstacleRecord> &obstacles, double stiffness,
             const std::vector<double> &skin_compliance = {}, double shear_compliance = 0.0,
             double path = 1.0, std::vector<StickAnchor> anchors = {});
    bool empty() const { return obstacles_.empty(); }

    // Finds the touching points at `pose` (sorted by link) and the friction
    // of the anchored points, and returns U_c (with sum D).
    double update(const ChainPose &pose);
    const std::vector<Touch> &touches() const { return touches_; }
    double                    stiffness() const { return stiffness_; }
    const CoulombFriction    &friction() const { return friction_; }
    // A row of the contact's tangent: g^T J_b of one link (LinkWrenchStiffness)
    // with its weight.
    struct LinkRow
    {
      int                           link = 0;
      LinkWrenchStiffness::Vector6d row;
      double                        weight = 0.0;
    };
    // The Hessian rows of the friction at the last update (weights > 0).
    void friction_rows(std::vector<LinkRow> &rows) const;
    // The anchors of a pass of a frictional load step at the last update
    // (at `pose`): one per point touching an obstacle with friction, at its
    // anchor in `held` (the step's start) or, new in contact, where it
    // entered the obstacle on its way from where it stood at the step's
    // start (`start`, surface_positions), with the touch's normal and
    // normal force.
    std::vector<StickAnchor> touching_anchors(const ChainPose &pose, const std::vector<StickAnchor> &held,
                                              const std::vector<Eigen::Vector3d> &start) const;
    // Every point of the rigid sections at `pose`, c_b + R_b L_k(p).
    void surface_positions(const ChainPose &pose, std::vector<Eigen::Vector3d> &positions) const;

    // The tangent's low-rank part at the last update, J^T k_c (n n^T + g H_g) J
    // (with the friction's and the skins' rows) = sum of w J_b^T g g^T J_b over `rows`.
    void tangent_rows(const ChainPose &pose, std::vector<LinkRow> &rows) const;
    // Only the curvature rows of the touching points (weights k_c g mu).
    void curvature_rows(std::vector<LinkRow> &rows) const;

    // The candidates of a Newton step's active set at `pose`: every surface
    // point within `margin` of an obstacle (g < margin, the touching ones
    // among them); without their curvature (H_g = 0 in each) unless asked.
    void candidates(const ChainPose &pose, double margin, std::vector<Touch> &near,
                    bool with_curvature = true) const;
    // A lower bound of the distance to the obstacles of every point of the
    // surface's node `node` (CollisionSurface::nodes) at the pose of the
    // last search (candidates, penetrates): min over obstacles of
    // g(centre) - radius - |s_b|, its sphere at the load's pressure.
    double clearance(int node) const;
    // Whether a surface point lies inside an obstacle at `pose` (touches()
    // would not be empty after update(pose)), found without the touches or
    // the skins: the search stops at the first such point.
    bool penetrates(const ChainPose &pose) const;
    // The surface's spheres at the load's pressure (CollisionSurface::spheres_at).
    const std::vector<CollisionSurface::Sphere> &spheres() const { return *spheres_; }
    // A touching link's skin at the last update: its displacement s_b, the
    // direction d_b (world), k_s, and the parts of u_b and D_b (header) that
    // the touching points' penetrations g_k carry (t_b, e_b), which a Newton
    // step's model adds to the rows a_k n_k^T J_k of the points it takes.
    struct Skin
    {
      int                link      = 0;
      Eigen::Vector3d    direction = Eigen::Vector3d::Zero();
      double             shift = 0.0, stiffness = 0.0;
      LinkWrenchStiffness::Vector6d penetration_row = LinkWrenchStiffness::Vector6d::Zero(); // t_b, of link b
      double                        penetration_curvature = 0.0;                             // e_b
    };
    void skins(const ChainPose &pose, std::vector<Skin> &skins) const;
    bool has_skin() const { return !skin_compliance_.empty(); }
    // Whether the point of `touch` moves with its link's skin (a link with
    // skin compliance, a point of CollisionSurface::gives).
    bool gives(const Touch &touch) const;
    // d_b = R_b e_y of `link` at `pose`.
    Eigen::Vector3d skin_direction(const ChainPose &pose, int link) const;

    // What each obstacle receives at the last update (normal and friction
    // forces): the force [N] and its moment about the origin [N m], world
    // axes, in the obstacles' order.
    std::vector<data::ObstacleWrench> obstacle_wrenches() const;
    // The deepest penetration at the last update, m (0 without touches).
    double max_penetration() const;

  private:
    // A run of one link's points near the obstacles, in near_at_rest_.
    struct Points
    {
      const Touch *first;
      std::size_t  size;
      const Touch *begin() const { return first; }
      const Touch *end() const { return first + size; }
    };
    // s_b of one link from its points near the obstacles (at s = 0):
    // E'(s) = k_s s + sum k_c <g_k(s)>- a_k(s) = 0, safeguarded Newton.
    double skin_shift(int link, Points near) const;
    // The touch of surface point k of `link` against obstacle o at x, or
    // false if x is outside.
    bool touch_at(const Eigen::Vector3d &x, int link, int k, int o, Touch &touch) const;
    // The same for a candidate `point` (at its position with the skins at
    // rest) whose skin has moved it by s along the link's e_y (`shift` =
    // s d_b in the world), if inside only: false, and `touch` untouched,
    // outside. At the pose of the last frame_obstacles.
    bool touch_inside(const Touch &point, double s, const Eigen::Vector3d &shift, Touch &touch) const;
    // The obstacles seen from every link's frame at `pose` (framed_): a
    // search then tests the points' offsets L_k and the spheres' centres
    // as they are, without mapping each to the world and on to the
    // obstacle's rest frame.
    void frame_obstacles(const ChainPose &pose) const;
    const geometry::ObstacleInFrame &framed(int link, int obstacle) const
    {
      return framed_[link * obstacles_.size() + obstacle];
    }
    // clearance with the skins at rest (s_b = 0).
    double clearance_at_rest(int node) const;
    // |s_b|: how far link b's skin has moved its points (0 without skins).
    double skin_reach(int link) const;
    // Appends the points of `cluster` within `margin` of an obstacle to `near`.
    void add_candidates(const ChainPose &pose, const CollisionSurface::Cluster &cluster,
                        const CollisionSurface::Sphere &sphere, double margin, bool with_curvature,
                        std::vector<Touch> &near) const;
    // Appends the rows of `touch`, with or without its normal row.
    void append_rows(const Touch &touch, bool normal, std::vector<LinkRow> &rows) const;

    const CollisionSurface        *surface_ = nullptr;
    const std::vector<CollisionSurface::Sphere> *spheres_ = nullptr; // the surface's at the load's pressure
    std::vector<geometry::Obstacle> obstacles_;
    std::vector<geometry::RigidTransform> poses_; // each obstacle at the end of its motion (path parameter 1)
    std::vector<Eigen::Vector3d>    offsets_; // L_k(p)
    double                          stiffness_ = 0.0;
    std::vector<Touch>              touches_;
    std::vector<double>             skin_compliance_; // c_b, m/N (empty: no skin)
    std::vector<double>             skin_shift_;      // s_b at the last update
    std::vector<Touch>              near_at_rest_;    // update's points near the obstacles at s = 0
    mutable std::vector<geometry::ObstacleInFrame> framed_; // obstacle o seen from link b at [b * n_obstacles + o]
    CoulombFriction                 friction_;
  };
} // namespace softchain::chain
