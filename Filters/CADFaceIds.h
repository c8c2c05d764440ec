#ifndef PTM_CAD_FACE_IDS_H
#define PTM_CAD_FACE_IDS_H
// Carrying the CAD face of every input triangle (cell data CADFaceId of
// vtkCADSurfaceReader) through the stages to the mesher's boundary port,
// without touching the core: the cutter stores a table "input triangle ->
// CAD face" in field data (SourceFaceCADFaceId, indexed like SourceFaceId),
// the triangulator and the relaxer pass it on, and the mesher looks up the
// SourceFaceId of every boundary triangle in it.
#include "TriangleSurface.h"

#include "vtkSmartPointer.h"

class vtkIdTypeArray;
class vtkMultiProcessController;
class vtkPolyData;

namespace ptm
{
// Collective (the cutter calls it on every rank after gathering the surface):
// the table for the `wholeTriangles` triangles of the gathered surface, built
// from the input's CADFaceId the way the surface was gathered (every rank's
// own copy, or every rank's piece in rank order); null when no rank's input
// has CADFaceId. `localTriangles` is the rank's own count before gathering.
vtkSmartPointer<vtkIdTypeArray> gatherCADFaceTable(vtkMultiProcessController* controller,
  vtkPolyData* input, std::size_t localTriangles, std::size_t wholeTriangles);

// Adds cell data CADFaceId to `boundary` (the mesher's port 1) from its
// SourceFaceId and the table in `complex`'s field data; -1 where there is no
// source face. Does nothing when the complex has no table. Local.
void addBoundaryCADFaceIds(vtkPolyData* complex, vtkPolyData* boundary);
} // namespace ptm
#endif
