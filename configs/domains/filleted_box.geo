// A box 2 x 1.5 x 1 with all edges filleted (radius 0.3), from OpenCASCADE: a closed surface of
// 26 Gmsh surface entities (faces, fillets, corner patches) meshed as one triangle mesh in 3D.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 1.5, 1};
f() = Abs(Boundary{Volume{1};});
e() = Unique(Abs(Boundary{Surface{f()};}));
Fillet{1}{e()}{0.3}
Mesh.MeshSizeMax = 0.25;
