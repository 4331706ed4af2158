// BodySamples: point location in the database's cells, interpolation of a
// sample's node positions at located points, and the body lattice.
#include <softchain/data/input_error.h>
#include <softchain/reduction/body_samples.h>
#include <softchain/data/vector_of_point.h>

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <map>

namespace softchain::reduction
{
  namespace
  {
    // Local coordinates may lie this far outside [0, 1] and still count as
    // inside: the round-off of locating a point on a face shared by two
    // cells (~1e-15) is far below it, and 1e-9 of a cell (~1e-12 m) is far
    // below any spacing a reduction uses.
    constexpr double inside_tolerance = 1e-9;

    // Trilinear shape functions of the hexahedron's corners a = i + 2j + 4k
    // (i, j, k the corner's local coordinates along xi_0, xi_1, xi_2).
    std::array<double, 8> trilinear(const Eigen::Vector3d &xi)
    {
      std::array<double, 8> N;
      for (int a = 0; a < 8; ++a)
        {
          N[a] = 1;
          for (int d = 0; d < 3; ++d)
            N[a] *= (a >> d & 1) ? xi(d) : 1 - xi(d);
        }
      return N;
    }

    bool inside_unit_cube(const Eigen::Vector3d &xi)
    {
      return (xi.array() >= -inside_tolerance).all() && (xi.array() <= 1 + inside_tolerance).all();
    }
  } // namespace

  BodySamples::BodySamples(const data::MeshRecord &mesh, double spacing, const std::string &source)
    : mesh_(mesh)
    , corners_(mesh.nodes_per_cell)
    , n_cells_(corners_ > 0 ? mesh.cells.size() / corners_ : 0)
    , spacing_(spacing)
  {
    if (corners_ != 4 && corners_ != 8)
      throw data::InputError(source + ": /mesh/cells has " + std::to_string(corners_) +
                             " nodes per cell; 4 (tetrahedra) or 8 (hexahedra) are read");
    if (n_cells_ == 0)
      throw data::InputError(source + ": /mesh/cells is empty; the joints on the "
                                      "strain-limiting layer sample the body through its cells");
    if (!(spacing_ > 0))
      throw data::InputError(source + ": the body sampling spacing must be positive");
    for (const auto &X : mesh.X)
      box_.extend(data::vector_of(X));
    check_lattice_size(source);
    for (std::size_t c = 0; c < n_cells_; ++c)
      {
        Eigen::AlignedBox3d cell_box;
        for (int a = 0; a < corners_; ++a)
          cell_box.extend(corner(c, a));
        cell_boxes_.push_back(cell_box);
      }
    build_buckets();
    build_lattice();
  }

  // (n - 1/2) h <= size, at least one; in double, as a spacing mistyped by
  // orders of magnitude would overflow an integer.
  double BodySamples::lattice_points_along(const int d) const
  {
    return std::max(1.0, std::floor(box_.sizes()(d) / spacing_ + 0.5));
  }

  // The lattice's grid over the bounding box, before any point is made: a
  // joint spacing mistyped by orders of magnitude (1e-7 for 1e-2) would
  // otherwise fill the memory for minutes.
  void BodySamples::check_lattice_size(const std::string &source) const
  {
    double points = 1;
    for (int d = 0; d < 3; ++d)
      points *= lattice_points_along(d);
    if (points <= max_lattice_points)
      return;
    const double smallest = std::cbrt(box_.volume() / max_lattice_points) * lattice_points_per_spacing;
    std::ostringstream message;
    message << source << ": Reduction/Joint spacing a = " << spacing_ * lattice_points_per_spacing
            << " m samples the body on a lattice of h = a/" << lattice_points_per_spacing << " with "
            << points << " points over the mesh's bounding box, more than " << max_lattice_points
            << "; a joint spacing of at least " << smallest << " m keeps it within";
    throw data::InputError(message.str());
  }

  Eigen::Vector3d BodySamples::corner(std::size_t cell, int a) const
  {
    return data::vector_of(mesh_.X[mesh_.cells[cell * corners_ + a]]);
  }

