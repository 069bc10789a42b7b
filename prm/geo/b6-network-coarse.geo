// Benchmark B6: the four-fracture network in the 100 m cube (see
// b6_network_common.geo), 4 m on the fractures growing to 11 m at 30 m
// from them: the coarse mesh of the B6 mesh study (about 1.5 times the
// 47k mesh's sizes, as the 127k mesh is about 1/1.5 of them).
hf = 4;
hb = 11;
Include "b6_network_common.geo";
