// Benchmark B6, fine mesh: the four-fracture network in the 100 m cube (see
// b6_network_common.geo), 1.78 m on the fractures growing to 6 m at 30 m
// from them: 126,414 tetrahedra (gmsh 4.8.4, one thread).
hf = 1.78;
hb = 6;
Include "b6_network_common.geo";
