// An ellipsoid with semi-axes 1.5, 1 and 0.7: an OpenCASCADE sphere stretched by Dilate.
SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 1};
Dilate {{0, 0, 0}, {1.5, 1, 0.7}} { Volume{1}; }
Mesh.MeshSizeMax = 0.3;
