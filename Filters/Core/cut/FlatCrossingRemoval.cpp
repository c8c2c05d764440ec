#include "FlatCrossingRemoval.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace ptm
{
namespace
{
// A crossing this close to a neighbour on its contour, as a fraction of the
// segment between its two neighbours, goes even where a triangle around
// gets thinner: it is the short edge that the next planes' needles start
// from. Farther ones go only where no angle gets smaller (on a box whose
// faces are grids of squares, taking out every crossing left 1.9 % of the
// complex's triangles under 10 degrees where there had been none).
constexpr double kNearFraction = 0.25;
// ... as long as no angle around falls below half of this or of the
// smallest there was (one degenerate triangle came out of a box with a
// cavity at K = 7 without it; no slack left most needles of the prism test)
constexpr double kNearFloor = kPi / 180;

// The triangles around every point and the loop edges through it, kept up
// to date as points go.
struct Collapser
{
  SurfaceComplex& c;
  const double tolerance;
  const std::vector<Index>& faceGroups;
  std::vector<std::vector<std::size_t>> star; // live triangles of each point
  std::vector<char> alive;                     // per triangle
  std::vector<Index> prevOf, nextOf;           // along the loop through a point (-1: none)
  std::vector<int> loopDegree;                 // loop edges in + out at a point
  std::vector<int> regionOf;                   // the region of those edges
  std::vector<char> removed;
  std::vector<std::size_t> touched; // triangles that took a new corner

  Collapser(SurfaceComplex& complex, double tol, const std::vector<Index>& groups);
  bool candidate(Index p) const;
  bool oneFace(Index p) const;
  bool planarStar(Index p, Vec3& normal) const;
  std::vector<Index> neighbours(Index v) const;
  bool linkHolds(Index p, Index t) const;
  bool improves(Index p, Index t, const Vec3& normal, bool near) const;
  bool tryRemove(Index p);
  void collapse(Index p, Index t);
  void rewireLoops();
  void dropDeadTriangles();
  void dropRemovedPoints();
};

Collapser::Collapser(SurfaceComplex& complex, double tol, const std::vector<Index>& groups)
  : c(complex)
  , tolerance(tol)
  , faceGroups(groups)
  , star(trianglesAtPoints(complex.triangles, complex.points.size()))
  , alive(complex.triangles.size(), 1)
  , prevOf(complex.points.size(), -1)
  , nextOf(complex.points.size(), -1)
  , loopDegree(complex.points.size(), 0)
  , regionOf(complex.points.size(), -1)
  , removed(complex.points.size(), 0)
{
  for (std::size_t r = 0; r < c.interfaces.size(); ++r)
  {
    for (const DirectedEdge& e : c.interfaces[r].edges)
    {
      nextOf[e[0]] = e[1];
      prevOf[e[1]] = e[0];
      for (Index v : e)
      {
        ++loopDegree[v];
        // a point on two regions (a line where planes meet) is never a candidate
        regionOf[v] = regionOf[v] < 0 || regionOf[v] == static_cast<int>(r) ? static_cast<int>(r) : -2;
      }
    }
  }
}

// On one loop edge in and one out, of one region, on a loop that keeps
// three points or more without it.
bool Collapser::candidate(Index p) const
{
  return loopDegree[p] == 2 && regionOf[p] >= 0 && prevOf[p] >= 0 && nextOf[p] >= 0 &&
    prevOf[p] != nextOf[p] && nextOf[nextOf[p]] != prevOf[p] && !star[p].empty();
}

// The face a triangle's input triangle belongs to (-1: none known).
Index faceOf(const SurfaceComplex& c, const std::vector<Index>& faceGroups, std::size_t t)
{
  const Index source = c.sourceFaces.empty() ? -1 : c.sourceFaces[t];
  return source >= 0 && source < static_cast<Index>(faceGroups.size()) ? faceGroups[source] : -1;
}

// Whether every triangle around p comes from one face.
bool Collapser::oneFace(Index p) const
{
  for (std::size_t t : star[p])
  {
    if (faceOf(c, faceGroups, t) != faceOf(c, faceGroups, star[p].front()))
    {
      return false;
    }
  }
  return true;
}

// Whether every triangle around p lies in one plane (within the tolerance),
// with its normal (oriented like the triangles) in `normal`.
bool Collapser::planarStar(Index p, Vec3& normal) const
{
  double largest = 0;
  for (std::size_t t : star[p])
  {
    const Triangle& tri = c.triangles[t];
    const Vec3 n = cross(c.points[tri[1]] - c.points[tri[0]], c.points[tri[2]] - c.points[tri[0]]);
    if (norm(n) > largest)
    {
      largest = norm(n);
      normal = (1.0 / largest) * n;
    }
  }
  if (largest == 0)
  {
    return false;
  }
  for (std::size_t t : star[p])
  {
    for (Index v : c.triangles[t])
    {
      if (std::fabs(dot(c.points[v] - c.points[p], normal)) > tolerance)
      {
        return false;
      }
    }
  }
  return true;
}

std::vector<Index> Collapser::neighbours(Index v) const
{
  std::vector<Index> around;
  for (std::size_t t : star[v])
  {
    for (Index w : c.triangles[t])
    {
      if (w != v)
      {
        around.push_back(w);
      }
    }
  }
  std::sort(around.begin(), around.end());
  around.erase(std::unique(around.begin(), around.end()), around.end());
  return around;
}

// p and t share exactly the two triangles of their edge, and no other
// neighbour: merging them keeps every edge on two triangles.
bool Collapser::linkHolds(Index p, Index t) const
{
  std::vector<Index> apexes;
  for (std::size_t k : star[p])
  {
    const Triangle& tri = c.triangles[k];
    if (std::find(tri.begin(), tri.end(), t) != tri.end())
    {
      for (Index w : tri)
      {
        if (w != p && w != t)
        {
          apexes.push_back(w);
        }
      }
    }
  }
  if (apexes.size() != 2 || apexes[0] == apexes[1])
  {
    return false;
  }
  std::sort(apexes.begin(), apexes.end());
  const std::vector<Index> a = neighbours(p), b = neighbours(t);
  std::vector<Index> common;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(common));
  return common == apexes;
}

// Every triangle of p without t, with t in p's place, still faces `normal`,
// and the smallest angle around does not get smaller (if p lies near t,
// `near`: not below half a degree, or half what it was).
bool Collapser::improves(Index p, Index t, const Vec3& normal, bool near) const
{
  double before = kPi, after = kPi;
  for (std::size_t k : star[p])
  {
    Triangle tri = c.triangles[k];
    before = std::min(before, triangleMinimumAngle(c.points[tri[0]], c.points[tri[1]], c.points[tri[2]]));
    if (std::find(tri.begin(), tri.end(), t) != tri.end())
    {
      continue;
    }
    std::replace(tri.begin(), tri.end(), p, t);
    const Vec3 a = c.points[tri[0]], b = c.points[tri[1]], d = c.points[tri[2]];
    if (!(dot(cross(b - a, d - a), normal) > 0))
    {
      return false;
    }
    after = std::min(after, triangleMinimumAngle(a, b, d));
  }
  return after >= (near ? 0.5 * std::min(before, kNearFloor) : before);
}

void Collapser::collapse(Index p, Index t)
{
  const std::vector<std::size_t> around = star[p]; // the loop below edits star[p]
  for (std::size_t k : around)
  {
    Triangle& tri = c.triangles[k];
    if (std::find(tri.begin(), tri.end(), t) != tri.end())
    {
      alive[k] = 0;
      for (Index w : tri)
      {
        auto& s = star[w];
        s.erase(std::remove(s.begin(), s.end(), k), s.end());
      }
      continue;
    }
    std::replace(tri.begin(), tri.end(), p, t);
    star[t].push_back(k);
    touched.push_back(k);
  }
  star[p].clear();
  const Index q = prevOf[p], r = nextOf[p];
  nextOf[q] = r;
  prevOf[r] = q;
  removed[p] = 1;
}

bool Collapser::tryRemove(Index p)
{
  Vec3 normal{ 0, 0, 0 };
  const Index q = prevOf[p], r = nextOf[p];
  if (!oneFace(p) || !planarStar(p, normal) || distanceToSegment(c.points[p], c.points[q], c.points[r]) > tolerance)
  {
    return false;
  }
  const int planeId = c.interfaces[regionOf[p]].planeId;
  if (planeId >= 0 && planeId < static_cast<int>(c.planes.size()) &&
    std::fabs(dot(normal, c.planes[planeId].normal)) > 1.0 - 1e-9)
  {
    return false; // a face in the cutting plane: the interface and the face meet along it
  }
  const bool qNearer = norm(c.points[q] - c.points[p]) <= norm(c.points[r] - c.points[p]);
  const double segment = norm(c.points[r] - c.points[q]);
  for (Index t : { qNearer ? q : r, qNearer ? r : q })
  {
    const bool near = norm(c.points[t] - c.points[p]) <= kNearFraction * segment;
    if (linkHolds(p, t) && improves(p, t, normal, near))
    {
      collapse(p, t);
      return true;
    }
  }
  return false;
}

// Every loop edge into a removed point now runs on to the first kept one.
void Collapser::rewireLoops()
{
  for (InterfaceRegion& region : c.interfaces)
  {
    std::vector<DirectedEdge> edges;
    for (DirectedEdge e : region.edges)
    {
      if (removed[e[0]])
      {
        continue;
      }
      while (removed[e[1]])
      {
        e[1] = nextOf[e[1]];
      }
      edges.push_back(e);
    }
    std::sort(edges.begin(), edges.end());
    region.edges = std::move(edges);
  }
}

void Collapser::dropDeadTriangles()
{
  std::size_t kept = 0;
  for (std::size_t t = 0; t < c.triangles.size(); ++t)
  {
    if (!alive[t])
    {
      continue;
    }
    c.triangles[kept] = c.triangles[t];
    c.trianglePairs[kept] = c.trianglePairs[t];
    if (!c.sourceFaces.empty())
    {
      c.sourceFaces[kept] = c.sourceFaces[t];
    }
    if (!c.trianglePlanes.empty())
    {
      c.trianglePlanes[kept] = c.trianglePlanes[t];
    }
    ++kept;
  }
  c.triangles.resize(kept);
  c.trianglePairs.resize(kept);
  c.sourceFaces.resize(c.sourceFaces.empty() ? 0 : kept);
  c.trianglePlanes.resize(c.trianglePlanes.empty() ? 0 : kept);
}

// Only points made by the cuts are ever removed, so the input's keep their indices.
void Collapser::dropRemovedPoints()
{
  std::vector<Index> newIndex(c.points.size(), -1);
  Index next = 0;
  for (std::size_t v = 0; v < c.points.size(); ++v)
  {
    if (!removed[v])
    {
      c.points[next] = c.points[v];
      newIndex[v] = next++;
    }
  }
  c.points.resize(static_cast<std::size_t>(next));
  for (Triangle& t : c.triangles)
  {
    for (Index& v : t)
    {
      v = newIndex[v];
    }
  }
  for (InterfaceRegion& region : c.interfaces)
  {
    for (DirectedEdge& e : region.edges)
    {
      e = { newIndex[e[0]], newIndex[e[1]] };
    }
  }
}

// Lawson flips between coplanar triangles of one side (the same pair) and
// one face, from the triangles the collapses changed outwards: the fans a
// collapse leaves become Delaunay in their plane, and the surface stays the
// same point set.
// Interface loop edges separate two sides, so they are never flipped.
struct PlanarFlipper
{
  SurfaceComplex& c;
  const std::vector<char>& alive;
  const double tolerance;
  const std::vector<Index>& faceGroups;
  std::map<std::pair<Index, Index>, std::vector<std::size_t>> edgeTriangles;

  static std::pair<Index, Index> key(Index a, Index b) { return { std::min(a, b), std::max(a, b) }; }
  void build();
  bool flip(const std::pair<Index, Index>& e, std::vector<std::pair<Index, Index>>& queue);
  void run(const std::vector<std::size_t>& seeds);
};

void PlanarFlipper::build()
{
  for (std::size_t t = 0; t < c.triangles.size(); ++t)
  {
    if (alive[t])
    {
      const Triangle& tri = c.triangles[t];
      for (int k = 0; k < 3; ++k)
      {
        edgeTriangles[key(tri[k], tri[(k + 1) % 3])].push_back(t);
      }
    }
  }
}

// Flips edge e if its two triangles lie on one side, in one plane, and the
// angles across it add up to more than 180 degrees (the Delaunay test).
bool PlanarFlipper::flip(const std::pair<Index, Index>& e, std::vector<std::pair<Index, Index>>& queue)
{
  const auto found = edgeTriangles.find(e);
  if (found == edgeTriangles.end() || found->second.size() != 2)
  {
    return false;
  }
  std::size_t t1 = found->second[0], t2 = found->second[1];
  if (c.trianglePairs[t1] != c.trianglePairs[t2] || faceOf(c, faceGroups, t1) != faceOf(c, faceGroups, t2))
  {
    return false;
  }
  // t1 = (a, b, x) and t2 = (b, a, y), both in their own orientation
  auto rotatedTo = [&](std::size_t t, Index first) {
    Triangle tri = c.triangles[t];
    std::rotate(tri.begin(), std::find(tri.begin(), tri.end(), first), tri.end());
    return tri;
  };
  Triangle one = rotatedTo(t1, e.first);
  if (one[1] != e.second)
  {
    std::swap(t1, t2);
    one = rotatedTo(t1, e.first);
  }
  const Triangle two = rotatedTo(t2, e.second);
  const Index a = one[0], b = one[1], x = one[2], y = two[2];
  if (two[1] != a || x == y || edgeTriangles.count(key(x, y)))
  {
    return false;
  }
  const Vec3 &pa = c.points[a], &pb = c.points[b], &px = c.points[x], &py = c.points[y];
  const Vec3 n = normalized(cross(pb - pa, px - pa));
  const bool coplanar = std::fabs(dot(py - pa, n)) <= tolerance;
  const bool convex = dot(cross(pa - px, py - px), n) > 0 && dot(cross(pb - py, px - py), n) > 0;
  if (!coplanar || !convex || cornerAngle(px, pa, pb) + cornerAngle(py, pb, pa) <= kPi * (1 + 1e-12) ||
    std::min(triangleMinimumAngle(px, pa, py), triangleMinimumAngle(py, pb, px)) <=
      std::min(triangleMinimumAngle(pa, pb, px), triangleMinimumAngle(pb, pa, py)))
  {
    return false; // (the last test only guards against rounding: in exact arithmetic a Delaunay flip raises it)
  }
  c.triangles[t1] = { x, a, y };
  c.triangles[t2] = { y, b, x };
  edgeTriangles.erase(found);
  auto moveEdge = [&](Index u, Index v, std::size_t from, std::size_t to) {
    for (std::size_t& t : edgeTriangles[key(u, v)])
    {
      t = t == from ? to : t;
    }
  };
  moveEdge(a, y, t2, t1);
  moveEdge(b, x, t1, t2);
  edgeTriangles[key(x, y)] = { t1, t2 };
  for (const auto& next : { key(a, y), key(y, b), key(b, x), key(x, a) })
  {
    queue.push_back(next);
  }
  return true;
}

void PlanarFlipper::run(const std::vector<std::size_t>& seeds)
{
  build();
  std::vector<std::pair<Index, Index>> queue;
  for (std::size_t t : seeds)
  {
    const Triangle& tri = c.triangles[t];
    for (int k = 0; k < 3 && alive[t]; ++k)
    {
      queue.push_back(key(tri[k], tri[(k + 1) % 3]));
    }
  }
  // each flip makes the triangulation strictly more Delaunay; the cap only
  // guards against rounding cycling between two nearly cocircular choices
  std::size_t budget = 4 * c.triangles.size();
  while (!queue.empty() && budget > 0)
  {
    const std::pair<Index, Index> e = queue.back();
    queue.pop_back();
    budget -= flip(e, queue) ? 1 : 0;
  }
}
} // namespace

std::size_t removeFlatCrossings(SurfaceComplex& c, Index firstCutPoint, double tolerance,
  const std::vector<Index>& faceGroups, const std::vector<char>* keep)
{
  Collapser collapser(c, tolerance, faceGroups);
  std::size_t count = 0;
  for (Index p = std::max<Index>(firstCutPoint, 0); p < static_cast<Index>(c.points.size()); ++p)
  {
    if ((!keep || !(*keep)[p]) && collapser.candidate(p) && collapser.tryRemove(p))
    {
      ++count;
    }
  }
  if (count == 0)
  {
    return 0;
  }
  collapser.rewireLoops();
  PlanarFlipper{ c, collapser.alive, tolerance, faceGroups, {} }.run(collapser.touched);
  collapser.dropDeadTriangles();
  collapser.dropRemovedPoints();
  return count;
}
} // namespace ptm
