// A square plate [0, 10] x [0, 10] with a circular hole of radius 1.5 at
// its centre, meshed by quadrilaterals in four structured blocks between
// the outer edges and the hole. Boundary ids (physical lines): 1 on the
// outer edges, 2 on the hole; material ids (physical surfaces): 1 the
// blocks along y = 0 and y = L, 2 those along x = 0 and x = L.
//   gmsh -2 -format msh22 plate_with_hole.geo -o plate_with_hole.msh
L = 10;          // side of the plate
r = 1.5;         // radius of the hole
n_side = 9;      // points along an outer edge and along a quarter of the hole
n_radial = 7;    // points from an outer corner to the hole

c = L / 2;
d = r / Sqrt(2);
Point(1) = {0, 0, 0};  Point(2) = {L, 0, 0};  Point(3) = {L, L, 0};  Point(4) = {0, L, 0};
Point(5) = {c, c, 0};
Point(6) = {c - d, c - d, 0};  Point(7) = {c + d, c - d, 0};
Point(8) = {c + d, c + d, 0};  Point(9) = {c - d, c + d, 0};

Line(1) = {1, 2};  Line(2) = {2, 3};  Line(3) = {3, 4};  Line(4) = {4, 1};
Circle(5) = {6, 5, 7};  Circle(6) = {7, 5, 8};  Circle(7) = {8, 5, 9};  Circle(8) = {9, 5, 6};
Line(9) = {1, 6};  Line(10) = {2, 7};  Line(11) = {3, 8};  Line(12) = {4, 9};

Curve Loop(1) = {1, 10, -5, -9};   Plane Surface(1) = {1};
Curve Loop(2) = {2, 11, -6, -10};  Plane Surface(2) = {2};
Curve Loop(3) = {3, 12, -7, -11};  Plane Surface(3) = {3};
Curve Loop(4) = {4, 9, -8, -12};   Plane Surface(4) = {4};

Transfinite Curve {1, 2, 3, 4, 5, 6, 7, 8} = n_side;
Transfinite Curve {9, 10, 11, 12} = n_radial Using Progression 0.85;
Transfinite Surface {1, 2, 3, 4};
Recombine Surface {1, 2, 3, 4};

Physical Curve(1) = {1, 2, 3, 4};
Physical Curve(2) = {5, 6, 7, 8};
Physical Surface(1) = {1, 3};
Physical Surface(2) = {2, 4};
