#pragma once
// NeutralLayer: the height y_n at which the chain's joints sit: the layer of
// the finger whose material points rigid links follow best. In a pneumatic
// finger that is the strain-limiting fabric layer; in pure bending onto an
// arc of radius R it is the neutral layer raised by a^2 / (24 R), which makes
// a rigid link as long as the arc's chord.
//
// Rigid link i of the chain carries the reference chord D_i = J_i+1,0 - J_i,0
// between its joints at height y to R_i D_i, with R_i the rotation of the
// link's own slab (M2, JointGeometry at b = a/2). The material chord is
// d_i(y) = x(J_i+1,0) - x(J_i,0) (x the deformed position, BodySamples).
// A chain started at the deformed first joint misses the deformed joint k
// by e_k(y) = sum_{i<k} (R_i D_i - d_i(y)), and the tip face's centroid T,
// which its last link carries from T_0, by
//   e_T(y) = e_n(y) + R_n (T_0 - J_n,0) - (T - x(J_n,0));
// over the pressure samples s (p != 0)
//   E(y) = sum_s (sum_k |e_k,s(y)|^2 + |e_T,s(y)|^2)
// is evaluated at 64 heights over the body's height, from the bottom up
// while every joint at that height lies in the body (the bottom layer below
// the cavity); y_n is its smallest value, refined by the parabola through it
// and its neighbours. Without a pressure sample, or when E does not change
// with y (no bending), y_n is the height of the body's centroid (the neutral
// axis of a homogeneous beam), or, where that lies in a cavity, the middle of
// the lowest band of heights at which every joint lies in the body.
#include <softchain/data/actuation_database.h>
#include <softchain/reduction/body_samples.h>
#include <softchain/reduction/joint_layout.h>

#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

namespace softchain::reduction
{
  class NeutralLayer
  {
  public:
    // `mesh` gives the tip face (/mesh/tip_nodes); without one y_n is the
    // centroid height.
    NeutralLayer(std::shared_ptr<const BodySamples> body, const JointLayout &layout,
                 const data::MeshRecord                        &mesh,
                 const std::vector<const data::SampleRecord *> &bending_samples);

    double height() const { return height_; }
    // True when measured from samples, false for the fallback (the centroid,
    // or the lowest solid band's middle).
    bool measured() const { return measured_; }
    // Root mean square of |e_k| and |e_T| at y_n over samples and points [m]
    // (0 when not measured).
    double residual() const { return residual_; }
    // One sentence for the reduction's log.
    std::string description() const;

  private:
    // The joints at height y located in the body, or empty when one lies outside.
    std::vector<CellPoint> joints_at(double y) const;
    // sum_k |e_k|^2 + |e_T|^2 of one sample at height y (link rotations
    // `rotations`, joints at y located as `joints`).
    double mismatch(double y, const std::vector<CellPoint> &joints,
                    const std::vector<data::Point3> &x, const std::vector<Eigen::Matrix3d> &rotations) const;

    std::shared_ptr<const BodySamples> body_;
    std::vector<std::int64_t>          tip_nodes_;
    Eigen::Vector3d                    tip_centroid_ = Eigen::Vector3d::Zero(); // T_0
    std::vector<double>                x_joints_;
    double                             z_centre_;
    double                             height_    = 0.0;
    bool                               measured_  = false;
    bool                               centroid_inside_ = true; // unmeasured: y the centroid's
    double                             residual_  = 0.0;
    int                                n_samples_ = 0;
  };
} // namespace softchain::reduction
