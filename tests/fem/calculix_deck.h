#pragma once
// CalculixDeck: the same mesh and load as a CalculiX (ccx) input deck, so
// that an independent code solves SoftChain's problem -- for the
// cross-check tests and the speed benchmark against CalculiX.
//
// Elements: C3D8 (trilinear, full 2x2x2 integration: SoftChain's Q1) or
// C3D20R (serendipity quadratic, reduced 2x2x2 integration: the quadratic
// element CalculiX users pick against SoftChain's Q2). Material: CalculiX's
// NEO HOOKE, W = C10 (I1bar - 3) + (J - 1)^2 / D1 with C10 = mu/2 and
// D1 = 2/kappa, which is SoftChain's `split` energy
// W = mu/2 (I1bar - 3) + kappa/4 (J^2 - 1 - 2 ln J) to O((J - 1)^3).
// Boundary: the `base` face clamped. Loads: a dead tip traction t_y (as
// consistent nodal loads of bilinear faces, C3D8 only) and a follower
// pressure on the `cavity` faces (face loads, follower under NLGEOM).
#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>

#include <map>
#include <string>
#include <vector>

namespace softchain::fem::test
{
  struct CalculixDeck
  {
    enum class Element
    {
      C3D8,
      C3D20R
    };
    struct Load
    {
      double tip_traction_y = 0; // N/m^2, dead
      double pressure       = 0; // Pa, follower, on the cavity
    };

    Element element        = Element::C3D8;
    double  youngs_modulus = 2.6e5;
    double  poissons_ratio = 0.48;
    // Newton tolerances of the step (CalculiX *CONTROLS, FIELD: residual
    // and correction, relative to the average force and increment).
    double  tolerance      = 1e-9;
    // First and largest increment as fractions of the step (CalculiX cuts
    // an increment that fails and grows one after easy increments).
    double  first_increment = 0.1;
    double  max_increment   = 0.25;

    // Writes the deck `file` (e.g. name.inp) for `mesh` under `load`;
    // the displacements of the mesh vertices `printed` go to name.dat.
    void write(const std::string &file, const dealii::Triangulation<3> &mesh, const Load &load,
               const std::vector<unsigned int> &printed) const;
  };

  // Tip-face vertices with their share of the face area (the consistent
  // nodal forces of a uniform traction on bilinear faces are t times these).
  std::map<unsigned int, double> tip_area_shares(const dealii::Triangulation<3> &mesh);

  // Displacements by mesh vertex index from the last block of a CalculiX
  // .dat file (later increments overwrite earlier ones).
  std::map<unsigned int, dealii::Tensor<1, 3>> calculix_displacements(const std::string &dat);
} // namespace softchain::fem::test
