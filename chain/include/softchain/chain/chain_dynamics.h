#pragma once
// ChainDynamics: the optional damped dynamic step, for using the chain inside
// a grasp simulation loop. Lumped parameters: the mass m_b of link b at the
// midpoint X_b of its reference segment, and a viscous damping c per joint
// angle. Lagrange's equations with the translational kinetic energy
// 1/2 sum_b m_b |dx_b/dt|^2, dropping the velocity-quadratic (Coriolis and
// centrifugal) terms, which is sound for the slow, damped motion it is meant
// for:
//   M(q) dv/dt + C v + r(q) = 0,   dq/dt = v,
//   M(q) = sum_b m_b G_b^T G_b,    G_b = dx_b/dq (columns a_{i,alpha} x (x_b - c_i)),
// with r(q) = K q - J_p p - J^T f of ChainEquilibrium. The step is linearly
// implicit (backward) Euler, r(q + h v+) ~ r(q) + h H v+:
//   (M + h C + h^2 H) v+ = M v - h r(q),   q+ = q + h v+,
// unconditionally stable for the linearised system whenever H is positive
// definite, and at rest exactly at the static equilibrium r = 0.
#include <softchain/chain/chain_equilibrium.h>

#include <vector>

namespace softchain::chain
{
  class ChainDynamics
  {
  public:
    // One mass per link (kg, >= 0) and one damping per joint angle (N m s,
    // >= 0, 3 per joint); std::invalid_argument otherwise. Keeps a reference
    // to `model`.
    ChainDynamics(const ChainModel &model, std::vector<double> link_masses,
                  Eigen::VectorXd damping);

    void set_load(const ChainLoad &load) { statics_.set_load(load); }
    void set_state(const Eigen::VectorXd &angles, const Eigen::VectorXd &velocities);
    // Advances the state by the time step h (s).
    void step(double h);

    const Eigen::VectorXd &angles() const { return angles_; }
    const Eigen::VectorXd &velocities() const { return velocities_; }

  private:
    Eigen::MatrixXd mass_matrix() const; // at the pose of the last evaluation

    const ChainModel            &model_;
    ChainEquilibrium             statics_;
    std::vector<double>          masses_;
    std::vector<Eigen::Vector3d> mass_points_; // X_b, reference
    Eigen::VectorXd              damping_;
    Eigen::VectorXd              angles_, velocities_;
  };
} // namespace softchain::chain
