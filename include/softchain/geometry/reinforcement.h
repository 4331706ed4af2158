#pragma once
// Reinforcement: the passive structures of a parametric finger, generated
// from the same dimensions as its mesh (meshes/finger.geo):
//  - the fabric: a grid of springs at height fabric_height in the bottom
//    layer, longitudinal lines that follow the taper and transverse lines,
//    half a wall thickness in from the side, base and tip faces;
//  - the threads: one closed ring per thread pitch along the cavity, running
//    through the middle of the side and top walls and of the bottom layer.
// Every node lies strictly inside the silicone (FingerDimensions::
// material_margin > 0).
//
// The same structures homogenised (`Finger design/Reinforcement = sheets`):
//  - fabric_sheet: the grid's trapezoid, fibres along x and z, each family
//    with the grid's spacing;
//  - thread_sheets: the rings' rectangle swept over the cavity, four planar
//    strips (bottom layer, side walls, top wall) with hoop fibres a thread
//    pitch apart.
#include <softchain/geometry/finger_design.h>
#include <softchain/geometry/spring_network.h>

namespace softchain::geometry
{
  class Reinforcement
  {
  public:
    static SpringNetwork fabric(const FingerDimensions &dimensions, const SpringLayout &layout);
    static SpringNetwork threads(const FingerDimensions &dimensions, const SpringLayout &layout);
    static SpringNetwork fabric_sheet(const FingerDimensions &dimensions, const SpringLayout &layout);
    static SpringNetwork thread_sheets(const FingerDimensions &dimensions, const SpringLayout &layout);
  };
} // namespace softchain::geometry
