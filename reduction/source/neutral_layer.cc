// NeutralLayer: y_n from the axial stretch of probe lines in bending samples.
#include <softchain/reduction/neutral_layer.h>
#include <softchain/reduction/vector_of_point.h>

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

    // Least-squares line v = alpha + beta y.
    std::pair<double, double> line_fit(const std::vector<double> &y, const std::vector<double> &v)
    {
      const double n  = double(y.size());
      double       my = 0, mv = 0, syy = 0, syv = 0;
      for (std::size_t k = 0; k < y.size(); ++k)
        my += y[k] / n, mv += v[k] / n;
      for (std::size_t k = 0; k < y.size(); ++k)
        syy += (y[k] - my) * (y[k] - my), syv += (y[k] - my) * (v[k] - mv);
      const double beta = syv / syy;
      return {mv - beta * my, beta};
    }
  } // namespace

  NeutralLayer::NeutralLayer(const BodySamples &body, const JointLayout &layout,
                             const std::vector<const data::SampleRecord *> &bending_samples)
    : body_(body)
    , z_centre_(body.reference_box().center()(2))
    , height_(centroid_height(body))
  {
    const double first = layout.x(1), last = layout.x(layout.n_joints());
    const int    n_steps = std::max(1, int(std::lround(4 * (last - first) / layout.spacing())));
    for (int k = 0; k <= n_steps; ++k)
      s_.push_back(first + (last - first) * k / n_steps);

    // The heights from the bottom up while the whole line lies in the body.
    const Eigen::AlignedBox3d &box = body.reference_box();
    std::vector<double>                  heights;
    std::vector<std::vector<CellPoint>>  lines;
    for (int j = 0; j < n_heights; ++j)
      {
        const double y    = box.min()(1) + (j + 0.5) * box.sizes()(1) / n_heights;
        auto         line = probe_line(y);
        if (line.empty())
          {
            if (!heights.empty())
              break;
            continue;
          }
        heights.push_back(y);
        lines.push_back(std::move(line));
      }
    if (heights.size() < 2 || first == last)
      return;

    double sum_alpha = 0, sum_beta = 0;
    for (const data::SampleRecord *sample : bending_samples)
      {
        std::vector<double> stretches;
        for (const auto &line : lines)
          stretches.push_back(stretch(sample->x, line));
        const auto [alpha, beta] = line_fit(heights, stretches);
        if (!std::isfinite(alpha) || !std::isfinite(beta))
          continue;
        sum_alpha += alpha;
        sum_beta += beta;
        ++n_samples_;
      }
    // A line that does not change with height (no bending) has no root.
    if (n_samples_ == 0 || std::abs(sum_beta) * (heights.back() - heights.front()) < 1e-9 * n_samples_)
      return;
    measured_ = true;
    height_   = std::clamp(-sum_alpha / sum_beta, heights.front(), heights.back());
    const auto line = probe_line(height_);
    for (const data::SampleRecord *sample : bending_samples)
      residual_stretch_ += stretch(sample->x, line) / n_samples_;
  }

  std::vector<CellPoint> NeutralLayer::probe_line(double y) const
  {
    std::vector<CellPoint> line;
    for (const double s : s_)
      {
        const auto located = body_.locate(Eigen::Vector3d(s, y, z_centre_));
        if (!located)
          return {};
        line.push_back(*located);
      }
    return line;
  }

  double NeutralLayer::stretch(const std::vector<data::Point3> &x, const std::vector<CellPoint> &line) const
  {
    if (line.size() < 2)
      return NAN;
    double deformed = 0;
    for (std::size_t k = 0; k + 1 < line.size(); ++k)
      deformed += (body_.deformed(line[k + 1], x) - body_.deformed(line[k], x)).norm();
    return deformed / (s_.back() - s_.front()) - 1;
  }

  std::string NeutralLayer::description() const
  {
    std::ostringstream text;
    text.precision(3);
    if (measured_)
      text << "joints on the neutral layer at y = " << 1e3 * height_ << " mm, measured on "
           << n_samples_ << " bending sample(s) (mean axial strain there " << residual_stretch_
           << ")";
    else
      text << "no bending sample: joints at the body's centroid height y = " << 1e3 * height_
           << " mm";
    return text.str();
  }
} // namespace softchain::reduction
