// Finite-difference checks of every tangent contribution: material (both
// strain energies), follower pressure and embedded springs (at states with
// slack, knee and taut springs, asserted). The tangent K must equal
// the directional derivative of the residual,
//   K v = (R(u + h v) - R(u - h v)) / (2h) + O(h^2).
#include "fem_test_tools.h"

#include <catch2/catch.hpp>

#include <array>

using namespace dealii;
using namespace softchain;
using namespace softchain::fem;

namespace
{
  // How many springs are slack (eps < -d), at the knee of the tension law
  // (|eps| <= d) and taut (eps > d) at the solver's state, d the smoothing
  // strain; eps = t - d^2 / (4 t) from the tension t = T/EA (the law's
  // t (t - eps) = d^2/4).
  std::array<int, 3> links_per_branch(const QuasiStaticSolver &solver, const double d)
  {
    std::array<int, 3> count{};
    const auto        &links    = solver.spring_network()->all_links();
    const auto         tensions = solver.spring_network()->tensions(solver.displacement());
    for (std::size_t k = 0; k < links.size(); ++k)
      {
        const double t = tensions[k] / links[k].axial_rigidity, eps = t - d * d / (4 * t);
        ++count[eps < -d ? 0 : eps <= d ? 1 : 2];
      }
    return count;
  }

  // Relative error |K v - FD| / |K v| at a random deformed state; with
  // `branches`, the springs per branch of the tension law at that state.
  double tangent_error(test::SolverFixture &f, const LoadState &load,
                       std::array<int, 3> *branches = nullptr)
  {
    QuasiStaticSolver &solver = *f.solver;
    const auto         u      = test::smooth_displacement(solver, 2e-3, 0.05, 1);
    const auto         v      = test::smooth_displacement(solver, 1.0, 1.0, 2);
    solver.set_displacement(u);
    if (branches)
      *branches = links_per_branch(solver, f.prm.springs.smoothing_strain);
    // Central difference of -R with a step h |v| ~ 1e-7 |u|-scale: the
    // truncation error O(h^2) and the round-off O(eps/h) are both ~1e-9
    // relative, well below the 1e-6 bound.
    auto [Kv, fd] = test::tangent_and_difference(solver, load, u, v, 1e-8);
    fd -= Kv;
    return fd.l2_norm() / Kv.l2_norm();
  }

  // With springs, a smoothing strain of 1e-3: the random states' link
  // strains (~1e-3 to 1e-2) then put links in the law's knee (|eps| <= d),
  // which the default's (1e-5) would miss; the code is the same for any d.
  std::string options(const std::string &energy, bool springs)
  {
    return "subsection Materials\n  set Strain energy = " + energy +
           "\nend\nsubsection Springs\n  set Generate for bender = " +
           (springs ? "true\n  set Tension smoothing strain = 1e-3" : "false") + "\nend\n";
  }
} // namespace

TEST_CASE("material tangent matches finite differences", "[fem][tangent]")
{
  for (const std::string energy : {"log", "split"})
    for (const std::string element : {"Q1", "P2"})
      {
        test::SolverFixture f(test::parameters_from_text(
          "tangent_material", test::bender_prm(element, 4, options(energy, false))));
        INFO(energy << " " << element);
        CHECK(tangent_error(f, LoadState()) < 1e-6);
      }
}

TEST_CASE("follower pressure tangent matches finite differences", "[fem][tangent]")
{
  test::SolverFixture f(test::parameters_from_text("tangent_pressure",
                                                   test::bender_prm("Q2", 4, options("log", false))));
  LoadState load;
  load.pressure = 5e4;
  CHECK(tangent_error(f, load) < 1e-6);
}

// The follower pressure alone, on each element shape: its load is exactly
// quadratic in u (the area vector F T1 x F T2 with F T1, F T2 linear in u),
// so the central difference has no truncation error and the two sides agree
// to round-off, whatever the step. With h |v| = 1e-4 m the round-off is
// ~1e-16 |f| / h ~ 1e-13 of |K v| (measured: 5e-15 to 2.4e-14 of |K v|); 1e-9 leaves a
// wide margin and still fails for any wrong term of the load stiffness,
// which the full tangent's check above sees only relative to the (larger)
// material part.
TEST_CASE("the follower pressure's own tangent matches finite differences", "[fem][tangent]")
{
  for (const std::string element : {"Q1", "Q2", "P2"})
    {
      INFO(element);
      test::SolverFixture f(test::parameters_from_text("tangent_pressure_alone",
                                                       test::bender_prm(element, 4, options("log", false))));
      QuasiStaticSolver &solver = *f.solver;
      const auto         u      = test::smooth_displacement(solver, 2e-3, 0.05, 1);
      const auto         v      = test::smooth_displacement(solver, 1.0, 1.0, 2);
      const auto        &space  = solver.space();
      const double       p = 5e4, h = 1e-4;

      TrilinosWrappers::SparseMatrix K;
      K.reinit(solver.tangent());
      TrilinosWrappers::MPI::Vector f_ext(solver.negative_residual()), fd(f_ext), Kv(v);
      auto load_at = [&](const TrilinosWrappers::MPI::Vector &state, TrilinosWrappers::SparseMatrix *matrix) {
        solver.set_displacement(state);
        f_ext = 0;
        if (matrix)
          *matrix = 0;
        solver.pressure_load().assemble(solver.displacement(), p, space.fixed_dofs, matrix, f_ext);
        f_ext.compress(VectorOperation::add);
        if (matrix)
          matrix->compress(VectorOperation::add);
        return f_ext;
      };
      load_at(u, &K);
      K.vmult(Kv, v); // K = -d f_ext / du
      TrilinosWrappers::MPI::Vector plus(u), minus(u);
      plus.add(h, v);
      minus.add(-h, v);
      fd = load_at(plus, nullptr);
      fd -= load_at(minus, nullptr);
      fd *= 1.0 / (2 * h);
      space.fixed_dofs.set_zero(fd);
      space.fixed_dofs.set_zero(Kv);
      fd += Kv;
      INFO("|K v| = " << Kv.l2_norm() << ", |K v + d f_ext/du v| = " << fd.l2_norm());
      CHECK(Kv.l2_norm() > 0);
      CHECK(fd.l2_norm() <= 1e-9 * Kv.l2_norm());
    }
}

TEST_CASE("embedded spring tangent matches finite differences", "[fem][tangent]")
{
  test::SolverFixture f(test::parameters_from_text("tangent_springs",
                                                   test::bender_prm("Q1", 4, options("log", true))));
  std::array<int, 3> branches{};
  CHECK(tangent_error(f, LoadState(), &branches) < 1e-6);
  // The state exercises every part of the tension law: slack, knee and taut
  // links, so that the tangent is checked on each.
  INFO("slack " << branches[0] << ", knee " << branches[1] << ", taut " << branches[2]);
  CHECK(branches[0] > 0);
  CHECK(branches[1] > 0);
  CHECK(branches[2] > 0);
}

TEST_CASE("full tangent (material, pressure, springs) matches finite differences",
          "[fem][tangent]")
{
  for (const std::string element : {"Q2", "P2"})
    {
      test::SolverFixture f(test::parameters_from_text(
        "tangent_all", test::bender_prm(element, 8, options("log", true))));
      LoadState load;
      load.pressure = 2e4;
      INFO(element);
      std::array<int, 3> branches{};
      CHECK(tangent_error(f, load, &branches) < 1e-6);
      INFO("slack " << branches[0] << ", knee " << branches[1] << ", taut " << branches[2]);
      CHECK((branches[0] > 0 && branches[1] > 0 && branches[2] > 0));
    }
}
