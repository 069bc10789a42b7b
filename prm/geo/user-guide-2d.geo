// The 2D scene of doc/user-guide.md: a 20 m x 20 m block of rock with two
// fractures that cross, embedded in the surface (their nodes are mesh
// vertices), the mesh finer along them. The physical groups are what
// PolyFrac reads: boundary ids 1 (bottom), 2 (top), 3 (left and right), the
// fractures 11 and 12, the rock 100.
L = 10;     // half the side
hf = 0.5;   // mesh size on the fractures
hb = 2.5;   // mesh size far from them

Point(1) = {-L, -L, 0, hb};
Point(2) = {L, -L, 0, hb};
Point(3) = {L, L, 0, hb};
Point(4) = {-L, L, 0, hb};
// Fracture 11: vertical, x = 0, from y = -4 to 4; fracture 12: inclined,
// from (-4, -2) to (4, 2). They cross at the origin, which must be a point
// of both: each fracture is two curves.
Point(5) = {0, -4, 0, hf};
Point(6) = {0, 4, 0, hf};
Point(7) = {-4, -2, 0, hf};
Point(8) = {4, 2, 0, hf};
Point(9) = {0, 0, 0, hf};

Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Line(5) = {5, 9};
Line(6) = {9, 6};
Line(7) = {7, 9};
Line(8) = {9, 8};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve{5, 6, 7, 8} In Surface{1};

Field[1] = Distance;
Field[1].CurvesList = {5, 6, 7, 8};
Field[1].NumPointsPerCurve = 100;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hf;
Field[2].SizeMax = hb;
Field[2].DistMin = 0.5;
Field[2].DistMax = 6;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

Physical Curve("bottom", 1) = {1};
Physical Curve("top", 2) = {3};
Physical Curve("sides", 3) = {2, 4};
Physical Curve("vertical fracture", 11) = {5, 6};
Physical Curve("inclined fracture", 12) = {7, 8};
Physical Surface("rock", 100) = {1};
