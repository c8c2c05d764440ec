#include "TetGenStream.h"

#include <unistd.h>

#include <cerrno>
#include <ctime>
#include <functional>
#include <memory>
#include <vector>

namespace ptm
{
namespace
{
// Values gathered in blocks of 1 MB and written a block at a time.
template <typename T>
class BlockWriter
{
public:
  explicit BlockWriter(int fd)
    : Fd(fd)
  {
    this->Block.reserve(kValues);
  }
  bool Add(T value)
  {
    this->Block.push_back(value);
    return this->Block.size() < kValues || this->Flush();
  }
  bool Flush()
  {
    const bool ok = writeAllBytes(this->Fd, this->Block.data(), sizeof(T) * this->Block.size());
    this->Block.clear();
    return ok;
  }

private:
  static constexpr std::size_t kValues = (1u << 20) / sizeof(T);
  int Fd;
  std::vector<T> Block;
};

// TetGen 1.5.0's stages between reading the input and writing the output,
// as its tetrahedralize() runs them for the switches this project uses.
void runStages(tetgenmesh& m, tetgenbehavior& b, tetgenio& in, tetgenio* addin)
{
  m.b = &b;
  m.in = &in;
  m.addin = addin;
  m.initializepools();
  m.transfernodes();
  exactinit(b.verbose, b.noexact, b.nostaticfilter, m.xmax - m.xmin, m.ymax - m.ymin, m.zmax - m.zmin);
  std::clock_t phase = 0; // TetGen's timing out-parameter, unused here
  if (b.refine)
  {
    m.reconstructmesh();
  }
  else
  {
    m.incrementaldelaunay(phase);
  }
  const bool surface = b.plc && !b.refine;
  if (surface)
  {
    m.meshsurface();
    if (b.nobisect)
    {
      m.recoverboundary(phase);
    }
    else
    {
      m.constraineddelaunay(phase);
    }
    m.carveholes(); // prints "Removing exterior tetrahedra" (tetgenPhase, TetGenWatch.h)
    if (b.nobisect && m.subvertstack->objects > 0)
    {
      m.suppresssteinerpoints();
    }
  }
  if (b.coarsen)
  {
    m.meshcoarsening();
  }
  if ((b.plc && b.nobisect) || b.coarsen)
  {
    m.recoverdelaunay();
  }
  if ((b.plc || b.refine) && b.insertaddpoints && addin && addin->numberofpoints > 0)
  {
    m.insertconstrainedpoints(addin);
  }
  if (b.quality)
  {
    m.delaunayrefinement();
  }
  if ((b.plc || b.refine) && b.optlevel > 0)
  {
    m.optimizemesh();
  }
  if (!b.nojettison && (m.dupverts > 0 || m.unuverts > 0 || (b.refine && in.numberofcorners == 10)))
  {
    m.jettisonnodes();
  }
}

// The points in pool order, then the tetrahedra (hull ones left out) as
// point indices, numbered as TetGen's outnodes and outelements number them.
bool sendMesh(tetgenmesh& m, const tetgenbehavior& b, const tetgenio& in, int fd)
{
  // both blocks first: nothing after the header may throw
  BlockWriter<double> coordinates(fd);
  BlockWriter<int> corners(fd);
  TetGenChildHeader h;
  h.points = m.points->items;
  h.tets = m.tetrahedrons->items > 0 ? m.tetrahedrons->items - m.hullsize : 0;
  if (!writeAllBytes(fd, &h, sizeof(h)))
  {
    return false;
  }
  m.points->traversalinit();
  for (tetgenmesh::point p = m.pointtraverse(); p; p = m.pointtraverse())
  {
    if (!coordinates.Add(p[0]) || !coordinates.Add(p[1]) || !coordinates.Add(p[2]))
    {
      return false;
    }
  }
  if (!coordinates.Flush())
  {
    return false;
  }
  if (h.tets == 0)
  {
    return true;
  }
  const int shift = in.firstnumber == 1 && b.zeroindex ? 1 : 0;
  m.tetrahedrons->traversalinit();
  for (tetgenmesh::tetrahedron* t = m.tetrahedrontraverse(); t; t = m.tetrahedrontraverse())
  {
    const int first = b.reversetetori ? 5 : 4, second = b.reversetetori ? 4 : 5;
    for (int k : { first, second, 6, 7 })
    {
      if (!corners.Add(m.pointmark(reinterpret_cast<tetgenmesh::point>(t[k])) - shift))
      {
        return false;
      }
    }
  }
  return corners.Flush();
}
} // namespace

void fillTetGenInput(const TriangleSurface& s, const std::vector<Index>& order,
  const std::vector<int>& position, const std::vector<Index>& facets, const std::vector<Vec3>& holes,
  const std::vector<double>& sizes, tetgenio& in)
{
  const std::size_t n = s.points.size();
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(n);
  in.pointlist = new REAL[3 * n];
  for (std::size_t i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      in.pointlist[3 * i + k] = s.points[order[i]][k];
    }
  }
  if (!sizes.empty())
  {
    in.numberofpointmtrs = 1;
    in.pointmtrlist = new REAL[n];
    for (std::size_t i = 0; i < n; ++i)
    {
      in.pointmtrlist[i] = sizes[order[i]];
    }
  }
  in.numberoffacets = static_cast<int>(s.triangles.size());
  in.facetlist = new tetgenio::facet[s.triangles.size()];
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
  {
    tetgenio::facet& f = in.facetlist[t];
    tetgenio::init(&f);
    f.numberofpolygons = 1;
    f.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&f.polygonlist[0]);
    f.polygonlist[0].numberofvertices = 3;
    f.polygonlist[0].vertexlist = new int[3];
    for (int k = 0; k < 3; ++k)
    {
      f.polygonlist[0].vertexlist[k] = position[s.triangles[facets[t]][k]];
    }
  }
  if (!holes.empty())
  {
    in.numberofholes = static_cast<int>(holes.size());
    in.holelist = new REAL[3 * holes.size()];
    for (std::size_t h = 0; h < holes.size(); ++h)
    {
      for (int k = 0; k < 3; ++k)
      {
        in.holelist[3 * h + k] = holes[h][k];
      }
    }
  }
}

