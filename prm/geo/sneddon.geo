// Benchmark B3 (Sneddon): a pressurised crack of half-length ell inclined by
// psi = 30 degrees in the square [-L, L]^2 (GEOS: 40 x 40 m, 2 m crack). The
// crack is embedded in the surface (its nodes are mesh vertices) and the mesh is
// refined towards it: size hf on the crack, hb far away.
L = 20;
ell = 1;
psi = Pi / 6;
hf = 0.1;
hb = 2.5;

Point(1) = {-L, -L, 0, hb};
Point(2) = {L, -L, 0, hb};
Point(3) = {L, L, 0, hb};
Point(4) = {-L, L, 0, hb};
// Written from -ell t to +ell t, t = (cos psi, sin psi): n+ = (-sin psi, cos psi).
Point(5) = {-ell * Cos(psi), -ell * Sin(psi), 0, hf};
Point(6) = {ell * Cos(psi), ell * Sin(psi), 0, hf};

Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Line(5) = {5, 6};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve{5} In Surface{1};

Field[1] = Distance;
Field[1].CurvesList = {5};
Field[1].NumPointsPerCurve = 400;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hf;
Field[2].SizeMax = hb;
Field[2].DistMin = 0.25;
Field[2].DistMax = 12;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

Physical Curve("outer boundary", 1) = {1, 2, 3, 4};
Physical Curve("fracture", 10) = {5};
Physical Surface("rock", 100) = {1};
