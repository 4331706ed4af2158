#include <softchain/chain/beam_theory_baseline.h>
#include <softchain/data/input_error.h>

#include <Eigen/Core>
#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace softchain::chain
{
  namespace
  {
    using Corners = std::array<Eigen::Vector3d, 8>;

    // 4-point Gauss-Legendre rule on [0, 1].
    constexpr std::array<double, 4> gauss_points = {0.0694318442029737, 0.3300094782075719,
                                                    0.6699905217924281, 0.9305681557970263};
    constexpr std::array<double, 4> gauss_weights = {0.1739274225687269, 0.3260725774312731,
                                                     0.3260725774312731, 0.1739274225687269};

    // Volume integrals of 1, y, y^2 over one slab.
    struct SlabMoments
    {
      double volume = 0.0, first = 0.0, second = 0.0;
    };

    // Corners of cell c in lexicographic order (a tet collapsed, see header).
    Corners cell_corners(const data::MeshRecord &mesh, std::size_t c)
    {
      static constexpr std::array<int, 8> tet_as_hex = {0, 1, 2, 2, 3, 3, 3, 3};
      const std::int64_t *nodes = &mesh.cells[c * mesh.nodes_per_cell];
      Corners             corners;
      for (int v = 0; v < 8; ++v)
        {
          const std::int64_t node = nodes[mesh.nodes_per_cell == 8 ? v : tet_as_hex[v]];
          if (node < 0 || node >= static_cast<std::int64_t>(mesh.X.size()))
            throw data::InputError("/mesh/cells: node index " + std::to_string(node) +
                                   " out of range in cell " + std::to_string(c));
          corners[v] = Eigen::Map<const Eigen::Vector3d>(mesh.X[node].data());
        }
      return corners;
    }

    // Trilinear map at (u, v, w) in [0,1]^3: position and |det Jacobian|.
    std::pair<Eigen::Vector3d, double> trilinear(const Corners &x, double u, double v, double w)
    {
      const double    s[3][2] = {{1 - u, u}, {1 - v, v}, {1 - w, w}};
      Eigen::Vector3d point   = Eigen::Vector3d::Zero();
      Eigen::Matrix3d jacobian = Eigen::Matrix3d::Zero();
      for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
          for (int i = 0; i < 2; ++i)
            {
              const Eigen::Vector3d &corner = x[i + 2 * j + 4 * k];
              const double           sign[2] = {-1.0, 1.0};
              point += s[0][i] * s[1][j] * s[2][k] * corner;
              jacobian.col(0) += sign[i] * s[1][j] * s[2][k] * corner;
              jacobian.col(1) += s[0][i] * sign[j] * s[2][k] * corner;
              jacobian.col(2) += s[0][i] * s[1][j] * sign[k] * corner;
            }
      return {point, std::abs(jacobian.determinant())};
    }

    void integrate_cell(const Corners &corners, const std::vector<double> &bounds,
                        std::vector<SlabMoments> &slabs)
    {
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
          for (int c = 0; c < 4; ++c)
            {
              const auto [x, det] =
                trilinear(corners, gauss_points[a], gauss_points[b], gauss_points[c]);
              const auto upper = std::upper_bound(bounds.begin(), bounds.end(), x.x());
              if (upper == bounds.begin() || upper == bounds.end())
                continue; // outside every section (e.g. beyond the last half spacing)
              SlabMoments &slab = slabs[upper - bounds.begin() - 1];
              const double dv   = gauss_weights[a] * gauss_weights[b] * gauss_weights[c] * det;
              slab.volume += dv;
              slab.first += dv * x.y();
              slab.second += dv * x.y() * x.y();
            }
    }

    // Section boundaries: midpoints between joints, half a spacing beyond the ends.
    std::vector<double> section_bounds(const std::vector<double> &x)
    {
      if (x.size() < 2)
        throw std::invalid_argument("BeamTheoryBaseline: need at least two joints");
      std::vector<double> bounds = {x[0] - 0.5 * (x[1] - x[0])};
      for (std::size_t i = 1; i < x.size(); ++i)
        {
          if (!(x[i] > x[i - 1]))
            throw std::invalid_argument("BeamTheoryBaseline: joint abscissae must increase");
          bounds.push_back(0.5 * (x[i - 1] + x[i]));
        }
      bounds.push_back(x.back() + 0.5 * (x.back() - x[x.size() - 2]));
      return bounds;
    }
  } // namespace

  BeamTheoryBaseline::BeamTheoryBaseline(const data::MeshRecord &mesh,
                                         const std::vector<double> &joint_x)
  {
    if (mesh.nodes_per_cell != 4 && mesh.nodes_per_cell != 8)
      throw data::InputError("/mesh/cells: " + std::to_string(mesh.nodes_per_cell) +
                             " nodes per cell, expected 4 (tetrahedra) or 8 (hexahedra)");
    const std::vector<double> bounds = section_bounds(joint_x);
    std::vector<SlabMoments>  slabs(joint_x.size());
    for (std::size_t c = 0; c * mesh.nodes_per_cell < mesh.cells.size(); ++c)
      integrate_cell(cell_corners(mesh, c), bounds, slabs);
    for (std::size_t i = 0; i < slabs.size(); ++i)
      {
        if (!(slabs[i].volume > 0.0))
          throw data::InputError("/mesh: no material in the section of joint " +
                                 std::to_string(i + 1) + " for the beam-theory baseline");
        lengths_.push_back(bounds[i + 1] - bounds[i]);
        const double centred = slabs[i].second - slabs[i].first * slabs[i].first / slabs[i].volume;
        second_moments_.push_back(centred / lengths_.back());
      }
  }

  JointStiffness BeamTheoryBaseline::stiffness(double youngs_modulus) const
  {
    std::vector<Eigen::Vector3d> k;
    for (std::size_t i = 0; i < lengths_.size(); ++i)
      {
        const double k_phi = youngs_modulus * second_moments_[i] / lengths_[i];
        k.emplace_back(4.0 * k_phi, k_phi, k_phi);
      }
    return JointStiffness(k);
  }
} // namespace softchain::chain
