#include <softchain/geometry/triangulated_obstacle.h>

#include <softchain/data/input_error.h>

#include <cmath>
#include <map>
#include <sstream>
#include <utility>

namespace softchain::geometry
{
  namespace
  {
    // Normals closer than this (1 - cos of the angle between them) are coplanar faces.
    constexpr double coplanar = 1e-12;

    std::string point_text(const Eigen::Vector3d &x)
    {
      std::ostringstream s;
      s.precision(9);
      s << "(" << x[0] << ", " << x[1] << ", " << x[2] << ")";
      return s.str();
    }
  } // namespace

  TriangulatedObstacle::TriangulatedObstacle(const std::vector<Triangle> &triangles, const std::string &source)
    : source(source)
  {
    if (triangles.empty())
      throw data::InputError(source + ": the obstacle's surface has no triangles");
    merge_vertices(triangles);
    check_edges();
    orient_outward();
    compute_pseudo_normals();
    Eigen::Vector3d low = vertices[0], high = vertices[0];
    for (const auto &v : vertices)
      {
        low  = low.cwiseMin(v);
        high = high.cwiseMax(v);
      }
    on_surface = 1e-12 * (high - low).norm();
    tree       = std::make_unique<TriangleTree>(vertices, faces);
  }

  // One vertex per distinct coordinate triple; a triangle without area is refused.
  void TriangulatedObstacle::merge_vertices(const std::vector<Triangle> &triangles)
  {
    std::map<std::array<double, 3>, int> index;
    for (std::size_t t = 0; t < triangles.size(); ++t)
      {
        std::array<int, 3> face;
        for (int k = 0; k < 3; ++k)
          {
            const Eigen::Vector3d &x = triangles[t][k];
            const auto [at, added]  = index.emplace(std::array<double, 3>{{x[0], x[1], x[2]}},
                                                    static_cast<int>(vertices.size()));
            if (added)
              vertices.push_back(x);
            face[k] = at->second;
          }
        const Eigen::Vector3d &a = triangles[t][0], &b = triangles[t][1], &c = triangles[t][2];
        const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
        if (!((b - a).cross(c - a).norm() > 1e-12 * longest * longest))
          throw data::InputError(source + ": triangle " + std::to_string(t + 1) + " at " + point_text(a) +
                                 " has no area (its vertices are on a line)");
        faces.push_back(face);
      }
  }

  // Every edge in exactly two triangles, run in opposite directions.
  void TriangulatedObstacle::check_edges() const
  {
    std::map<std::pair<int, int>, std::array<int, 2>> runs; // from the lower index up, down
    for (const auto &f : faces)
      for (int e = 0; e < 3; ++e)
        {
          const int a = f[e], b = f[(e + 1) % 3];
          ++runs[{std::min(a, b), std::max(a, b)}][a < b ? 0 : 1];
        }
    for (const auto &[edge, count] : runs)
      {
        const std::string where =
          "the edge from " + point_text(vertices[edge.first]) + " to " + point_text(vertices[edge.second]);
        if (count[0] + count[1] != 2)
          throw data::InputError(source + ": the obstacle's surface is not closed: " + where + " belongs to " +
                                 std::to_string(count[0] + count[1]) +
                                 " triangle(s); each edge of a closed surface belongs to exactly two");
        if (count[0] != 1)
          throw data::InputError(source + ": the obstacle's surface is not consistently oriented: the two "
                                 "triangles at " + where + " run it in the same direction");
      }
  }

  // volume = sum a . (b x c) / 6, taken about the first vertex for accuracy.
  void TriangulatedObstacle::orient_outward()
  {
    const Eigen::Vector3d &o = vertices[0];
    double                 six_volume = 0;
    for (const auto &f : faces)
      six_volume += (vertices[f[0]] - o).dot((vertices[f[1]] - o).cross(vertices[f[2]] - o));
    if (six_volume < 0)
      for (auto &f : faces)
        std::swap(f[1], f[2]);
    enclosed_volume = std::abs(six_volume) / 6;
  }

