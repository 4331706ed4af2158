#pragma once
// FingerDimensions: the parametric PneuFlex body of meshes/finger.geo. The
// outer cross-section is a width(x) by height(x) rectangle, both linear in x
// (the finger gets narrower and flatter toward the tip), standing on the
// fabric side y = 0 and centred on z = 0. One air cavity runs from the end of
// the solid base section (x = base_fill) to the closed tip cap
// (x = length - tip_cap), leaving side and top walls of thickness `wall` and
// a bottom (fabric) layer of thickness `bottom`. Every face is planar.
#include <Eigen/Core>

namespace softchain::geometry
{
  struct FingerDimensions
  {
    double length      = 0.09;   // m
    double base_width  = 0.020;  // m, at x = 0
    double base_height = 0.018;  // m, at x = 0
    double tip_width   = 0.016;  // m, at x = length
    double tip_height  = 0.012;  // m, at x = length
    double wall        = 0.0025; // side and top wall thickness, m
    double bottom      = 0.003;  // bottom layer (holds the fabric), m
    double base_fill   = 0.010;  // solid section at the base, m
    double tip_cap     = 0.0025; // closed tip, m

    double width(double x) const;
    double height(double x) const;
    double cavity_start() const { return base_fill; }
    double cavity_end() const { return length - tip_cap; }

    // Exact volumes of the parametric shape (integrals of products of two
    // linear functions of x).
    double body_volume() const;     // outer surface, cavity included
    double cavity_volume() const;   // air chamber
    double material_volume() const; // silicone: body minus cavity

    // How deep p lies inside the silicone: the smallest distance, measured
    // along the axes, to an outer face or to the cavity; negative outside
    // the material (outside the body or in the cavity).
    double material_margin(const Eigen::Vector3d &p) const;
  };
} // namespace softchain::geometry
