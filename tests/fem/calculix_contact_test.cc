// Cross-check of contact with an independent FEM code: CalculiX (ccx 2.20,
// Debian calculix-ccx) and SoftChain bend the cantilever of
// calculix_cross_check_test.cc -- a 100 x 10 x 10 mm neo-Hookean block,
// E = 2.6e5 Pa, nu = 0.48, clamped at x = 0, trilinear hexahedra (Q1 /
// C3D8) -- by a dead tip load F = 20 mN along -y onto a rigid frictionless
// plane g = 5 mm below its bottom face. It lands on its tip's bottom edge,
// and the statically indeterminate beam shares F between the plane and the
// clamp, F = R + R_clamp, as its compliance says (Euler-Bernoulli, support
// at x = a held at -g: R(a) = F (3L - a) / (2a) - 3 EI g / a^3), not as
// equilibrium alone does. Compared: R, the force the plane receives
// (SoftChain: ObstacleContact's obstacle wrench; CalculiX: minus the sum of
// the plane's fixed-node reactions), and the mean tip displacement u_y.
//
// The solids are the same (same mesh and elements, energies equal to
// O((J - 1)^3): the free cantilever agrees to 4e-5); the contacts are not:
//  - SoftChain (defaults): an augmented Lagrangian at the Gauss points of
//    the bottom faces, t_N = max(0, lambda - epsilon g), epsilon =
//    10 E / h_face, Uzawa until no point penetrates deeper than 1 % of h_face;
//  - CalculiX: node-to-surface penalty springs at the bottom nodes against
//    the top face of one fixed C3D8, p = K overclosure, K = 10 E / h_face
//    (5.2e8 Pa/m at dx = 5 mm, 1.04e9 at 2.5 mm), no augmentation: the edge
//    nodes (b dx / 4 of area) penetrate R / (K b dx / 4) = 2.4 and 2.5 um,
//    5e-4 of g.
// The edge carries the whole force. CalculiX presses it at its nodes;
// SoftChain's last pressed Gauss points sit d = (1 - 1/sqrt 3)/2 dx =
// 0.21 dx inward, at the plane, so that
//  - its support is nearer the load: dR/da = -3 (F - 2 R_clamp) / (2L)
//    gives dR / R = 3 d (F - 2 R_clamp) / (2 L R) = +1.10 % at dx = 5 mm
//    and +0.61 % at 2.5 mm; measured +1.14 % and +0.64 %;
//  - the edge beyond them dips theta d below the plane (theta = 0.075, the
//    tip's rotation): a deeper tip by 84 and 39 um, +1.67 % and +0.77 % of
//    u_y (u_y = -5.1 mm).
// The penalties are not the difference: ten times stiffer (both codes) or
// Uzawa to 1e-4 h moved the force by under 1e-4, and CalculiX's
// surface-to-surface contact (springs at integration points of the faces)
// moved it by under 0.1 %, u_y by under 0.35 % (measured at F = 10 mN). The bounds
// (0.35 dx / L on the force, 0.45 dx / L on u_y) are the measured ones with
// a third of margin, O(dx) as the offset d; the signs are asserted too. At
// F = 10 mN (nearly 2 R_clamp) the force is insensitive to d (measured
// +0.10 %), at 5 mN the beam barely lands (R ~ 0.2 mN): neither tests the
// contact's placement as well. Run time: ~3 s (Release), mostly CalculiX.
#include "calculix_deck.h"
#include "fem_test_tools.h"

#include <softchain/fem/boundary_average.h>
#include <softchain/fem/boundary_ids.h>

#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

using namespace dealii;
using namespace softchain;
using namespace softchain::fem;

// Its own namespace, so that the unity batch that compiles this file with
// others holds each file's constants once.
namespace calculix_contact_test
{

  namespace
  {
    constexpr double L = 0.1, h = 0.01, E = 2.6e5, nu = 0.48;
    constexpr double gap = 0.005, tip_load = 0.02; // m, N
    constexpr double penalty_factor = 10;         // SoftChain's default

    // The force the plane receives and the mean tip displacement.
    struct Landing
    {
      Tensor<1, 3> force, tip;
      double       seconds;
    };

    double seconds_since(const std::chrono::steady_clock::time_point t)
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    }

