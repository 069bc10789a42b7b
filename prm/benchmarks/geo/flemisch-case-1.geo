// Flemisch et al. (2018), benchmark 1: the Hydrocoin problem (level 1, case
// 2 of the HYDROCOIN project). A 1,600 m cross-section of rock whose top is
// a piecewise linear water table (y from 100 to 150 m), down to y = -1,000
// m, cut by two fracture zones that cross at (500 + 7500/13, -7500/13):
// zone 11 from (400, 100) to (1500, -1000) (slope -1), zone 12 from (1200,
// 100) to (1000, -1000) (slope 5.5). Both reach the top, where they take the
// water table's head, and end on the no-flow bottom. The coordinates are
// those of the benchmark's description (Flemisch et al. 2018, Fig. 5, and
// the notebook hydrocoin.ipynb of gridfunction/fracturedPorousMedia).
// Physical groups: boundary ids 1 (bottom), 2 (top), 3 (left and right),
// the zones 11 and 12, the rock 100.
h = 100;    // mesh size (level 0)

Point(1) = {0, 150, 0, h};
Point(2) = {400, 100, 0, h};
Point(3) = {800, 150, 0, h};
Point(4) = {1200, 100, 0, h};
Point(5) = {1600, 150, 0, h};
Point(6) = {1600, -1000, 0, h};
Point(7) = {1500, -1000, 0, h};
Point(8) = {1000, -1000, 0, h};
Point(9) = {0, -1000, 0, h};
Point(10) = {500 + 7500/13, -7500/13, 0, h};

Line(1) = {1, 9};
Line(2) = {9, 8};
Line(3) = {8, 7};
Line(4) = {7, 6};
Line(5) = {6, 5};
Line(6) = {5, 4};
Line(7) = {4, 3};
Line(8) = {3, 2};
Line(9) = {2, 1};
Line(10) = {2, 10};
Line(11) = {10, 7};
Line(12) = {4, 10};
Line(13) = {10, 8};
Curve Loop(1) = {1, 2, 3, 4, 5, 6, 7, 8, 9};
Plane Surface(1) = {1};
Curve{10, 11, 12, 13} In Surface{1};

Physical Curve("bottom", 1) = {2, 3, 4};
Physical Curve("top", 2) = {6, 7, 8, 9};
Physical Curve("sides", 3) = {1, 5};
Physical Curve("zone 1", 11) = {10, 11};
Physical Curve("zone 2", 12) = {12, 13};
Physical Surface("rock", 100) = {1};
