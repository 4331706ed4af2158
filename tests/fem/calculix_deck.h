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
// Boundary: the `base` face clamped. Loads: a dead tip traction (t_y, t_z)
// as the consistent nodal loads of parallelogram faces (C3D8: A/4 per
// corner; C3D20R: -A/12 per corner and A/3 per mid-side node) and a
// follower pressure on the `cavity` faces (face loads, follower under
// NLGEOM).
// Contact (optional): a rigid plane y = const below the body, as the fixed
// top face of one C3D8 whose nodes are all clamped (the master surface),
// met by the body's faces on the -y side of their cells (the slave
// surface) through CalculiX's penalty contact: the contact pressure is
// p = K * overclosure (PRESSURE-OVERCLOSURE=LINEAR), and with friction the
// shear stress grows as (stick slope) * slip up to mu p.
#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>

#include <map>
#include <optional>
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
      double tip_traction_z = 0; // N/m^2, dead
    };
    struct RigidPlane
    {
      double y       = 0; // m, below the body; its normal is +y
      double penalty = 0; // K, Pa/m: contact pressure per overclosure
      // Node to surface: a spring at each slave node (its share of the
      // slave faces' area); surface to surface: springs at integration
      // points of the slave faces' overlaps with the master face.
      bool   surface_to_surface = false;
      double friction           = 0; // Coulomb's mu; 0: frictionless
      double stick_slope        = 0; // Pa/m: shear stress per slip while sticking
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
    // The rigid plane, if any; the total reaction of its fixed nodes goes
    // to name.dat as the set PLANE (calculix_total_force).
    std::optional<RigidPlane> plane;

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

  // The area-weighted mean displacement of the tip face from a CalculiX
  // .dat that printed the tip's vertices (throws if one is missing).
  dealii::Tensor<1, 3> calculix_mean_tip_displacement(const std::string &dat,
                                                      const dealii::Triangulation<3> &mesh);

  // The last total force printed for the node set `set` (CalculiX spells
  // set names in capitals) in a CalculiX .dat file: the sum of the
  // reaction forces of a set of fixed nodes.
  dealii::Tensor<1, 3> calculix_total_force(const std::string &dat, const std::string &set);
} // namespace softchain::fem::test
