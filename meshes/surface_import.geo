// SoftChain import of a design given as closed surfaces (source/geometry/
// surface_import.cc writes the four STL pieces beside this script): the outer
// surface split into side, base face and tip face, and the cavity surface.
// The surface triangles are kept; the volume between the outer surface and
// the cavity is filled with tetrahedra no larger than `size` (m).
DefineConstant[ size = {0.004, Name "element size"} ];

Merge "outer_side.stl"; // discrete surface 1
Merge "base.stl";       // 2
Merge "tip.stl";        // 3
Merge "cavity.stl";     // 4
Coherence Mesh;         // the pieces share their boundary nodes

Surface Loop(1) = {1, 2, 3};
Surface Loop(2) = {4};
Volume(1) = {1, 2};

Physical Surface("base") = {2};
Physical Surface("tip") = {3};
Physical Surface("cavity") = {4};
Physical Volume("silicone") = {1};

Mesh.MeshSizeMax = size;
Mesh.Algorithm3D = 10; // HXT, as in finger.geo (fewer slivers)
