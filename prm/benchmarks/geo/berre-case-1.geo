// Berre et al. (2021), "Verification benchmarks for single-phase flow in
// three-dimensional fractured porous media", case 1: a single fracture.
// The cube [0, 100]^3 m cut by the planes z = 10 (the top of the more
// permeable bottom layer) and z = 90 (the top of the inflow window on
// x = 0) and by the fracture, the plane through (0, 0, 80), (100, 0, 20),
// (100, 100, 20), (0, 100, 80); gmsh's OpenCASCADE kernel fragments the
// volume along them, so the mesh conforms to all three.
// Physical groups: volumes 2 (z > 10) and 3 (z < 10), the fracture 11, the
// inflow window 1 ({x = 0, z > 90}) and the outflow window 2
// ({y = 0, z < 10}); every other boundary face has id 0 (no flow).
// The mesh is graded: 12 m within reach of the fracture and of the two
// windows, where the pressure varies most (its gradient is singular at the
// windows' edges), growing linearly to 40 m at 40 m from them (1,477
// tetrahedra; the refinement levels halve it).
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 100, 100, 100};
Point(101) = {0, 0, 80}; Point(102) = {100, 0, 20}; Point(103) = {100, 100, 20}; Point(104) = {0, 100, 80};
Line(101) = {101, 102}; Line(102) = {102, 103}; Line(103) = {103, 104}; Line(104) = {104, 101};
Curve Loop(101) = {101, 102, 103, 104};
Plane Surface(101) = {101};
Rectangle(102) = {0, 0, 10, 100, 100};
Rectangle(103) = {0, 0, 90, 100, 100};
BooleanFragments{ Volume{1}; Delete; }{ Surface{101, 102, 103}; Delete; }
e = 1e-3;
Physical Volume("upper", 2) = Volume In BoundingBox{-e, -e, 10 - e, 100 + e, 100 + e, 100 + e};
Physical Volume("lower", 3) = Volume In BoundingBox{-e, -e, -e, 100 + e, 100 + e, 10 + e};
Physical Surface("fracture", 11) = Surface In BoundingBox{-e, -e, 20 - e, 100 + e, 100 + e, 80 + e};
Physical Surface("inflow", 1) = Surface In BoundingBox{-e, -e, 90 - e, e, 100 + e, 100 + e};
Physical Surface("outflow", 2) = Surface In BoundingBox{-e, -e, -e, 100 + e, e, 10 + e};
near() = Surface In BoundingBox{-e, -e, 20 - e, 100 + e, 100 + e, 80 + e};
near() += Surface In BoundingBox{-e, -e, 90 - e, e, 100 + e, 100 + e};
near() += Surface In BoundingBox{-e, -e, -e, 100 + e, e, 10 + e};
Field[1] = Distance;
Field[1].SurfacesList = {near()};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = 12;
Field[2].SizeMax = 40;
Field[2].DistMin = 0;
Field[2].DistMax = 40;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