    Landing calculix_landing(const std::string &name, const Triangulation<3> &mesh,
                             const test::CalculixDeck::RigidPlane &plane)
    {
      const auto         start = std::chrono::steady_clock::now();
      test::CalculixDeck deck;
      deck.youngs_modulus = E;
      deck.poissons_ratio = nu;
      deck.plane          = plane;
      std::vector<unsigned int> tip;
      for (const auto &[v, a] : test::tip_area_shares(mesh))
        tip.push_back(v);
      deck.write(name + ".inp", mesh, {-tip_load / (h * h), 0}, tip);
      REQUIRE(std::system(("ccx -i " + name + " > " + name + ".log 2>&1").c_str()) == 0);
      const auto reaction = test::calculix_total_force(name + ".dat", "PLANE");
      return {-reaction, test::calculix_mean_tip_displacement(name + ".dat", mesh), seconds_since(start)};
    }

    Landing softchain_landing(const std::string &name, const Triangulation<3> &mesh)
    {
      const auto         start = std::chrono::steady_clock::now();
      std::ostringstream contact;
      contact << "subsection Contact\n  set Penalty factor = " << penalty_factor
              << "\n  subsection table\n    set Shape = plane\n"
              << "    set Position = 0, " << -gap << ", 0\n    set Normal = 0, 1, 0\n  end\nend\n";
      test::MeshSolverFixture f(test::parameters_from_text(name, test::solid_prm("Q1", "split", E, nu, contact.str())),
                                mesh);
      LoadState load;
      load.tip_traction[1] = -tip_load / (h * h);
      REQUIRE(f.solver->solve(load).converged);
      const auto &u = f.solver->displacement();
      return {f.solver->obstacle_contact()->obstacle_wrenches(u, 0.0)[0].force,
              mean_boundary_displacement(f.solver->space(), u, boundary::tip), seconds_since(start)};
    }

    struct Agreement
    {
      double force, tip; // relative differences of F_y and of the tip's u_y
    };

    // Both codes on the block of `cells`, SoftChain with its default
    // contact settings, CalculiX's node-to-surface springs as stiff.
    Agreement compare(const std::string &name, const std::vector<unsigned int> &cells)
    {
      Triangulation<3> mesh;
      test::cantilever_block(mesh, cells, L, h);
      test::CalculixDeck::RigidPlane plane;
      plane.y       = -gap;
      plane.penalty = penalty_factor * E / std::sqrt(L / cells[0] * h / cells[2]);
      const Landing   ccx  = calculix_landing(name + "_ccx", mesh, plane);
      const Landing   ours = softchain_landing(name, mesh);
      const Agreement a{ours.force[1] / ccx.force[1] - 1, ours.tip[1] / ccx.tip[1] - 1};
      WARN(name << ": plane force F_y SoftChain " << ours.force[1] << " N, CalculiX " << ccx.force[1]
                << " N, relative difference " << a.force << "; tip u_y SoftChain " << ours.tip[1]
                << " m, CalculiX " << ccx.tip[1] << " m, relative difference " << a.tip
                << "; CalculiX K = " << plane.penalty << " Pa/m; wall time SoftChain " << ours.seconds
                << " s, CalculiX " << ccx.seconds << " s");
      return a;
    }
  } // namespace

  TEST_CASE("a cantilever landing on a rigid plane agrees with CalculiX", "[fem][calculix][contact]")
  {
    if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
      return;
    REQUIRE(std::system("command -v ccx > /dev/null 2>&1") == 0); // scripts/setup installs calculix-ccx
    for (const auto &cells : {std::vector<unsigned int>{20, 2, 2}, {40, 4, 4}})
      {
        const double    dx = L / cells[0];
        const Agreement a  = compare("landing_" + std::to_string(cells[0]), cells);
        // SoftChain's edge sinks below the plane and its contact sits inward
        // of CalculiX's: a deeper tip, a larger force (header).
        CHECK(a.tip > 0);
        CHECK(a.force > 0);
        // Both differences O(dx), the Gauss points' offset: measured 0.33 and
        // 0.31 dx / L (tip), 0.23 and 0.26 dx / L (force).
        CHECK(a.tip < 0.45 * dx / L);
        CHECK(a.force < 0.35 * dx / L);
      }
  }
} // namespace calculix_contact_test
