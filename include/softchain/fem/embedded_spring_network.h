#pragma once
// EmbeddedSpringNetwork: the paper's passive structures (Sec. III-A), 1D
// tension-only springs between nodes embedded in the body. A link of rest
// length L, current length l and strain eps = (l - L)/L carries the tension
//     T = EA t(eps),   t(eps) = (eps + sqrt(eps^2 + delta^2)) / 2,
// the tension-only law T = EA max(eps, 0) (the paper's f = -k/L ((l - L)/L)
// v/|v| with k = EA L) with its kink relaxed over a strain delta (Springs/
// Tension smoothing strain; TensionOnlyLaw). The force T e on node b (-T e
// on a) and its tangent
//     H = dT/dl e(x)e + T/l (I - e(x)e),   e = (x_b - x_a)/l,
// reach the element DoFs through the embedded nodes' shape functions: with
// delta_i = N_i(node b) - N_i(node a) and c_i the component of DoF i,
//     f_int,i = delta_i T e_{c_i},   K_ij = delta_i H_{c_i c_j} delta_j.
//
// Newton carries each link's tension t and gap g = t - eps as unknowns of
// their own (a primal-dual method, as interior-point methods treat
// complementarity): the link equations are condensed cell by cell, so the
// global system keeps its size, and after each displacement update every
// link takes its own Newton step in (t, g) inside t, g > 0. A link that is
// taut at an iterate but slack at the solution then sheds its tension at
// once, where Newton on the law t(eps(u)) alone halves its strain per
// iteration (docs/history.md, "Link tensions as Newton unknowns").
//
// Fibre sheets (FibreSheet) enter as fields of infinitesimal links: at each
// point of the sheet's quadrature (sheet_quadrature), a family of unit
// direction a and membrane stiffness k = EA / spacing is a link of rest
// vector a (L = 1) whose current vector is F a, the fibre's stretch, so that
//     delta_i = grad N_i . a,   EA_link = k w_q   (w_q the point's area),
// and the link's energy EA_link L psi(eps) is the sheet's k psi(eps) dA at
// that point. The sheet's links are local to the rank that owns their cell.
#include <softchain/fem/embedded_points.h>
#include <softchain/fem/fibre_sheet.h>
#include <softchain/fem/spring_polyline.h>
#include <softchain/fem/tension_only_law.h>

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
                          const std::vector<FibreSheet>       &sheets,
                          const std::map<std::string, double> &axial_rigidity,
                          double                               smoothing_strain);

    const TensionOnlyLaw &law() const { return tension_law; }
    // The norm of the link forces at rest, where every link carries the
    // relaxed law's EA delta/2: a force scale of a scene with no load.
    double rest_force() const { return rest_force_norm; }

    // Each link lies in one cell (cell_conforming_polylines() splits the
    // polylines at cell faces; the constructor checks it) and is assembled
    // with that cell: cell_matrix += K, cell_rhs -= f_int of the links in the
    // cell with this active_cell_index(), from the cell's DoF values, in the
    // cell's DoF order, with the links' condensed tensions (below). Returns
    // sum |T_eff - T(eps)| |f_int / T| over the cell's links, a bound on how
    // far the assembled residual lies from the law's at these DoF values.
    // Safe to call for different cells in parallel.
    double assemble_cell(unsigned int cell_index, const dealii::Vector<double> &cell_u,
                         dealii::FullMatrix<double> *cell_matrix,
                         dealii::Vector<double>     &cell_rhs) const;

    // The links' own unknowns (this rank's links). set_link_states() puts
    // every link on the law at the displacement `ghosted_u` (the assembled
    // residual is then the law's), except a link at its rest length, which
    // starts on the taut side of the knee (TensionOnlyLaw::rest_start).
    // After a Newton update du of the displacement u (both ghosted),
    // prepare_link_updates() computes each link's Newton step in (t, g) for
    // the linearised strain increment, and move_link_states(a) sets the
    // states to those before it plus a times it (a < 1 when a line search
    // shortens the update).
    void set_link_states(const dealii::TrilinosWrappers::MPI::Vector &ghosted_u);
    void prepare_link_updates(const dealii::TrilinosWrappers::MPI::Vector &ghosted_u,
                              const dealii::TrilinosWrappers::MPI::Vector &ghosted_du);
    void move_link_states(double a);
    const std::vector<TensionOnlyLaw::State> &link_states() const { return link_state; }
    void restore_link_states(const std::vector<TensionOnlyLaw::State> &states) { link_state = states; }

    // Tension of every polyline link on the law (identical on every rank).
    std::vector<double> tensions(const dealii::TrilinosWrappers::MPI::Vector &ghosted_u) const;

    const EmbeddedPoints             &points() const { return *nodes; }
    // A sheet's fibre family at one quadrature point, at the displacement
    // given to sheet_fibres(): deformed place, unit deformed direction
    // F a / |F a| and membrane tension per unit width (EA / spacing) t(eps) [N/m].
    struct SheetFibre
    {
      dealii::Point<3>     place;
      dealii::Tensor<1, 3> direction;
      double               tension_per_width;
      unsigned int         network;
    };
    bool has_sheets() const { return with_sheets; }
    // This rank's sheet fibres.
    std::vector<SheetFibre> sheet_fibres(const dealii::TrilinosWrappers::MPI::Vector &ghosted_u) const;

    // The polylines' links (the sheets' have no nodes).
    const std::vector<Link>          &all_links() const { return links; }
    const std::vector<std::string>   &networks() const { return network_names; }

  private:
    std::unique_ptr<EmbeddedPoints> nodes;
    std::vector<Link>               links; // the polylines' (owned: indices 0 .. links.size())
    std::vector<std::string>        network_names;
    TensionOnlyLaw                  tension_law;
    double                          rest_force_norm = 0;

    // How a link's vector x_b - x_a depends on the DoFs i of its cell: each
    // DoF carries one displacement component (the elements are primitive),
    // so x_b - x_a = X_b - X_a + sum_i delta_i u_i e_{component_i} with
    // delta_i = N_i(node b) - N_i(node a).
    struct LinkStencil
    {
      std::vector<dealii::types::global_dof_index> dof; // the cell's, in its order
      std::vector<unsigned int>                    component;
      std::vector<double>                          delta;
      dealii::Tensor<1, 3>                         rest_vector; // X_b - X_a
      double                                       rest_length;
      double                                       axial_rigidity;
    };
    LinkStencil link_stencil(const Link &link) const;
    unsigned int network_index(const std::string &network) const;
    // Adds the links of a sheet's quadrature points (after the polylines'
    // links, indices links.size() and up).
    void add_sheet(const FiniteElementSpace &space, const FibreSheet &sheet, double axial_rigidity);
    // Where each sheet link's quadrature point lies: reference place and
    // the shape values there (in its stencil's DoF order), for the output.
    struct SheetPlace
    {
      unsigned int        link;
      dealii::Point<3>    reference;
      std::vector<double> value;
      double              area; // the point's weight [m^2]: the family's EA / s = EA_link / area
      unsigned int        network;
    };
    std::vector<SheetPlace> sheet_places;
    bool                    with_sheets = false;
    // x_b - x_a of owned link k, from the DoF values of its cell or of a
    // global ghosted vector (zero: the rest vector).
    dealii::Tensor<1, 3> link_vector(unsigned int k, const dealii::Vector<double> &cell_u) const;
    dealii::Tensor<1, 3> link_vector(unsigned int                                 k,
                                     const dealii::TrilinosWrappers::MPI::Vector &ghosted_u,
                                     bool                                         with_rest) const;
    // Adds link k's -f_int and K on its cell's DoFs, given their values;
    // returns its term of assemble_cell()'s bound.
    double add_link(unsigned int k, const dealii::Vector<double> &u,
                    dealii::FullMatrix<double> *matrix, dealii::Vector<double> &rhs) const;

    // Stencils of this rank's links (a polyline link k at k, the sheets'
    // after them); the links of each cell (by active cell index).
    std::vector<LinkStencil>               owned_stencils;
    std::vector<std::vector<unsigned int>> links_in_cell;
    std::vector<unsigned int>              owned_links;
    // Tension and gap of each owned link (indexed by link), and the state
    // and Newton step that move_link_states() combines.
    std::vector<TensionOnlyLaw::State>     link_state, state_before, state_step;
  };
} // namespace softchain::fem
