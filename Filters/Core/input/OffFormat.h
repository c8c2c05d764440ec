#ifndef PTM_OFF_FORMAT_H
#define PTM_OFF_FORMAT_H
// Reading (and writing) surfaces in the Object File Format (OFF), with errors
// that say exactly what is wrong and where.
//
// Accepted: the header keywords OFF, COFF, NOFF, CNOFF, STOFF (and the ST..
// combinations; the extra per-vertex values of colours, normals and texture
// coordinates are read past), the three counts `vertices faces edges` on the
// header line or on the next one (the edge count may be missing and is not
// checked), '#' comments anywhere, blank lines, CR LF line ends, one vertex
// per line, faces `n i1 ... in` followed by at most 4 optional colour values.
// Polygons with more than three corners are triangulated by ear clipping in
// the plane of their Newell normal, so non-convex polygons come out right.
//
// Everything else is an error with a message naming the line and the problem:
// an empty file, a missing or foreign header, BINARY OFF, bad or zero counts,
// a truncated file, lines after the last face (wrong counts), non-numeric,
// NaN or infinite coordinates, faces with fewer than 3 corners, a corner
// count that does not match the indices listed, indices out of range,
// a vertex repeated within a face, and polygons that cannot be triangulated
// (zero area or self-intersecting). Numbers are parsed independently of the
// C locale.
#include "TriangleSurface.h"

#include <cstddef>
#include <istream>
#include <ostream>
#include <string>
#include <vector>

namespace ptm
{
struct OffSurface
{
  TriangleSurface surface;
  std::vector<Index> sourcePolygon; // per triangle: the face of the file it came from (0-based)
  std::size_t polygonCount = 0;     // number of faces in the file
};

struct OffReadResult
{
  bool ok = false;
  std::string error; // "line N: what is wrong" (readOffFile: "FILE: line N: what is wrong")
  OffSurface data;   // empty when !ok
};

// Parses an OFF text; never throws for malformed input (only std::bad_alloc
// could escape).
OffReadResult readOff(std::istream& in);
// As readOff, with the file name in front of any error; a missing, unreadable
// file or a directory is an error too.
OffReadResult readOffFile(const std::string& path);

// Writes the surface as OFF with round-trip (17 digit) coordinates.
void writeOff(std::ostream& out, const TriangleSurface& surface, const std::string& comment = "");

// Appends the triangles of a simple polygon (indices into `points`, in the
// order of its boundary) to `triangles`, by ear clipping in the plane of its
// Newell normal; every triangle is oriented like the polygon. Returns false
// (and appends nothing) if the polygon has zero area or no ear can be found
// (it intersects itself).
bool triangulatePolygon(const std::vector<Vec3>& points, const std::vector<Index>& corners,
  std::vector<Triangle>& triangles);
} // namespace ptm
#endif
