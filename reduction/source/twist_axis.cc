// TwistAxis: t fitted to the torsion samples' tip-face centroids.
#include <softchain/data/tip_pose_fit.h>
#include <softchain/reduction/sample_reduction.h>
#include <softchain/reduction/twist_axis.h>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <sstream>

namespace softchain::reduction
{
  TwistAxis::TwistAxis(const JointGeometry &geometry, const data::MeshRecord &mesh,
                       const std::vector<const data::SampleRecord *> &torsion_samples,
                       const double highest, const std::string &source)
    : n_samples_(static_cast<int>(torsion_samples.size()))
  {
    if (torsion_samples.empty())
      return;
    const data::TipPoseFit       tip_fit = data::TipPoseFit::of_mesh(mesh, source);
    std::vector<JointFrames>     frames;
    std::vector<Eigen::Vector3d> fem_tips;
    for (const data::SampleRecord *s : torsion_samples)
      {
        frames.emplace_back(RotationMethod::affine_fit, geometry.slabs(), geometry.reference_points(),
                            geometry.points(s->x), s->id);
        fem_tips.push_back(tip_fit.fit(data::select_nodes(s->x, mesh.tip_nodes)).position);
      }
    const auto mismatch = [&](const double t) {
      double sum = 0.0;
      for (std::size_t k = 0; k < frames.size(); ++k)
        sum += (chain_tip(geometry, frames[k], tip_fit.reference_centroid(), t).position - fem_tips[k])
                 .squaredNorm();
      return sum;
    };
    double smallest = std::numeric_limits<double>::infinity();
    for (double t = 0.0; t <= highest; t += 2.5e-4)
      if (const double e = mismatch(t); e < smallest)
        smallest = e, offset_ = t;
    residual_  = std::sqrt(smallest / n_samples_);
    at_joints_ = std::sqrt(mismatch(0.0) / n_samples_);
  }

  TwistAxis::ChainTip TwistAxis::chain_tip(const JointGeometry &geometry, const JointFrames &frames,
                                           const Eigen::Vector3d &tip_reference, const double t)
  {
    return chain_tip(frames, reference_links(geometry, tip_reference), t);
  }

  std::vector<Eigen::Vector3d> TwistAxis::reference_links(const JointGeometry &geometry,
                                                         const Eigen::Vector3d &tip_reference)
  {
    std::vector<Eigen::Vector3d> links;
    for (std::size_t i = 0; i < geometry.n_joints(); ++i)
      links.push_back(geometry.reference_centre(i));
    links.push_back(tip_reference);
    return links;
  }

  TwistAxis::ChainTip TwistAxis::chain_tip(const JointFrames &frames, const std::vector<Eigen::Vector3d> &links,
                                           const double t)
  {
    const Eigen::Vector3d s(0, t, 0);
    ChainTip              tip{links.front(), Eigen::Matrix3d::Identity()};
    for (std::size_t i = 0; i < frames.size(); ++i)
      {
        if (i > 0)
          tip.position += tip.rotation * (links[i] - links[i - 1]);
        const data::JointAngles q = frames.relative_angles(i);
        tip.position += tip.rotation * (s - Eigen::AngleAxisd(q.psi, Eigen::Vector3d::UnitX()) * s);
        tip.rotation = tip.rotation * data::rotation_from_angles(q);
      }
    tip.position += tip.rotation * (links.back() - links[frames.size() - 1]);
    return tip;
  }

  std::vector<Eigen::Vector3d> TwistAxis::links_of(const JointGeometry &geometry, const JointFrames &frames,
                                                  const std::vector<data::Point3> &x, const Eigen::Vector3d &tip)
  {
    std::vector<Eigen::Vector3d> centres;
    std::vector<Eigen::Matrix3d> rotations;
    for (std::size_t i = 0; i < frames.size(); ++i)
      {
        centres.push_back(geometry.deformed_centre(i, frames, x));
        rotations.push_back(frames[i].rotation);
      }
    centres.push_back(tip);
    return SampleReduction::link_points(centres, rotations);
  }

  std::string TwistAxis::description() const
  {
    std::ostringstream text;
    if (n_samples_ == 0)
      text << "no torsion sample: the joints twist about their centres";
    else
      text << "the joints twist about an axis " << 1e3 * offset_ << " mm above them, fitted to "
           << n_samples_ << " torsion sample(s) (rms tip-centroid error of the chain driven by "
           << "their rotations " << 1e3 * residual_ << " mm, " << 1e3 * at_joints_
           << " mm about the joints)";
    return text.str();
  }
} // namespace softchain::reduction
