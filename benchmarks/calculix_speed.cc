// SoftChain against CalculiX (ccx) on the same mesh and load, one thread
// each: the built-in hollow bender without springs (CalculiX has no
// embedded tension-only springs), the `split` neo-Hookean energy (CalculiX's
// NEO HOOKE to O((J - 1)^3)), the cavity under a follower pressure given in
// one load step (each code cuts it if Newton fails). Element pairs: Q1
// against C3D8 (both 2x2x2 Gauss points) and Q2 against C3D20R (27-node
// Lagrange, 3x3x3 points, against 20-node serendipity, 2x2x2 points: the
// quadratic element a CalculiX user picks). Both solve to a relative
// residual of 1e-6. Per pair: the median wall time of RUNS solves of each
// code (interleaved; SoftChain's time includes its mesh and setup, ccx's
// its input), Newton iterations, the displacement of the outer tip corner
// in both codes, and the ratio of the times.
//
// Run: calculix_speed [CELLS along the length = 16] [PRESSURE Pa = 5000] [RUNS = 3]
//                     [ELEMENTS = Q1,Q2: SoftChain's elements of the pairs to run]
// Both codes write their files (.prm, the ccx deck and its output) into a
// scratch directory, $TMPDIR/softchain_calculix_speed.
#include <calculix_deck.h>
#include <fem_test_tools.h>

#include <softchain/data/statistics.h>
#include <softchain/fem/blas_kernel.h>
#include <softchain/fem/lone_process_mpi.h>
#include <softchain/fem/boundary_ids.h>

#include <deal.II/base/multithread_info.h>
#include <deal.II/base/mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace dealii;
using namespace softchain::fem;
using softchain::data::median;

namespace
{
  struct Run
  {
    double       seconds;
    unsigned int newton_iterations;
    double       corner_u; // |u| at the outer tip corner [m]
    unsigned int dofs;
  };

  double seconds_since(const std::chrono::steady_clock::time_point t)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  }

  std::string bender_prm(const std::string &element, const unsigned int cells)
  {
    return test::bender_prm(element, cells,
                            "subsection Springs\n  set Generate for bender = false\nend\n"
                            "subsection Materials\n  set Strain energy = split\nend\n"
                            "subsection Solver\n  set Initial load step = 1\nend\n");
  }

  // The tip-face vertex farthest from the finger's axis: a corner of the box.
  unsigned int outer_tip_corner(const Triangulation<3> &mesh)
  {
    unsigned int best = 0;
    double       far  = -1;
    for (const auto &[v, share] : test::tip_area_shares(mesh))
      if (const Point<3> &x = mesh.get_vertices()[v]; x[1] + x[2] > far)
        {
          far  = x[1] + x[2];
          best = v;
        }
    return best;
  }

  Run softchain_run(const std::string &element, const unsigned int cells, const double pressure)
  {
    const auto         start = std::chrono::steady_clock::now();
    test::SolverFixture f(test::parameters_from_text("calculix_speed_" + element, bender_prm(element, cells)));
    LoadState           load;
    load.pressure     = pressure;
    const auto result = f.solver->solve(load);
    const double seconds = seconds_since(start);
    if (!result.converged)
      {
        std::fprintf(stderr, "SoftChain %s did not converge: %s\n", element.c_str(), result.reason.c_str());
        std::exit(2);
      }
    const Point<3> corner = f.mesh.triangulation.get_vertices()[outer_tip_corner(f.mesh.triangulation)];
    return {seconds, result.newton_iterations, test::displacement_at(*f.solver, corner).norm(),
            f.solver->space().dof_handler.n_dofs()};
  }

  // Newton iterations of a ccx run: the ITRS column of its .sta file.
  unsigned int calculix_iterations(const std::string &sta)
  {
    std::ifstream in(sta);
    std::string   line;
    unsigned int  total = 0;
    while (std::getline(in, line))
      {
        std::istringstream words(line);
        unsigned int       step, increment, iterations;
        std::string        attempt; // e.g. "1U": an attempt that failed and was cut
        if (words >> step >> increment >> attempt >> iterations)
          total += iterations;
      }
    return total;
  }

  Run calculix_run(const test::CalculixDeck::Element element, const unsigned int cells,
                   const double pressure)
  {
    const std::string name  = element == test::CalculixDeck::Element::C3D8 ? "ccx_c3d8" : "ccx_c3d20r";
    // The same mesh as SoftChain's (FingerMesh of the same .prm), built
    // before the clock starts: CalculiX's time is its deck and its solve.
    FingerMesh mesh;
    FingerMesh::build(test::parameters_from_text(name, bender_prm("Q1", cells)), mesh);
    const unsigned int corner = outer_tip_corner(mesh.triangulation);
    const auto         start  = std::chrono::steady_clock::now();
    test::CalculixDeck deck;
    deck.element         = element;
    deck.tolerance       = 1e-6;
    deck.first_increment = 1.0;
    deck.max_increment   = 1.0;
    deck.write(name + ".inp", mesh.triangulation, {0, pressure}, {corner});
    const std::string command = "OMP_NUM_THREADS=1 CCX_NPROC_STIFFNESS=1 CCX_NPROC_EQUATION_SOLVER=1 "
                                "ccx -i " + name + " > " + name + ".log 2>&1";
    if (std::system(command.c_str()) != 0)
      {
        std::fprintf(stderr, "ccx failed: see %s.log\n", name.c_str());
        std::exit(2);
      }
    const double seconds = seconds_since(start);
    const auto   u       = test::calculix_displacements(name + ".dat");
    if (u.count(corner) == 0)
      {
        std::fprintf(stderr, "%s.dat has no displacement of node %u\n", name.c_str(), corner + 1);
        std::exit(2);
      }
    return {seconds, calculix_iterations(name + ".sta"), u.at(corner).norm(), 0};
  }
} // namespace

