// The CAD-like benchmark part: a pipe flange with a hub, a bore with a
// keyway, six bolt holes and three radial ribs, made with OpenCASCADE
// booleans. Unlike the ball it has sharp edges, small features next to large
// ones (bolt holes and ribs against the plate), rotated faces that no cutting
// plane follows, and faces in coordinate planes that cutting planes can hit
// exactly: the input a mechanical engineer brings.
//
//   gmsh -2 flange.geo -setnumber h 0.07 -format stl -bin -o flange.stl
//
// h is the surface mesh size (also the target edge length of the volume mesh
// in the benchmark).
SetFactory("OpenCASCADE");
DefineConstant[ h = {0.2, Name "surface mesh size"} ];

Cylinder(1) = {0, 0, 0, 0, 0, 0.6, 3.0};   // plate
Cylinder(2) = {0, 0, 0.6, 0, 0, 1.4, 1.5}; // hub
ribs[] = {};
For i In {0:2}
  // a rib from the hub to the rim, between two bolt holes
  Box(10 + i) = {1.3, -0.15, 0.6, 1.6, 0.3, 0.8};
  Rotate {{0, 0, 1}, {0, 0, 0}, Pi / 6 + i * 2 * Pi / 3} { Volume{10 + i}; }
  ribs[] += {10 + i};
EndFor
BooleanUnion(100) = { Volume{1}; Delete; }{ Volume{2, ribs[]}; Delete; };

Cylinder(20) = {0, 0, -1, 0, 0, 4, 0.9};     // bore
Box(21) = {0.8, -0.2, -1, 0.35, 0.4, 4};     // keyway
holes[] = {20, 21};
For i In {0:5}
  Cylinder(30 + i) = {2.3 * Cos(i * Pi / 3), 2.3 * Sin(i * Pi / 3), -1, 0, 0, 3, 0.25};
  holes[] += {30 + i};
EndFor
BooleanDifference(101) = { Volume{100}; Delete; }{ Volume{holes[]}; Delete; };

Mesh.MeshSizeMin = h;
Mesh.MeshSizeMax = h;
