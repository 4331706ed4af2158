#pragma once
// SvgCurvePlot: a line plot as an SVG document, without a graphics library:
// one or more named series of (x, y) points, each a polyline with a marker
// at every point, on axes from zero (or the data's minimum, if negative) to
// a "nice" bound (1, 2 or 5 times a power of ten) with five ticks each.
// The report's force-pressure curves of the contact samples.
#include <string>
#include <utility>
#include <vector>

namespace softchain::report
{
  class SvgCurvePlot
  {
  public:
    using Points = std::vector<std::pair<double, double>>;

    SvgCurvePlot(std::string x_label, std::string y_label);

    void add(const std::string &name, Points points);

    // The SVG document, `title` at the top.
    std::string render(const std::string &title) const;

    // The smallest 1, 2 or 5 times a power of ten at or above `value` > 0.
    static double nice_bound(double value);

    static constexpr int width = 480, height = 320; // pixels

  private:
    struct Series
    {
      std::string name;
      Points      points;
    };
    std::string         x_label_, y_label_;
    std::vector<Series> series_;
  };
} // namespace softchain::report
