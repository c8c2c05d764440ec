// Two disjoint bodies in one surface.
SetFactory("OpenCASCADE");
Sphere(1) = {-2, 0, 0, 1};
Box(2) = {1, -1, -1, 2, 2, 2};
Mesh.MeshSizeMin = 0.15;
Mesh.MeshSizeMax = 0.15;
