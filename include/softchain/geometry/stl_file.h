#pragma once
// StlFile: a triangulated surface from or to an STL file (ASCII or binary on
// reading, ASCII on writing). Facet normals are ignored: orientation comes
// from the mesh, not from the STL.
#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace softchain::geometry
{
  class StlFile
  {
  public:
    using Triangle = std::array<Eigen::Vector3d, 3>;

    // Throws InputError naming the file if it is missing or malformed.
    static StlFile read(const std::string &path);
    std::string    ascii_text() const; // 17 significant digits
    void           write(const std::string &path) const;

    // Each triangle split into four at its edge midpoints, `levels` times;
    // conforming because shared edges get the same midpoints.
    StlFile subdivided(int levels) const;
    double  longest_edge() const;

    std::vector<Triangle> triangles;
  };
} // namespace softchain::geometry
