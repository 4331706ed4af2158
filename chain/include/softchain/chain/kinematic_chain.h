#pragma once
// KinematicChain: the paper's lumped finger (Sec. II, III-C): rigid links joined
// by spherical joints. Joint i (0-based here, i = 0..n-1) sits at its reference
// centre J_i; link i is the rigid body between J_i and J_{i+1} (the last link
// reaches the tip point T). The clamped base carries everything proximal to J_0.
//
// Joint angles q = (psi_0, theta_0, phi_0, ..., psi_{n-1}, theta_{n-1},
// phi_{n-1}) are the relative rotations of docs/conventions.md ("Joints") with the shared
// Euler convention (data/joint_angles.h): E(q_i) = Rx(psi) Ry(theta) Rz(phi),
// the convention of the reduction that measured the angles.
// Forward kinematics (R_{-1} = I, c_0 = U_0):
//   R_i     = R_{i-1} E(q_i)
//   c_{i+1} = c_i + R_i (U_{i+1} - U_i),   tip = c_{n-1} + R_{n-1} (U_T - U_{n-1})
// where U_i, U_T are the link geometry: the positions of the joints and the
// tip at zero angles. By default U = J (rigid links between the reference
// centres); with_link_geometry sets another one, e.g. the finger's links
// stretched and sheared by the pressure (ChainModel::chain_at). A material
// point X of link b (reference position) moves with its link, stretched
// linearly along it: with s = (X - J_b)_x / (J_{b+1} - J_b)_x clipped to
// [0, 1] and the end shifts D_i = U_i - J_i (D_n = U_T - T),
//   x = c_b + R_b (X + (1 - s) D_b + s D_{b+1} - U_b),
// which is x = c_b + R_b (X - J_b) for the default geometry and carries the
// reference tip T to the chain's tip. The tip frame is R_{n-1} Q_T, Q_T the
// tip face's rotation in the last link's frame (identity by default).
// The world axes of the three angles of joint i are the columns of
//   A_i = R_{i-1} [ e_x,  Rx(psi) e_y,  Rx(psi) Ry(theta) e_z ]
// so that dx/dq_{i,alpha} = a_{i,alpha} x (x - p_{i,alpha}) for points distal
// to i, the pivot p_{i,alpha} being c_i for theta and phi.
//
// Twist axes (with_twist_offsets). Joint i may twist about an axis of its
// own: psi turns about a_psi through the twist pivot s_i, the point
// U_i + o_i of the proximal link (o_i the offset of the twist axis point
// S_i from J_i), while theta and phi turn about c_i:
//   s_i = c_i^0 + R_{i-1} o_i,   c_i = s_i - R_{i-1} Rx(psi_i) o_i,
// c_i^0 the centre c_i would have at psi_i = 0 (the recursion above). The
// pivot of psi is p_{i,psi} = s_i; o_i = 0 is the spherical joint.
//
// Links that shift as their joint turns in the plane (assign_link_shift):
// joint i's in-plane turn from its pressure-only state phi_i^p moves link i,
// and everything distal to it, along the link's own frame by
//   o_i = c_i + R_i g_i (phi_i - phi_i^p),   c_{i+1} = o_i + R_i (U_{i+1} - U_i),
// g_i (in the link's x-y plane, m/rad) the shift per radian
// (LinkShiftPerTurn). Link i's material points move with o_i in place of c_i.
// Then dx/dphi_i = a_phi x (x - c_i) + R_i g_i for x distal to i, the turn
// about the pivot p_{i,phi} = c_i + a_phi x (R_i g_i) (R_i g_i is normal to
// a_phi = R_i e_z): a joint whose pivot rolls. Without shifts o_i = c_i.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace softchain::chain
{
  // The chain's configuration for one set of joint angles.
  struct ChainPose
  {
    std::vector<Eigen::Vector3d> joint_positions; // c_i, world
    std::vector<Eigen::Vector3d> twist_pivots;    // s_i, world (= c_i without twist offsets)
    std::vector<Eigen::Vector3d> bend_pivots;     // p_{i,phi}, world (= c_i without link shifts)
    std::vector<Eigen::Vector3d> link_origins;    // o_i: where link i's frame sits (= c_i without link shifts)
    std::vector<Eigen::Vector3d> shift_rates;     // R_i g_i = d o_i / d phi_i at fixed R_i, world
    std::vector<Eigen::Matrix3d> link_rotations;  // R_i
    std::vector<Eigen::Matrix3d> joint_axes;      // A_i (world axes as columns)
    Eigen::Vector3d              tip_position = Eigen::Vector3d::Zero();
    Eigen::Matrix3d              tip_rotation = Eigen::Matrix3d::Identity(); // R_{n-1} Q_T

    // The pivot of angle alpha (0 psi, 1 theta, 2 phi) of joint i.
    const Eigen::Vector3d &pivot(int i, int alpha) const
    {
      return alpha == 0 ? twist_pivots[i] : alpha == 1 ? joint_positions[i] : bend_pivots[i];
    }
  };

  class KinematicChain
  {
  public:
    // Joint centres in order along +x (strictly increasing x) and the tip
    // point beyond the last one; throws std::invalid_argument otherwise.
    KinematicChain(std::vector<Eigen::Vector3d> joint_centres,
                   const Eigen::Vector3d       &tip);

    int n_joints() const { return static_cast<int>(joint_centres_.size()); }
    int n_angles() const { return 3 * n_joints(); }
    const Eigen::Vector3d &joint_centre(int i) const { return joint_centres_[i]; }
    const Eigen::Vector3d &tip() const { return tip_; }

    // The same joints with link geometry U (one point per joint), U_T and
    // the tip frame Q_T; throws std::invalid_argument unless U increases
    // strictly along x and U_T lies beyond the last one.
    KinematicChain with_link_geometry(std::vector<Eigen::Vector3d> joints,
                                      const Eigen::Vector3d       &tip,
                                      const Eigen::Matrix3d       &tip_frame) const;
    // The same in place, U_i = joint_at(i) (no allocation: the equilibrium
    // sets the geometry of every load's pressure).
    template <class JointAt>
    void assign_link_geometry(const JointAt &joint_at, const Eigen::Vector3d &tip,
                              const Eigen::Matrix3d &tip_frame)
    {
      for (int i = 0; i < n_joints(); ++i)
        link_joints_[i] = joint_at(i);
      link_tip_  = tip;
      tip_frame_ = tip_frame;
      check_link_order();
    }
    const Eigen::Vector3d &link_joint(int i) const { return link_joints_[i]; }
    const Eigen::Vector3d &link_tip() const { return link_tip_; }

    // The same chain whose joint i twists about the proximal link's x axis
    // through its twist axis point J_i + offsets[i] (one finite offset per
    // joint, else std::invalid_argument; the x part moves the point along
    // the axis and changes nothing).
    KinematicChain         with_twist_offsets(std::vector<Eigen::Vector3d> offsets) const;
    const Eigen::Vector3d &twist_offset(int i) const { return twist_offsets_[i]; }
    bool                   has_twist_offsets() const { return has_twist_offsets_; }

    // Links that shift as their joints turn in the plane (header): g_i =
    // shift_at(i) in link i's frame (its z part must be 0), about the
    // pressure-only angles phi_i^p = reference_angle(i). No allocation.
    template <class ShiftAt, class ReferenceAngle>
    void assign_link_shift(const ShiftAt &shift_at, const ReferenceAngle &reference_angle)
    {
      has_link_shift_ = false;
      for (int i = 0; i < n_joints(); ++i)
        {
          link_shifts_[i]   = shift_at(i);
          shift_origins_[i] = reference_angle(i);
          has_link_shift_   = has_link_shift_ || link_shifts_[i] != Eigen::Vector3d::Zero();
        }
      check_link_shift();
    }
    bool has_link_shift() const { return has_link_shift_; }

    // Link that carries the material point with reference position X: the
    // last joint i with J_i,x <= X_x, or -1 for the clamped base.
    int link_of(const Eigen::Vector3d &X) const;

    ChainPose rest_pose() const;
    // Overwrites `pose` (sized by rest_pose(); no allocation) for angles q.
    void update_pose(const Eigen::VectorXd &q, ChainPose &pose) const;
    // Current position of the reference point X carried by `link` (-1: base).
    Eigen::Vector3d point_position(const ChainPose &pose, int link,
                                   const Eigen::Vector3d &X) const;

  private:
    void check_link_order() const;
    void check_link_shift() const;

    std::vector<Eigen::Vector3d> joint_centres_;
    Eigen::Vector3d              tip_;
    std::vector<Eigen::Vector3d> link_joints_; // U_i
    Eigen::Vector3d              link_tip_;    // U_T
    Eigen::Matrix3d              tip_frame_ = Eigen::Matrix3d::Identity(); // Q_T
    std::vector<Eigen::Vector3d> twist_offsets_; // o_i
    bool                         has_twist_offsets_ = false;
    std::vector<Eigen::Vector3d> link_shifts_;   // g_i, link frame
    std::vector<double>          shift_origins_; // phi_i^p
    bool                         has_link_shift_ = false;
  };
} // namespace softchain::chain
