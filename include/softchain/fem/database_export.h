#pragma once
// DatabaseExport: the bridge from a FiniteElementSpace to the database's
// node-based layout (data/actuation_database.h). The nodes are the support
// points of the Lagrange element (Q2/P2 mid-side nodes included), numbered by
// sorting their reference coordinates, so the numbering and the stored
// coordinates do not depend on the MPI rank count. Construction is
// collective on the space's communicator; every rank then holds the whole
// MeshRecord.
#include <softchain/data/actuation_database.h>
#include <softchain/fem/finite_element_space.h>

#include <deal.II/lac/trilinos_vector.h>

#include <map>
#include <utility>
#include <vector>

namespace softchain::fem
{
  class DatabaseExport
  {
  public:
    explicit DatabaseExport(const FiniteElementSpace &space);

    // X, cavity triangles (linear sub-triangles of the element faces,
    // oriented out of the body), tip and base nodes, cells' corner nodes.
    const data::MeshRecord &mesh() const { return record; }

    // x = X + u at every node (collective; the result is on every rank).
    std::vector<data::Point3> deformed_nodes(const dealii::TrilinosWrappers::MPI::Vector &ghosted_u) const;
    // The locally owned displacement u = x - X of stored positions x.
    dealii::TrilinosWrappers::MPI::Vector displacement(const std::vector<data::Point3> &x) const;

  private:
    const FiniteElementSpace            &space;
    data::MeshRecord                     record;
    std::vector<dealii::types::global_dof_index> node_dofs; // 3 per node (x, y, z)

    void number_nodes();
    void collect_faces_and_cells();
    // Appends the oriented linear sub-triangles of one cavity face, given
    // its nodes by lattice position.
    void add_cavity_triangles(const std::map<std::pair<int, int>, std::int64_t> &nodes,
                              bool quad, const dealii::Tensor<1, 3> &outward,
                              std::vector<std::int64_t> &triangles) const;
  };
} // namespace softchain::fem
