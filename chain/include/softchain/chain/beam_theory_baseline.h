#pragma once
// BeamTheoryBaseline: the paper's comparison model (Sec. IV-B, from [10]):
// Euler-Bernoulli bending of each section, k_phi,i = E I_z,i / a_i, with the
// ad hoc k_theta = k_phi and k_psi = 4 k_phi.
//
// Section i is the slab of the finger between the midpoints to the
// neighbouring joints (x_i -+ a/2 for evenly spaced joints), of length a_i.
// Its area moment about the slab's neutral axis (parallel to z through the
// centroid) is the volume average over the slab,
//   I_z,i = (1/a_i) int_slab (y - y_c,i)^2 dV,   y_c,i = int_slab y dV / V_i,
// which for a prismatic slab is the cross section's int (y - y_c)^2 dA.
// The integrals run over the database mesh (/mesh/cells, /mesh/X): hexahedra
// with the trilinear map of deal.II's lexicographic vertex order and
// tetrahedra as hexahedra collapsed onto their vertices (v0 v1 v2 v2 v3 v3 v3
// v3: the Duffy map, a polynomial of degree 3), with a 4x4x4 Gauss rule (exact
// for the degree-7 integrands of affine tets). Each quadrature point counts for
// the slab its x falls in, so cells cut by a slab boundary err by at most
// their own share: O(h / a) relative for cell size h.
#include <softchain/chain/joint_stiffness.h>
#include <softchain/data/actuation_database.h>

#include <vector>

namespace softchain::chain
{
  class BeamTheoryBaseline
  {
  public:
    // Sections around the joint abscissae (increasing, at least two).
    BeamTheoryBaseline(const data::MeshRecord &mesh, const std::vector<double> &joint_x);

    const std::vector<double> &section_lengths() const { return lengths_; }    // a_i, m
    const std::vector<double> &second_moments() const { return second_moments_; } // I_z,i, m^4

    // k_phi = E I_z / a, k_theta = k_phi, k_psi = 4 k_phi.
    JointStiffness stiffness(double youngs_modulus) const;

  private:
    std::vector<double> lengths_;
    std::vector<double> second_moments_;
  };
} // namespace softchain::chain
