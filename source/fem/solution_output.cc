#include <softchain/fem/solution_output.h>

#include <deal.II/base/mpi.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <filesystem>
#include <fstream>
#include <iomanip>

namespace softchain::fem
{
  using namespace dealii;

  namespace
  {
    // Cauchy stress sigma = tau / J, von Mises stress and J at output points.
    class StressPostprocessor : public DataPostprocessor<3>
    {
    public:
      explicit StressPostprocessor(const QuasiStaticSolver &solver)
        : solver(solver)
      {}

      void evaluate_vector_field(const DataPostprocessorInputs::Vector<3> &inputs,
                                 std::vector<Vector<double>> &computed) const override
      {
        const auto  cell = inputs.template get_cell<3>();
        const auto &mat  = solver.material(cell->material_id());
        for (unsigned int q = 0; q < computed.size(); ++q)
          {
            Tensor<2, 3> F = unit_symmetric_tensor<3>();
            for (unsigned int c = 0; c < 3; ++c)
              F[c] += inputs.solution_gradients[q][c];
            const double                J     = determinant(F);
            const SymmetricTensor<2, 3> sigma = mat.kirchhoff_stress(F) / J;
            for (unsigned int k = 0; k < 6; ++k)
              computed[q](k) = sigma.access_raw_entry(k);
            computed[q](6) = std::sqrt(1.5 * deviator(sigma).norm() * deviator(sigma).norm());
            computed[q](7) = J;
          }
      }
      std::vector<std::string> get_names() const override
      {
        return {"cauchy_xx", "cauchy_yy", "cauchy_zz", "cauchy_xy", "cauchy_xz",
                "cauchy_yz", "von_mises", "J"};
      }
      UpdateFlags get_needed_update_flags() const override { return update_gradients; }

    private:
      const QuasiStaticSolver &solver;
    };

    void write_pvd(const std::string &file, const std::vector<std::pair<double, std::string>> &series)
    {
      std::ofstream out(file);
      DataOutBase::write_pvd_record(out, series);
    }
  } // namespace

  SolutionOutput::SolutionOutput(const std::string &dir, const unsigned int subdivisions)
    : directory(dir)
    , subdivisions(subdivisions)
  {
    std::filesystem::create_directories(directory);
  }

  std::string SolutionOutput::write(const QuasiStaticSolver &solver, const std::string &name,
                                    const double time)
  {
    const FiniteElementSpace &space = solver.space();
    const MPI_Comm            comm  = space.communicator;
    DataOut<3>                data_out;
    data_out.attach_dof_handler(space.dof_handler);
    const std::vector<DataComponentInterpretation::DataComponentInterpretation> vector(
      3, DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(solver.displacement(), std::vector<std::string>(3, "displacement"),
                             DataOut<3>::type_dof_data, vector);
    const StressPostprocessor stress(solver);
    data_out.add_data_vector(solver.displacement(), stress);
    Vector<float> material(space.triangulation.n_active_cells());
    for (const auto &cell : space.triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        material(cell->active_cell_index()) = cell->material_id();
    data_out.add_data_vector(material, "material_id");

    const unsigned int n_sub = subdivisions > 0 ? subdivisions : space.degree;
    data_out.build_patches(*space.mapping, space.simplex ? 1 : n_sub,
                           DataOut<3>::curved_inner_cells);
    DataOutBase::VtkFlags flags;
    flags.write_higher_order_cells = !space.simplex && n_sub > 1;
    data_out.set_flags(flags);
    const std::string body =
      data_out.write_vtu_with_pvtu_record(directory + "/", name, counter, comm, 4);
    body_series.emplace_back(time, body);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      write_pvd(directory + "/" + name + ".pvd", body_series);

    if (solver.spring_network())
      {
        std::ostringstream springs;
        springs << name << "_springs_" << std::setw(4) << std::setfill('0') << counter << ".vtu";
        write_springs(solver, springs.str());
        spring_series.emplace_back(time, springs.str());
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          write_pvd(directory + "/" + name + "_springs.pvd", spring_series);
      }
    ++counter;
    return body;
  }

  // The spring network as VTK line cells (ASCII VTU), written by rank 0.
  void SolutionOutput::write_springs(const QuasiStaticSolver &solver, const std::string &file) const
  {
    const auto &network  = *solver.spring_network();
    const auto  x        = network.points().deformed(solver.displacement());
    const auto  tensions = network.tensions(solver.displacement());
    if (Utilities::MPI::this_mpi_process(solver.space().communicator) != 0)
      return;
    const auto   &links = network.all_links();
    std::ofstream out(directory + "/" + file);
    out << std::setprecision(10)
        << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n"
        << "<UnstructuredGrid><Piece NumberOfPoints=\"" << x.size() << "\" NumberOfCells=\""
        << links.size() << "\">\n<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const auto &p : x)
      out << p << '\n';
    out << "</DataArray></Points>\n<Cells><DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (const auto &l : links)
      out << l.a << ' ' << l.b << '\n';
    out << "</DataArray><DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (std::size_t k = 0; k < links.size(); ++k)
      out << 2 * (k + 1) << '\n';
    out << "</DataArray><DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (std::size_t k = 0; k < links.size(); ++k)
      out << "3\n";
    out << "</DataArray></Cells>\n<CellData Scalars=\"tension\">"
        << "<DataArray type=\"Float64\" Name=\"tension\" format=\"ascii\">\n";
    for (const double t : tensions)
      out << t << '\n';
    out << "</DataArray><DataArray type=\"Int32\" Name=\"network\" format=\"ascii\">\n";
    for (const auto &l : links)
      out << l.network << '\n';
    out << "</DataArray></CellData>\n</Piece></UnstructuredGrid>\n</VTKFile>\n";
  }
} // namespace softchain::fem
