// A CAD-like bracket: a plate with a boss, a through hole, a slot and a
// rib, made with OpenCASCADE booleans. Many vertices lie on round-valued
// planes and faces lie in coordinate planes: degenerate input for the cutter.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 6, 3, 1};
Cylinder(2) = {4.5, 1.5, 1, 0, 0, 1.5, 1.0};
Cylinder(3) = {4.5, 1.5, -1, 0, 0, 4, 0.5};
Box(4) = {0.8, 1.2, -1, 1.6, 0.6, 3};
Box(5) = {0, 1.25, 1, 4.0, 0.5, 1.0};
BooleanUnion(10) = { Volume{1}; Delete; }{ Volume{2, 5}; Delete; };
BooleanDifference(11) = { Volume{10}; Delete; }{ Volume{3, 4}; Delete; };
Mesh.MeshSizeMin = 0.12;
Mesh.MeshSizeMax = 0.2;
