// The 3D scene of doc/user-guide.md: a 40 m cube of rock, [-20, 20]^3 (z
// up), with one vertical fracture, a 16 m x 16 m square through the
// origin whose normal is (cos 30, sin 30, 0) (its strike 30 degrees from
// the y axis), meshed by tetrahedra of 4 m on the fracture growing to 10 m
// at 12 m from it (872 tetrahedra, 44 fracture faces). The OpenCASCADE
// kernel: BooleanFragments embeds the fracture in the volume, so that its
// nodes are mesh vertices. Physical groups: boundary
// ids 1 (bottom, z = -20), 2 (top), 3 (the four sides); the fracture 11;
// the rock 100.
SetFactory("OpenCASCADE");
L = 20;
hf = 4;
hb = 10;
Box(1) = {-L, -L, -L, 2 * L, 2 * L, 2 * L};
Rectangle(10) = {-8, -8, 0, 16, 16};            // in the plane z = 0
Rotate {{0, 1, 0}, {0, 0, 0}, Pi / 2} { Surface{10}; } // now x = 0
Rotate {{0, 0, 1}, {0, 0, 0}, Pi / 6} { Surface{10}; } // strike 30 deg
BooleanFragments{ Volume{1}; Delete; }{ Surface{10}; Delete; }

// The pieces, sorted by their bounding boxes: a box face has one constant
// coordinate at +-L; the rest is the fracture.
e = 1e-6 * L;
bottom() = {}; top() = {}; sides() = {}; fracture() = {};
all() = Surface{:};
For k In {0 : #all() - 1}
  b() = BoundingBox Surface{all(k)};
  If (Fabs(b(5) - b(2)) < e && b(2) < -L + e)
    bottom() += all(k);
  ElseIf (Fabs(b(5) - b(2)) < e && b(2) > L - e)
    top() += all(k);
  ElseIf ((Fabs(b(3) - b(0)) < e && Fabs(b(0)) > L - e) || (Fabs(b(4) - b(1)) < e && Fabs(b(1)) > L - e))
    sides() += all(k);
  Else
    fracture() += all(k);
  EndIf
EndFor

Field[1] = Distance;
Field[1].SurfacesList = {fracture()};
Field[1].NumPointsPerCurve = 40;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hf;
Field[2].SizeMax = hb;
Field[2].DistMin = 0;
Field[2].DistMax = 12;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

Physical Surface("bottom", 1) = {bottom()};
Physical Surface("top", 2) = {top()};
Physical Surface("sides", 3) = {sides()};
Physical Surface("fracture", 11) = {fracture()};
Physical Volume("rock", 100) = {Volume{:}};
