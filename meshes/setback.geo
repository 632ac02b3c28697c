// Irregular (set-back) frame: two bays, three storeys over the left bay,
// two over the right. Physical line 1 = columns, 2 = beams.
// Mesh with: gmsh -1 -format msh22 setback.geo -o setback.msh
lc = 100; // larger than any member: one element per line
Point(1) = {0, 0, 0, lc};  Point(2) = {6, 0, 0, lc};  Point(3) = {12, 0, 0, lc};
Point(4) = {0, 3.5, 0, lc}; Point(5) = {6, 3.5, 0, lc}; Point(6) = {12, 3.5, 0, lc};
Point(7) = {0, 6.5, 0, lc}; Point(8) = {6, 6.5, 0, lc}; Point(9) = {12, 6.5, 0, lc};
Point(10) = {0, 9.5, 0, lc}; Point(11) = {6, 9.5, 0, lc};
// columns
Line(1) = {1, 4}; Line(2) = {2, 5}; Line(3) = {3, 6};
Line(4) = {4, 7}; Line(5) = {5, 8}; Line(6) = {6, 9};
Line(7) = {7, 10}; Line(8) = {8, 11};
// beams
Line(9) = {4, 5}; Line(10) = {5, 6};
Line(11) = {7, 8}; Line(12) = {8, 9};
Line(13) = {10, 11};
Physical Line(1) = {1, 2, 3, 4, 5, 6, 7, 8};
Physical Line(2) = {9, 10, 11, 12, 13};