int main(int argc, char **argv)
{
  // Both codes get the CPU's BLAS kernel: the variable passes to ccx.
  use_the_cpus_blas_kernel(argv);
  use_no_network_transport_when_alone();
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MultithreadInfo::set_thread_limit(1);
  const unsigned int cells    = argc > 1 ? std::atoi(argv[1]) : 16;
  const double       pressure = argc > 2 ? std::atof(argv[2]) : 5e3;
  const unsigned int runs     = argc > 3 ? std::atoi(argv[3]) : 3;
  const std::string  elements = argc > 4 ? argv[4] : "Q1,Q2";
  if (std::system("command -v ccx > /dev/null 2>&1") != 0)
    {
      std::fprintf(stderr, "ccx not found (scripts/setup installs calculix-ccx)\n");
      return 2;
    }
  const auto scratch = std::filesystem::temp_directory_path() / "softchain_calculix_speed";
  std::filesystem::create_directories(scratch);
  std::filesystem::current_path(scratch);
  std::printf("hollow bender, %u cells along the length, %.0f Pa in one step, %u runs each, 1 thread\n",
              cells, pressure, runs);
  std::printf("%-16s %7s %10s %10s %8s %8s %14s %14s %9s\n", "pair", "DoFs", "softchain", "ccx",
              "its sc", "its ccx", "|u| corner sc", "|u| corner ccx", "ccx/sc");
  const std::pair<std::string, test::CalculixDeck::Element> pairs[] = {
    {"Q1", test::CalculixDeck::Element::C3D8}, {"Q2", test::CalculixDeck::Element::C3D20R}};
  for (const auto &[element, ccx_element] : pairs)
    {
      if (elements.find(element) == std::string::npos)
        continue;
      std::vector<double> ours, theirs;
      Run                 sc{}, ccx{};
      for (unsigned int r = 0; r < runs; ++r) // interleaved: both see the same machine load
        {
          sc  = softchain_run(element, cells, pressure);
          ccx = calculix_run(ccx_element, cells, pressure);
          ours.push_back(sc.seconds);
          theirs.push_back(ccx.seconds);
        }
      const std::string pair = element + (element == "Q1" ? " / C3D8" : " / C3D20R");
      std::printf("%-16s %7u %9.3gs %9.3gs %8u %8u %14.6e %14.6e %9.2f\n", pair.c_str(), sc.dofs,
                  median(ours), median(theirs), sc.newton_iterations, ccx.newton_iterations,
                  sc.corner_u, ccx.corner_u, median(theirs) / median(ours));
    }
  return 0;
}
