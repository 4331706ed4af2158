#pragma once
// ObstacleContact: contact of the body's boundary with rigid obstacles
// (ContactScene), with Coulomb friction, enforced at the boundary faces'
// quadrature points -- not at nodes, whose Q2/P2 face weights may be
// negative -- by an augmented Lagrangian in the normal direction and a
// penalty-regularised return mapping in the tangential one (Wriggers,
// Computational Contact Mechanics, 2nd ed., 2006, Secs. 5.2 and 6.3).
//
// At a point X of a contact face, deformed to x = X + u(X), an obstacle
// in the pose x = R (y - p) + p + c of its path (Obstacle::pose: turned by R
// about the pivot p, moved by c) has the signed distance g, normal n and
// curvature H (RigidObstacle, in world axes), x being y = R^T (x - p - c) + p
// of its rest frame. Per unit reference area:
//  - normal: t_N = max(0, lambda - epsilon g), lambda the point's
//    multiplier, epsilon = Penalty factor E / h (E the cell's Young's
//    modulus, h the face's size);
//  - tangential: with y_s the point's stick anchor (its history, a point
//    of the obstacle's rest frame, so that it moves with the obstacle) and
//    z = R (y - y_s) (dz/dx = I), the trial traction t* = -epsilon P z,
//    P = I - n n^T. Stick where |t*| <= mu t_N: t_T = t*; slip otherwise:
//    t_T = mu t_N t* / |t*|. A converged state moves the anchor of a
//    slipping point to y + R^T t_T / epsilon, of an open point to y.
// The obstacle pushes the body with t = t_N n + t_T: node a of the face
// receives f_a = int phi_a t dA0, and df_a/du_b = int phi_a phi_b dt/dx dA0
// with
//     d(t_N n)/dx = -epsilon n n^T + t_N H,
//     dt*/dx      = -epsilon (P - (n.z) H - n (H z)^T),
//     dt_T/dx     = dt*/dx (stick),
//                   mu t_N (I - tau tau^T) / |t*| dt*/dx - mu epsilon tau n^T (slip),
// tau = t* / |t*|. Without friction the tangent is symmetric (f derives
// from Pi = int (max(0, lambda - epsilon g)^2 - lambda^2) / (2 epsilon) dA0
// at fixed multipliers) and Newton's energy line search holds; with it, the
// slip branch makes it non-symmetric: its coupling mu epsilon tau n^T of the
// friction force to the normal pressure has no mirror, and on a curved
// obstacle n (H z)^T has none either (small: |z| <= mu t_N / epsilon).
// What is left without them, the symmetric part of dt/dx with the slip
// coupling dropped, is the tangent of a symmetric problem close to this one
// (the friction force taken at a fixed bound); assemble() can hand the
// difference, the friction's unsymmetric part, to a solver that factorises
// the symmetric rest and iterates on the whole (SerialDirectSolver).
//
// With lambda = 0 this is the penalty method, whose penetration -g =
// t_N / epsilon is t_N / (factor E) of h; where a converged state
// penetrates deeper than Penetration tolerance h, Uzawa's update
// lambda <- t_N and a new Newton solve follow (augment()), which drives the
// penetration to zero at a fixed epsilon.
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

    bool has_friction() const;

    // rhs += f (the contact forces on the body), matrix -= df/du (if given),
    // with the obstacles in their pose at path parameter `motion`
    // (Obstacle::pose); and, if
    // given, unsymmetric_part -= the part of df/du that the symmetric
    // approximation leaves out (the header's comment; zero without friction).
    void assemble(const dealii::TrilinosWrappers::MPI::Vector &ghosted_u, double motion,
                  const dealii::AffineConstraints<double> &constraints,
                  dealii::TrilinosWrappers::SparseMatrix  *matrix,
                  dealii::TrilinosWrappers::MPI::Vector   &rhs,
                  dealii::TrilinosWrappers::SparseMatrix  *unsymmetric_part = nullptr) const;

    // The deepest penetration over all contact points, as a fraction of the
    // local face size (0 where nothing penetrates).
    double deepest_penetration(const dealii::TrilinosWrappers::MPI::Vector &ghosted_u, double motion) const;
    // The largest fraction a in (0, 1] of the step from u to u + du for which
    // no contact point that no obstacle presses at u (t_N = 0) enters one
    // deeper than `depth` times its face's size, the gap taken as linear
    // along the step: a_i = (g_0 + depth h) / (g_0 - g_1) where g_1 <
    // -depth h. Such a point has no stiffness in the tangent that made du,
    // so the step may carry it through the obstacle's surface as far as the
    // free body would go; its penalty then pushes back with epsilon g.
    double entry_fraction(const dealii::TrilinosWrappers::MPI::Vector &ghosted_u,
                          const dealii::TrilinosWrappers::MPI::Vector &ghosted_u_stepped, double motion,
                          double depth) const;
    // Uzawa's update lambda <- t_N if it changes some multiplier by more
    // than the penetration tolerance: |t_N - lambda| > Penetration tolerance
    // epsilon h, where a point penetrates deeper than that or a point with
    // lambda > 0 has lifted off; returns whether it did (a new Newton solve
    // is due).
    bool augment(const dealii::TrilinosWrappers::MPI::Vector &ghosted_u, double motion);

    // The history of the contact points: multipliers and stick anchors.
    struct History
    {
      std::vector<double>          lambda; // per point and obstacle
      std::vector<Eigen::Vector3d> anchor; // y_s per point and obstacle
    };
    const History &history() const { return state; }
    // The history of the body at rest.
    void           reset();
    void           restore(const History &saved) { state = saved; }
    // A converged state: the anchors of slipping and open points move.
    void           commit(const dealii::TrilinosWrappers::MPI::Vector &ghosted_u, double motion);

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

    enum class Status
    {
      open,
      stick,
      slip // also every pressed point without friction
    };
    // The contact state at one point of this rank, for output.
    struct PointState
    {
      dealii::Point<3>     reference;
      dealii::Point<3>     deformed;
      double               gap;        // to the closest obstacle, m
      double               pressure;   // t_N per reference area, Pa
      dealii::Tensor<1, 3> tangential; // t_T per reference area, Pa
      Status               status;     // of the closest obstacle
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
      Eigen::Vector3d          y;          // R^T (x - p - c) + p, the point in the obstacle's rest frame
      double                   pressure;   // t_N
      Eigen::Vector3d          tangential; // t_T
      Eigen::Matrix3d          stiffness;  // -dt/dx, t = t_N n + t_T
      // The part of `stiffness` outside its symmetric approximation: the
      // stiffness minus the symmetric part of the stiffness without the slip
      // coupling mu epsilon tau n^T.
      Eigen::Matrix3d          unsymmetric_part;
      Status                   status;
    };

    const FiniteElementSpace               &space;
    const geometry::ContactScene            scene;
    std::vector<std::array<unsigned int, 3>> node_dofs;
    std::vector<ContactFace>                faces;
    std::vector<ReferencePoint>             points;
    std::vector<double>                     values; // phi_a at the points
    History                                 state;

    // Whether a face of boundary id `id` may touch (Surfaces), and whether it
    // belongs to the boundary group `group` ("all": any but base and symmetry).
    bool         touches(dealii::types::boundary_id id) const;
    static bool  in_group(const std::string &group, dealii::types::boundary_id id);
    void         check_surfaces() const;
    void         add_face(const dealii::FEFaceValues<3> &fe_face,
                          const dealii::DoFHandler<3>::active_cell_iterator &cell, double youngs_modulus);
    // Calls face_start(face, dofs) per face and at_point(face, q, point, x)
    // for each of its points with its deformed position x.
    template <typename FaceStart, typename AtPoint>
    void         for_each_point(const dealii::TrilinosWrappers::MPI::Vector &u, FaceStart face_start,
                                AtPoint at_point) const;
    // Calls at_point(point, x) for each contact point of this rank.
    template <typename AtPoint>
    void         for_each_point(const dealii::TrilinosWrappers::MPI::Vector &u, AtPoint at_point) const;
    PointContact contact(std::size_t point, unsigned int obstacle, const dealii::Point<3> &x,
                         double motion) const;
  };
} // namespace softchain::fem
