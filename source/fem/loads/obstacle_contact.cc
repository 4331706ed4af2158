#include <softchain/data/input_error.h>
#include <softchain/fem/boundary_ids.h>
#include <softchain/fem/obstacle_contact.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace softchain::fem
{
  using namespace dealii;

  namespace
  {
    Eigen::Vector3d eigen(const Point<3> &x) { return {x[0], x[1], x[2]}; }
  } // namespace

  ObstacleContact::ObstacleContact(const FiniteElementSpace &space, const geometry::ContactScene &scene,
                                   const std::vector<double> &youngs_modulus)
    : space(space)
    , scene(scene)
    , node_dofs(node_dof_table(*space.fe))
  {
    if (scene.empty())
      return;
    FEFaceValues<3> fe_face(*space.mapping, *space.fe, space.face_quadrature,
                            update_values | update_JxW_values | update_quadrature_points);
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto face : cell->face_indices())
          if (cell->face(face)->at_boundary() && touches(cell->face(face)->boundary_id()))
            {
              fe_face.reinit(cell, face);
              add_face(fe_face, cell, youngs_modulus.at(cell->material_id()));
            }
    check_surfaces();
    reset();
  }

  // Each named boundary group must have faces in this mesh.
  void ObstacleContact::check_surfaces() const
  {
    for (const auto &s : scene.surfaces)
      {
        unsigned long n = 0;
        for (const auto &face : faces)
          for (const auto f : face.cell->face_indices())
            if (face.cell->face(f)->at_boundary() && in_group(s, face.cell->face(f)->boundary_id()))
              ++n;
        if (Utilities::MPI::sum(n, space.communicator) == 0)
          throw data::InputError(scene.file + ": parameter 'Surfaces' in subsection 'Contact': the mesh "
                                 "has no boundary faces in '" + s + "'");
      }
  }

  // No multipliers; every anchor at its point at rest.
  void ObstacleContact::reset()
  {
    const std::size_t n = points.size() * scene.obstacles.size();
    state.lambda.assign(n, 0.0);
    state.anchor.resize(n);
    for (std::size_t point = 0; point < points.size(); ++point)
      for (std::size_t k = 0; k < scene.obstacles.size(); ++k)
        state.anchor[point * scene.obstacles.size() + k] = eigen(points[point].X);
  }

  bool ObstacleContact::has_friction() const
  {
    return std::any_of(scene.obstacles.begin(), scene.obstacles.end(),
                       [](const geometry::Obstacle &o) { return o.friction() > 0; });
  }

  // "all": every boundary face but the clamped base and the symmetry planes.
  bool ObstacleContact::touches(const types::boundary_id id) const
  {
    return std::any_of(scene.surfaces.begin(), scene.surfaces.end(),
                       [id](const std::string &s) { return in_group(s, id); });
  }

  bool ObstacleContact::in_group(const std::string &group, const types::boundary_id id)
  {
    if (group == "all")
      return id != boundary::base && id != boundary::fixed_x && id != boundary::fixed_y &&
             id != boundary::fixed_z;
    return (group == "tip" && id == boundary::tip) || (group == "outer" && id == boundary::other) ||
           (group == "cavity" && id == boundary::cavity);
  }

  // The face's points and the values of the nodes on it (a node off the
  // face has phi = 0 there, up to round-off: kept where |phi| > 1e-10).
  void ObstacleContact::add_face(const FEFaceValues<3> &fe_face,
                                 const DoFHandler<3>::active_cell_iterator &cell,
                                 const double youngs_modulus)
  {
    const unsigned int n_q = fe_face.n_quadrature_points;
    ContactFace        face{cell, {}, points.size(), values.size()};
    double             area = 0;
    for (unsigned int q = 0; q < n_q; ++q)
      area += fe_face.JxW(q);
    const double h = std::sqrt(area);
    for (unsigned int q = 0; q < n_q; ++q)
      points.push_back({fe_face.quadrature_point(q), fe_face.JxW(q), h,
                        scene.penalty_factor * youngs_modulus / h});
    for (unsigned int a = 0; a < node_dofs.size(); ++a)
      for (unsigned int q = 0; q < n_q; ++q)
        if (std::abs(fe_face.shape_value(node_dofs[a][0], q)) > 1e-10)
          {
            face.nodes.push_back(a);
            break;
          }
    for (unsigned int q = 0; q < n_q; ++q)
      for (const unsigned int a : face.nodes)
        values.push_back(fe_face.shape_value(node_dofs[a][0], q));
    faces.push_back(std::move(face));
  }

  template <typename FaceStart, typename AtPoint>
  void ObstacleContact::for_each_point(const TrilinosWrappers::MPI::Vector &u, FaceStart g, AtPoint f) const
  {
    std::vector<types::global_dof_index> dofs(space.fe->n_dofs_per_cell());
    const unsigned int                   n_q = space.face_quadrature.size();
    for (const ContactFace &face : faces)
      {
        face.cell->get_dof_indices(dofs);
        g(face, dofs);
        const std::size_t n = face.nodes.size();
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const std::size_t point = face.first_point + q;
            Point<3>          x     = points[point].X;
            for (std::size_t b = 0; b < n; ++b)
              for (unsigned int c = 0; c < 3; ++c)
                x[c] += values[face.first_value + q * n + b] * u(dofs[node_dofs[face.nodes[b]][c]]);
            f(face, q, point, x);
          }
      }
  }

  template <typename AtPoint>
  void ObstacleContact::for_each_point(const TrilinosWrappers::MPI::Vector &u, AtPoint at_point) const
  {
    for_each_point(u, [](const ContactFace &, const std::vector<types::global_dof_index> &) {},
                   [&](const ContactFace &, unsigned int, const std::size_t point, const Point<3> &x) {
                     at_point(point, x);
                   });
  }

  // The normal law, then the tangential return mapping (the header's
  // equations).
  ObstacleContact::PointContact ObstacleContact::contact(const std::size_t point, const unsigned int k,
                                                         const Point<3> &x, const double motion) const
  {
    const auto       &o       = scene.obstacles[k];
    const std::size_t index   = point * scene.obstacles.size() + k;
    const double      epsilon = points[point].epsilon;
    PointContact      c;
    const geometry::RigidTransform pose = o.pose(motion);
    c.y          = pose.to_rest(eigen(x));
    c.distance   = o.body->distance(eigen(x), pose);
    c.pressure   = std::max(0.0, state.lambda[index] - epsilon * c.distance.gap);
    c.tangential = Eigen::Vector3d::Zero();
    c.stiffness  = Eigen::Matrix3d::Zero();
    c.unsymmetric_part = Eigen::Matrix3d::Zero();
    c.status     = Status::open;
    if (c.pressure <= 0)
      return c;
    const Eigen::Vector3d &n = c.distance.normal;
    const Eigen::Matrix3d &H = c.distance.hessian;
    c.stiffness              = epsilon * n * n.transpose() - c.pressure * H;
    c.status                 = Status::slip;
    if (o.friction() == 0)
      return c;
    const Eigen::Vector3d z     = pose.rotation() * (c.y - state.anchor[index]);
    const Eigen::Matrix3d P     = Eigen::Matrix3d::Identity() - n * n.transpose();
    const Eigen::Vector3d trial = -epsilon * P * z;
    const Eigen::Matrix3d dtrial =
      -epsilon * (P - n.dot(z) * H - n * (H * z).transpose());
    const double bound = o.friction() * c.pressure, size = trial.norm();
    if (size <= bound)
      {
        c.status     = Status::stick;
        c.tangential = trial;
        c.stiffness -= dtrial;
        c.unsymmetric_part = 0.5 * (c.stiffness - c.stiffness.transpose());
        return c;
      }
    const Eigen::Vector3d tau = trial / size;
    c.tangential              = bound * tau;
    const Eigen::Matrix3d slip_coupling = o.friction() * epsilon * tau * n.transpose();
    c.stiffness -= bound / size * (Eigen::Matrix3d::Identity() - tau * tau.transpose()) * dtrial;
    const Eigen::Matrix3d symmetric = 0.5 * (c.stiffness + c.stiffness.transpose());
    c.stiffness += slip_coupling;
    c.unsymmetric_part = c.stiffness - symmetric;
    return c;
  }

  void ObstacleContact::assemble(const TrilinosWrappers::MPI::Vector &u, const double motion,
                                 const AffineConstraints<double> &constraints,
                                 TrilinosWrappers::SparseMatrix *matrix,
                                 TrilinosWrappers::MPI::Vector  &rhs,
                                 TrilinosWrappers::SparseMatrix *unsymmetric_part) const
  {
    std::vector<types::global_dof_index>        dofs; // the face nodes' DoFs
    FullMatrix<double>                          K, N; // the face's stiffness, its unsymmetric part
    Vector<double>                              f;
    bool                                        touched = false;
    const auto flush = [&]() {
      if (!touched)
        return;
      if (matrix)
        constraints.distribute_local_to_global(K, f, dofs, *matrix, rhs);
      else
        constraints.distribute_local_to_global(f, dofs, rhs);
      if (unsymmetric_part)
        constraints.distribute_local_to_global(N, dofs, *unsymmetric_part);
    };
    const auto face_start = [&](const ContactFace &face, const std::vector<types::global_dof_index> &d) {
      flush();
      touched = false;
      const std::size_t n = 3 * face.nodes.size();
      dofs.resize(n);
      for (std::size_t b = 0; b < face.nodes.size(); ++b)
        for (unsigned int c = 0; c < 3; ++c)
          dofs[3 * b + c] = d[node_dofs[face.nodes[b]][c]];
      f.reinit(n);
      if (matrix)
        K.reinit(n, n);
      if (unsymmetric_part)
        N.reinit(n, n);
    };
    const auto at_point = [&](const ContactFace &face, const unsigned int q, const std::size_t point,
                              const Point<3> &x) {
      const std::size_t n   = face.nodes.size();
      const double     *phi = &values[face.first_value + q * n];
      const double      dA  = points[point].dA;
      for (unsigned int k = 0; k < scene.obstacles.size(); ++k)
        {
          const PointContact c = contact(point, k, x, motion);
          if (c.status == Status::open)
            continue;
          touched                 = true;
          const Eigen::Vector3d t = c.pressure * c.distance.normal + c.tangential;
          const Eigen::Matrix3d &D = c.stiffness;
          for (std::size_t a = 0; a < n; ++a)
            for (unsigned int i = 0; i < 3; ++i)
              {
                f(3 * a + i) += phi[a] * t[i] * dA;
                if (matrix)
                  for (std::size_t b = 0; b < n; ++b)
                    for (unsigned int j = 0; j < 3; ++j)
                      K(3 * a + i, 3 * b + j) += phi[a] * phi[b] * D(i, j) * dA;
                if (unsymmetric_part)
                  for (std::size_t b = 0; b < n; ++b)
                    for (unsigned int j = 0; j < 3; ++j)
                      N(3 * a + i, 3 * b + j) += phi[a] * phi[b] * c.unsymmetric_part(i, j) * dA;
              }
        }
    };
    for_each_point(u, face_start, at_point);
    flush();
  }

  double ObstacleContact::deepest_penetration(const TrilinosWrappers::MPI::Vector &u, const double motion) const
  {
    double deepest = 0;
    for_each_point(u, [&](const std::size_t point, const Point<3> &x) {
      for (unsigned int k = 0; k < scene.obstacles.size(); ++k)
        deepest = std::max(deepest, -contact(point, k, x, motion).distance.gap / points[point].h);
    });
    return Utilities::MPI::max(deepest, space.communicator);
  }

  double ObstacleContact::entry_fraction(const TrilinosWrappers::MPI::Vector &u,
                                         const TrilinosWrappers::MPI::Vector &u_stepped, const double motion,
                                         const double depth) const
  {
    const std::size_t                     n_obstacles = scene.obstacles.size();
    std::vector<geometry::RigidTransform> poses;
    for (const auto &o : scene.obstacles)
      poses.push_back(o.pose(motion));
    // The gaps at u of the points that no obstacle presses there (NaN: pressed).
    std::vector<double> gap_before(points.size() * n_obstacles);
    for_each_point(u, [&](const std::size_t point, const Point<3> &x) {
      for (unsigned int k = 0; k < n_obstacles; ++k)
        {
          const std::size_t i = point * n_obstacles + k;
          const double      g = scene.obstacles[k].body->gap(eigen(x), poses[k]);
          const bool pressed  = state.lambda[i] - points[point].epsilon * g > 0;
          gap_before[i]       = pressed ? std::numeric_limits<double>::quiet_NaN() : g;
        }
    });
    double fraction = 1.0;
    for_each_point(u_stepped, [&](const std::size_t point, const Point<3> &x) {
      const double allowed = -depth * points[point].h;
      for (unsigned int k = 0; k < n_obstacles; ++k)
        {
          const double g0 = gap_before[point * n_obstacles + k];
          if (std::isnan(g0) || g0 <= allowed)
            continue;
          const double g1 = scene.obstacles[k].body->gap(eigen(x), poses[k]);
          if (g1 < allowed)
            fraction = std::min(fraction, (g0 - allowed) / (g0 - g1));
        }
    });
    return Utilities::MPI::min(fraction, space.communicator);
  }

  bool ObstacleContact::augment(const TrilinosWrappers::MPI::Vector &u, const double motion)
  {
    std::vector<double> updated(state.lambda.size());
    double              change = 0; // max |t_N - lambda| / (epsilon h)
    for_each_point(u, [&](const std::size_t point, const Point<3> &x) {
      for (unsigned int k = 0; k < scene.obstacles.size(); ++k)
        {
          const std::size_t i = point * scene.obstacles.size() + k;
          updated[i]          = contact(point, k, x, motion).pressure;
          change = std::max(change, std::abs(updated[i] - state.lambda[i]) / (points[point].epsilon * points[point].h));
        }
    });
    if (Utilities::MPI::max(change, space.communicator) <= scene.penetration_tolerance)
      return false;
    state.lambda = std::move(updated);
    return true;
  }

  void ObstacleContact::commit(const TrilinosWrappers::MPI::Vector &u, const double motion)
  {
    std::vector<Eigen::Vector3d> anchor = state.anchor;
    for_each_point(u, [&](const std::size_t point, const Point<3> &x) {
      for (unsigned int k = 0; k < scene.obstacles.size(); ++k)
        {
          const PointContact c = contact(point, k, x, motion);
          const std::size_t  i = point * scene.obstacles.size() + k;
          if (c.status == Status::open)
            anchor[i] = c.y;
          else if (c.status == Status::slip)
            anchor[i] = c.y + scene.obstacles[k].pose(motion).rotation().transpose() * c.tangential /
                                points[point].epsilon;
        }
    });
    state.anchor = std::move(anchor);
  }

  std::vector<ObstacleContact::Wrench> ObstacleContact::obstacle_wrenches(const TrilinosWrappers::MPI::Vector &u,
                                                                          const double motion) const
  {
    std::vector<Wrench> w(scene.obstacles.size());
    for_each_point(u, [&](const std::size_t point, const Point<3> &x) {
      for (unsigned int k = 0; k < scene.obstacles.size(); ++k)
        {
          const PointContact    c = contact(point, k, x, motion);
          const Eigen::Vector3d t = c.pressure * c.distance.normal + c.tangential;
          Tensor<1, 3>          on_obstacle;
          for (unsigned int i = 0; i < 3; ++i)
            on_obstacle[i] = -t[i] * points[point].dA;
          w[k].force += on_obstacle;
          w[k].moment += cross_product_3d(Tensor<1, 3>(x), on_obstacle);
        }
    });
    for (auto &wrench : w)
      {
        wrench.force  = Utilities::MPI::sum(wrench.force, space.communicator);
        wrench.moment = Utilities::MPI::sum(wrench.moment, space.communicator);
      }
    return w;
  }

  std::vector<ObstacleContact::PointState> ObstacleContact::point_states(const TrilinosWrappers::MPI::Vector &u,
                                                                         const double motion) const
  {
    std::vector<PointState> states;
    for_each_point(u, [&](const std::size_t point, const Point<3> &x) {
      PointState s{points[point].X, x, std::numeric_limits<double>::infinity(), 0.0, Tensor<1, 3>(), Status::open};
      for (unsigned int k = 0; k < scene.obstacles.size(); ++k)
        {
          const PointContact c = contact(point, k, x, motion);
          s.pressure += c.pressure;
          for (unsigned int i = 0; i < 3; ++i)
            s.tangential[i] += c.tangential[i];
          if (c.distance.gap < s.gap)
            {
              s.gap    = c.distance.gap;
              s.status = c.status;
            }
        }
      states.push_back(s);
    });
    return states;
  }

  // An obstacle that already cuts into the body at rest would throw it out
  // with the full penalty force in the first step: refused as input.
  void ObstacleContact::check_rest_state(const std::string &file) const
  {
    std::vector<double> deepest(scene.obstacles.size(), 0.0);
    for (std::size_t point = 0; point < points.size(); ++point)
      for (unsigned int k = 0; k < scene.obstacles.size(); ++k)
        deepest[k] = std::max(deepest[k], -scene.obstacles[k].body->distance(eigen(points[point].X)).gap);
    for (unsigned int k = 0; k < scene.obstacles.size(); ++k)
      {
        const double d = Utilities::MPI::max(deepest[k], space.communicator);
        if (d > 0)
          {
            std::ostringstream why;
            why << file << ": subsection 'Contact/" << scene.obstacles[k].name() << "': the " << scene.obstacles[k].body->shape()
                << " intersects the finger at rest (it reaches " << d
                << " m into the body); place it outside and bring it in with Motion";
            throw data::InputError(why.str());
          }
      }
  }
} // namespace softchain::fem
