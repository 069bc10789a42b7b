// Benchmark B3 (3D): the penny-shaped crack of radius 1 m in a 10 m cube,
// 0.05 m on the crack and 0.02 m at its front, growing by 0.1 m per metre
// away from the crack (see penny_common.geo).
R = 1;
L = 5;
hc = 0.05;
hf = 0.02;
hb = 1;
gr = 0.1;
Include "penny_common.geo";
