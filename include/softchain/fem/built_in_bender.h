#pragma once
// BuiltInBender: the default demo finger, a hollow box (length x height x
// width, wall thickness t) clamped at x = 0, closed at the tip, with a fabric
// spring grid in the bottom wall (smallest y) and thread rings around the
// cross-section every `thread pitch` (the demo bender: 80 x 12 x 18 mm, 2 mm
// walls). Built with deal.II's structured generator, no gmsh needed.
#include <softchain/fem/finger_mesh.h>

namespace softchain::fem
{
  class BuiltInBender
  {
  public:
    explicit BuiltInBender(const Parameters &prm);
    void build(FingerMesh &mesh) const;

    // Analytic volumes, for tests.
    double body_volume() const;
    double cavity_volume() const;

  private:
    double       length, width, height, wall;
    unsigned int cells_along_length;
    bool         tetrahedra;
    unsigned int refinements;
    bool         with_springs;
    double       thread_pitch;

    std::vector<SpringPolyline> springs() const;
  };
} // namespace softchain::fem
