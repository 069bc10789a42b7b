// The layered column of prm/layered-consolidation-2d.prm as a gmsh mesh:
// 1 m wide, 2 m tall, the layers y < 1 and y > 1 as the physical surfaces
// 1 and 2, which PolyFrac reads as the regions (material ids) 1 and 2.
// Boundary ids: 1 (left), 2 (right), 3 (bottom), 4 (top). Unstructured
// triangles of size h; the interface y = 1 is a mesh line (the two
// surfaces share it).
h = 0.1;

Point(1) = {0, 0, 0, h};
Point(2) = {1, 0, 0, h};
Point(3) = {1, 1, 0, h};
Point(4) = {0, 1, 0, h};
Point(5) = {1, 2, 0, h};
Point(6) = {0, 2, 0, h};

Line(1) = {1, 2}; // bottom
Line(2) = {2, 3}; // right, lower layer
Line(3) = {3, 4}; // the interface
Line(4) = {4, 1}; // left, lower layer
Line(5) = {3, 5}; // right, upper layer
Line(6) = {5, 6}; // top
Line(7) = {6, 4}; // left, upper layer
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {-3, 5, 6, 7};
Plane Surface(2) = {2};

Physical Curve("left", 1) = {4, 7};
Physical Curve("right", 2) = {2, 5};
Physical Curve("bottom", 3) = {1};
Physical Curve("top", 4) = {6};
Physical Surface("lower layer", 1) = {1};
Physical Surface("upper layer", 2) = {2};
