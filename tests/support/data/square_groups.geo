// Source of square_groups.msh (gmsh square_groups.geo -2 -format msh41 -o square_groups.msh):
// the unit square, coarse, with two named physical curves and one unnamed (tag 7).
Point(1) = {0, 0, 0, 0.5};
Point(2) = {1, 0, 0, 0.5};
Point(3) = {1, 1, 0, 0.5};
Point(4) = {0, 1, 0, 0.5};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("bottom") = {1};
Physical Curve("sides") = {2, 4};
Physical Curve(7) = {3};
Physical Surface("square") = {1};
