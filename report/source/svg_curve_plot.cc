#include <softchain/report/html_document.h>
#include <softchain/report/svg_curve_plot.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace softchain::report
{
  namespace
  {
    constexpr double left = 60, right = 20, top = 34, bottom = 46; // pixels
    const char      *colours[] = {"#c0392b", "#2e6da4", "#27ae60", "#8e44ad"};

    // The axis range [low, high] of `values`: from 0 (or below, for negative
    // data) to a nice bound.
    std::pair<double, double> range(const std::vector<double> &values)
    {
      double low = 0, high = 0;
      for (const double v : values)
        if (std::isfinite(v))
          {
            low  = std::min(low, v);
            high = std::max(high, v);
          }
      high = high > 0 ? SvgCurvePlot::nice_bound(high) : 1;
      low  = low < 0 ? -SvgCurvePlot::nice_bound(-low) : 0;
      return {low, high};
    }

    std::string number(const double v)
    {
      std::ostringstream text;
      text << std::round(v * 1e6) / 1e6;
      return text.str();
    }
  } // namespace

  SvgCurvePlot::SvgCurvePlot(std::string x_label, std::string y_label)
    : x_label_(std::move(x_label))
    , y_label_(std::move(y_label))
  {}

  void SvgCurvePlot::add(const std::string &name, Points points)
  {
    series_.push_back({name, std::move(points)});
  }

  double SvgCurvePlot::nice_bound(const double value)
  {
    const double power = std::pow(10.0, std::floor(std::log10(value)));
    for (const double m : {1.0, 2.0, 5.0, 10.0})
      if (m * power >= value * (1 - 1e-12))
        return m * power;
    return 10 * power;
  }

  std::string SvgCurvePlot::render(const std::string &title) const
  {
    std::vector<double> xs, ys;
    for (const auto &s : series_)
      for (const auto &[x, y] : s.points)
        {
          xs.push_back(x);
          ys.push_back(y);
        }
    const auto [x0, x1] = range(xs);
    const auto [y0, y1] = range(ys);
    const double w = width - left - right, h = height - top - bottom;
    const auto   px = [&, x0 = x0, x1 = x1](double x) { return left + w * (x - x0) / (x1 - x0); };
    const auto   py = [&, y0 = y0, y1 = y1](double y) { return top + h * (1 - (y - y0) / (y1 - y0)); };

    std::ostringstream svg;
    svg.setf(std::ios::fixed);
    svg.precision(1);
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
        << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        << "<text x=\"" << width / 2 << "\" y=\"20\" text-anchor=\"middle\" font-size=\"14\">" << HtmlDocument::escape(title) << "</text>\n"
        << "<g stroke=\"#333\" fill=\"none\"><rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << w
        << "\" height=\"" << h << "\"/></g>\n";
    for (int k = 0; k <= 5; ++k) // ticks and their labels
      {
        const double x = x0 + (x1 - x0) * k / 5, y = y0 + (y1 - y0) * k / 5;
        svg << "<line x1=\"" << px(x) << "\" y1=\"" << top + h << "\" x2=\"" << px(x) << "\" y2=\""
            << top + h + 4 << "\" stroke=\"#333\"/><text x=\"" << px(x) << "\" y=\"" << top + h + 17
            << "\" text-anchor=\"middle\">" << number(x) << "</text>\n"
            << "<line x1=\"" << left - 4 << "\" y1=\"" << py(y) << "\" x2=\"" << left << "\" y2=\""
            << py(y) << "\" stroke=\"#333\"/><text x=\"" << left - 7 << "\" y=\"" << py(y) + 4
            << "\" text-anchor=\"end\">" << number(y) << "</text>\n";
      }
    svg << "<text x=\"" << left + w / 2 << "\" y=\"" << height - 8 << "\" text-anchor=\"middle\">"
        << x_label_ << "</text>\n<text transform=\"translate(14," << top + h / 2
        << ") rotate(-90)\" text-anchor=\"middle\">" << y_label_ << "</text>\n";
    for (std::size_t s = 0; s < series_.size(); ++s)
      {
        const char *colour = colours[s % 4];
        svg << "<g stroke=\"" << colour << "\" fill=\"" << colour << "\"><polyline fill=\"none\" stroke-width=\"2\" points=\"";
        for (const auto &[x, y] : series_[s].points)
          if (std::isfinite(y))
            svg << px(x) << ',' << py(y) << ' ';
        svg << "\"/>\n";
        for (const auto &[x, y] : series_[s].points)
          if (std::isfinite(y))
            svg << "<circle cx=\"" << px(x) << "\" cy=\"" << py(y) << "\" r=\"3.5\"/>\n";
        svg << "<text x=\"" << left + 10 << "\" y=\"" << top + 18 + 16 * s << "\" stroke=\"none\">"
            << HtmlDocument::escape(series_[s].name) << "</text></g>\n";
      }
    return svg.str() + "</svg>\n";
  }
} // namespace softchain::report
