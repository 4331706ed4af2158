#pragma once
// ChainModel: one finger of the chain tier, i.e. the geometry (KinematicChain,
// optionally with links shaped by the pressure: LinkGeometry), the joint
// stiffness K, the pressure actuation J_p and, optionally, the links' series
// compliance (LinkCompliance), the joints' nonlinear response to forces
// (JointForceLaw) and the surface it touches obstacles with
// (CollisionSurface); everything the equilibrium K q = J_p p + J(q)^T f
// needs besides the load.
#include <softchain/chain/collision_surface.h>
#include <softchain/chain/joint_force_law.h>
#include <softchain/chain/joint_stiffness.h>
#include <softchain/chain/kinematic_chain.h>
#include <softchain/chain/link_compliance.h>
#include <softchain/chain/piecewise_linear.h>
#include <softchain/chain/link_geometry.h>
#include <softchain/chain/link_shift_per_turn.h>
#include <softchain/chain/pressure_actuation.h>

#include <optional>
#include <string>
#include <vector>

namespace softchain::chain
{
  class ChainModel
  {
  public:
    // Joint counts must agree; throws std::invalid_argument otherwise.
    ChainModel(std::string name, KinematicChain chain, JointStiffness stiffness,
               PressureActuation actuation);

    const std::string       &name() const { return name_; }
    ChainModel               with_name(std::string name) const;
    // The reference geometry (rigid links between the reference joint centres).
    const KinematicChain    &chain() const { return chain_; }
    // The geometry under `pressure`: the links of the LinkGeometry if set,
    // else the reference one, shifting per in-plane turn (LinkShiftPerTurn)
    // about the pressure-only angles K(p)^-1 J_p(p) p if set.
    KinematicChain           chain_at(double pressure) const;
    // The same into `chain`, which must be a copy of chain(), about the
    // pressure-only angles `pressure_angles` (3 per joint; no allocation).
    void                     chain_at(double pressure, const Eigen::VectorXd &pressure_angles,
                                      KinematicChain &chain) const;
    void                     set_link_geometry(LinkGeometry geometry);
    void                     set_link_shift(LinkShiftPerTurn shift);
    bool                     has_link_shift() const { return link_shift_.has_value(); }
    // The same model with links that do not shift as their joints turn.
    ChainModel               without_link_shift() const;
    // The same model with rigid links between the reference centres (no
    // link geometry, shift or compliance).
    ChainModel               with_rigid_links() const;
    void                     set_link_compliance(LinkCompliance compliance);
    // The same model with links rigid under forces (no link compliance).
    ChainModel               without_link_compliance() const;
    bool                     has_link_compliance() const { return link_compliance_.has_value(); }
    // c(p) of the links in series with the joints, m/N (0: rigid links).
    double                   link_compliance(double pressure) const;
    // The tip's deflection by the links under `load` (LinkCompliance; zero
    // without link compliance), m, world.
    Eigen::Vector3d          link_deflection(const ChainLoad &load) const;
    bool                     has_link_geometry() const { return link_geometry_.has_value(); }
    // c_s(p), how far a link's section gives along its palm normal per newton
    // of contact force (ChainContact's skin), m/N; 0 without a table (none:
    // rigid sections).
    void                     set_skin_compliance(std::optional<PiecewiseLinear> compliance);
    double                   skin_compliance(double pressure) const;
    bool                     has_skin_compliance() const { return skin_compliance_.has_value(); }
    // c_t(p), how far a link's section gives along the palm per newton of
    // friction (CoulombFriction), m/N; 0 without a table (none: sections
    // rigid in shear).
    void                     set_skin_shear_compliance(std::optional<PiecewiseLinear> compliance);
    double                   skin_shear_compliance(double pressure) const;
    void                     set_collision_surface(CollisionSurface surface);
    // The collision surface, or nullptr (the model cannot touch).
    const CollisionSurface  *collision_surface() const;
    const JointStiffness    &stiffness() const { return stiffness_; }
    // The joints' response to forces along measured curves (JointForceLaw),
    // or nullptr: linear springs K(p) about the pressure-only state.
    void                     set_force_law(JointForceLaw law);
    const JointForceLaw     *force_law() const { return force_law_ ? &*force_law_ : nullptr; }
    // The same model with linear springs (no force law).
    ChainModel               with_linear_joints() const;
    const PressureActuation &actuation() const { return actuation_; }
    // The tabulated pressures of K(p), J_p(p) and the link geometry U(p)
    // together (sorted, unique): between consecutive ones all three are
    // linear in p, so these rows sampled at them reproduce the model exactly.
    std::vector<double>      table_pressures() const;

  private:
    std::string       name_;
    KinematicChain    chain_;
    JointStiffness    stiffness_;
    PressureActuation actuation_;
    std::optional<LinkGeometry> link_geometry_;
    std::optional<LinkShiftPerTurn> link_shift_;
    std::optional<LinkCompliance> link_compliance_;
    std::optional<PiecewiseLinear> skin_compliance_;
    std::optional<PiecewiseLinear> skin_shear_compliance_;
    std::optional<JointForceLaw>  force_law_;
    std::optional<CollisionSurface> collision_surface_;
  };
} // namespace softchain::chain
