// Benchmark B6: a network of four planar fractures in the 100 m cube
// [-50, 50]^3 (z up), built with the OpenCASCADE kernel: BooleanFragments
// cuts the fractures along their intersection lines and embeds them in the
// volume, so their nodes are mesh vertices and the lines are mesh edges.
// Expects the mesh sizes hf (on the fractures) and hb (far away; the size
// grows linearly from hf at distance 0 to hb at distance dmax = 30 m).
// Included by b6-network.geo (about 47k tetrahedra) and
// b6-network-fine.geo (about 127k).
//
//   F1 (physical tag 11): a 60 m x 50 m rectangle through the origin,
//       strike along y, dipping 60 degrees (down towards -x).
//   F2 (tag 12): a 60 m x 50 m rectangle through (5, -5, -5), strike
//       along y, dipping 30 degrees the other way; F1 and F2 cross along a
//       line parallel to y (an X).
//   F3 (tag 13): the vertical rectangle y = 10, x in [-35, 35],
//       z in [-25, 25]; it crosses F1 and F2 (two X lines) and the line
//       F1 ^ F2 pierces it (a point on three fractures).
//   F4 (tag 14): the vertical rectangle x = 10, y in [-22, -2], from F1
//       (z = 10 tan 60) up to z = 40: it ends on F1 (a T).
// All four have free tips and corners inside the rock.
//
// Physical tags: 1 bottom (z = -50), 2 top (z = 50), 3 sides; 100 rock.
SetFactory("OpenCASCADE");
L = 50;
Box(1) = {-L, -L, -L, 2 * L, 2 * L, 2 * L};

// A rectangle with centre (cx, cy, cz), its strike along y (half-length
// hy) and its dip direction in the x-z plane at angle a from the
// horizontal (half-length hd), as a plane surface.
Macro DippingRectangle
  ca = Cos(a * Pi / 180);
  sa = Sin(a * Pi / 180);
  p1 = newp; Point(p1) = {cx - hd * ca, cy - hy, cz - hd * sa};
  p2 = newp; Point(p2) = {cx + hd * ca, cy - hy, cz + hd * sa};
  p3 = newp; Point(p3) = {cx + hd * ca, cy + hy, cz + hd * sa};
  p4 = newp; Point(p4) = {cx - hd * ca, cy + hy, cz - hd * sa};
  l1 = newl; Line(l1) = {p1, p2};
  l2 = newl; Line(l2) = {p2, p3};
  l3 = newl; Line(l3) = {p3, p4};
  l4 = newl; Line(l4) = {p4, p1};
  c = newll; Curve Loop(c) = {l1, l2, l3, l4};
  s = news; Plane Surface(s) = {c};
Return

cx = 0; cy = 0; cz = 0; hy = 25; hd = 30; a = 60;
Call DippingRectangle;
f1 = s;
cx = 5; cy = -5; cz = -5; hy = 25; hd = 30; a = -30;
Call DippingRectangle;
f2 = s;
f3 = news; Rectangle(f3) = {-35, -25, 0, 70, 50};
Rotate {{1, 0, 0}, {0, 0, 0}, Pi / 2} { Surface{f3}; }
Translate {0, 10, 0} { Surface{f3}; }
z4 = 10 * Tan(60 * Pi / 180);
f4 = news; Rectangle(f4) = {z4, -22, 0, 40 - z4, 20};
Rotate {{0, 1, 0}, {0, 0, 0}, -Pi / 2} { Surface{f4}; }
Translate {10, 0, 0} { Surface{f4}; }

pieces() = BooleanFragments{ Volume{1}; Delete; }
                           { Surface{f1, f2, f3, f4}; Delete; };

// Each piece is classified by its bounding box: the box faces have one
// constant coordinate at +-L, F3 and F4 have y = 10 and x = 10, and a piece
// of F1 or F2 (strike along y) has its lowest and highest points on the
// plane at its smallest and largest x.
t1 = Tan(60 * Pi / 180);
t2 = Tan(-30 * Pi / 180);
e = 1e-6 * L;
bottom() = {}; top() = {}; sides() = {};
frac1() = {}; frac2() = {}; frac3() = {}; frac4() = {};
all() = Surface{:};
For k In {0 : #all() - 1}
  b() = BoundingBox Surface{all(k)};
  If (Fabs(b(5) - b(2)) < e && Fabs(b(2) + L) < e)
    bottom() += all(k);
  ElseIf (Fabs(b(5) - b(2)) < e && Fabs(b(2) - L) < e)
    top() += all(k);
  ElseIf ((Fabs(b(3) - b(0)) < e && Fabs(Fabs(b(0)) - L) < e) || (Fabs(b(4) - b(1)) < e && Fabs(Fabs(b(1)) - L) < e))
    sides() += all(k);
  ElseIf (Fabs(b(4) - b(1)) < e)
    frac3() += all(k);
  ElseIf (Fabs(b(3) - b(0)) < e)
    frac4() += all(k);
  ElseIf (Fabs(b(2) - t1 * b(0)) < e && Fabs(b(5) - t1 * b(3)) < e)
    frac1() += all(k);
  ElseIf (Fabs(b(5) - (-5 + t2 * (b(0) - 5))) < e && Fabs(b(2) - (-5 + t2 * (b(3) - 5))) < e)
    frac2() += all(k);
  Else
    Error("b6_network_common.geo: surface %g is on no fracture and no box face", all(k));
  EndIf
EndFor
Printf("B6 pieces: F1 %g, F2 %g, F3 %g, F4 %g; bottom %g, top %g, sides %g", #frac1(), #frac2(), #frac3(), #frac4(), #bottom(), #top(), #sides());

Physical Surface("bottom", 1) = {bottom()};
Physical Surface("top", 2) = {top()};
Physical Surface("sides", 3) = {sides()};
Physical Surface("F1", 11) = {frac1()};
Physical Surface("F2", 12) = {frac2()};
Physical Surface("F3", 13) = {frac3()};
Physical Surface("F4", 14) = {frac4()};
Physical Volume("rock", 100) = {Volume{:}};

// Sizes: hf on the fractures growing linearly to hb at 30 m from them.
Field[1] = Distance;
Field[1].SurfacesList = {frac1(), frac2(), frac3(), frac4()};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hf;
Field[2].SizeMax = hb;
Field[2].DistMin = 0;
Field[2].DistMax = 30;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
