#include <softchain/chain/finger_collision_surface.h>
#include <softchain/data/vector_of_point.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <array>
#include <functional>
#include <optional>
#include <map>
#include <set>

namespace softchain::chain
{
  namespace
  {
    using Face = std::array<std::int64_t, 4>; // node indices, -1 padded, sorted

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

    // Every face of the mesh (keyed by its sorted nodes) with the number of
    // cells that share it and its vertices in the first one's local order.
    struct FaceUse
    {
      int                       cells = 0;
      std::vector<std::int64_t> vertices;
    };

    std::map<Face, FaceUse> face_uses(const data::MeshRecord &mesh)
    {
      std::map<Face, FaceUse> uses;
      const int               k = mesh.nodes_per_cell;
      for (std::size_t c = 0; c + k <= mesh.cells.size(); c += k)
        for (const std::vector<int> &local : local_faces(k))
          {
            std::vector<std::int64_t> vertices;
            for (const int v : local)
              vertices.push_back(mesh.cells[c + v]);
            Face face{-1, -1, -1, -1};
            std::copy(vertices.begin(), vertices.end(), face.begin());
            std::sort(face.begin(), face.end());
            FaceUse &use = uses[face];
            if (use.cells++ == 0)
              use.vertices = std::move(vertices);
          }
      return uses;
    }

    // The boundary faces that are not cavity faces, vertices in local order
    // (a quadrilateral's lexicographic: the unit square's (0,0), (1,0),
    // (0,1), (1,1)).
    std::vector<std::vector<std::int64_t>> outer_faces(const data::MeshRecord &mesh)
    {
      std::set<std::int64_t> cavity;
      for (const auto &triangle : mesh.cavity_triangles)
        cavity.insert(triangle.begin(), triangle.end());
      std::vector<std::vector<std::int64_t>> outer;
      for (const auto &[face, use] : face_uses(mesh))
        if (use.cells == 1 && !std::all_of(use.vertices.begin(), use.vertices.end(),
                                           [&](std::int64_t v) { return cavity.count(v) > 0; }))
          outer.push_back(use.vertices);
      return outer;
    }

    // A point of the outer surface: a combination sum w_i y_i of the
    // vertices of the face it lies on, so that it follows the deformed mesh.
    using Weights = std::vector<std::pair<std::int64_t, double>>;

    data::Point3 combination(const Weights &weights, const std::vector<data::Point3> &y)
    {
      data::Point3 x{0.0, 0.0, 0.0};
      for (const auto &[node, w] : weights)
        for (int i = 0; i < 3; ++i)
          x[i] += w * y[node][i];
      return x;
    }

    // Where a reference position is carried: its link (-1: the clamped base)
    // and whether it lies on a section that gives under contact.
    using Carrier = std::function<std::pair<int, bool>(const Eigen::Vector3d &)>;

    // A point of the outer surface, and whether it lies strictly between two
    // points of a row of one of its faces' grids (either direction) that the
    // same link carries with the same skin: a combination of them wherever
    // the link goes (CollisionSurface::between_vertices).
    struct GridPoint
    {
      Weights              weights;
      std::pair<int, bool> carrier; // Carrier's answer at the point
      bool                 between_vertices = false;
    };

    // The points of the outer faces on a grid of `subdivisions` intervals
    // per edge: bilinear on a quadrilateral, barycentric on a triangle. A point shared by faces
    // is kept once (keyed by its weights); those carried only by clamped
    // base vertices are left out (and are no row's ends).
    std::vector<GridPoint> outer_surface_points(const data::MeshRecord &mesh, const int subdivisions,
                                                const Carrier &carried)
    {
      const std::set<std::int64_t> base(mesh.base_nodes.begin(), mesh.base_nodes.end());
      std::map<std::vector<std::pair<std::int64_t, long>>, GridPoint> points;
      const auto add = [&](const Weights &weights, const std::pair<int, bool> &carrier, const bool between) {
        std::vector<std::pair<std::int64_t, long>> key;
        for (const auto &[node, w] : weights)
          key.emplace_back(node, std::lround(w * 1e9));
        std::sort(key.begin(), key.end());
        GridPoint &point = points.try_emplace(key, GridPoint{weights, carrier, false}).first->second;
        point.between_vertices |= between;
      };
      // The combination's vertices of positive weight, or none if all of them
      // are clamped.
      const auto surface_point = [&](const Weights &combination) -> std::optional<Weights> {
        Weights kept;
        for (const auto &[node, w] : combination)
          if (w > 0.0)
            kept.emplace_back(node, w);
        if (std::all_of(kept.begin(), kept.end(), [&](const auto &nw) { return base.count(nw.first) > 0; }))
          return std::nullopt;
        return kept;
      };
      const int m = subdivisions;
      struct Node
      {
        Weights              weights;
        std::pair<int, bool> carrier;
      };
      std::vector<std::vector<std::optional<Node>>> grid(m + 1, std::vector<std::optional<Node>>(m + 1));
      // Whether (i, j) lies strictly between two grid points of its carrier
      // along the direction (di, dj).
      const auto between_along = [&](const int i, const int j, const int di, const int dj) {
        const auto same_on_side = [&](const int sign) {
          for (int a = i + sign * di, b = j + sign * dj; a >= 0 && a <= m && b >= 0 && b <= m;
               a += sign * di, b += sign * dj)
            if (grid[a][b] && grid[a][b]->carrier == grid[i][j]->carrier)
              return true;
          return false;
        };
        return same_on_side(-1) && same_on_side(1);
      };
      for (const std::vector<std::int64_t> &face : outer_faces(mesh))
        {
          for (int i = 0; i <= m; ++i)
            for (int j = 0; j <= m; ++j)
              {
                const double           u = double(i) / m, v = double(j) / m;
                std::optional<Weights> point;
                if (face.size() == 4)
                  point = surface_point({{face[0], (1 - u) * (1 - v)}, {face[1], u * (1 - v)},
                                         {face[2], (1 - u) * v}, {face[3], u * v}});
                else if (i + j <= m)
                  point = surface_point({{face[0], 1 - u - v}, {face[1], u}, {face[2], v}});
                grid[i][j].reset();
                if (point)
                  grid[i][j] = Node{*point, carried(data::vector_of(combination(*point, mesh.X)))};
              }
          for (int i = 0; i <= m; ++i)
            for (int j = 0; j <= m; ++j)
              if (grid[i][j])
                add(grid[i][j]->weights, grid[i][j]->carrier, between_along(i, j, 1, 0) || between_along(i, j, 0, 1));
        }
      std::vector<GridPoint> all;
      for (auto &[key, point] : points)
        all.push_back(std::move(point));
      return all;
    }

