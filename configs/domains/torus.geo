// A torus (major radius 1, minor radius 0.4) from OpenCASCADE, meshed as a surface in 3D.
SetFactory("OpenCASCADE");
Torus(1) = {0, 0, 0, 1, 0.4};
Mesh.MeshSizeMax = 0.45;
