#pragma once
// ObstacleContact: frictionless contact of the body's boundary with rigid
// obstacles (ContactScene), enforced at the boundary faces' quadrature
// points -- not at nodes, whose Q2/P2 face weights may be negative -- by an
// augmented Lagrangian (Wriggers, Computational Contact Mechanics, 2nd ed.,
// 2006, Sec. 6.3). At a point X of a contact face, deformed to
// x = X + u(X), each obstacle's signed distance g(x) with normal n and
// curvature H (RigidObstacle) gives the contact pressure per unit
// reference area
//     t_N = max(0, lambda - epsilon g),
// lambda the point's multiplier and epsilon = Penalty factor E / h (E the
// cell's Young's modulus, h the face's size). The obstacle pushes the body
// with t_N n: node a of the face receives
//     f_a = int phi_a t_N n dA0,
// and where t_N > 0 its derivative along the displacement of node b is
//     df_a/du_b = -int phi_a phi_b (epsilon n n^T - t_N H) dA0,
// the second term the turning of the normal on a curved obstacle. For fixed
// multipliers f derives from the potential
//     Pi = int 1/(2 epsilon) (max(0, lambda - epsilon g)^2 - lambda^2) dA0,
// so the tangent is symmetric and Newton's energy line search holds. With
// lambda = 0 this is the penalty method, whose penetration -g = t_N /
// epsilon is t_N / (factor E) of h; where a converged state penetrates
// deeper than Penetration tolerance h, Uzawa's update lambda <- t_N and a
// new Newton solve follow (augment()), which drives the penetration to zero
// at a fixed epsilon.
#include <softchain/fem/finite_element_space.h>

#include <softchain/geometry/contact_scene.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vector>

namespace softchain::fem
{
  class ObstacleContact
  {
  public:
    // `youngs_modulus[id]` is the Young's modulus of material id, for the penalty.
    ObstacleContact(const FiniteElementSpace &space, const geometry::ContactScene &scene,
                    const std::vector<double> &youngs_modulus);

    bool active() const { return !scene.empty(); }

    // rhs += f (the contact forces on the body), matrix -= df/du (if given),
    // with the obstacles moved by `motion` times their Motion.
    void assemble(const dealii::TrilinosWrappers::MPI::Vector &ghosted_u, double motion,
                  const dealii::AffineConstraints<double> &constraints,
                  dealii::TrilinosWrappers::SparseMatrix  *matrix,
                  dealii::TrilinosWrappers::MPI::Vector   &rhs) const;

    // The deepest penetration over all contact points, as a fraction of the
    // local face size (0 where nothing penetrates).
    double deepest_penetration(const dealii::TrilinosWrappers::MPI::Vector &ghosted_u, double motion) const;
    // Uzawa's update lambda <- t_N if the deepest penetration exceeds the
    // tolerance; returns whether it did (a new Newton solve is due).
    bool augment(const dealii::TrilinosWrappers::MPI::Vector &ghosted_u, double motion);
    // Back to the penalty method (all multipliers zero).
    void reset_multipliers();
    const std::vector<double> &multipliers() const { return lambda; }
    void restore_multipliers(const std::vector<double> &saved) { lambda = saved; }

    // The force and the moment about the origin that each obstacle receives
    // from the body (the negative of what it exerts), on every rank.
    struct Wrench
    {
      dealii::Tensor<1, 3> force, moment;
    };
    std::vector<Wrench> obstacle_wrenches(const dealii::TrilinosWrappers::MPI::Vector &ghosted_u,
                                          double motion) const;

    // Throws InputError naming `file` and the obstacle if it penetrates the
    // body at rest.
    void check_rest_state(const std::string &file) const;

    // The contact state at one point, for output.
    struct PointState
    {
      dealii::Point<3> reference;
      double           gap;      // of the closest obstacle, m
      double           pressure; // t_N per reference area, Pa
      unsigned int     obstacle; // index of the closest obstacle
    };
    std::vector<PointState> point_states(const dealii::TrilinosWrappers::MPI::Vector &ghosted_u,
                                         double motion) const;

  private:
    // A contact quadrature point in the reference configuration.
    struct ReferencePoint
    {
      dealii::Point<3> X;
      double           dA;      // area weight (JxW)
      double           h;       // the face's size, sqrt(area)
      double           epsilon; // penalty per unit reference area, Pa/m
    };
    // A contact face of a locally owned cell: the nodes on it, its points
    // from `first_point` on and their shape values from `first_value` on
    // (point-major).
    struct ContactFace
    {
      dealii::DoFHandler<3>::active_cell_iterator cell;
      std::vector<unsigned int>                   nodes;
      std::size_t                                 first_point;
      std::size_t                                 first_value;
    };
    // One obstacle's action at one point.
    struct PointContact
    {
      geometry::SignedDistance distance;
      double                   pressure; // t_N
    };

    const FiniteElementSpace               &space;
    const geometry::ContactScene            scene;
    std::vector<std::array<unsigned int, 3>> node_dofs;
    std::vector<ContactFace>                faces;
    std::vector<ReferencePoint>             points;
    std::vector<double>                     values; // phi_a at the points
    std::vector<double>                     lambda; // per point and obstacle

    bool         touches(dealii::types::boundary_id id) const;
    void         add_face(const dealii::FEFaceValues<3> &fe_face,
                          const dealii::DoFHandler<3>::active_cell_iterator &cell, double youngs_modulus);
    // Calls f(face, q, point index, x) for each contact point with its
    // deformed position x, and (per face) before it g(face, dofs).
    template <typename FaceStart, typename AtPoint>
    void         for_each_point(const dealii::TrilinosWrappers::MPI::Vector &u, FaceStart g, AtPoint f) const;
    PointContact contact(std::size_t point, unsigned int obstacle, const dealii::Point<3> &x,
                         double motion) const;
  };
} // namespace softchain::fem
