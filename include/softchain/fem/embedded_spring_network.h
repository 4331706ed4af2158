#pragma once
// EmbeddedSpringNetwork: the paper's passive structures (Sec. III-A), 1D
// tension-only springs between nodes embedded in the body. A link of rest
// length L and current length l carries the tension
//     T = EA (l - L) / L  for l > L,   T = 0 otherwise,
// i.e. the strain energy Psi = EA/(2L) (l - L)^2 in tension. (The paper's
// f = -k/L ((l - L)/L) v/|v| is the same law with k = EA L.) Its force and
// its tangent
//     H = EA/L e(x)e + T/l (I - e(x)e),   e = (x_b - x_a)/l,
// reach the element DoFs through the embedded nodes' shape functions.
#include <softchain/fem/embedded_points.h>
#include <softchain/fem/spring_polyline.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <map>
#include <memory>

namespace softchain::fem
{
  class EmbeddedSpringNetwork
  {
  public:
    struct Link
    {
      unsigned int a, b;          // embedded node indices
      double       rest_length;   // L
      double       axial_rigidity; // EA [N]
      unsigned int network;       // index into network_names
    };

    // Throws data::InputError if a network has no rigidity in
    // `axial_rigidity` or a node lies outside the body.
    EmbeddedSpringNetwork(const FiniteElementSpace            &space,
                          const std::vector<SpringPolyline>   &polylines,
                          const std::map<std::string, double> &axial_rigidity,
                          double                               smoothing_strain);

    bool empty() const { return links.empty(); }

    // DoF couplings of this rank's links (condensed by `constraints`, as
    // DoFTools::make_sparsity_pattern does), and the DoFs they write to.
    void     add_couplings(const dealii::AffineConstraints<double> &constraints,
                           dealii::DynamicSparsityPattern          &pattern) const;
    dealii::IndexSet touched_dofs(dealii::types::global_dof_index n_dofs) const;

    // rhs -= f_int, matrix += K (if given) for this rank's links.
    void assemble(const dealii::TrilinosWrappers::MPI::Vector &ghosted_u,
                  const dealii::AffineConstraints<double>     &constraints,
                  dealii::TrilinosWrappers::SparseMatrix      *matrix,
                  dealii::TrilinosWrappers::MPI::Vector       &rhs) const;

    // Tension of every link (identical on every rank).
    std::vector<double> tensions(const dealii::TrilinosWrappers::MPI::Vector &ghosted_u) const;

    const EmbeddedPoints             &points() const { return *nodes; }
    const std::vector<Link>          &all_links() const { return links; }
    const std::vector<std::string>   &networks() const { return network_names; }

  private:
    std::unique_ptr<EmbeddedPoints> nodes;
    std::vector<Link>               links;
    std::vector<std::string>        network_names;
    double                          smoothing; // d

    // Union of both nodes' stencil DoFs of a link, and for each the weights
    // that map it to the six coordinates (x_a, x_b).
    struct LinkStencil
    {
      std::vector<dealii::types::global_dof_index> dofs;
      std::vector<std::vector<std::pair<unsigned int, double>>> to_coordinate;
    };
    LinkStencil link_stencil(const Link &link) const;
    // link_stencil() of each link this rank assembles (empty for the others).
    std::vector<LinkStencil> owned_stencils;
  };
} // namespace softchain::fem
