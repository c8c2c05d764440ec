// Unit ball: the simplest curved closed surface.
SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 1};
Mesh.MeshSizeMin = 0.12;
Mesh.MeshSizeMax = 0.12;
