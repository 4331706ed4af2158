#include <softchain/chain/chain_model.h>

#include <stdexcept>

namespace softchain::chain
{
  ChainModel::ChainModel(std::string name, KinematicChain chain, JointStiffness stiffness,
                         PressureActuation actuation)
    : name_(std::move(name))
    , chain_(std::move(chain))
    , stiffness_(std::move(stiffness))
    , actuation_(std::move(actuation))
  {
    if (stiffness_.n_joints() != chain_.n_joints() ||
        actuation_.rest_torque_per_pascal().size() != chain_.n_angles())
      throw std::invalid_argument("ChainModel: joint counts of geometry, stiffness and J_p differ");
  }

  ChainModel ChainModel::with_name(std::string name) const
  {
    ChainModel renamed = *this;
    renamed.name_      = std::move(name);
    return renamed;
  }

  ChainModel ChainModel::with_rigid_links() const
  {
    ChainModel rigid = *this;
    rigid.link_geometry_.reset();
    rigid.link_shift_.reset();
    rigid.link_compliance_.reset();
    rigid.skin_compliance_.reset();
    rigid.skin_shear_compliance_.reset();
    rigid.collision_surface_.reset(); // shaped for the links it leaves
    return rigid;
  }

  void ChainModel::set_link_compliance(LinkCompliance compliance)
  {
    link_compliance_ = std::move(compliance);
  }

  void ChainModel::set_skin_compliance(std::optional<PiecewiseLinear> compliance)
  {
    skin_compliance_ = std::move(compliance);
  }

  double ChainModel::skin_compliance(const double pressure) const
  {
    return skin_compliance_ ? (*skin_compliance_)(pressure) : 0.0;
  }

  void ChainModel::set_skin_shear_compliance(std::optional<PiecewiseLinear> compliance)
  {
    skin_shear_compliance_ = std::move(compliance);
  }

  double ChainModel::skin_shear_compliance(const double pressure) const
  {
    return skin_shear_compliance_ ? (*skin_shear_compliance_)(pressure) : 0.0;
  }

  void ChainModel::set_collision_surface(CollisionSurface surface)
  {
    if (surface.link_begin().size() != static_cast<std::size_t>(chain_.n_joints()) + 1)
      throw std::invalid_argument("ChainModel: the collision surface has another number of links");
    collision_surface_ = std::move(surface);
  }

  const CollisionSurface *ChainModel::collision_surface() const
  {
    return collision_surface_ ? &*collision_surface_ : nullptr;
  }

  ChainModel ChainModel::without_link_compliance() const
  {
    ChainModel rigid = *this;
    rigid.link_compliance_.reset();
    return rigid;
  }

  void ChainModel::set_force_law(JointForceLaw law)
  {
    if (law.n_joints() != chain_.n_joints())
      throw std::invalid_argument("ChainModel: the force law has another number of joints");
    force_law_ = std::move(law);
  }

  ChainModel ChainModel::with_linear_joints() const
  {
    ChainModel linear = *this;
    linear.force_law_.reset();
    return linear;
  }

  double ChainModel::link_compliance(const double pressure) const
  {
    return link_compliance_ ? link_compliance_->at(pressure) : 0.0;
  }

  Eigen::Vector3d ChainModel::link_deflection(const ChainLoad &load) const
  {
    return link_compliance_ ? link_compliance_->tip_deflection(load, chain_) : Eigen::Vector3d::Zero();
  }

  std::vector<double> ChainModel::table_pressures() const
  {
    std::vector<double> pressures = stiffness_.table_pressures();
    merge_abscissae(actuation_.table_pressures(), pressures);
    if (link_geometry_)
      merge_abscissae(link_geometry_->table_pressures(), pressures);
    if (link_shift_)
      merge_abscissae(link_shift_->table_pressures(), pressures);
    if (skin_compliance_)
      merge_abscissae(skin_compliance_->abscissae(), pressures);
    if (skin_shear_compliance_)
      merge_abscissae(skin_shear_compliance_->abscissae(), pressures);
    return pressures;
  }

  KinematicChain ChainModel::chain_at(const double pressure) const
  {
    KinematicChain chain = chain_;
    chain_at(pressure, actuation_.torque(pressure).cwiseQuotient(stiffness_.diagonal(pressure)), chain);
    return chain;
  }

  void ChainModel::chain_at(const double pressure, const Eigen::VectorXd &pressure_angles,
                            KinematicChain &chain) const
  {
    if (link_geometry_)
      link_geometry_->apply(pressure, chain);
    if (link_shift_)
      chain.assign_link_shift([&](const int i) { return link_shift_->at(pressure, i); },
                              [&](const int i) { return pressure_angles[3 * i + 2]; });
  }

  void ChainModel::set_link_shift(LinkShiftPerTurn shift)
  {
    if (shift.n_links() != chain_.n_joints())
      throw std::invalid_argument("ChainModel: the link shift has another number of links");
    link_shift_ = std::move(shift);
  }

  ChainModel ChainModel::without_link_shift() const
  {
    ChainModel rigid = *this;
    rigid.link_shift_.reset();
    return rigid;
  }

  void ChainModel::set_link_geometry(LinkGeometry geometry)
  {
    if (geometry.n_joints() != chain_.n_joints())
      throw std::invalid_argument("ChainModel: the link geometry has another number of joints");
    link_geometry_ = std::move(geometry);
  }

} // namespace softchain::chain
