#pragma once
// The hollow box finger of the layer and twist-axis tests: 90 mm x 12 mm x
// 16 mm, y from -2 mm (the layer y = 0 is 2 mm above the bottom), hollow
// with 2 mm walls, 5 mm long cells: 9 joints at 5, 15, ..., 85 mm, each on
// a node plane.
#include <softchain/reduction/reduction_parameters.h>

#include "../chain/box_mesh.h"

namespace softchain::reduction::testing
{
  inline data::MeshRecord layer_finger_mesh(const bool tetrahedra)
  {
    chain::testing::BoxMeshSpec spec;
    spec.wall_cells = 1;
    spec.tetrahedra = tetrahedra;
    return chain::testing::box_mesh(spec);
  }

  // The reduction of the box finger (joints 10 mm apart) with one role per
  // kind of sample: "pressure", "chord", "skin".
  inline ReductionParameters layer_finger_parameters()
  {
    ReductionParameters p;
    p.joint_spacing  = 0.01;
    p.pressure_roles = {"pressure"};
    p.chord_roles    = {"chord"};
    p.skin_roles     = {"skin"};
    return p;
  }
} // namespace softchain::reduction::testing
