#include <softchain/fem/boundary_dofs.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/component_mask.h>

#include <map>

namespace softchain::fem
{
  using namespace dealii;

  std::vector<BoundaryDof> owned_boundary_dofs(const FiniteElementSpace  &space,
                                               const types::boundary_id boundary)
  {
    std::map<types::global_dof_index, Point<3>> support_points;
    DoFTools::map_dofs_to_support_points(*space.mapping, space.dof_handler, support_points);
    std::vector<BoundaryDof> dofs;
    for (unsigned int c = 0; c < 3; ++c)
      {
        std::vector<bool> mask(3, false);
        mask[c] = true;
        for (const auto index :
             DoFTools::extract_boundary_dofs(space.dof_handler, ComponentMask(mask), {boundary}))
          if (space.owned_dofs.is_element(index))
            dofs.push_back({index, c, support_points.at(index)});
      }
    return dofs;
  }
} // namespace softchain::fem
