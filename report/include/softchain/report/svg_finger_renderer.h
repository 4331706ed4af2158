#pragma once
// SvgFingerRenderer: a picture of the deformed finger as an SVG document,
// without a graphics library. The boundary faces (SurfaceMesh) are placed at
// the sample's deformed node positions, projected with a fixed ObliqueView,
// the faces turned away from the viewer dropped (the surface is closed) and
// the others drawn from the farthest to the nearest (painter's algorithm),
// each flat-shaded by Lambert's cosine law. The rest shape is drawn first,
// as a faint grey silhouette.
#include <softchain/data/actuation_database.h>
#include <softchain/report/oblique_view.h>
#include <softchain/report/surface_mesh.h>

#include <string>
#include <vector>

namespace softchain::report
{
  class SvgFingerRenderer
  {
  public:
    using Positions = std::vector<data::Point3>;
    // A closed polygon in space (e.g. a piece of an obstacle's surface,
    // ObstacleOutline), drawn behind the finger.
    using Outline = std::vector<Eigen::Vector3d>;

    SvgFingerRenderer(SurfaceMesh surface, Positions reference, ObliqueView view = ObliqueView());

    // Widens the picture's frame to hold the finger at `positions`. All
    // pictures of one renderer share the frame (scale and origin), so that
    // the pictures of several pressures can be compared; the rest shape is
    // always inside it.
    void include(const Positions &positions);
    void include(const std::vector<Outline> &outlines);

    // The SVG document of the finger at `deformed` (node positions, same
    // numbering as the reference) over its rest shape, `title` at the top;
    // `chain` (joint positions, then the tip) is drawn on top as a red
    // polyline with a dot at every point; `backdrop` (obstacles) is drawn
    // in translucent blue behind the finger.
    std::string render(const Positions &deformed, const std::string &title,
                       const std::vector<Eigen::Vector3d> &chain    = {},
                       const std::vector<Outline>         &backdrop = {}) const;

    // Painter's algorithm: the indices of `depths` from the farthest face
    // (smallest depth) to the nearest; ties keep their order.
    static std::vector<std::size_t> far_to_near(const std::vector<double> &depths);

    static constexpr int width = 480, height = 360; // pixels

  private:
    struct ScreenPolygon
    {
      std::vector<Eigen::Vector2d> corners; // screen coordinates
      double                       depth;   // of the centroid
      double                       brightness; // Lambert: ambient + diffuse
    };
    // The faces facing the viewer at positions `x`, in no particular order.
    std::vector<ScreenPolygon> facing_polygons(const Positions &x) const;
    std::string                polygons_svg(const Positions &x, bool shaded) const;
    std::string                axes_svg() const;
    std::string                chain_svg(const std::vector<Eigen::Vector3d> &chain) const;
    std::string                backdrop_svg(const std::vector<Outline> &backdrop) const;
    Eigen::Vector2d            to_pixels(const Eigen::Vector2d &screen) const;

    SurfaceMesh     surface_;
    Positions       reference_;
    ObliqueView     view_;
    Eigen::Vector2d frame_low_, frame_high_; // screen-coordinate box
  };
} // namespace softchain::report
