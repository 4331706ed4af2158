// SoftChain parametric PneuFlex finger (P10, P13, parallelepiped): one script,
// the designs differ only in the numbers passed with -setnumber (SI units).
//
//   x: long axis, clamped base face x = 0, tip face x = L
//   y: height, fabric (strain-limiting) layer at the bottom y in [0, bottom]
//   z: width, symmetric about z = 0
//
// The outer cross-section is a w(x) by h(x) rectangle, both linear in x from
// (w_base, h_base) to (w_tip, h_tip), so every face is planar. One air cavity
// runs from x = fill (solid base section) to x = L - cap (closed tip), with
// side and top walls of thickness d and a bottom layer of thickness bottom.
//
// The body is split into 3 x 3 x 3 blocks by the stations
//   x: 0, fill, L - cap, L      y: 0, bottom, h - d, h      z: -w/2, -w/2 + d, w/2 - d, w/2
// and the centre block of the middle section is the cavity. hex = 1 meshes
// every block as a transfinite, recombined hexahedral grid (cells of size
// along x, default size, and size across); hex = 0 fills the
// same blocks with unstructured tetrahedra (gmsh's HXT mesher) of size at
// most size.

DefineConstant[
  L      = {0.09,   Name "length"},
  w_base = {0.020,  Name "base width"},
  h_base = {0.018,  Name "base height"},
  w_tip  = {0.016,  Name "tip width"},
  h_tip  = {0.012,  Name "tip height"},
  d      = {0.0025, Name "wall thickness"},
  bottom = {0.003,  Name "bottom layer thickness"},
  fill   = {0.010,  Name "base fill length"},
  cap    = {0.0025, Name "tip cap thickness"},
  size   = {0.004,  Name "element size"},
  hex    = {0,      Name "hexahedra"},
  layers = {1,      Name "elements across the walls"},
  along  = {0,      Name "hexahedra: element size along the finger (0: size)"}
];

sx[] = {0, fill, L - cap, L};

// Tags: point p(i,j,k) = 1 + 16 i + 4 j + k with station indices i (x), j (y),
// k (z) in 0..3; lines and surfaces add a per-direction offset to that index.
For i In {0:3}
  s = sx[i] / L;
  w = w_base + (w_tip - w_base) * s;
  h = h_base + (h_tip - h_base) * s;
  sy[] = {0, bottom, h - d, h};
  sz[] = {-w / 2, -w / 2 + d, w / 2 - d, w / 2};
  For j In {0:3}
    For k In {0:3}
      Point(1 + 16 * i + 4 * j + k) = {sx[i], sy[j], sz[k]};
    EndFor
  EndFor
EndFor

For i In {0:3}
  For j In {0:3}
    For k In {0:3}
      p = 1 + 16 * i + 4 * j + k;
      If (i < 3)
        Line(1000 + p) = {p, p + 16};
      EndIf
      If (j < 3)
        Line(2000 + p) = {p, p + 4};
      EndIf
      If (k < 3)
        Line(3000 + p) = {p, p + 1};
      EndIf
    EndFor
  EndFor
EndFor

// Faces normal to x (4000 + p), to y (5000 + p), to z (6000 + p), each named
// by its corner with the smallest indices.
For i In {0:3}
  For j In {0:3}
    For k In {0:3}
      p = 1 + 16 * i + 4 * j + k;
      If (j < 3 && k < 3)
        Curve Loop(4000 + p) = {2000 + p, 3000 + p + 4, -(2000 + p + 1), -(3000 + p)};
        Plane Surface(4000 + p) = {4000 + p};
      EndIf
      If (i < 3 && k < 3)
        Curve Loop(5000 + p) = {1000 + p, 3000 + p + 16, -(1000 + p + 1), -(3000 + p)};
        Plane Surface(5000 + p) = {5000 + p};
      EndIf
      If (i < 3 && j < 3)
        Curve Loop(6000 + p) = {1000 + p, 2000 + p + 16, -(1000 + p + 4), -(2000 + p)};
        Plane Surface(6000 + p) = {6000 + p};
      EndIf
    EndFor
  EndFor
EndFor

cavity_block = 1 + 16 + 4 + 1;
silicone[] = {};
For i In {0:2}
  For j In {0:2}
    For k In {0:2}
      p = 1 + 16 * i + 4 * j + k;
      If (p != cavity_block)
        Surface Loop(7000 + p) = {4000 + p, 4000 + p + 16, 5000 + p, 5000 + p + 4,
                                  6000 + p, 6000 + p + 1};
        Volume(7000 + p) = {7000 + p};
        silicone[] += {7000 + p};
      EndIf
    EndFor
  EndFor
EndFor

base[] = {};
tip[] = {};
For j In {0:2}
  For k In {0:2}
    base[] += {4000 + 1 + 4 * j + k};
    tip[] += {4000 + 1 + 48 + 4 * j + k};
  EndFor
EndFor
c = cavity_block;
cavity[] = {4000 + c, 4000 + c + 16, 5000 + c, 5000 + c + 4, 6000 + c, 6000 + c + 1};

Physical Surface("base") = {base[]};
Physical Surface("tip") = {tip[]};
Physical Surface("cavity") = {cavity[]};
Physical Volume("silicone") = {silicone[]};

If (hex)
  // One node count per interval and direction (opposite block edges must
  // match), from the longest edge of that interval; along the finger of
  // size `along` where that is given.
  size_x = along > 0 ? along : size;
  For i In {0:2}
    Transfinite Curve{1001 + 16 * i : 1016 + 16 * i} = Ceil((sx[i + 1] - sx[i]) / size_x) + 1;
  EndFor
  hmax = h_base > h_tip ? h_base : h_tip;
  wmax = w_base > w_tip ? w_base : w_tip;
  // Across the side and top walls and the bottom layer at least `layers`
  // elements, whatever the size along the finger (an anisotropic mesh).
  ny[] = {Max(layers, Ceil(bottom / size)), Ceil((hmax - d - bottom) / size),
          Max(layers, Ceil(d / size))};
  nz[] = {Max(layers, Ceil(d / size)), Ceil((wmax - 2 * d) / size), Max(layers, Ceil(d / size))};
  For i In {0:3}
    For j In {0:3}
      For k In {0:3}
        p = 1 + 16 * i + 4 * j + k;
        If (j < 3)
          Transfinite Curve{2000 + p} = ny[j] + 1;
        EndIf
        If (k < 3)
          Transfinite Curve{3000 + p} = nz[k] + 1;
        EndIf
      EndFor
    EndFor
  EndFor
  Transfinite Surface{:};
  Recombine Surface{:};
  Transfinite Volume{:};
Else
  Mesh.MeshSizeMax = size;
  // HXT: on these thin-walled shapes its worst tetrahedron over the three
  // designs and resolutions has shape 6 sqrt(2) V / l_max^3 = 0.04, against
  // 0.006 (slivers) with the default Delaunay mesher (benchmarks/mesh_generation).
  Mesh.Algorithm3D = 10;
EndIf
