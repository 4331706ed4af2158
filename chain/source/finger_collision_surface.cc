#include <softchain/chain/finger_collision_surface.h>
#include <softchain/data/vector_of_point.h>

#include <algorithm>
#include <limits>
#include <array>
#include <map>
#include <set>

namespace softchain::chain
{
  namespace
  {
    using Face = std::array<std::int64_t, 4>; // sorted node indices, -1 padded

    // The faces of a cell by its local vertices: a tetrahedron's four
    // triangles, a hexahedron's six quadrilaterals (deal.II's lexicographic
    // vertex order: vertex v at (v & 1, v >> 1 & 1, v >> 2 & 1)).
    const std::vector<std::vector<int>> &local_faces(const int nodes_per_cell)
    {
      static const std::vector<std::vector<int>> tetrahedron{{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
      static const std::vector<std::vector<int>> hexahedron{
        {0, 2, 4, 6}, {1, 3, 5, 7}, {0, 1, 4, 5}, {2, 3, 6, 7}, {0, 1, 2, 3}, {4, 5, 6, 7}};
      return nodes_per_cell == 8 ? hexahedron : tetrahedron;
    }

    // Every face of the mesh with the number of cells that share it.
    std::map<Face, int> face_counts(const data::MeshRecord &mesh)
    {
      std::map<Face, int> counts;
      const int           k = mesh.nodes_per_cell;
      for (std::size_t c = 0; c + k <= mesh.cells.size(); c += k)
        for (const std::vector<int> &local : local_faces(k))
          {
            Face face{-1, -1, -1, -1};
            for (std::size_t v = 0; v < local.size(); ++v)
              face[v] = mesh.cells[c + local[v]];
            std::sort(face.begin(), face.begin() + local.size());
            ++counts[face];
          }
      return counts;
    }

    // Points of the outer surface on links, sorted by link, and whether each
    // lies on a section that gives under contact: strictly between the
    // cavity's ends along x, where the palm is a plate spanning the cavity
    // (the solid base fill and tip cap do not give; ChainContact's skin).
    struct SurfacePoints
    {
      std::vector<std::int64_t> nodes;
      std::vector<int>          links;
      std::vector<char>         gives;
    };

    SurfacePoints surface_points(const KinematicChain &chain, const data::MeshRecord &mesh)
    {
      std::vector<std::pair<int, std::int64_t>> by_link;
      for (const std::int64_t node : outer_surface_nodes(mesh))
        {
          const int link = chain.link_of(data::vector_of(mesh.X[node]));
          if (link >= 0)
            by_link.emplace_back(link, node);
        }
      std::sort(by_link.begin(), by_link.end());
      const auto [low, high] = cavity_span(mesh);
      SurfacePoints points;
      for (const auto &[link, node] : by_link)
        {
          points.links.push_back(link);
          points.nodes.push_back(node);
          points.gives.push_back(mesh.X[node][0] > low && mesh.X[node][0] < high);
        }
      return points;
    }

    // L_k = R_b^T (y_k - c_b) at `pose`, y the node positions.
    std::vector<Eigen::Vector3d> offsets_in_links(const SurfacePoints &points, const ChainPose &pose,
                                                  const std::vector<data::Point3> &y)
    {
      std::vector<Eigen::Vector3d> offsets;
      for (std::size_t k = 0; k < points.nodes.size(); ++k)
        {
          const int b = points.links[k];
          offsets.push_back(pose.link_rotations[b].transpose() *
                            (data::vector_of(y[points.nodes[k]]) - pose.joint_positions[b]));
        }
      return offsets;
    }

    bool pressure_only(const data::SampleRecord &sample)
    {
      const data::Actuation &a = sample.actuation;
      return sample.converged() && a.role == "pressure" && a.pressure > 0.0 && a.point_forces.empty() &&
             !a.tip_motion && a.obstacles.empty() && !a.cavity_volume_ratio;
    }
  } // namespace

  std::pair<double, double> cavity_span(const data::MeshRecord &mesh)
  {
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (const auto &triangle : mesh.cavity_triangles)
      for (const std::int64_t v : triangle)
        {
          low  = std::min(low, mesh.X[v][0]);
          high = std::max(high, mesh.X[v][0]);
        }
    return {low, high};
  }

  std::vector<std::int64_t> outer_surface_nodes(const data::MeshRecord &mesh)
  {
    std::set<std::int64_t> cavity;
    for (const auto &triangle : mesh.cavity_triangles)
      cavity.insert(triangle.begin(), triangle.end());
    const std::set<std::int64_t> base(mesh.base_nodes.begin(), mesh.base_nodes.end());
    std::set<std::int64_t>       outer;
    for (const auto &[face, count] : face_counts(mesh))
      {
        if (count != 1)
          continue;
        const bool on_cavity = std::all_of(face.begin(), face.end(), [&](std::int64_t v) {
          return v < 0 || cavity.count(v) > 0;
        });
        if (!on_cavity)
          for (const std::int64_t v : face)
            if (v >= 0 && base.count(v) == 0)
              outer.insert(v);
      }
    return {outer.begin(), outer.end()};
  }

  CollisionSurface rigid_collision_surface(const ChainModel &model, const data::MeshRecord &mesh)
  {
    const SurfacePoints points = surface_points(model.chain(), mesh);
    CollisionSurface::Row rest{0.0, offsets_in_links(points, model.chain().rest_pose(), mesh.X)};
    return CollisionSurface(points.links, {rest}, model.chain().n_joints(), points.gives);
  }

  SurfaceSamples SurfaceSamples::read(const data::ActuationDatabase &database)
  {
    SurfaceSamples samples;
    for (const std::string &id : database.sample_ids())
      {
        data::SampleRecord sample = database.read_sample(id);
        samples.contact |= !sample.actuation.obstacles.empty();
        if (pressure_only(sample))
          samples.inflated.emplace(sample.actuation.pressure, std::move(sample.x));
      }
    return samples;
  }

  CollisionSurface pressure_shaped_collision_surface(const ChainModel &model, const data::MeshRecord &mesh,
                                                     const InflatedNodes       &inflated,
                                                     const EquilibriumSettings &settings)
  {
    const SurfacePoints                points = surface_points(model.chain(), mesh);
    std::vector<CollisionSurface::Row> rows{
      {0.0, offsets_in_links(points, model.chain().rest_pose(), mesh.X)}};
    ChainEquilibrium equilibrium(model, settings);
    for (const auto &[pressure, y] : inflated)
      if (equilibrium.solve(ChainLoad{pressure, {}}).converged)
        rows.push_back({pressure, offsets_in_links(points, equilibrium.pose(), y)});
    return CollisionSurface(points.links, std::move(rows), model.chain().n_joints(), points.gives);
  }
} // namespace softchain::chain
