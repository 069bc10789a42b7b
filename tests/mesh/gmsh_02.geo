// Unit cube with an embedded inclined planar fracture, the quadrangle
// (0.3, 0.3, 0.3), (0.7, 0.3, 0.5), (0.7, 0.7, 0.5), (0.3, 0.7, 0.3), meshed
// by PolyFrac through the gmsh API (tests/mesh/gmsh_02).
// Boundary physical tags: 1 x = 0, 2 x = 1, 3 y = 0, 4 y = 1, 5 z = 0,
// 6 z = 1; fracture: 10.
h = 0.25;
Point(1) = {0, 0, 0, h};
Point(2) = {1, 0, 0, h};
Point(3) = {1, 1, 0, h};
Point(4) = {0, 1, 0, h};
Point(5) = {0, 0, 1, h};
Point(6) = {1, 0, 1, h};
Point(7) = {1, 1, 1, h};
Point(8) = {0, 1, 1, h};
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
Curve Loop(1) = {4, 9, -8, -12};   // x = 0
Plane Surface(1) = {1};
Curve Loop(2) = {2, 11, -6, -10};  // x = 1
Plane Surface(2) = {2};
Curve Loop(3) = {1, 10, -5, -9};   // y = 0
Plane Surface(3) = {3};
Curve Loop(4) = {3, 12, -7, -11};  // y = 1
Plane Surface(4) = {4};
Curve Loop(5) = {1, 2, 3, 4};      // z = 0
Plane Surface(5) = {5};
Curve Loop(6) = {5, 6, 7, 8};      // z = 1
Plane Surface(6) = {6};
Surface Loop(1) = {1, 2, 3, 4, 5, 6};
Volume(1) = {1};

Point(11) = {0.3, 0.3, 0.3, h};
Point(12) = {0.7, 0.3, 0.5, h};
Point(13) = {0.7, 0.7, 0.5, h};
Point(14) = {0.3, 0.7, 0.3, h};
Line(21) = {11, 12};
Line(22) = {12, 13};
Line(23) = {13, 14};
Line(24) = {14, 11};
Curve Loop(20) = {21, 22, 23, 24};
Plane Surface(20) = {20};
Surface{20} In Volume{1};

Physical Surface(1) = {1};
Physical Surface(2) = {2};
Physical Surface(3) = {3};
Physical Surface(4) = {4};
Physical Surface(5) = {5};
Physical Surface(6) = {6};
Physical Surface(10) = {20};
Physical Volume(100) = {1};
