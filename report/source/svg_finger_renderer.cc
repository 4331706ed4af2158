#include <softchain/report/svg_finger_renderer.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace softchain::report
{
  namespace
  {
    constexpr double margin = 16, title_band = 26; // pixels

    Eigen::Vector3d vector(const data::Point3 &p) { return {p[0], p[1], p[2]}; }

    // Light from above, in front and a little from the left: the top and the
    // side walls facing the viewer get different shades.
    const Eigen::Vector3d light = Eigen::Vector3d(-0.3, 0.8, 1.0).normalized();

    // Silicone orange, scaled by the face's brightness.
    std::string shade(const double brightness)
    {
      const int base[3] = {236, 142, 74};
      std::ostringstream colour;
      colour << "rgb(";
      for (int c = 0; c < 3; ++c)
        colour << (c ? "," : "") << static_cast<int>(std::lround(base[c] * brightness));
      colour << ")";
      return colour.str();
    }

    std::string escape_xml(const std::string &text)
    {
      std::string escaped;
      for (const char c : text)
        escaped += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
      return escaped;
    }
  } // namespace

  SvgFingerRenderer::SvgFingerRenderer(SurfaceMesh surface, Positions reference, ObliqueView view)
    : surface_(std::move(surface))
    , reference_(std::move(reference))
    , view_(view)
    , frame_low_(Eigen::Vector2d::Constant(INFINITY))
    , frame_high_(Eigen::Vector2d::Constant(-INFINITY))
  {
    include(reference_);
  }

  void SvgFingerRenderer::include(const Positions &positions)
  {
    for (const auto &face : surface_.faces())
      for (const auto node : face)
        {
          const Eigen::Vector2d p = view_.project(vector(positions[node]));
          frame_low_              = frame_low_.cwiseMin(p);
          frame_high_             = frame_high_.cwiseMax(p);
        }
  }

  void SvgFingerRenderer::include(const std::vector<Outline> &outlines)
  {
    for (const auto &outline : outlines)
      for (const auto &x : outline)
        {
          frame_low_  = frame_low_.cwiseMin(view_.project(x));
          frame_high_ = frame_high_.cwiseMax(view_.project(x));
        }
  }

  std::vector<std::size_t> SvgFingerRenderer::far_to_near(const std::vector<double> &depths)
  {
    std::vector<std::size_t> order(depths.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](const std::size_t a, const std::size_t b) { return depths[a] < depths[b]; });
    return order;
  }

  std::vector<SvgFingerRenderer::ScreenPolygon>
  SvgFingerRenderer::facing_polygons(const Positions &x) const
  {
    std::vector<ScreenPolygon> polygons;
    for (const auto &face : surface_.faces())
      {
        Eigen::Vector3d normal = Eigen::Vector3d::Zero(), centroid = Eigen::Vector3d::Zero();
        for (std::size_t i = 0; i < face.size(); ++i) // Newell's normal
          {
            normal += vector(x[face[i]]).cross(vector(x[face[(i + 1) % face.size()]]));
            centroid += vector(x[face[i]]) / face.size();
          }
        // Back faces (and faces collapsed to a line) are hidden by the
        // front of the closed surface: not drawn.
        if (normal.dot(view_.toward_viewer()) <= 0)
          continue;
        ScreenPolygon polygon;
        for (const auto node : face)
          polygon.corners.push_back(view_.project(vector(x[node])));
        polygon.depth      = view_.depth(centroid);
        polygon.brightness = 0.35 + 0.65 * std::max(0.0, normal.normalized().dot(light));
        polygons.push_back(std::move(polygon));
      }
    return polygons;
  }

  Eigen::Vector2d SvgFingerRenderer::to_pixels(const Eigen::Vector2d &screen) const
  {
    const Eigen::Vector2d extent = (frame_high_ - frame_low_).cwiseMax(1e-12);
    const double          scale  = std::min((width - 2 * margin) / extent.x(),
                                            (height - 2 * margin - title_band) / extent.y());
    // Centred in the free area below the title; SVG's y axis points down.
    const Eigen::Vector2d centre = 0.5 * (frame_low_ + frame_high_);
    return {0.5 * width + scale * (screen.x() - centre.x()),
            title_band + 0.5 * (height - title_band) - scale * (screen.y() - centre.y())};
  }

  std::string SvgFingerRenderer::polygons_svg(const Positions &x, const bool shaded) const
  {
    const std::vector<ScreenPolygon> polygons = facing_polygons(x);
    std::vector<double>              depths;
    for (const auto &polygon : polygons)
      depths.push_back(polygon.depth);
    std::ostringstream svg;
    svg.setf(std::ios::fixed);
    svg.precision(1);
    for (const std::size_t i : far_to_near(depths))
      {
        svg << "<polygon points=\"";
        for (const auto &corner : polygons[i].corners)
          {
            const Eigen::Vector2d p = to_pixels(corner);
            svg << p.x() << ',' << p.y() << ' ';
          }
        svg << '"';
        // The stroke in the fill colour closes the hairline gaps that
        // anti-aliasing leaves between neighbouring faces.
        if (shaded)
          svg << " fill=\"" << shade(polygons[i].brightness) << "\" stroke=\""
              << shade(polygons[i].brightness) << '"';
        svg << "/>\n";
      }
    return svg.str();
  }

  // A small x, y, z triad in the lower right corner, for orientation.
  std::string SvgFingerRenderer::axes_svg() const
  {
    const Eigen::Vector2d origin(width - 50, height - 30);
    std::ostringstream    svg;
    svg.setf(std::ios::fixed);
    svg.precision(1);
    const char *names[3] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k)
      {
        const Eigen::Vector2d d   = view_.project(Eigen::Vector3d::Unit(k));
        const Eigen::Vector2d end = origin + 22 * Eigen::Vector2d(d.x(), -d.y());
        const Eigen::Vector2d tag = origin + 30 * Eigen::Vector2d(d.x(), -d.y());
        svg << "<line x1=\"" << origin.x() << "\" y1=\"" << origin.y() << "\" x2=\"" << end.x()
            << "\" y2=\"" << end.y() << "\" stroke=\"#333\"/>\n"
            << "<text x=\"" << tag.x() - 3 << "\" y=\"" << tag.y() + 4 << "\">" << names[k]
            << "</text>\n";
      }
    return svg.str();
  }

  std::string SvgFingerRenderer::chain_svg(const std::vector<Eigen::Vector3d> &chain) const
  {
    if (chain.empty())
      return "";
    std::ostringstream svg, points;
    svg.setf(std::ios::fixed);
    svg.precision(1);
    points.setf(std::ios::fixed);
    points.precision(1);
    for (const Eigen::Vector3d &c : chain)
      {
        const Eigen::Vector2d p = to_pixels(view_.project(c));
        points << p.x() << ',' << p.y() << ' ';
        svg << "<circle cx=\"" << p.x() << "\" cy=\"" << p.y() << "\" r=\"3\"/>\n";
      }
    return "<g fill=\"#c00\" stroke=\"#c00\">\n<polyline points=\"" + points.str() +
           "\" fill=\"none\" stroke-width=\"2\"/>\n" + svg.str() + "</g>\n";
  }

  // The outlines from the farthest to the nearest, one translucent group.
  std::string SvgFingerRenderer::backdrop_svg(const std::vector<Outline> &backdrop) const
  {
    if (backdrop.empty())
      return "";
    std::vector<double> depths;
    for (const auto &outline : backdrop)
      {
        Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
        for (const auto &x : outline)
          centroid += x / outline.size();
        depths.push_back(view_.depth(centroid));
      }
    std::ostringstream svg;
    svg.setf(std::ios::fixed);
    svg.precision(1);
    svg << "<g fill=\"#9ab8d8\" fill-opacity=\"0.55\" stroke=\"#4a6f96\" stroke-width=\"0.8\">\n";
    for (const std::size_t i : far_to_near(depths))
      {
        svg << "<polygon points=\"";
        for (const auto &x : backdrop[i])
          {
            const Eigen::Vector2d p = to_pixels(view_.project(x));
            svg << p.x() << ',' << p.y() << ' ';
          }
        svg << "\"/>\n";
      }
    return svg.str() + "</g>\n";
  }

  std::string SvgFingerRenderer::render(const Positions &deformed, const std::string &title,
                                        const std::vector<Eigen::Vector3d> &chain,
                                        const std::vector<Outline>         &backdrop) const
  {
    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
        << "\" viewBox=\"0 0 " << width << ' ' << height << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        << "<text x=\"" << width / 2 << "\" y=\"18\" text-anchor=\"middle\" font-size=\"14\">"
        << escape_xml(title) << "</text>\n"
        // One group opacity: overlapping rest faces do not darken each other.
        << "<g opacity=\"0.25\" fill=\"#777\" stroke=\"#777\" stroke-width=\"0.5\">\n"
        << polygons_svg(reference_, false) << "</g>\n"
        << backdrop_svg(backdrop) << "<g stroke-width=\"0.5\" stroke-linejoin=\"round\">\n"
        << polygons_svg(deformed, true) << "</g>\n"
        << chain_svg(chain) << axes_svg() << "</svg>\n";
    return svg.str();
  }
} // namespace softchain::report
