#include <softchain/fem/boundary_ids.h>
#include <softchain/fem/follower_pressure.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>

namespace softchain::fem
{
  using namespace dealii;

  namespace
  {
    // Orthonormal tangents of the unit normal N with T1 x T2 = N: the
    // coordinate axis least aligned with N, N's part removed, and N x T1.
    std::pair<Tensor<1, 3>, Tensor<1, 3>> tangents_of(const Tensor<1, 3> &N)
    {
      unsigned int k = 0;
      for (unsigned int i = 1; i < 3; ++i)
        if (std::abs(N[i]) < std::abs(N[k]))
          k = i;
      Tensor<1, 3> T1;
      T1[k] = 1;
      T1 -= (T1 * N) * N;
      T1 /= T1.norm();
      return {T1, cross_product_3d(N, T1)};
    }
  } // namespace

  FollowerPressure::FollowerPressure(const FiniteElementSpace &space)
    : space(space)
    , points_per_face(space.face_quadrature.size())
    , node_dofs(node_dof_table(*space.fe))
  {
    FEFaceValues<3> fe_face(*space.mapping, *space.fe, space.face_quadrature,
                            update_values | update_gradients | update_normal_vectors |
                              update_JxW_values | update_quadrature_points);
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto face : cell->face_indices())
          if (cell->face(face)->at_boundary() && cell->face(face)->boundary_id() == boundary::cavity)
            {
              fe_face.reinit(cell, face);
              add_face(fe_face, cell);
            }
    n_faces = Utilities::MPI::sum(static_cast<unsigned long>(faces.size()), space.communicator);
  }

  // The face's reference points and the terms of the nodes on it. A node off
  // the face has phi = 0 there and Grad phi along N, so all three of its
  // terms are round-off: a node is kept where one of them exceeds 1e-10 of
  // its scale (phi ~ 1, its tangential derivatives ~ 1/h, h the face's size).
  void FollowerPressure::add_face(const FEFaceValues<3> &fe_face, const DoFHandler<3>::active_cell_iterator &cell)
  {
    const unsigned int n_q = fe_face.n_quadrature_points;
    CavityFace         face{cell, {}, points.size(), terms.size()};
    double             area = 0;
    for (unsigned int q = 0; q < n_q; ++q)
      {
        const auto [T1, T2] = tangents_of(fe_face.normal_vector(q));
        points.push_back({T1, T2, fe_face.quadrature_point(q), fe_face.JxW(q)});
        area += fe_face.JxW(q);
      }
    const double                        h = std::sqrt(area);
    std::vector<std::vector<NodeTerms>> per_node(node_dofs.size(), std::vector<NodeTerms>(n_q));
    for (unsigned int a = 0; a < node_dofs.size(); ++a)
      {
        double largest = 0;
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const ReferencePoint &x    = points[face.first_point + q];
            const double          phi  = fe_face.shape_value(node_dofs[a][0], q);
            const Tensor<1, 3>    grad = fe_face.shape_grad(node_dofs[a][0], q);
            per_node[a][q]             = {phi, grad * x.T1, grad * x.T2};
            largest = std::max({largest, std::abs(phi), h * std::abs(grad * x.T1), h * std::abs(grad * x.T2)});
          }
        if (largest > 1e-10)
          face.nodes.push_back(a);
      }
    for (unsigned int q = 0; q < n_q; ++q)
      for (const unsigned int a : face.nodes)
        terms.push_back(per_node[a][q]);
    faces.push_back(std::move(face));
  }

  template <typename Function>
  void FollowerPressure::for_each_face(const TrilinosWrappers::MPI::Vector &u, Function f) const
  {
    std::vector<types::global_dof_index> dofs(space.fe->n_dofs_per_cell());
    std::vector<Tensor<1, 3>>            u_nodes;
    for (const CavityFace &face : faces)
      {
        face.cell->get_dof_indices(dofs);
        u_nodes.resize(face.nodes.size());
        for (unsigned int b = 0; b < face.nodes.size(); ++b)
          for (unsigned int c = 0; c < 3; ++c)
            u_nodes[b][c] = u(dofs[node_dofs[face.nodes[b]][c]]);
        f(face, dofs, u_nodes);
      }
  }

  // F Tk = Tk + sum_b u_b (Grad phi_b . Tk) at the face's point q.
  FollowerPressure::SurfacePoint FollowerPressure::at(const CavityFace &face, const unsigned int q,
                                                      const std::vector<Tensor<1, 3>> &u_nodes) const
  {
    const ReferencePoint &reference = points[face.first_point + q];
    const NodeTerms      *nodes     = &terms[face.first_term + q * u_nodes.size()];
    DeformedTangents      t{reference.T1, reference.T2};
    for (unsigned int b = 0; b < u_nodes.size(); ++b)
      {
        t.FT1 += nodes[b].d1 * u_nodes[b];
        t.FT2 += nodes[b].d2 * u_nodes[b];
      }
    return {reference, nodes, t};
  }

  void FollowerPressure::assemble(const TrilinosWrappers::MPI::Vector &u,
                                  const double                         p,
                                  const AffineConstraints<double>     &constraints,
                                  TrilinosWrappers::SparseMatrix      *matrix,
                                  TrilinosWrappers::MPI::Vector       &rhs,
                                  const CellMatrixScatter             *places) const
  {
    std::vector<types::global_dof_index> face_dofs;
    std::vector<unsigned int>            local; // the face's DoFs among its cell's
    std::vector<Tensor<1, 3>>            v(node_dofs.size());
    FullMatrix<double>                   face_matrix;
    Vector<double>                       face_rhs;
    for_each_face(u, [&](const CavityFace &face, const auto &dofs, const auto &u_nodes) {
      const unsigned int n = face.nodes.size();
      if (matrix)
        face_matrix.reinit(3 * n, 3 * n);
      face_rhs.reinit(3 * n);
      for (unsigned int q = 0; q < points_per_face; ++q)
        {
          const SurfacePoint  x    = at(face, q, u_nodes);
          const double        dA   = x.reference.dA;
          const Tensor<1, 3>  area = x.deformed.area();
          for (unsigned int b = 0; b < n && matrix; ++b)
            v[b] = dA * (x.nodes[b].d1 * x.deformed.FT2 - x.nodes[b].d2 * x.deformed.FT1);
          for (unsigned int a = 0; a < n; ++a)
            {
              const double w = p * x.nodes[a].phi;
              for (unsigned int c = 0; c < 3; ++c)
                face_rhs(3 * a + c) -= w * dA * area[c];
              for (unsigned int b = 0; b < n && matrix; ++b) // K_ac,bd += p phi_a (e_d x v_b)_c
                {
                  face_matrix(3 * a + 0, 3 * b + 1) += w * v[b][2];
                  face_matrix(3 * a + 0, 3 * b + 2) -= w * v[b][1];
                  face_matrix(3 * a + 1, 3 * b + 0) -= w * v[b][2];
                  face_matrix(3 * a + 1, 3 * b + 2) += w * v[b][0];
                  face_matrix(3 * a + 2, 3 * b + 0) += w * v[b][1];
                  face_matrix(3 * a + 2, 3 * b + 1) -= w * v[b][0];
                }
            }
        }
      local.resize(3 * n);
      face_dofs.resize(3 * n);
      for (unsigned int b = 0; b < n; ++b)
        for (unsigned int c = 0; c < 3; ++c)
          {
            local[3 * b + c]     = node_dofs[face.nodes[b]][c];
            face_dofs[3 * b + c] = dofs[local[3 * b + c]];
          }
      if (places)
        places->add(face.cell->active_cell_index(), dofs, local, matrix ? &face_matrix : nullptr,
                    face_rhs, matrix, rhs);
      else if (matrix)
        constraints.distribute_local_to_global(face_matrix, face_rhs, face_dofs, *matrix, rhs);
      else
        constraints.distribute_local_to_global(face_rhs, face_dofs, rhs);
    });
  }

  Tensor<1, 3> FollowerPressure::resultant(const TrilinosWrappers::MPI::Vector &u, const double p) const
  {
    Tensor<1, 3> force;
    for_each_face(u, [&](const CavityFace &face, const auto &, const auto &u_nodes) {
      for (unsigned int q = 0; q < points_per_face; ++q)
        {
          const SurfacePoint x = at(face, q, u_nodes);
          force -= p * x.reference.dA * x.deformed.area();
        }
    });
    return Utilities::MPI::sum(force, space.communicator);
  }

  double FollowerPressure::cavity_volume(const TrilinosWrappers::MPI::Vector &u) const
  {
    double volume = 0;
    for_each_face(u, [&](const CavityFace &face, const auto &, const auto &u_nodes) {
      for (unsigned int q = 0; q < points_per_face; ++q)
        {
          const SurfacePoint x = at(face, q, u_nodes);
          Tensor<1, 3>       position = x.reference.X;
          for (unsigned int b = 0; b < u_nodes.size(); ++b)
            position += x.nodes[b].phi * u_nodes[b];
          volume -= (position * x.deformed.area()) * x.reference.dA / 3.0;
        }
    });
    return Utilities::MPI::sum(volume, space.communicator);
  }
} // namespace softchain::fem
