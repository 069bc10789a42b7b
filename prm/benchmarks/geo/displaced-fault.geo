// The displaced-fault reactivation benchmark (Novikov et al. 2024, after
// Jansen, Singhal and Vossepoel 2019; open-DARTS, roderickperez/open-DARTS
// commit befdddcf, models/displaced_fault_reactivation/meshes/
// new_setup_coarse.geo): a plane-strain section x, y in [-2250, 2250] m, y
// up, its origin at the reservoir's centre on the fault. The fault is the
// segment through the origin dipping at 70 degrees (x = y cot 70), its tips
// at y = -170 and 170. The reservoir (height 225 m, throw 75 m) lies at
// -150 < y < 75 left of the fault (the hanging wall) and at -75 < y < 150
// right of it (the footwall); its four edges and the fault's points at
// y = -150, -75, 75, 150 are mesh lines and vertices, so that a cell lies
// within the reservoir or outside it.
// Physical groups: the surface 1 (one region: the reservoir is told apart by
// the expressions of the scene), the fault 11, the boundary x = -2250 (id 4),
// x = 2250 (5), y = -2250 (6), y = 2250 (7).
// The mesh: h_fault along the fault, growing linearly to 300 m at 1,500 m
// from it.
SetFactory("OpenCASCADE");
If (!Exists(h_fault))
  h_fault = 4;
EndIf
c = Cos(70 * Pi / 180) / Sin(70 * Pi / 180);
W = 2250;
Rectangle(1) = {-W, -W, 0, 2 * W, 2 * W};
ys[] = {-170, -150, -75, 75, 150, 170};
For k In {0 : 5}
  Point(100 + k) = {ys[k] * c, ys[k], 0};
EndFor
For k In {0 : 4}
  Line(100 + k) = {100 + k, 101 + k};
EndFor
// The reservoir's edges: left of the fault at y = -150 and 75, right of it
// at y = -75 and 150.
Point(110) = {-W, -150, 0}; Point(111) = {-W, 75, 0};
Point(112) = {W, -75, 0}; Point(113) = {W, 150, 0};
Line(110) = {110, 101}; Line(111) = {111, 103};
Line(112) = {102, 112}; Line(113) = {104, 113};
BooleanFragments{ Surface{1}; Delete; }{ Curve{100 : 104, 110 : 113}; Delete; }
e = 1e-3;
fault() = Curve In BoundingBox{-170 * c - e, -170 - e, -e, 170 * c + e, 170 + e, e};
Physical Surface("rock", 1) = Surface{:};
Physical Curve("fault", 11) = fault();
Physical Curve("left", 4) = Curve In BoundingBox{-W - e, -W - e, -e, -W + e, W + e, e};
Physical Curve("right", 5) = Curve In BoundingBox{W - e, -W - e, -e, W + e, W + e, e};
Physical Curve("bottom", 6) = Curve In BoundingBox{-W - e, -W - e, -e, W + e, -W + e, e};
Physical Curve("top", 7) = Curve In BoundingBox{-W - e, W - e, -e, W + e, W + e, e};
Field[1] = Distance;
Field[1].EdgesList = {fault()};
Field[1].NNodesByEdge = 400;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h_fault;
Field[2].SizeMax = 300;
Field[2].DistMin = 0;
Field[2].DistMax = 1500;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
