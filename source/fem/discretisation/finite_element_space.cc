#include <softchain/fem/boundary_ids.h>
#include <softchain/data/input_error.h>
#include <softchain/fem/finite_element_space.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria_description.h>
#include <deal.II/numerics/vector_tools.h>

namespace softchain::fem
{
  using namespace dealii;

  namespace
  {
    bool is_simplex_mesh(const Triangulation<3> &mesh)
    {
      return mesh.begin_active()->reference_cell() == ReferenceCells::Tetrahedron;
    }
  } // namespace

  FiniteElementSpace::FiniteElementSpace(const Triangulation<3> &serial_mesh,
                                         const ElementType       element_type,
                                         MPI_Comm                comm)
    : communicator(comm)
    , triangulation(comm)
    , simplex(is_simplex(element_type))
    , degree(fem::degree(element_type))
  {
    if (simplex != is_simplex_mesh(serial_mesh))
      throw data::InputError("Mesh/Element type = " + name(element_type) + " needs a " +
                             (simplex ? "tetrahedral" : "hexahedral") +
                             " mesh, but the mesh has the other cell shape");

    // Partition a copy of the serial mesh and keep only this rank's part
    // (plus a ghost layer): the same code runs on 1 or N ranks.
    Triangulation<3> partitioned;
    partitioned.copy_triangulation(serial_mesh);
    GridTools::partition_triangulation(Utilities::MPI::n_mpi_processes(comm), partitioned);
    triangulation.create_triangulation(
      TriangulationDescription::Utilities::create_description_from_triangulation(partitioned,
                                                                                 comm));
    if (simplex)
      {
        fe              = std::make_unique<FESystem<3>>(FE_SimplexP<3>(degree), 3);
        mapping         = std::make_unique<MappingFE<3>>(FE_SimplexP<3>(1));
        cell_quadrature = QGaussSimplex<3>(degree + 1);
        face_quadrature = QGaussSimplex<2>(degree + 1);
      }
    else
      {
        fe              = std::make_unique<FESystem<3>>(FE_Q<3>(degree), 3);
        mapping         = std::make_unique<MappingQ<3>>(1);
        cell_quadrature = QGauss<3>(degree + 1);
        face_quadrature = QGauss<2>(degree + 1);
      }
    setup_dofs();
  }

  void FiniteElementSpace::setup_dofs()
  {
    dof_handler.reinit(triangulation);
    dof_handler.distribute_dofs(*fe);
    owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant_dofs);

    // The fixed DoFs of all ranks are known to every rank, so that spring
    // and point-load stencils that reach into another rank's cells still
    // see which of their DoFs are fixed.
    AffineConstraints<double> local;
    local.reinit(relevant_dofs);
    VectorTools::interpolate_boundary_values(*mapping, dof_handler, boundary::base,
                                             Functions::ZeroFunction<3>(3), local);
    const types::boundary_id fixed_component[3] = {boundary::fixed_x, boundary::fixed_y,
                                                   boundary::fixed_z};
    for (unsigned int c = 0; c < 3; ++c)
      {
        ComponentMask component(3, false);
        component.set(c, true);
        VectorTools::interpolate_boundary_values(*mapping, dof_handler, fixed_component[c],
                                                 Functions::ZeroFunction<3>(3), local,
                                                 component);
      }
    std::vector<types::global_dof_index> fixed;
    for (const auto &line : local.get_lines())
      fixed.push_back(line.index);
    fixed_dofs.clear();
    for (const auto &rank_fixed : Utilities::MPI::all_gather(communicator, fixed))
      for (const auto dof : rank_fixed)
        if (!fixed_dofs.is_constrained(dof))
          fixed_dofs.add_line(dof);
    fixed_dofs.close();
    if (Utilities::MPI::sum(fixed.size(), communicator) == 0)
      throw data::InputError("the mesh has no face in the physical group 'base': "
                             "nothing is clamped");
  }

  Point<3>
  FiniteElementSpace::support_point(const typename DoFHandler<3>::active_cell_iterator &cell,
                                    const unsigned int base_index) const
  {
    const auto &unit = fe->base_element(0).get_unit_support_points()[base_index];
    return mapping->transform_unit_to_real_cell(cell, unit);
  }

  std::vector<std::array<unsigned int, 3>> node_dof_table(const FiniteElement<3> &fe)
  {
    AssertThrow(fe.n_components() == 3 && fe.n_base_elements() == 1 &&
                  fe.element_multiplicity(0) == 3 && fe.is_primitive(),
                ExcMessage("node_dof_table needs three copies of one scalar element"));
    std::vector<std::array<unsigned int, 3>> table(fe.n_dofs_per_cell() / 3);
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      {
        const auto [component, node] = fe.system_to_component_index(i);
        table[node][component]       = i;
      }
    return table;
  }
} // namespace softchain::fem
