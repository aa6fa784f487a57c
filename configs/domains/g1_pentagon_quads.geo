// Pentagonal plate for the G1 space: Gmsh meshes it with triangles recombined into quadrilaterals
// (the config's `recombine: true` sets Mesh.RecombineAll = 1): 13 bilinear quads at h = 0.8.
// A config's `mesh_size` caps the element size (Gmsh Mesh.MeshSizeMax).
h = 0.8;
Point(1) = {0, 0, 0, h};
Point(2) = {2, 0, 0, h};
Point(3) = {2, 1.2, 0, h};
Point(4) = {1, 2, 0, h};
Point(5) = {0, 1.4, 0, h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 1};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};
