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

    // A cell data array of an ASCII VTU: `components` values per cell.
    struct CellArray
    {
      std::string         name;
      std::string         type; // Float64 or Int32
      unsigned int        components;
      std::vector<double> values;
    };

    // An ASCII VTU of cells with `per_cell` points each (consecutive in
    // `connectivity`), all of VTK type `vtk_type` (1 vertex, 3 line).
    void write_cells_vtu(const std::string &file, const std::vector<Point<3>> &points,
                         const std::vector<unsigned int> &connectivity, const unsigned int per_cell,
                         const unsigned int vtk_type, const std::vector<CellArray> &arrays)
    {
      const std::size_t n_cells = connectivity.size() / per_cell;
      std::ofstream     out(file);
      out << std::setprecision(10)
          << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n"
          << "<UnstructuredGrid><Piece NumberOfPoints=\"" << points.size() << "\" NumberOfCells=\""
          << n_cells << "\">\n<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
      for (const auto &p : points)
        out << p << '\n';
      out << "</DataArray></Points>\n<Cells><DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
      for (std::size_t k = 0; k < connectivity.size(); ++k)
        out << connectivity[k] << ((k + 1) % per_cell == 0 ? '\n' : ' ');
      out << "</DataArray><DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
      for (std::size_t k = 0; k < n_cells; ++k)
        out << per_cell * (k + 1) << '\n';
      out << "</DataArray><DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
      for (std::size_t k = 0; k < n_cells; ++k)
        out << vtk_type << '\n';
      out << "</DataArray></Cells>\n<CellData Scalars=\"" << arrays.front().name << "\">";
      for (const auto &a : arrays)
        {
          out << "<DataArray type=\"" << a.type << "\" Name=\"" << a.name << "\""
              << (a.components > 1 ? " NumberOfComponents=\"" + std::to_string(a.components) + "\"" : "")
              << " format=\"ascii\">\n";
          for (std::size_t k = 0; k < a.values.size(); ++k)
            out << a.values[k] << ((k + 1) % a.components == 0 ? '\n' : ' ');
          out << "</DataArray>";
        }
      out << "</CellData>\n</Piece></UnstructuredGrid>\n</VTKFile>\n";
    }

    // Each rank's points as flat records, x (3) and then the components of
    // every array of `arrays` in order (their `values` left empty),
    // gathered to rank 0 and written there as VTK vertices.
    void write_gathered_vertices(const std::string &file, const MPI_Comm communicator,
                                 const std::vector<double> &local, std::vector<CellArray> arrays)
    {
      const auto all = Utilities::MPI::gather(communicator, local, 0);
      if (Utilities::MPI::this_mpi_process(communicator) != 0)
        return;
      unsigned int record = 3;
      for (const auto &a : arrays)
        record += a.components;
      std::vector<Point<3>>     x;
      std::vector<unsigned int> vertices;
      for (const auto &rank : all)
        for (std::size_t k = 0; k + record <= rank.size(); k += record)
          {
            vertices.push_back(x.size());
            x.emplace_back(rank[k], rank[k + 1], rank[k + 2]);
            std::size_t i = k + 3;
            for (auto &a : arrays)
              for (unsigned int c = 0; c < a.components; ++c)
                a.values.push_back(rank[i++]);
          }
      write_cells_vtu(file, x, vertices, 1, 1, arrays);
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

    if (solver.spring_network() && !solver.spring_network()->all_links().empty())
      write_series_part(solver, name, "springs", time, spring_series,
                        [this](const QuasiStaticSolver &s, const std::string &f) { write_springs(s, f); });
    if (solver.spring_network() && solver.spring_network()->has_sheets())
      write_series_part(solver, name, "sheets", time, sheet_series,
                        [this](const QuasiStaticSolver &s, const std::string &f) { write_sheets(s, f); });
    if (solver.obstacle_contact())
      write_series_part(solver, name, "contact", time, contact_series,
                        [this](const QuasiStaticSolver &s, const std::string &f) { write_contact(s, f); });
    ++counter;
    return body;
  }

  template <typename WritePart>
  void SolutionOutput::write_series_part(const QuasiStaticSolver &solver, const std::string &name,
                                         const std::string &part, const double time,
                                         std::vector<std::pair<double, std::string>> &series,
                                         WritePart write_part)
  {
    std::ostringstream file;
    file << name << "_" << part << "_" << std::setw(4) << std::setfill('0') << counter << ".vtu";
    write_part(solver, file.str());
    series.emplace_back(time, file.str());
    if (Utilities::MPI::this_mpi_process(solver.space().communicator) == 0)
      write_pvd(directory + "/" + name + "_" + part + ".pvd", series);
  }

  // The spring network as VTK line cells, written by rank 0.
  void SolutionOutput::write_springs(const QuasiStaticSolver &solver, const std::string &file) const
  {
    const auto &network  = *solver.spring_network();
    const auto  x        = network.points().deformed(solver.displacement());
    const auto  tensions = network.tensions(solver.displacement());
    if (Utilities::MPI::this_mpi_process(solver.space().communicator) != 0)
      return;
    const auto               &links = network.all_links();
    std::vector<unsigned int> ends;
    std::vector<double>       networks;
    for (const auto &l : links)
      {
        ends.insert(ends.end(), {l.a, l.b});
        networks.push_back(l.network);
      }
    write_cells_vtu(directory + "/" + file, x, ends, 2, 3,
                    {{"tension", "Float64", 1, tensions}, {"network", "Int32", 1, networks}});
  }

  // The fibre sheets' quadrature points of all ranks as VTK vertices at
  // their deformed places, one per fibre family, written by rank 0.
  void SolutionOutput::write_sheets(const QuasiStaticSolver &solver, const std::string &file) const
  {
    std::vector<double> local; // per fibre: x (3), direction (3), tension per width, network
    for (const auto &f : solver.spring_network()->sheet_fibres(solver.displacement()))
      local.insert(local.end(), {f.place[0], f.place[1], f.place[2], f.direction[0], f.direction[1],
                                 f.direction[2], f.tension_per_width, static_cast<double>(f.network)});
    write_gathered_vertices(directory + "/" + file, solver.space().communicator, local,
                            {{"tension_per_width", "Float64", 1, {}},
                             {"fibre_direction", "Float64", 3, {}},
                             {"network", "Int32", 1, {}}});
  }

  // The contact quadrature points of all ranks as VTK vertices at their
  // deformed places, written by rank 0.
  void SolutionOutput::write_contact(const QuasiStaticSolver &solver, const std::string &file) const
  {
    const auto &contact = *solver.obstacle_contact();
    const auto  states  = contact.point_states(solver.displacement(), solver.load_state().obstacle_motion);
    std::vector<double> local; // per point: x (3), pressure, t_T (3), gap, status
    for (const auto &s : states)
      local.insert(local.end(), {s.deformed[0], s.deformed[1], s.deformed[2], s.pressure, s.tangential[0],
                                 s.tangential[1], s.tangential[2], s.gap, static_cast<double>(s.status)});
    write_gathered_vertices(directory + "/" + file, solver.space().communicator, local,
                            {{"contact_pressure", "Float64", 1, {}},
                             {"tangential_traction", "Float64", 3, {}},
                             {"gap", "Float64", 1, {}},
                             {"contact_status", "Int32", 1, {}}});
  }
} // namespace softchain::fem
