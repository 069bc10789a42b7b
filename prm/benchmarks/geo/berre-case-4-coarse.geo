// Berre et al. (2021), case 4, at three times the mesh size of
// berre-case-4.geo (the benchmark's geometry): 41,481 tetrahedra,
// for the test polyfrac/berre_case_4.
Mesh.MeshSizeFactor = 3;
Include "berre-case-4.geo";
