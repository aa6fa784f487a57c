// L-shaped domain [-1,1]^2 minus [0,1]x[-1,0] (the lower right quarter), for iga-run.
// A config's `mesh_size` caps the element size (Gmsh Mesh.MeshSizeMax); h is the default.
h = 0.5;
Point(1) = {-1, -1, 0, h};
Point(2) = {0, -1, 0, h};
Point(3) = {0, 0, 0, h};
Point(4) = {1, 0, 0, h};
Point(5) = {1, 1, 0, h};
Point(6) = {-1, 1, 0, h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 1};
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};
// Boundary parts by name: the two sides meeting at the re-entrant corner, and the rest.
Physical Curve("reentrant") = {2, 3};
Physical Curve("outer") = {1, 4, 5, 6};
Physical Surface("domain") = {1};
