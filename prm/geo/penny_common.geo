// Benchmark B3 (3D): a penny-shaped crack of radius R in the plane z = 0,
// centred in the cube [-L, L]^3, embedded in the volume (its nodes are mesh
// vertices). Expects R, L and the mesh sizes: hc on the crack, hf at its
// front (the circle, where the opening has its square-root profile), hb far
// away, and the growth rate gr of the size with the distance from the crack.
// Included by penny.geo (the scene) and by a coarse test geometry.
Point(1) = {-L, -L, -L, hb};
Point(2) = {L, -L, -L, hb};
Point(3) = {L, L, -L, hb};
Point(4) = {-L, L, -L, hb};
Point(5) = {-L, -L, L, hb};
Point(6) = {L, -L, L, hb};
Point(7) = {L, L, L, hb};
Point(8) = {-L, L, L, hb};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Line(5) = {5, 6};
Line(6) = {6, 7};
Line(7) = {7, 8};
Line(8) = {8, 5};
Line(9) = {1, 5};
Line(10) = {2, 6};
Line(11) = {3, 7};
Line(12) = {4, 8};
Curve Loop(1) = {-4, -3, -2, -1};
Curve Loop(2) = {5, 6, 7, 8};
Curve Loop(3) = {1, 10, -5, -9};
Curve Loop(4) = {2, 11, -6, -10};
Curve Loop(5) = {3, 12, -7, -11};
Curve Loop(6) = {4, 9, -8, -12};
For k In {1 : 6}
  Plane Surface(k) = {k};
EndFor
Surface Loop(1) = {1, 2, 3, 4, 5, 6};
Volume(1) = {1};

// The crack: a disk drawn counter-clockwise seen from +z (n+ = +e_z).
Point(101) = {0, 0, 0, hc};
Point(102) = {R, 0, 0, hf};
Point(103) = {0, R, 0, hf};
Point(104) = {-R, 0, 0, hf};
Point(105) = {0, -R, 0, hf};
Circle(101) = {102, 101, 103};
Circle(102) = {103, 101, 104};
Circle(103) = {104, 101, 105};
Circle(104) = {105, 101, 102};
Curve Loop(101) = {101, 102, 103, 104};
Plane Surface(101) = {101};
Surface{101} In Volume{1};

// Sizes, from the distances to the disk, d = ((r - R)_+^2 + z^2)^(1/2),
// and to its front, e = ((r - R)^2 + z^2)^(1/2), r = (x^2 + y^2)^(1/2):
// hc on the crack growing like gr d up to hb, hf at the front growing to hc.
// The opening needs the rock next to the crack resolved, not only the crack:
// at level 0, gr = 0.3 gives a maximum opening 4.3 % short, gr = 0.1 3.5 %
// (with hc = 0.05, hf = 0.02), while a finer crack and front (hc = 0.025,
// hf = 0.02 or hc = 0.05, hf = 0.005) at gr = 0.3 still misses 6.4-6.7 %.
Field[1] = MathEval;
Field[1].F = Sprintf("Min(Min(%g + %g * Sqrt(Max(Sqrt(x*x + y*y) - %g, 0)^2 + z*z), %g), %g + 0.5 * Sqrt((Sqrt(x*x + y*y) - %g)^2 + z*z))", hc, gr, R, hb, hf, R);
Background Field = 1;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

Physical Surface("outer boundary", 1) = {1, 2, 3, 4, 5, 6};
Physical Surface("fracture", 10) = {101};
Physical Volume("rock", 100) = {1};
