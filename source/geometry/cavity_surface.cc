#include <softchain/data/input_error.h>
#include <softchain/geometry/cavity_surface.h>
#include <softchain/geometry/cell_geometry.h>

#include <Eigen/Geometry> // cross products

#include <algorithm>
#include <map>

namespace softchain::geometry
{
  namespace
  {
    std::vector<std::size_t> sorted(std::vector<std::size_t> nodes)
    {
      std::sort(nodes.begin(), nodes.end());
      return nodes;
    }

    // Centroid of the cell owning each facet (same order as `facets`).
    std::vector<Eigen::Vector3d> owner_centroids(const MshFile                         &mesh,
                                                 const std::vector<const MshElement *> &facets)
    {
      std::map<std::vector<std::size_t>, std::size_t> position;
      for (std::size_t i = 0; i < facets.size(); ++i)
        position[sorted(facets[i]->nodes)] = i;
      std::vector<Eigen::Vector3d> centroids(facets.size());
      std::vector<bool>            found(facets.size(), false);
      for (const auto &cell : mesh.cells)
        for (const auto &face : CellGeometry::faces(cell))
          if (const auto it = position.find(sorted(face)); it != position.end())
            {
              centroids[it->second] = CellGeometry::centroid(mesh, cell.nodes);
              found[it->second]     = true;
            }
      for (std::size_t i = 0; i < facets.size(); ++i)
        if (!found[i])
          throw data::InputError(mesh.path + ": cavity facet " + std::to_string(facets[i]->id) +
                                 " is not the face of any cell");
      return centroids;
    }
  } // namespace

  CavitySurface::CavitySurface(const MshFile &mesh)
    : nodes_(mesh.nodes)
  {
    const auto facets    = mesh.facets_of("cavity");
    const auto centroids = owner_centroids(mesh, facets);
    for (std::size_t i = 0; i < facets.size(); ++i)
      {
        std::vector<std::size_t> n = facets[i]->nodes;
        // Diagonal cross product: the facet normal for triangles and quads.
        const Eigen::Vector3d normal = n.size() == 3 ?
                                         (nodes_[n[1]] - nodes_[n[0]]).cross(nodes_[n[2]] - nodes_[n[0]]) :
                                         (nodes_[n[2]] - nodes_[n[0]]).cross(nodes_[n[3]] - nodes_[n[1]]);
        if (normal.dot(CellGeometry::centroid(mesh, n) - centroids[i]) < 0.0)
          std::reverse(n.begin(), n.end());
        triangles_.push_back({n[0], n[1], n[2]});
        if (n.size() == 4)
          triangles_.push_back({n[0], n[2], n[3]});
      }
  }

  Eigen::Vector3d CavitySurface::area_vector(const std::array<std::size_t, 3> &t) const
  {
    return 0.5 * (nodes_[t[1]] - nodes_[t[0]]).cross(nodes_[t[2]] - nodes_[t[0]]);
  }

  Eigen::Vector3d CavitySurface::area_vector_sum() const
  {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const auto &t : triangles_)
      sum += area_vector(t);
    return sum;
  }

  double CavitySurface::total_area() const
  {
    double area = 0.0;
    for (const auto &t : triangles_)
      area += area_vector(t).norm();
    return area;
  }

  double CavitySurface::enclosed_volume() const
  {
    // V = (1/3) sum x.n_out A over the cavity's boundary, where the cavity's
    // outward normal is minus our (into the cavity) orientation.
    double v = 0.0;
    for (const auto &t : triangles_)
      v -= nodes_[t[0]].dot(area_vector(t)) / 3.0;
    return v;
  }
} // namespace softchain::geometry
