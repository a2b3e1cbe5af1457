// A unit square plate with a circular hole (radius 0.2, centre (0.5, 0.5)), for readGmsh.
// Mesh with:  gmsh -2 -format msh41 plate.geo -o plate.msh        (linear triangles)
//             gmsh -2 -format msh41 -setnumber quads 1 plate.geo -o plate_quad.msh
// Physical groups name the node sets a setup uses for boundary conditions.
If (!Exists(quads))
  quads = 0;
EndIf
lc = 0.1;
Point(1) = {0, 0, 0, lc};   Point(2) = {1, 0, 0, lc};
Point(3) = {1, 1, 0, lc};   Point(4) = {0, 1, 0, lc};
Point(5) = {0.5, 0.5, 0, lc};                                  // the hole's centre
Point(6) = {0.7, 0.5, 0, lc}; Point(7) = {0.5, 0.7, 0, lc};
Point(8) = {0.3, 0.5, 0, lc}; Point(9) = {0.5, 0.3, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Circle(5) = {6, 5, 7}; Circle(6) = {7, 5, 8}; Circle(7) = {8, 5, 9}; Circle(8) = {9, 5, 6};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(1) = {1, 2};
If (quads)
  Recombine Surface {1};
EndIf
Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("top") = {3};
Physical Curve("left") = {4};
Physical Curve("hole") = {5, 6, 7, 8};
Physical Surface("plate") = {1};
