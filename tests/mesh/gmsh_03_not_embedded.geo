// As gmsh_01.geo, but the fracture line is NOT embedded in the surface:
// its nodes are not mesh vertices (an error case of tests/mesh/gmsh_03).
h = 0.2;
Point(1) = {0, 0, 0, h};
Point(2) = {1, 0, 0, h};
Point(3) = {1, 1, 0, h};
Point(4) = {0, 1, 0, h};
Point(5) = {0.25, 0.3, 0, h};
Point(6) = {0.75, 0.7, 0, h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Line(5) = {5, 6};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve(1) = {1};
Physical Curve(2) = {2};
Physical Curve(3) = {3};
Physical Curve(4) = {4};
Physical Curve(10) = {5};
Physical Surface(100) = {1};