  // A uniform grid of about one cell per bucket: each cell is listed in
  // every bucket its bounding box touches.
  void BodySamples::build_buckets()
  {
    const Eigen::Vector3d extent = box_.sizes();
    const double per_axis = std::max(1.0, std::cbrt(double(n_cells_)));
    const double edge     = std::max(extent.maxCoeff() / per_axis, 1e-12);
    for (int d = 0; d < 3; ++d)
      n_buckets_[d] = std::max(1, int(std::ceil(extent(d) / edge)));
    buckets_.assign(std::size_t(n_buckets_[0]) * n_buckets_[1] * n_buckets_[2], {});
    for (std::size_t c = 0; c < n_cells_; ++c)
      {
        const auto low = bucket_of(cell_boxes_[c].min()), high = bucket_of(cell_boxes_[c].max());
        for (int k = low[2]; k <= high[2]; ++k)
          for (int j = low[1]; j <= high[1]; ++j)
            for (int i = low[0]; i <= high[0]; ++i)
              buckets_[i + n_buckets_[0] * (j + std::size_t(n_buckets_[1]) * k)].push_back(c);
      }
  }

  std::array<int, 3> BodySamples::bucket_of(const Eigen::Vector3d &X) const
  {
    std::array<int, 3> ijk;
    for (int d = 0; d < 3; ++d)
      {
        const double extent = std::max(box_.sizes()(d), 1e-300);
        const int    k      = int(std::floor((X(d) - box_.min()(d)) / extent * n_buckets_[d]));
        ijk[d]              = std::clamp(k, 0, n_buckets_[d] - 1);
      }
    return ijk;
  }

  // Lattice points are located cell by cell (each cell tests the lattice
  // points inside its bounding box); a point on a shared face keeps the
  // first cell, and the lattice is ordered by its grid index.
  void BodySamples::build_lattice()
  {
    std::array<long, 3> n;
    for (int d = 0; d < 3; ++d)
      n[d] = long(lattice_points_along(d));
    const auto point = [&](long i, long j, long k) {
      return Eigen::Vector3d(box_.min()(0) + (i + 0.5) * spacing_,
                             box_.min()(1) + (j + 0.5) * spacing_,
                             box_.min()(2) + (k + 0.5) * spacing_);
    };
    const auto first_index = [&](const Eigen::AlignedBox3d &cell_box, int d) {
      return std::max(0L, long(std::ceil((cell_box.min()(d) - box_.min()(d)) / spacing_ - 0.5)));
    };
    const auto last_index = [&](const Eigen::AlignedBox3d &cell_box, int d) {
      return std::min(n[d] - 1, long(std::floor((cell_box.max()(d) - box_.min()(d)) / spacing_ - 0.5)));
    };
    std::map<long, std::pair<Eigen::Vector3d, CellPoint>> found;
    for (std::size_t c = 0; c < n_cells_; ++c)
      for (long k = first_index(cell_boxes_[c], 2); k <= last_index(cell_boxes_[c], 2); ++k)
        for (long j = first_index(cell_boxes_[c], 1); j <= last_index(cell_boxes_[c], 1); ++j)
          for (long i = first_index(cell_boxes_[c], 0); i <= last_index(cell_boxes_[c], 0); ++i)
            {
              const long index = i + n[0] * (j + n[1] * k);
              if (found.count(index))
                continue;
              const Eigen::Vector3d X = point(i, j, k);
              if (const auto located = locate_in(c, X))
                found.emplace(index, std::make_pair(X, *located));
            }
    for (const auto &[index, entry] : found)
      {
        lattice_.push_back({entry.first(0), entry.first(1), entry.first(2)});
        lattice_cells_.push_back(entry.second);
      }
  }

  std::vector<data::Point3> BodySamples::deformed_lattice(const std::vector<data::Point3> &x) const
  {
    std::vector<data::Point3> moved;
    moved.reserve(lattice_cells_.size());
    for (const CellPoint &p : lattice_cells_)
      {
        const Eigen::Vector3d y = deformed(p, x);
        moved.push_back({y(0), y(1), y(2)});
      }
    return moved;
  }