bool transferAllBytes(std::size_t bytes, const std::function<long(std::size_t done, std::size_t left)>& step)
{
  std::size_t done = 0;
  while (done < bytes)
  {
    const long moved = step(done, bytes - done);
    if (moved < 0 && errno == EINTR)
    {
      continue;
    }
    if (moved <= 0)
    {
      return false;
    }
    done += static_cast<std::size_t>(moved);
  }
  return true;
}

bool writeAllBytes(int fd, const void* data, std::size_t bytes)
{
  const char* p = static_cast<const char*>(data);
  return transferAllBytes(bytes, [&](std::size_t done, std::size_t left) { return ::write(fd, p + done, left); });
}

bool readAllBytes(int fd, void* data, std::size_t bytes)
{
  char* p = static_cast<char*>(data);
  return transferAllBytes(bytes, [&](std::size_t done, std::size_t left) { return ::read(fd, p + done, left); });
}

bool tetrahedralizeToPipe(tetgenbehavior& b, tetgenio& in, tetgenio* addin, int fd)
{
  // On a TetGen failure the mesh is freed as the int it throws unwinds, as
  // inside tetrahedralize() (libtet 1.5 often crashes there; the parent
  // counts such a crash as a failed run). After success it is left to the
  // child's exit: freeing the pools of a large mesh takes a while.
  auto m = std::make_unique<tetgenmesh>();
  runStages(*m, b, in, addin);
  const bool sent = sendMesh(*m, b, in, fd);
  m.release(); // NOLINT: the child process ends next
  return sent;
}
} // namespace ptm
