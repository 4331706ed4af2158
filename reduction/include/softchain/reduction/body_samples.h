#pragma once
// BodySamples: the finger's body sampled through the database's cells, so
// that a slab holds material points on every mesh, also on hexahedral meshes
// whose node planes lie farther apart than a slab is wide.
//
// A reference point X is located once in the cell that contains it, at local
// coordinates xi; a sample's deformed position of that material point is then
//   x(X) = sum_a N_a(xi) x_a
// over the cell's corner nodes a, with the linear shape functions of a
// tetrahedron (barycentric coordinates) or the trilinear ones of a hexahedron
// (deal.II's lexicographic corner order, N_a = prod_d (xi_d or 1 - xi_d)).
// For quadratic elements this is the corners' linear interpolation; the
// mid-side nodes are not used.
//
// The lattice is the regular grid X = X_min + (k + 1/2) h (per axis, X_min
// the corner of the mesh's bounding box) restricted to the body: equally
// spaced material points, so that an unweighted fit over a slab of them is a
// fit over the slab's volume.
#include <softchain/data/actuation_database.h>

#include <Eigen/Geometry>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace softchain::reduction
{
  // The reduction's lattice spacing is h = a / lattice_points_per_spacing (a
  // the joint spacing): a slab of the smallest default half-width b = a/3
  // holds 5 planes of it, and a 2 mm wall 1-2 points across.
  constexpr double lattice_points_per_spacing = 8;
  // The most lattice points over the mesh's bounding box (about 1 GB of
  // located points): P10's 90 mm at a joint spacing of 1.3 mm.
  constexpr double max_lattice_points = 1e7;

  // A material point located in a cell: the corners' shape-function values.
  struct CellPoint
  {
    std::size_t           cell = 0;
    std::array<double, 8> weights{}; // N_a(xi); the first 4 for a tetrahedron
  };

  class BodySamples
  {
  public:
    // Keeps a reference to `mesh`, which must outlive it. Throws
    // data::InputError naming `source` when the mesh has no cells, the
    // spacing is not positive, or the lattice would have more than
    // max_lattice_points over the mesh's bounding box.
    BodySamples(const data::MeshRecord &mesh, double spacing, const std::string &source);

    const Eigen::AlignedBox3d       &reference_box() const { return box_; }
    double                           spacing() const { return spacing_; }
    const std::vector<data::Point3> &lattice() const { return lattice_; }
    // The lattice's points moved with the sample's node positions x.
    std::vector<data::Point3> deformed_lattice(const std::vector<data::Point3> &x) const;

    // The cell that contains X (the first one, for a point on shared faces),
    // or nothing when X lies outside the body.
    std::optional<CellPoint> locate(const Eigen::Vector3d &X) const;
    Eigen::Vector3d          deformed(const CellPoint &point, const std::vector<data::Point3> &x) const;

  private:
    double lattice_points_along(int d) const; // the lattice's grid size along axis d
    void   check_lattice_size(const std::string &source) const;
    std::optional<CellPoint> locate_in(std::size_t cell, const Eigen::Vector3d &X) const;
    std::optional<CellPoint> locate_in_tetrahedron(std::size_t cell, const Eigen::Vector3d &X) const;
    std::optional<CellPoint> locate_in_hexahedron(std::size_t cell, const Eigen::Vector3d &X) const;
    Eigen::Vector3d          corner(std::size_t cell, int a) const;
    void                     build_buckets();
    void                     build_lattice();
    // Bucket index of a point, clamped into the bucket grid.
    std::array<int, 3> bucket_of(const Eigen::Vector3d &X) const;

    const data::MeshRecord                &mesh_;
    int                                    corners_;
    std::size_t                            n_cells_;
    double                                 spacing_;
    Eigen::AlignedBox3d                    box_;
    std::vector<Eigen::AlignedBox3d>       cell_boxes_;
    std::array<int, 3>                     n_buckets_{};
    std::vector<std::vector<std::size_t>>  buckets_;
    std::vector<data::Point3>              lattice_;
    std::vector<CellPoint>                 lattice_cells_;
  };
} // namespace softchain::reduction
