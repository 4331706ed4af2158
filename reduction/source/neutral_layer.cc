// NeutralLayer: y_n where the chain of rigid links through the joints on a
// layer lands on the layer's deformed joints best.
#include <softchain/reduction/joint_geometry.h>
#include <softchain/reduction/neutral_layer.h>
#include <softchain/data/vector_of_point.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace softchain::reduction
{
  namespace
  {
    // Heights probed over the body's height: fine enough to put ~10 heights
    // in a 3 mm bottom layer of an 18 mm finger.
    constexpr int n_heights = 64;

    double centroid_height(const BodySamples &body)
    {
      double sum = 0;
      for (const auto &X : body.lattice())
        sum += X[1];
      return body.lattice().empty() ? body.reference_box().center()(1) :
                                      sum / double(body.lattice().size());
    }

    // Vertex of the parabola through (y - h, e0), (y, e1), (y + h, e2),
    // clamped to [y - h, y + h]; y itself when the three do not curve up.
    double parabola_vertex(double y, double h, double e0, double e1, double e2)
    {
      const double curvature = e0 - 2 * e1 + e2;
      if (!(curvature > 0))
        return y;
      return y + std::clamp(0.5 * h * (e0 - e2) / curvature, -h, h);
    }
  } // namespace

  NeutralLayer::NeutralLayer(std::shared_ptr<const BodySamples> body, const JointLayout &layout,
                             const data::MeshRecord                        &mesh,
                             const std::vector<const data::SampleRecord *> &bending_samples)
    : body_(std::move(body))
    , tip_nodes_(mesh.tip_nodes)
    , z_centre_(body_->reference_box().center()(2))
    , height_(centroid_height(*body_))
  {
    for (int joint = 1; joint <= layout.n_joints(); ++joint)
      x_joints_.push_back(layout.x(joint));
    for (const auto node : tip_nodes_)
      tip_centroid_ += data::vector_of(mesh.X[node]) / double(tip_nodes_.size());
    // The heights from the bottom up while every joint lies in the body.
    const Eigen::AlignedBox3d          &box  = body_->reference_box();
    const double                        step = box.sizes()(1) / n_heights;
    std::vector<double>                 heights;
    std::vector<std::vector<CellPoint>> joints;
    for (int j = 0; j < n_heights; ++j)
      {
        const double y        = box.min()(1) + (j + 0.5) * step;
        auto         at_height = joints_at(y);
        if (at_height.empty())
          {
            if (!heights.empty())
              break;
            continue;
          }
        heights.push_back(y);
        joints.push_back(std::move(at_height));
      }
    // A hollow finger's centroid may lie in its cavity: without a measured
    // height the joints then go to the middle of the lowest solid band.
    if (joints_at(height_).empty() && !heights.empty())
      {
        height_         = 0.5 * (heights.front() + heights.back());
        centroid_inside_ = false;
      }
    if (heights.size() < 3 || x_joints_.size() < 2 || tip_nodes_.empty() || bending_samples.empty())
      return;

    // The links' rotations (M2 of their slabs) do not depend on the joints' height.
    const JointGeometry                       geometry(layout, body_, heights.front(), 0.5 * layout.spacing());
    std::vector<std::vector<Eigen::Matrix3d>> rotations;
    for (const data::SampleRecord *sample : bending_samples)
      {
        const JointFrames frames(RotationMethod::affine_fit, geometry.slabs(),
                                 geometry.reference_points(), geometry.points(sample->x), sample->id);
        rotations.emplace_back();
        for (std::size_t i = 0; i < frames.size(); ++i)
          rotations.back().push_back(frames[i].rotation);
      }
    n_samples_           = int(bending_samples.size());
    const auto total_at = [&](double y, const std::vector<CellPoint> &at_height) {
      double total = 0;
      for (std::size_t s = 0; s < bending_samples.size(); ++s)
        total += mismatch(y, at_height, bending_samples[s]->x, rotations[s]);
      return total;
    };
    std::vector<double> total;
    for (std::size_t k = 0; k < heights.size(); ++k)
      total.push_back(total_at(heights[k], joints[k]));
    const auto [lowest, highest] = std::minmax_element(total.begin(), total.end());
    // A mismatch that does not change with height (no bending) has no minimum.
    if (!(*highest - *lowest > 1e-9 * *highest))
      return;
    measured_           = true;
    const std::size_t k = std::size_t(lowest - total.begin());
    height_             = k == 0 || k + 1 == total.size() ?
                            heights[k] :
                            parabola_vertex(heights[k], step, total[k - 1], total[k], total[k + 1]);
    auto at_height = joints_at(height_);
    if (at_height.empty())
      height_ = heights[k], at_height = joints[k];
    residual_ = std::sqrt(total_at(height_, at_height) / (n_samples_ * double(x_joints_.size())));
  }

  std::vector<CellPoint> NeutralLayer::joints_at(double y) const
  {
    std::vector<CellPoint> joints;
    for (const double x : x_joints_)
      {
        const auto located = body_->locate(Eigen::Vector3d(x, y, z_centre_));
        if (!located)
          return {};
        joints.push_back(*located);
      }
    return joints;
  }

  double NeutralLayer::mismatch(double y, const std::vector<CellPoint> &joints,
                                const std::vector<data::Point3>    &x,
                                const std::vector<Eigen::Matrix3d> &rotations) const
  {
    double          sum   = 0;
    Eigen::Vector3d error = Eigen::Vector3d::Zero(); // c_k - x(J_k,0), with c_1 = x(J_1,0)
    for (std::size_t i = 0; i + 1 < joints.size(); ++i)
      {
        const Eigen::Vector3d d = body_->deformed(joints[i + 1], x) - body_->deformed(joints[i], x);
        const Eigen::Vector3d D(x_joints_[i + 1] - x_joints_[i], 0, 0);
        error += rotations[i] * D - d;
        sum += error.squaredNorm();
      }
    // The last link carries the tip face's centroid T_0 to T.
    Eigen::Vector3d tip = Eigen::Vector3d::Zero();
    for (const auto node : tip_nodes_)
      tip += data::vector_of(x[node]) / double(tip_nodes_.size());
    const Eigen::Vector3d J_n(x_joints_.back(), y, z_centre_);
    error += rotations.back() * (tip_centroid_ - J_n) - (tip - body_->deformed(joints.back(), x));
    return sum + error.squaredNorm();
  }

  std::string NeutralLayer::description() const
  {
    std::ostringstream text;
    text.precision(3);
    if (measured_)
      text << "joints on the layer at y = " << 1e3 * height_ << " mm that rigid links follow best, "
           << "measured on " << n_samples_ << " pressure sample(s) (rms joint position error there "
           << 1e3 * residual_ << " mm)";
    else
      text << "no pressure sample: joints at " << (centroid_inside_ ? "the body's centroid height" :
                                                                     "the middle of its lowest solid layer")
           << " y = " << 1e3 * height_ << " mm";
    return text.str();
  }
} // namespace softchain::reduction
