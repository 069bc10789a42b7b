// Benchmark B6: the four-fracture network in the 100 m cube (see
// b6_network_common.geo), 2.65 m on the fractures growing to 8 m at 30 m
// from them: 47,649 tetrahedra (gmsh 4.8.4, one thread).
hf = 2.65;
hb = 8;
Include "b6_network_common.geo";