  void TriangulatedObstacle::compute_pseudo_normals()
  {
    for (const auto &f : faces)
      face_normals.push_back((vertices[f[1]] - vertices[f[0]]).cross(vertices[f[2]] - vertices[f[0]]).normalized());
    // Edges: the sum of the two faces' normals (each face's angle at an edge is pi).
    std::map<std::pair<int, int>, std::pair<int, int>> first_side; // an edge -> its first face and edge index
    edge_normals.resize(faces.size());
    edge_flat.resize(faces.size());
    for (std::size_t t = 0; t < faces.size(); ++t)
      for (int e = 0; e < 3; ++e)
        {
          const int  a = faces[t][e], b = faces[t][(e + 1) % 3];
          const auto key = std::make_pair(std::min(a, b), std::max(a, b));
          const auto other = first_side.find(key);
          if (other == first_side.end())
            {
              first_side.emplace(key, std::make_pair(static_cast<int>(t), e));
              continue;
            }
          const auto [u, k]         = other->second;
          const Eigen::Vector3d sum = face_normals[t] + face_normals[u];
          const Eigen::Vector3d m   = sum.norm() > 0 ? sum.normalized() : face_normals[t];
          const bool            flat = face_normals[t].dot(face_normals[u]) > 1 - coplanar;
          edge_normals[t][e] = edge_normals[u][k] = m;
          edge_flat[t][e] = edge_flat[u][k] = flat;
        }
    // Vertices: each face's normal weighted by its angle at the vertex.
    vertex_normals.assign(vertices.size(), Eigen::Vector3d::Zero());
    vertex_flat.assign(vertices.size(), true);
    std::vector<int> some_face(vertices.size(), -1);
    for (std::size_t t = 0; t < faces.size(); ++t)
      for (int k = 0; k < 3; ++k)
        {
          const int             v = faces[t][k];
          const Eigen::Vector3d u = vertices[faces[t][(k + 1) % 3]] - vertices[v],
                                w = vertices[faces[t][(k + 2) % 3]] - vertices[v];
          vertex_normals[v] += std::atan2(u.cross(w).norm(), u.dot(w)) * face_normals[t];
          if (some_face[v] < 0)
            some_face[v] = static_cast<int>(t);
          else if (face_normals[t].dot(face_normals[some_face[v]]) <= 1 - coplanar)
            vertex_flat[v] = false;
        }
    for (auto &m : vertex_normals)
      m.normalize();
  }

  SignedDistance TriangulatedObstacle::distance_at_rest(const Eigen::Vector3d &x) const
  {
    using Feature              = TriangleClosestPoint::Feature;
    const TriangleTree::Nearest hit = tree->nearest(x);
    const std::array<int, 3>  &f   = faces[hit.triangle];
    const int                  i   = hit.closest.index;
    Eigen::Matrix3d            P   = Eigen::Matrix3d::Identity(); // the directions n may turn in
    Eigen::Vector3d            m;                                 // the pseudo-normal
    bool                       flat = true;
    if (hit.closest.feature == Feature::face)
      m = face_normals[hit.triangle];
    else if (hit.closest.feature == Feature::edge)
      {
        m                       = edge_normals[hit.triangle][i];
        flat                    = edge_flat[hit.triangle][i];
        const Eigen::Vector3d e = (vertices[f[(i + 1) % 3]] - vertices[f[i]]).normalized();
        P -= e * e.transpose();
      }
    else
      {
        m    = vertex_normals[f[i]];
        flat = vertex_flat[f[i]];
      }
    const Eigen::Vector3d w    = x - hit.closest.point;
    const double          d    = std::sqrt(hit.squared_distance);
    const double          sign = w.dot(m) < 0 ? -1.0 : 1.0;
    if (d <= on_surface)
      return {sign * d, m, Eigen::Matrix3d::Zero()};
    const Eigen::Vector3d n = sign * w / d;
    const double          g = sign * d;
    return {g, n, flat ? Eigen::Matrix3d::Zero() : Eigen::Matrix3d((P - n * n.transpose()) / g)};
  }
} // namespace softchain::geometry
