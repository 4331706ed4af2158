#pragma once
// CollisionSurface: where the chain's links touch the world. The FEM finger
// touches an obstacle with its outer surface -- the palm, the tip face's lower edge --
// not with the line of joints, so the chain carries the FEM's own outer
// surface: the vertices of the database mesh's boundary faces that are
// neither cavity nor clamped base, each a material point of the link that
// carries it (KinematicChain::link_of). A point k of link b sits at
//     x_k = c_b + R_b L_k(p)
// with L_k(p) its offset in the link's frame. The offsets are shaped by the
// pressure like the links (LinkGeometry): at each pressure-only sample p_s
// of the database the chain's own equilibrium pose (c_b, R_b at
// q_s = K^-1 J_p p_s) is taken and
//     L_k(p_s) = R_b^T (y_k(p_s) - c_b),
// y_k the FEM's deformed vertex, so that the chain at p_s carries the FEM's
// inflated surface exactly (its bulging cross-sections too); in between the
// offsets are linear in p and held beyond the last sample, the rest row
// (p = 0) being the reference surface. Rigid links (the paper's, and the
// beam-theory baseline) carry the reference surface at every pressure.
//
// Each link's points are split into clusters of at most eight neighbours
// (halving the link's points along their longest extent, recursively). The
// halvings form a tree per link, and every node of it has a bounding sphere
// (centre and radius in the link's frame) holding its children's, for each
// interval between two tabulated pressures: the points move linearly in p
// there, so a sphere that holds them at both ends holds them in between.
// A contact search skips a whole branch far from an obstacle (most of a
// finger, most of the time) with one test, and tests a point only where its
// cluster's sphere reaches into the obstacle. Spheres over all pressures
// at once, which the inflation of the cavity widens, made P10's contact
// equilibria about 10 % slower (a median of 313 against 282 us). The surface is built from a database by
// finger_collision_surface.h.
//
// A point may lie between vertices: strictly between two other points of a
// row of its face's grid that its own link carries with the same skin
// (`gives`). The grid is bilinear in the face's vertices (barycentric on a
// triangle), so along a row the point is a convex combination of the two,
// its offset the same combination of theirs at every pressure, and it moves
// with them: an affine function of the position -- a plane's gap -- is never
// smaller there than at the deeper of them, and the deepest point of the
// surface is always one that is not between vertices. A plane is therefore
// searched at those points only (ChainContact): the same constraint with
// fewer points (P10's default surface: 409 of 1849), exact in the
// rigid-contact limit; the penalty shares a force among fewer points, each
// deeper by the difference (10 um per newton on one point at P10's contact
// stiffness). Round obstacles are searched at every point.
#include <Eigen/Core>

#include <vector>

namespace softchain::chain
{
  class CollisionSurface
  {
  public:
    // One offset per point at each tabulated pressure.
    struct Row
    {
      double                       pressure = 0.0; // Pa
      std::vector<Eigen::Vector3d> offsets;        // L_k(p), m, in link frames
    };

    // A run of points of one link.
    struct Cluster
    {
      int link = 0, begin = 0, end = 0; // points [begin, end)
    };

    // Points sorted by link (`links[k]` the link of point k, 0-based, none on
    // the base); rows by increasing pressure, the first at 0. Throws
    // std::invalid_argument otherwise. The points are reordered within their
    // link into clusters. `gives[k]`: point k lies on a section that gives
    // under contact (ChainContact's skin; empty: every point).
    // `between_vertices[k]`: point k lies between two grid points of its
    // face on its link with its skin (above; empty: none does).
    CollisionSurface(std::vector<int> links, std::vector<Row> rows, int n_links,
                     std::vector<char> gives = {}, std::vector<char> between_vertices = {});

    int                     n_points() const { return static_cast<int>(links_.size()); }
    const std::vector<int> &links() const { return links_; }
    bool                    gives(int k) const { return gives_[k] != 0; }
    // Whether point k lies between vertices (above): no plane reaches it first.
    bool                    between_vertices(int k) const { return between_vertices_[k] != 0; }
    // The first point of each link and one past its last (size n_links + 1).
    const std::vector<int> &link_begin() const { return link_begin_; }
    // The clusters, by link.
    const std::vector<Cluster> &clusters() const { return clusters_; }
    // A node of a link's tree of bounding spheres: a cluster (cluster >= 0)
    // or the halving above two nodes, whose sphere holds both of theirs.
    struct Node
    {
      int link = 0, cluster = -1;
      int begin = 0, end = 0; // its points
      int skip = 0;           // the next node after this one's subtree
    };
    struct Sphere
    {
      Eigen::Vector3d centre = Eigen::Vector3d::Zero(); // in the link's frame
      double          radius = 0.0;
    };
    // Every link's tree in pre-order, links in order: a search walks it from
    // node 0, stepping to node + 1 to descend and to `skip` past a far
    // branch, and meets the clusters in their order.
    const std::vector<Node> &nodes() const { return nodes_; }
    // Walks the trees: skips the subtree of every node i for which far(i)
    // holds, calls reached(i) for every cluster's node it comes to, and
    // stops at the first for which that returns true (then returns true).
    template <class Far, class Reached>
    bool walk(const Far &far, const Reached &reached) const
    {
      for (std::size_t i = 0; i < nodes_.size();)
        {
          const int node = static_cast<int>(i);
          if (far(node))
            i = nodes_[i].skip;
          else if (nodes_[i].cluster < 0)
            ++i;
          else if (reached(node))
            return true;
          else
            i = nodes_[i].skip;
        }
      return false;
    }
    // Each node's sphere, holding its points at every pressure of the
    // interval of tabulated pressures that holds `pressure` (beyond the
    // table: of its end).
    const std::vector<Sphere> &spheres_at(double pressure) const;
    std::vector<double>     table_pressures() const;
    // L_k(p) of every point into `offsets` (sized n_points; no allocation).
    void offsets_at(double pressure, std::vector<Eigen::Vector3d> &offsets) const;

  private:
    // Reorders the points [begin, end) into clusters of <= 8 and appends them.
    // Returns the index of its node.
    int  split(int link, int begin, int end);
    // The nodes' spheres for the rows r0 and r1 (one interval).
    std::vector<Sphere> spheres_between(const Row &r0, const Row &r1) const;
    void reorder(const std::vector<int> &order);

    std::vector<int>             links_;
    std::vector<Row>             rows_;
    std::vector<char>            gives_;
    std::vector<char>            between_vertices_;
    std::vector<int>             link_begin_;
    std::vector<Cluster>         clusters_;
    std::vector<Node>            nodes_;
    std::vector<std::vector<Sphere>> spheres_; // per interval between rows (one for a single row)
  };
} // namespace softchain::chain
