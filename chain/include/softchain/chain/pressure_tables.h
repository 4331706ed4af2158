#pragma once
// PressureTables: what the chain does with the pressure, tabulated for a
// simulator that holds one value per model field (MuJoCo's MJCF). The chain
// at pressure p has the joint stiffness K(p), the pressure torque J_p(p) p
// and the link geometry U(p) (ChainModel), each linear in p between the
// pressures of the reduction's tables. Sampled at the union of those
// pressures, 0 and the top pressure p_top, rows linear in p between
// consecutive grid pressures reproduce the chain exactly on [0, p_top]:
//
//   k_{i,a}(p), J_p,{i,a}(p)    per joint i and axis a (psi, theta, phi)
//   U_1(p) .. U_n(p), U_T(p)    joint and tip points at zero angles, world
//   tau_{i,a}(p) = J_p,{i,a}(p) p
//
// The rows go into the MJCF as <custom><numeric> fields (names below), one
// row per grid pressure, one value per hinge in the model's hinge order
// (joint1_psi, joint1_theta, joint1_phi, joint2_psi, ...), or x y z per point:
//
//   softchain_pressure           m values, Pa, increasing, the first 0
//   softchain_stiffness          m x 3n, N m / rad (hinge stiffness k)
//   softchain_torque_per_pascal  m x 3n, N m / Pa (J_p; torque J_p p)
//   softchain_link_points        m x 3(n + 1), m (U_1 .. U_n, U_T)
//   softchain_skin_compliance    m values, m/N (c_s, the sections' give in
//                                contact; only for a chain that has it)
//
// A MuJoCo front end reproduces the chain at p by interpolating each row
// linearly in p and setting hinge stiffness k, the pressure tendon's
// coefficients J_p (control = p), and the body positions U_1, U_{i+1} - U_i
// and tip site U_T - U_n, and the skin joints' stiffness 1 / c_s
// (MujocoPressureActuation does it in C++).
#include <softchain/chain/chain_model.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace softchain::chain
{
  class PressureTables
  {
  public:
    static constexpr const char *pressure_name          = "softchain_pressure";
    static constexpr const char *stiffness_name         = "softchain_stiffness";
    static constexpr const char *torque_per_pascal_name = "softchain_torque_per_pascal";
    static constexpr const char *link_points_name       = "softchain_link_points";
    static constexpr const char *skin_compliance_name   = "softchain_skin_compliance";

    using Rows = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

    // Rows per pressure: pressures strictly increasing from 0, finite,
    // stiffness and torque_per_pascal 3n columns, link_points 3(n + 1);
    // skin_compliance one value per pressure, each positive, or none;
    // std::invalid_argument saying which is wrong otherwise.
    PressureTables(std::vector<double> pressures, Rows stiffness, Rows torque_per_pascal,
                   Rows link_points, std::vector<double> skin_compliance = {});
    // `model` sampled at its table pressures on [0, top_pressure] (top_pressure >= 0).
    static PressureTables of_model(const ChainModel &model, double top_pressure);

    int                        n_joints() const { return static_cast<int>(stiffness_.cols() / 3); }
    const std::vector<double> &pressures() const { return pressures_; }
    // At `pressure` in [0, top]; std::out_of_range naming the table's range otherwise.
    Eigen::VectorXd stiffness(double pressure) const;
    Eigen::VectorXd torque_per_pascal(double pressure) const;
    Eigen::VectorXd link_points(double pressure) const; // U_1 .. U_n, U_T (x y z each)
    bool            has_skin() const { return !skin_compliance_.empty(); }
    double          skin_compliance(double pressure) const; // c_s, m/N (0 without a skin)
    // Whether the pressure turns hinge j (J_p non-zero at some grid pressure).
    bool turns_hinge(int j) const { return (torque_per_pascal_.col(j).array() != 0.0).any(); }

    // The <custom> element of the MJCF, each line starting with `indent`.
    std::string mjcf(const std::string &indent) const;

  private:
    Eigen::VectorXd row_at(const Eigen::Ref<const Rows> &rows, double pressure) const;

    std::vector<double> pressures_;
    Rows                stiffness_;
    Rows                torque_per_pascal_;
    Rows                link_points_;
    std::vector<double> skin_compliance_;
  };
} // namespace softchain::chain
