#ifndef PTM_CAD_TESSELLATION_H
#define PTM_CAD_TESSELLATION_H
// Reading CAD files (STEP, IGES, BREP) into one closed triangle surface with
// OpenCASCADE 7.6, for the cutter's input check to accept.
//
// The solids of the file (one chosen by index, or all as separate shells) are
// tessellated with BRepMesh_IncrementalMesh. OCCT tessellates every face on
// its own but discretizes each edge once, so the nodes of a shared edge are
// the same points in both faces' triangulations; they are merged by exact
// coordinates into one surface. Triangles of faces with orientation
// TopAbs_REVERSED are flipped so every shell faces outward. Every triangle
// carries the index of its face in a TopExp face map of the whole file
// (deterministic: the map follows the file's topology, not the selection).
//
// A file without solids (IGES mostly holds trimmed faces) has its faces sewn
// (BRepBuilderAPI_Sewing) and every closed shell made a solid, with a warning.
//
// Refused with a message naming the file and the problem: an unknown
// extension, a file OCCT cannot read, no solid (and faces that do not sew
// into a closed shell), an empty solid chosen alone (empty ones are left
// out of "all" with a warning), a solid index out of range, a
// shell that is open (free edges, before tessellation), a face that could
// not be tessellated. Solids that touch each other (non-manifold as a whole)
// only warn: the cutter refuses them and the alpha wrap repairs them.
#include "TriangleSurface.h"

#include <string>
#include <vector>

namespace ptm
{
struct CADReadOptions
{
  // Largest distance between a triangle and its face, as a fraction of the
  // bounding-box diagonal (used when linearDeflection is 0). 1e-3 with 0.5
  // rad: OCCT's screw.step becomes 1,344 triangles, Pump_Nut.brep 2,498 and
  // hammer.iges 2,732, in 0.1 to 0.4 s each (measured, CADTessellationTest).
  double relativeLinearDeflection = 1e-3;
  double linearDeflection = 0;    // absolute; overrides the relative one when > 0
  double angularDeflection = 0.5; // radians between neighbouring triangle normals on a face
  int solid = -1;                 // -1: every solid, as a separate shell; else its index
};

struct CADSurface
{
  bool ok = false;
  std::string error;
  std::vector<std::string> warnings;
  TriangleSurface surface;
  std::vector<Index> faceId; // per triangle: 0-based index in the file's face map
  int solids = 0;            // solids in the file
  int faces = 0;             // faces in the file
  double linearDeflection = 0; // absolute value used
};

CADSurface readCADSurface(const std::string& fileName, const CADReadOptions& options);

// The same call under a C name, for the plugin to find with dlsym: the
// plugin does not link this library (libptmcad.so, built next to it) but
// opens it on the first CAD file. OpenCASCADE's 19 libraries are bound at
// load (BIND_NOW); linked into the plugin they cost every rank of every run
// 0.35-0.52 s and 18 MB before anything was read, CAD input or not.
// Exceptions do not cross it: `result` carries the error.
constexpr const char* kReadCADSurfaceSymbol = "ptmReadCADSurface";
using ReadCADSurfaceFunction = void (*)(const char* fileName, const CADReadOptions* options, CADSurface* result);
} // namespace ptm

extern "C" void ptmReadCADSurface(
  const char* fileName, const ptm::CADReadOptions* options, ptm::CADSurface* result);
#endif
