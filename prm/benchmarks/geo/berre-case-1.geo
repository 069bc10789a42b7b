// Berre et al. (2021), case 1: the cube [0, 100]^3 m on the benchmark's own
// structured hexahedral mesh, the one its participants' refinements were
// made of (USTUTT's MPFA: 1,000 cells at refinement 0, 9,600 at refinement
// 1). Four slabs stacked in z, cut by the planes z = 10 (the bottom layer's
// top), the fracture through (0, y, 80) and (100, y, 20), and the plane
// through (0, y, 90) and (100, y, 60) (the inflow window's lower edge on
// x = 0); n x n hexahedra across every slab and m_k through slab k:
//
//   refinement 0: n = 10, m = 4, 4, 1, 1 (1,000 cells, 100 fracture faces)
//   refinement 1: n = 20, m = 8, 8, 4, 4 (9,600 cells, 400 fracture faces)
//
// Written for PolyFrac from the benchmark's description of its mesh (the
// counts are those of its results.csv and of data/single/geometry/gmsh.geo
// in gridfunction/fracturedPorousMedia, commit e9efa85b); the file that
// includes this one may set `refinement` first (default 1, the benchmark's
// middle refinement).
If (!Exists(refinement))
  refinement = 1;
EndIf
If (refinement == 0)
  n = 10;
  m[] = {4, 4, 1, 1};
Else
  n = 20;
  m[] = {8, 8, 4, 4};
EndIf

// Column c (0 to 3: (0, 0), (100, 0), (100, 100), (0, 100)) at level k (0
// to 4: z = 0, 10, the fracture, the window's plane, 100) is point
// 1 + c + 4 k.
X[] = {0, 100, 100, 0};
Y[] = {0, 0, 100, 100};
For k In {0 : 4}
  For c In {0 : 3}
    z = k == 0 ? 0 : (k == 1 ? 10 : (k == 4 ? 100 :
        (k == 2 ? 80 - 0.6 * X[c] : 90 - 0.3 * X[c])));
    Point(1 + c + 4 * k) = {X[c], Y[c], z};
  EndFor
EndFor
// Line 100 + 4 k + c along level k from column c to c + 1; line
// 200 + 4 k + c from level k to k + 1 at column c.
For k In {0 : 4}
  For c In {0 : 3}
    Line(100 + 4 * k + c) = {1 + c + 4 * k, 1 + (c + 1) % 4 + 4 * k};
  EndFor
  Curve Loop(300 + k) = {100 + 4 * k : 103 + 4 * k};
  Plane Surface(300 + k) = {300 + k};
EndFor
For k In {0 : 3}
  For c In {0 : 3}
    Line(200 + 4 * k + c) = {1 + c + 4 * k, 1 + c + 4 * (k + 1)};
  EndFor
  For c In {0 : 3}
    Curve Loop(400 + 4 * k + c) = {100 + 4 * k + c,
                                   200 + 4 * k + (c + 1) % 4,
                                   -(100 + 4 * (k + 1) + c),
                                   -(200 + 4 * k + c)};
    Plane Surface(400 + 4 * k + c) = {400 + 4 * k + c};
  EndFor
  Surface Loop(500 + k) = {300 + k, 301 + k, 400 + 4 * k : 403 + 4 * k};
  Volume(1 + k) = {500 + k};
  Transfinite Curve{200 + 4 * k : 203 + 4 * k} = m[k] + 1;
EndFor
Transfinite Curve{100 : 119} = n + 1;
Transfinite Surface "*";
Recombine Surface "*";
Transfinite Volume "*";

Physical Volume("upper", 2) = {2, 3, 4};
Physical Volume("lower", 3) = {1};
Physical Surface("fracture", 11) = {302};
Physical Surface("inflow", 1) = {415};
Physical Surface("outflow", 2) = {400};