    // Points of the outer surface on links, sorted by link; whether each
    // lies on a section that gives under contact: strictly between the
    // cavity's ends along x, where the palm is a plate spanning the cavity
    // (the solid base fill and tip cap do not give; ChainContact's skin);
    // and whether it lies between vertices (GridPoint).
    struct SurfacePoints
    {
      std::vector<Weights> points;
      std::vector<int>     links;
      std::vector<char>    gives;
      std::vector<char>    between_vertices;
    };

    SurfacePoints surface_points(const KinematicChain &chain, const data::MeshRecord &mesh, const int subdivisions)
    {
      const auto [low, high] = cavity_span(mesh);
      const Carrier carried  = [&chain, low = low, high = high](const Eigen::Vector3d &X) {
        return std::make_pair(chain.link_of(X), X.x() > low && X.x() < high);
      };
      struct OnLink
      {
        int       link;
        bool      gives;
        GridPoint point;
      };
      std::vector<OnLink> by_link;
      for (GridPoint &point : outer_surface_points(mesh, subdivisions, carried))
        {
          const auto [link, gives] = point.carrier;
          if (link >= 0)
            by_link.push_back({link, gives, std::move(point)});
        }
      std::stable_sort(by_link.begin(), by_link.end(), [](const OnLink &a, const OnLink &b) { return a.link < b.link; });
      SurfacePoints points;
      for (OnLink &p : by_link)
        {
          points.links.push_back(p.link);
          points.gives.push_back(p.gives);
          points.between_vertices.push_back(p.point.between_vertices);
          points.points.push_back(std::move(p.point.weights));
        }
      return points;
    }

    // L_k = R_b^T (y_k - c_b) at `pose`, y the node positions.
    std::vector<Eigen::Vector3d> offsets_in_links(const SurfacePoints &points, const ChainPose &pose,
                                                  const std::vector<data::Point3> &y)
    {
      std::vector<Eigen::Vector3d> offsets;
      for (std::size_t k = 0; k < points.points.size(); ++k)
        {
          const int b = points.links[k];
          offsets.push_back(pose.link_rotations[b].transpose() *
                            (data::vector_of(combination(points.points[k], y)) - pose.link_origins[b]));
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
    const std::set<std::int64_t> base(mesh.base_nodes.begin(), mesh.base_nodes.end());
    std::set<std::int64_t>       outer;
    for (const std::vector<std::int64_t> &face : outer_faces(mesh))
      for (const std::int64_t v : face)
        if (base.count(v) == 0)
          outer.insert(v);
    return {outer.begin(), outer.end()};
  }

  CollisionSurface rigid_collision_surface(const ChainModel &model, const data::MeshRecord &mesh,
                                           const int subdivisions)
  {
    const SurfacePoints points = surface_points(model.chain(), mesh, subdivisions);
    CollisionSurface::Row rest{0.0, offsets_in_links(points, model.chain().rest_pose(), mesh.X)};
    return CollisionSurface(points.links, {rest}, model.chain().n_joints(), points.gives, points.between_vertices);
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
                                                     const EquilibriumSettings &settings, const int subdivisions)
  {
    const SurfacePoints                points = surface_points(model.chain(), mesh, subdivisions);
    std::vector<CollisionSurface::Row> rows{
      {0.0, offsets_in_links(points, model.chain().rest_pose(), mesh.X)}};
    ChainEquilibrium equilibrium(model, settings);
    for (const auto &[pressure, y] : inflated)
      if (equilibrium.solve(ChainLoad{pressure, {}}).converged)
        rows.push_back({pressure, offsets_in_links(points, equilibrium.pose(), y)});
    return CollisionSurface(points.links, std::move(rows), model.chain().n_joints(), points.gives,
                            points.between_vertices);
  }
} // namespace softchain::chain
