// A box with a spherical cavity: interfaces through the cavity have a hole.
SetFactory("OpenCASCADE");
Box(1) = {-2, -2, -2, 4, 4, 4};
Sphere(2) = {0, 0, 0, 1};
BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Mesh.MeshSizeMin = 0.25;
Mesh.MeshSizeMax = 0.25;
