// Benchmark B1 on a mesh graded towards the crack tips and mirror-symmetric
// about the crack near it (benchmarks/B1.md, "The tip"): a straight crack
// of half-length ell, inclined by psi = 20 degrees, through the centre of
// the square [-L, L]^2, embedded in the mesh.
//
// - Sizes: htip at the tips, growing by grade per metre of distance from
//   the nearer tip, at most hf along the crack and at most the size of
//   b1.geo's field away from it (hf within 0.25 m of the crack, growing to
//   hb 12 m away).
// - Symmetry: the disc of radius R around the crack is cut by the crack's
//   line into two halves, and gmsh copies the mesh of the upper half onto
//   the lower one mirrored about that line (Periodic ... Affine). With
//   Contact/Bubble placement = split, the multiplier of each crack face
//   then balances the mean traction of two mirror cells, in which the
//   part of the tip's singular stress that is odd across the crack
//   cancels exactly.
L = 20;
ell = 1;
psi = Pi / 9;
R = 2;
hf = 0.05;
hb = 2.5;
htip = 0.002;
grade = 0.1;

c = Cos(psi);
s = Sin(psi);
Point(1) = {-L, -L, 0, hb};
Point(2) = {L, -L, 0, hb};
Point(3) = {L, L, 0, hb};
Point(4) = {-L, L, 0, hb};
// Written from -ell t to +ell t, t = (cos psi, sin psi): n+ = (-sin psi, cos psi).
Point(5) = {-ell * c, -ell * s, 0, hf};
Point(6) = {ell * c, ell * s, 0, hf};
Point(7) = {-R * c, -R * s, 0, hf};
Point(8) = {R * c, R * s, 0, hf};
Point(9) = {0, 0, 0, hf};

Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Line(5) = {5, 6};                 // the crack
Line(6) = {7, 5};                 // its line, continued to the circle
Line(7) = {6, 8};
Circle(8) = {8, 9, 7};            // upper half circle
Circle(9) = {7, 9, 8};            // lower half circle
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {8, 9};
Plane Surface(1) = {1, 2};        // the square outside the disc
Curve Loop(3) = {6, 5, 7, 8};
Plane Surface(2) = {3};           // upper half disc
Curve Loop(4) = {-7, -5, -6, 9};
Plane Surface(3) = {4};           // lower half disc: the mirror image

// The mirror about the crack's line, 2 t t^T - I, as a 4 x 4 affine map.
a = 2 * c * c - 1;
b = 2 * c * s;
d = 2 * s * s - 1;
Periodic Curve{9} = {8} Affine{a, b, 0, 0, b, d, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
Periodic Surface{3} = {2} Affine{a, b, 0, 0, b, d, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

Field[1] = Distance;
Field[1].CurvesList = {5};
Field[1].NumPointsPerCurve = 400;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hf;
Field[2].SizeMax = hb;
Field[2].DistMin = 0.25;
Field[2].DistMax = 12;
Field[3] = Distance;
Field[3].PointsList = {5, 6};
Field[4] = MathEval;
Field[4].F = Sprintf("%g + %g * F3", htip, grade);
Field[5] = Min;
Field[5].FieldsList = {2, 4};
Background Field = 5;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

Physical Curve("outer boundary", 1) = {1, 2, 3, 4};
Physical Curve("fracture", 10) = {5};
Physical Surface("rock", 100) = {1, 2, 3};
