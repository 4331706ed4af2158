#pragma once
// EmbeddedSpringNetwork: the paper's passive structures (Sec. III-A), 1D
// tension-only springs between nodes embedded in the body. A link of rest
// length L and current length l carries the tension
//     T = EA (l - L) / L  for l > L,   T = 0 otherwise,
// i.e. the strain energy Psi = EA/(2L) (l - L)^2 in tension. (The paper's
// f = -k/L ((l - L)/L) v/|v| is the same law with k = EA L.) For Newton the
// kink at l = L is rounded over a strain band d (Springs/Tension smoothing
// strain): T = EA eps^2 / (2 d) for 0 < eps < d, EA (eps - d/2) above. The
// force T e on node b (-T e on a) and its tangent
//     H = dT/dl e(x)e + T/l (I - e(x)e),   e = (x_b - x_a)/l,
// reach the element DoFs through the embedded nodes' shape functions: with
// delta_i = N_i(node b) - N_i(node a) and c_i the component of DoF i,
//     f_int,i = delta_i T e_{c_i},   K_ij = delta_i H_{c_i c_j} delta_j.
#include <softchain/fem/embedded_points.h>
#include <softchain/fem/spring_polyline.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

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
    // `axial_rigidity`, a node lies outside the body or a link does not lie
    // in one cell.
    EmbeddedSpringNetwork(const FiniteElementSpace            &space,
                          const std::vector<SpringPolyline>   &polylines,
                          const std::map<std::string, double> &axial_rigidity,
                          double                               smoothing_strain);

    bool empty() const { return links.empty(); }

    // The strain band d over which the tension law is rounded: the .prm's,
    // or a wider one while the solver continues in it (QuasiStaticSolver).
    double band() const { return smoothing; }
    void   set_band(double d) { smoothing = d; }

    // Each link lies in one cell (cell_conforming_polylines() splits the
    // polylines at cell faces; the constructor checks it) and is assembled
    // with that cell: cell_matrix += K, cell_rhs -= f_int of the links in the
    // cell with this active_cell_index(), from the cell's DoF values, in the
    // cell's DoF order. Safe to call for different cells in parallel.
    void assemble_cell(unsigned int cell_index, const dealii::Vector<double> &cell_u,
                       dealii::FullMatrix<double> *cell_matrix,
                       dealii::Vector<double>     &cell_rhs) const;

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

    // How a link's vector x_b - x_a depends on the DoFs i of its cell: each
    // DoF carries one displacement component (the elements are primitive),
    // so x_b - x_a = X_b - X_a + sum_i delta_i u_i e_{component_i} with
    // delta_i = N_i(node b) - N_i(node a).
    struct LinkStencil
    {
      std::vector<unsigned int>                    component;
      std::vector<double>                          delta;
      dealii::Tensor<1, 3>                         rest_vector; // X_b - X_a
    };
    LinkStencil link_stencil(const Link &link) const;
    // Adds the link's -f_int and K on its cell's DoFs, given their values.
    void add_link(const Link &link, const LinkStencil &stencil, const dealii::Vector<double> &u,
                  dealii::FullMatrix<double> *matrix, dealii::Vector<double> &rhs) const;

    // Stencils of this rank's links; the links of each cell (by active cell index).
    std::vector<LinkStencil>               owned_stencils;
    std::vector<std::vector<unsigned int>> links_in_cell;
  };
} // namespace softchain::fem
