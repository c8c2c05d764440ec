#ifndef PTM_OFF_FORMAT_H
#define PTM_OFF_FORMAT_H
// Reading surfaces in the Object File Format (OFF), with errors that say
// exactly what is wrong and where.
//
// Accepted: the header keywords OFF, COFF, NOFF, CNOFF, STOFF (the extra
// per-vertex values of colours, normals and texture coordinates are read past),
// the three counts on the header line or on the next one, '#' comments
// anywhere, blank lines, faces `n i1 ... in` followed by optional colour
// values. Polygons with more than three corners are triangulated by ear
// clipping in the plane of their Newell normal, so non-convex polygons come
// out right.
#include "TriangleSurface.h"

#include <istream>
#include <string>

namespace ptm
{
struct OffSurface
{
  TriangleSurface surface;
  std::vector<Index> sourcePolygon; // per triangle: the face of the file it came from
  std::size_t polygonCount = 0;
};

struct OffReadResult
{
  bool ok = false;
  std::string error; // "line N: what is wrong"
  OffSurface data;
};

OffReadResult readOff(std::istream& in);
// As readOff, with the file name in front of any error; a missing or
// unreadable file is an error too.
OffReadResult readOffFile(const std::string& path);

// Triangles of a simple polygon (indices into `corners`) by ear clipping in
// the plane of its Newell normal; false if it is degenerate (zero area).
bool triangulatePolygon(const std::vector<Vec3>& points, const std::vector<Index>& corners,
  std::vector<Triangle>& triangles);
} // namespace ptm
#endif
