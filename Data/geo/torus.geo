// Torus around z: a plane through the axis cuts it in two contours.
SetFactory("OpenCASCADE");
Torus(1) = {0, 0, 0, 2, 0.7};
Mesh.MeshSizeMin = 0.15;
Mesh.MeshSizeMax = 0.15;
