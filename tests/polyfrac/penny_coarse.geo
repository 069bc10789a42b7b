// A coarse penny-shaped crack for the program test b3_penny: 0.25 m on the
// crack, 0.1 m at its front (prm/geo/penny.geo: 0.05 and 0.02 m).
R = 1;
L = 5;
hc = 0.25;
hf = 0.1;
hb = 2;
gr = 0.3;
Include "../../prm/geo/penny_common.geo";
