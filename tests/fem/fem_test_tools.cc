#include "fem_test_tools.h"

#include <softchain/fem/boundary_ids.h>

#include <deal.II/base/mpi.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/numerics/vector_tools.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <random>
#include <stdexcept>

#include <unistd.h>

namespace softchain::fem::test
{
  using namespace dealii;

  std::string write_prm(const std::string &name, const std::string &text)
  {
    // Written beside and renamed into place: another test process (ctest -j)
    // reading the same name then sees a whole file, never a half-written one.
    const std::string file = name + ".prm";
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        const std::string partial = file + "." + std::to_string(::getpid());
        std::ofstream(partial) << text;
        std::filesystem::rename(partial, file);
      }
    MPI_Barrier(MPI_COMM_WORLD);
    return file;
  }

  Parameters parameters_from_text(const std::string &name, const std::string &text)
  {
    return Parameters::read(write_prm(name, text));
  }

  std::string bender_prm(const std::string &element, const unsigned int cells,
                         const std::string &extra)
  {
    std::ostringstream prm;
    prm << "subsection Mesh\n  set Source = built-in bender\n  set Element type = " << element
        << "\n  set Bender cells along length = " << cells << "\nend\n"
        << "subsection Output\n  set Write VTU = false\n  set Verbose = false\nend\n"
        << extra;
    return prm.str();
  }

  std::string solid_prm(const std::string &element, const std::string &strain_energy,
                        const double youngs_modulus, const double poissons_ratio,
                        const std::string &extra)
  {
    std::ostringstream prm;
    prm << std::setprecision(17) << "subsection Mesh\n  set Element type = " << element
        << "\nend\nsubsection Materials\n  set Strain energy = " << strain_energy
        << "\n  subsection solid\n    set Young's modulus = " << youngs_modulus
        << "\n    set Poisson's ratio = " << poissons_ratio << "\n  end\nend\n"
        << "subsection Output\n  set Write VTU = false\n  set Verbose = false\nend\n"
        << extra;
    return prm.str();
  }

  void cantilever_block(Triangulation<3> &mesh, const std::vector<unsigned int> &cells,
                        const double length, const double height)
  {
    GridGenerator::subdivided_hyper_rectangle(mesh, cells, Point<3>(),
                                              Point<3>(length, height, height));
    for (const auto &face : mesh.active_face_iterators())
      if (face->at_boundary())
        face->set_boundary_id(face->center()[0] < 1e-9 * length       ? boundary::base :
                              face->center()[0] > length * (1 - 1e-9) ? boundary::tip :
                                                                        boundary::other);
  }

  MeshSolverFixture::MeshSolverFixture(const Parameters &p, const Triangulation<3> &mesh)
    : prm(p)
    , solver(std::make_unique<QuasiStaticSolver>(prm, mesh, std::vector<std::string>{"solid"},
                                                 std::vector<SpringPolyline>(),
                                                 std::vector<FibreSheet>(), MPI_COMM_WORLD,
                                                 log))
  {}

  Tensor<1, 3> displacement_at(const QuasiStaticSolver &solver, const Point<3> &p)
  {
    return solver.deformed_points({p})[0] - p;
  }

  std::pair<TrilinosWrappers::MPI::Vector, TrilinosWrappers::MPI::Vector>
  tangent_and_difference(QuasiStaticSolver &solver, const LoadState &load,
                         const TrilinosWrappers::MPI::Vector &u, const TrilinosWrappers::MPI::Vector &v,
                         const double h)
  {
    const auto assemble = [&](const bool with_matrix) {
      if (!solver.assemble(load, with_matrix))
        throw std::runtime_error("tangent_and_difference: an element is inverted (J <= 0)");
    };
    solver.set_displacement(u);
    assemble(true);
    TrilinosWrappers::MPI::Vector Kv(v);
    solver.tangent().vmult(Kv, v);
    TrilinosWrappers::MPI::Vector plus(u), minus(u);
    plus.add(h, v);
    minus.add(-h, v);
    solver.set_displacement(plus);
    assemble(false);
    TrilinosWrappers::MPI::Vector fd(solver.negative_residual());
    solver.set_displacement(minus);
    assemble(false);
    fd -= solver.negative_residual();
    fd *= -1.0 / (2 * h); // K = dR/du = -d(rhs)/du
    solver.space().fixed_dofs.set_zero(fd);
    solver.space().fixed_dofs.set_zero(Kv);
    return {Kv, fd};
  }

  SolverFixture::SolverFixture(const Parameters &p)
    : prm(p)
  {
    FingerMesh::build(prm, mesh);
    solver = std::make_unique<QuasiStaticSolver>(prm, mesh.triangulation, mesh.material_names,
                                                 mesh.springs, mesh.sheets, MPI_COMM_WORLD, log);
  }

  namespace
  {
    class SmoothField : public Function<3>
    {
    public:
      SmoothField(double scale)
        : Function<3>(3), scale(scale)
      {}
      double value(const Point<3> &p, const unsigned int c) const override
      {
        const double x = p[0] / 0.08;
        const double field[3] = {0.3 * x * p[1] / 0.012, -x * x + 0.2 * x * p[2] / 0.018,
                                 0.4 * x * (p[1] - 0.006) / 0.012};
        return scale * field[c];
      }
      double scale;
    };
  } // namespace

  TrilinosWrappers::MPI::Vector smooth_displacement(const QuasiStaticSolver &solver,
                                                    const double scale, const double noise,
                                                    const unsigned int seed)
  {
    const auto                   &space = solver.space();
    TrilinosWrappers::MPI::Vector u(space.owned_dofs, space.communicator);
    VectorTools::interpolate(*space.mapping, space.dof_handler, SmoothField(scale), u);
    std::mt19937                           random(seed);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    for (const auto dof : space.owned_dofs)
      u[dof] += noise * scale * uniform(random);
    u.compress(VectorOperation::insert);
    space.fixed_dofs.set_zero(u);
    return u;
  }
} // namespace softchain::fem::test
