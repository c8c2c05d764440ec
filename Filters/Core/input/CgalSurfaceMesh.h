#ifndef PTM_CGAL_SURFACE_MESH_H
#define PTM_CGAL_SURFACE_MESH_H
// A TriangleSurface out of a CGAL::Surface_mesh, for the input stages that
// make a new surface with CGAL (AlphaWrap.h, IsotropicRemeshing.h). Header
// only: it includes CGAL, so only those stages' sources include it.
#include "TriangleSurface.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

namespace ptm
{
using CgalKernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalMesh = CGAL::Surface_mesh<CgalKernel::Point_3>;

// The mesh's points and triangles (garbage collected first, so vertex k is
// point k); faces that are not triangles are left out.
inline TriangleSurface surfaceOfMesh(CgalMesh& mesh)
{
  mesh.collect_garbage();
  TriangleSurface s;
  s.points.reserve(mesh.number_of_vertices());
  for (CgalMesh::Vertex_index v : mesh.vertices())
  {
    const CgalKernel::Point_3& p = mesh.point(v);
    s.points.push_back({ p.x(), p.y(), p.z() });
  }
  for (CgalMesh::Face_index f : mesh.faces())
  {
    Triangle t{};
    int k = 0;
    for (CgalMesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
    {
      if (k < 3)
      {
        t[k] = static_cast<Index>(v.idx());
      }
      ++k;
    }
    if (k == 3)
    {
      s.triangles.push_back(t);
    }
  }
  return s;
}
} // namespace ptm
#endif