  std::optional<CellPoint> BodySamples::locate(const Eigen::Vector3d &X) const
  {
    if (!box_.contains(X))
      return std::nullopt;
    const auto ijk = bucket_of(X);
    for (const std::size_t c : buckets_[ijk[0] + n_buckets_[0] * (ijk[1] + std::size_t(n_buckets_[1]) * ijk[2])])
      if (const auto located = locate_in(c, X))
        return located;
    return std::nullopt;
  }

  Eigen::Vector3d BodySamples::deformed(const CellPoint &point, const std::vector<data::Point3> &x) const
  {
    Eigen::Vector3d y = Eigen::Vector3d::Zero();
    for (int a = 0; a < corners_; ++a)
      y += point.weights[a] * data::vector_of(x[mesh_.cells[point.cell * corners_ + a]]);
    return y;
  }

  std::optional<CellPoint> BodySamples::locate_in(std::size_t cell, const Eigen::Vector3d &X) const
  {
    const double margin = inside_tolerance * cell_boxes_[cell].sizes().maxCoeff();
    const Eigen::AlignedBox3d grown(cell_boxes_[cell].min().array() - margin,
                                    cell_boxes_[cell].max().array() + margin);
    if (!grown.contains(X))
      return std::nullopt;
    return corners_ == 4 ? locate_in_tetrahedron(cell, X) : locate_in_hexahedron(cell, X);
  }

  // Barycentric coordinates: X = X_0 + [X_1 - X_0, X_2 - X_0, X_3 - X_0] l,
  // N = (1 - l_1 - l_2 - l_3, l_1, l_2, l_3).
  std::optional<CellPoint> BodySamples::locate_in_tetrahedron(std::size_t cell, const Eigen::Vector3d &X) const
  {
    Eigen::Matrix3d T;
    for (int a = 1; a < 4; ++a)
      T.col(a - 1) = corner(cell, a) - corner(cell, 0);
    const Eigen::Vector3d l = T.partialPivLu().solve(X - corner(cell, 0));
    CellPoint             p{cell, {1 - l.sum(), l(0), l(1), l(2)}};
    for (int a = 0; a < 4; ++a)
      if (!(p.weights[a] >= -inside_tolerance))
        return std::nullopt;
    return p;
  }

  // Newton's method on X(xi) = sum_a N_a(xi) X_a from the cell's centre; the
  // trilinear map of a cell that is not badly distorted converges in a few
  // steps, and a point outside the cell ends outside [0, 1]^3. Weights are
  // returned only where Newton converged (|X(xi) - X| <= 1e-13 of the
  // cell's size): a point it cannot invert counts as not in this cell.
  std::optional<CellPoint> BodySamples::locate_in_hexahedron(std::size_t cell, const Eigen::Vector3d &X) const
  {
    Eigen::Vector3d xi = Eigen::Vector3d::Constant(0.5);
    const double    size = cell_boxes_[cell].sizes().maxCoeff();
    bool            converged = false;
    for (int iteration = 0; iteration < 30 && !converged; ++iteration)
      {
        const auto      N = trilinear(xi);
        Eigen::Vector3d r = -X;
        Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
        for (int a = 0; a < 8; ++a)
          {
            const Eigen::Vector3d Xa = corner(cell, a);
            r += N[a] * Xa;
            for (int d = 0; d < 3; ++d)
              {
                // dN_a/dxi_d: the factor along d differentiated.
                double dN = (a >> d & 1) ? 1 : -1;
                for (int e = 0; e < 3; ++e)
                  if (e != d)
                    dN *= (a >> e & 1) ? xi(e) : 1 - xi(e);
                J.col(d) += dN * Xa;
              }
          }
        converged = r.norm() <= 1e-13 * size;
        if (converged)
          break;
        xi -= J.partialPivLu().solve(r);
        if (!xi.allFinite() || xi.cwiseAbs().maxCoeff() > 10)
          return std::nullopt;
      }
    if (!converged || !inside_unit_cube(xi))
      return std::nullopt;
    return CellPoint{cell, trilinear(xi)};
  }
} // namespace softchain::reduction
