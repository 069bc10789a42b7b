// B4, Mandel: the quarter [0, a] x [0, b] = [0, 100] x [0, 10] m meshed by
// gmsh with a uniform target size of 2 m, as PorePy's Mandel set-up does
// (its `meshing_arguments`: cell_size = 2 m, simplices).
a = 100;
b = 10;
h = 2;

Point(1) = {0, 0, 0, h};
Point(2) = {a, 0, 0, h};
Point(3) = {a, b, 0, h};
Point(4) = {0, b, 0, h};

Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

// Boundary ids: 1 right (drained, traction-free), 2 bottom (roller),
// 3 top (the plate), 4 left (roller).
Physical Curve("right", 1) = {2};
Physical Curve("bottom", 2) = {1};
Physical Curve("top", 3) = {3};
Physical Curve("left", 4) = {4};
Physical Surface("rock", 100) = {1};
