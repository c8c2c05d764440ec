#ifndef PTM_TETGEN_STREAM_H
#define PTM_TETGEN_STREAM_H
// TetGen's meshing run inside its own process (TetGenProcess.h: ptm-tetgen,
// one per run), with the mesh sent to the rank straight from TetGen's own
// pools.
//
// Why: tetrahedralize() copies the finished mesh into its output tetgenio
// (points 24 bytes, tetrahedra 16 bytes each) while its pools still hold it,
// and that moment is the child's memory peak. A 10.3 M-tetrahedron ball at
// K = 2 on 2 ranks peaked at 1150 / 1108 MB per rank with the copies and
// 1050 / 1009 MB without (session 34, one run each).
//
// fillTetGenInput: TetGen's input for a surface, the surface points in the
// given order (position[i] is where surface point i goes), one facet per
// triangle in the order `facets` (the surface triangle of each facet), the
// hole points, and the sizes at the points (-m; none if empty).
//
// Contract of tetrahedralizeToPipe: the same stages, in the same order and
// under the same switches, as libtet 1.5.0's tetrahedralize(b, in, out,
// addin) for what this project asks of it (p or r, Y, q, a, m with sizes at
// the points and no background mesh, i, O, z, no -d, -R or -o2), then
//  * a TetGenChildHeader (status 0, the point and tetrahedron counts),
//  * every point's x, y, z (double) in the order of TetGen's point pool,
//  * every tetrahedron's four point indices (int) in the order of its pool,
//    hull tetrahedra left out,
// written to `fd`: byte for byte what writing out.pointlist and
// out.tetrahedronlist after tetrahedralize() wrote (TetGenStream.
// SendsWhatTetrahedralizeOutputs in TetGenSubdomainMesherTest.cpp compares
// the two). TetGen's failures propagate (it throws an int) before anything
// is written, and free the mesh as they unwind, as in tetrahedralize();
// false if the pipe broke. After success the mesh is not freed: the child
// ends right after.
#include "TriangleSurface.h"

#include <tetgen.h>

#include <cstddef>
#include <functional>
#include <vector>

namespace ptm
{
struct TetGenChildHeader
{
  int status = 0; // 0 meshed, 1 TetGen error code, 2 out of memory, 3 bad switches
  int code = 0;
  long long points = 0;
  long long tets = 0;
};

void fillTetGenInput(const TriangleSurface& s, const std::vector<Index>& order,
  const std::vector<int>& position, const std::vector<Index>& facets, const std::vector<Vec3>& holes,
  const std::vector<double>& sizes, tetgenio& in);

bool tetrahedralizeToPipe(tetgenbehavior& b, tetgenio& in, tetgenio* addin, int fd);

// Moves `bytes` with `step(done, left)`, a read, write or send of at most
// `left` bytes after the first `done` that returns how many it moved,
// through interrupted and partial steps; false at end of file (a step
// moving 0) or on an error.
bool transferAllBytes(std::size_t bytes, const std::function<long(std::size_t done, std::size_t left)>& step);

// Writes `bytes` of `data` to fd; false if the pipe broke.
bool writeAllBytes(int fd, const void* data, std::size_t bytes);

// Reads exactly `bytes` from fd; false at end of file or on an error.
bool readAllBytes(int fd, void* data, std::size_t bytes);
} // namespace ptm
#endif
