#include "SurfaceInputCheck.h"

#include "SelfIntersectionCheck.h"
#include "UnionFind.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <set>
#include <sstream>
#include <unordered_map>

namespace ptm
{
namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

std::string at(const Vec3& p)
{
  char buffer[96];
  std::snprintf(buffer, sizeof(buffer), "(%.6g, %.6g, %.6g)", p[0], p[1], p[2]);
  return buffer;
}

std::string plural(std::size_t n, const char* one, const char* many)
{
  std::ostringstream s;
  s << n << " " << (n == 1 ? one : many);
  return s.str();
}

std::uint64_t edgeKey(Index a, Index b, std::size_t pointCount)
{
  const Index lo = std::min(a, b), hi = std::max(a, b);
  return static_cast<std::uint64_t>(lo) * static_cast<std::uint64_t>(pointCount) +
    static_cast<std::uint64_t>(hi);
}

// Edge use counts of a triangle set, keyed by the unordered edge.
struct EdgeTable
{
  std::unordered_map<std::uint64_t, std::vector<Index>> uses;
  EdgeTable(const TriangleSurface& s)
  {
    uses.reserve(s.triangles.size() * 2);
    for (std::size_t t = 0; t < s.triangles.size(); ++t)
    {
      for (int c = 0; c < 3; ++c)
      {
        uses[edgeKey(s.triangles[t][c], s.triangles[t][(c + 1) % 3], s.points.size())].push_back(
          static_cast<Index>(t));
      }
    }
  }
  const std::vector<Index>& of(Index a, Index b, std::size_t pointCount) const
  {
    return uses.at(edgeKey(a, b, pointCount));
  }
};
// The checks and safe repairs of one input surface, and what they share:
// the result being built, the problems found so far and the working copy
// of the surface with the input triangle of each of its triangles. A step
// that finds a problem adds it to `problems`; fail() turns them into the
// error.
struct InputPreparation
{
  InputPreparation(const TriangleSurface& in, const InputCheckOptions& o);

  const TriangleSurface& input;
  const InputCheckOptions& options;
  PreparedSurface out;
  InputCheckCounts& n;
  std::vector<std::string> problems;
  // Open, non-manifold, unorientable and self-intersecting surfaces are what
  // the alpha wrap repairs (AlphaWrap.h): the refusal says how to turn it on.
  bool wrappable = false;
  TriangleSurface s;
  std::vector<Index> source;
  std::vector<Triangle> removed; // duplicated and zero-area triangles, for the closure check

  PreparedSurface fail();
  bool checkBasics();
  void checkPoints();
  void checkTriangleIndices();
  void mergePoints();
  void removeDegenerateTriangles();
  void dropUnusedPoints();
  std::string edgeAt(std::uint64_t key) const;
  std::size_t boundaryEdgesAlongRemoved(const EdgeTable& edges) const;
  void checkEdges(const EdgeTable& edges);
  void checkVertices(const EdgeTable& edges);
  bool orient();
  bool checkSelfIntersections();
  bool measureVolume();
};

InputPreparation::InputPreparation(const TriangleSurface& in, const InputCheckOptions& o)
  : input(in)
  , options(o)
  , n(out.counts)
{
  n.inputPoints = input.points.size();
  n.inputTriangles = input.triangles.size();
}

PreparedSurface InputPreparation::fail()
{
  std::ostringstream msg;
  for (std::size_t i = 0; i < problems.size(); ++i)
  {
    msg << (i ? "; " : "") << problems[i];
  }
  if (wrappable)
  {
    msg << " (repair the model, or mesh a closed wrap of it: tetmesh.py --wrap, or the Alpha Wrap "
           "filter before the cutter)";
  }
  out.error = msg.str();
  out.ok = false;
  return out;
}

// Whether the surface passes what makes every later check meaningless.
bool InputPreparation::checkBasics()
{
  if (input.triangles.empty())
  {
    problems.push_back("the input surface is empty (no triangles)");
    return false;
  }
  if (input.points.size() < 4)
  {
    problems.push_back("the input surface has " + plural(input.points.size(), "point", "points") +
      "; a closed surface needs at least 4");
    return false;
  }
  checkPoints();
  checkTriangleIndices();
  return problems.empty();
}

void InputPreparation::checkPoints()
{
  Index firstNonFinite = -1, largestPoint = -1;
  double largest = 0;
  for (std::size_t i = 0; i < input.points.size(); ++i)
  {
    const Vec3& p = input.points[i];
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      if (n.nonFinitePoints++ == 0)
      {
        firstNonFinite = static_cast<Index>(i);
      }
    }
    else if (const double magnitude = largestCoordinate(p);
             magnitude > largest)
    {
      largest = magnitude;
      largestPoint = static_cast<Index>(i);
    }
  }
  if (n.nonFinitePoints > 0)
  {
    std::ostringstream msg;
    msg << plural(n.nonFinitePoints, "point has", "points have")
        << " a NaN or infinite coordinate (the first is point " << firstNonFinite << ")";
    problems.push_back(msg.str());
  }
  // Every volume (the input's, the balance, each subdomain's) is a sum of
  // terms of |p|^3; beyond 1e100 they overflow double precision and the cut
  // would fail without a reason.
  constexpr double kLargestCoordinate = 1e100;
  if (largest > kLargestCoordinate)
  {
    std::ostringstream msg;
    msg << "point " << largestPoint << " has a coordinate of magnitude " << largest
        << ", beyond the 1e100 that volumes in double precision allow; scale the surface down";
    problems.push_back(msg.str());
  }
  // At the other end, the products inside the exact predicates (up to the
  // fifth power of a length in TetGen's insphere) underflow: CGAL then
  // falls back to exact arithmetic on every call, and a surface of 22
  // triangles 3e-106 across took 36 s to cut into 4 (found by the
  // decomposition fuzzer), where the same at unit size takes milliseconds.
  constexpr double kSmallestExtent = 1e-50;
  if (n.nonFinitePoints == 0)
  {
    const double extent = boundingBoxDiagonal(input.points);
    if (extent > 0 && extent < kSmallestExtent)
    {
      std::ostringstream msg;
      msg << "the surface spans only " << extent
          << " (its bounding-box diagonal), below the 1e-50 at which the exact predicates' products "
             "underflow double precision; scale the surface up";
      problems.push_back(msg.str());
    }
  }
}

void InputPreparation::checkTriangleIndices()
{
  Index firstBadTriangle = -1;
  for (std::size_t t = 0; t < input.triangles.size(); ++t)
  {
    for (Index v : input.triangles[t])
    {
      if (v < 0 || v >= static_cast<Index>(input.points.size()))
      {
        if (n.badIndexTriangles++ == 0)
        {
          firstBadTriangle = static_cast<Index>(t);
        }
        break;
      }
    }
  }
  if (n.badIndexTriangles > 0)
  {
    std::ostringstream msg;
    msg << plural(n.badIndexTriangles, "triangle refers", "triangles refer")
        << " to a point that does not exist (the first is triangle " << firstBadTriangle << ")";
    problems.push_back(msg.str());
  }
}

void InputPreparation::mergePoints()
{
  s = input;
  n.mergedPoints = mergeDuplicatePoints(s, n.collapsedTriangles, source, options.mergeTolerance);
  if (n.mergedPoints > 0)
  {
    out.warnings.push_back("merged " + plural(n.mergedPoints, "duplicate point", "duplicate points"));
  }
  if (n.collapsedTriangles > 0)
  {
    out.warnings.push_back("removed " +
      plural(n.collapsedTriangles, "triangle that repeats a corner",
        "triangles that repeat a corner"));
  }
}

void InputPreparation::removeDegenerateTriangles()
{
  std::set<std::array<Index, 3>> seen;
  std::vector<Triangle> kept;
  std::vector<Index> keptSource;
  Index firstDuplicate = -1, firstZeroArea = -1;
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
  {
    const Triangle& tri = s.triangles[t];
    std::array<Index, 3> sorted = tri;
    std::sort(sorted.begin(), sorted.end());
    const Vec3 &a = s.points[tri[0]], &b = s.points[tri[1]], &c = s.points[tri[2]];
    if (!seen.insert(sorted).second)
    {
      if (n.duplicateTriangles++ == 0)
      {
        firstDuplicate = source[t];
      }
      removed.push_back(tri);
      continue;
    }
    if (CGAL::collinear(Kernel::Point_3(a[0], a[1], a[2]), Kernel::Point_3(b[0], b[1], b[2]),
          Kernel::Point_3(c[0], c[1], c[2])))
    {
      if (n.zeroAreaTriangles++ == 0)
      {
        firstZeroArea = source[t];
      }
      removed.push_back(tri);
      continue;
    }
    kept.push_back(tri);
    keptSource.push_back(source[t]);
  }
  s.triangles = std::move(kept);
  source = std::move(keptSource);
  if (n.duplicateTriangles > 0)
  {
    std::ostringstream msg;
    msg << "removed " << plural(n.duplicateTriangles, "duplicated triangle", "duplicated triangles")
        << " (the first is input triangle " << firstDuplicate << ")";
    out.warnings.push_back(msg.str());
  }
  if (n.zeroAreaTriangles > 0)
  {
    std::ostringstream msg;
    msg << "removed " << plural(n.zeroAreaTriangles, "zero-area triangle", "zero-area triangles")
        << " (three collinear corners; the first is input triangle " << firstZeroArea << ")";
    out.warnings.push_back(msg.str());
  }
}

// Drops points only the removed triangles used, keeping the order.
void InputPreparation::dropUnusedPoints()
{
  if (removed.empty())
  {
    return;
  }
  std::vector<Index> newIndex(s.points.size(), -1);
  for (const Triangle& tri : s.triangles)
  {
    for (Index v : tri)
    {
      newIndex[v] = 0;
    }
  }
  std::vector<Vec3> points;
  for (std::size_t i = 0; i < s.points.size(); ++i)
  {
    if (newIndex[i] == 0)
    {
      newIndex[i] = static_cast<Index>(points.size());
      points.push_back(s.points[i]);
    }
  }
  for (Triangle& tri : s.triangles)
  {
    for (Index& v : tri)
    {
      v = newIndex[v];
    }
  }
  for (Triangle& tri : removed)
  {
    for (Index& v : tri)
    {
      v = newIndex[v]; // -1 where the point went with it
    }
  }
  s.points = std::move(points);
}

std::string InputPreparation::edgeAt(std::uint64_t key) const
{
  const std::size_t pointCount = s.points.size();
  const Index a = static_cast<Index>(key / pointCount), b = static_cast<Index>(key % pointCount);
  return "from " + at(s.points[a]) + " to " + at(s.points[b]);
}

// How many boundary edges are edges of removed triangles.
std::size_t InputPreparation::boundaryEdgesAlongRemoved(const EdgeTable& edges) const
{
  const std::size_t pointCount = s.points.size();
  std::size_t alongRemoved = 0;
  for (const Triangle& tri : removed)
  {
    for (int c = 0; c < 3; ++c)
    {
      if (tri[c] < 0 || tri[(c + 1) % 3] < 0)
      {
        continue;
      }
      auto it = edges.uses.find(edgeKey(tri[c], tri[(c + 1) % 3], pointCount));
      alongRemoved += (it != edges.uses.end() && it->second.size() == 1) ? 1 : 0;
    }
  }
  return alongRemoved;
}

// Boundary edges and non-manifold edges.
void InputPreparation::checkEdges(const EdgeTable& edges)
{
  std::uint64_t firstBoundary = 0, firstNonManifold = 0;
  std::size_t worstUse = 0;
  for (const auto& [key, uses] : edges.uses)
  {
    if (uses.size() == 1 && n.boundaryEdges++ == 0)
    {
      firstBoundary = key;
    }
    else if (uses.size() > 2)
    {
      if (n.nonManifoldEdges++ == 0)
      {
        firstNonManifold = key;
      }
      worstUse = std::max(worstUse, uses.size());
    }
  }
  if (n.boundaryEdges > 0)
  {
    std::ostringstream msg;
    msg << "the surface is open: " << plural(n.boundaryEdges, "boundary edge", "boundary edges")
        << " (used by one triangle), e.g. " << edgeAt(firstBoundary);
    wrappable = true;
    if (!removed.empty())
    {
      const std::size_t alongRemoved = boundaryEdgesAlongRemoved(edges);
      if (alongRemoved > 0)
      {
        msg << ", " << alongRemoved
            << " of them along duplicated or zero-area triangles that cannot be removed without "
               "opening the surface";
      }
    }
    problems.push_back(msg.str());
  }
  if (n.nonManifoldEdges > 0)
  {
    std::ostringstream msg;
    msg << plural(n.nonManifoldEdges, "non-manifold edge", "non-manifold edges")
        << " (used by more than two triangles, up to " << worstUse << "), e.g. "
        << edgeAt(firstNonManifold);
    problems.push_back(msg.str());
    wrappable = true;
  }
}

// A vertex is manifold when its triangles form one fan: join the corners
// of two triangles that share a manifold edge at both ends of that edge,
// then count the groups of corners at every vertex.
void InputPreparation::checkVertices(const EdgeTable& edges)
{
  const std::size_t pointCount = s.points.size();
  UnionFind corners(3 * s.triangles.size());
  auto cornerOf = [&](Index t, Index v) {
    const Triangle& tri = s.triangles[t];
    return static_cast<std::size_t>(3 * t + (tri[0] == v ? 0 : tri[1] == v ? 1 : 2));
  };
  for (const auto& [key, uses] : edges.uses)
  {
    if (uses.size() == 2)
    {
      const Index a = static_cast<Index>(key / pointCount), b = static_cast<Index>(key % pointCount);
      corners.unite(cornerOf(uses[0], a), cornerOf(uses[1], a));
      corners.unite(cornerOf(uses[0], b), cornerOf(uses[1], b));
    }
  }
  std::vector<std::size_t> groupOf(pointCount, SIZE_MAX);
  std::vector<char> counted(pointCount, 0);
  Index firstVertex = -1;
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
  {
    for (int c = 0; c < 3; ++c)
    {
      const Index v = s.triangles[t][c];
      const std::size_t root = corners.find(3 * t + c);
      if (groupOf[v] == SIZE_MAX)
      {
        groupOf[v] = root;
      }
      else if (groupOf[v] != root && !counted[v])
      {
        counted[v] = 1;
        if (n.nonManifoldVertices++ == 0)
        {
          firstVertex = v;
        }
      }
    }
  }
  // edges that are already non-manifold or open make their ends look
  // non-manifold too; report vertices only when the edges are fine
  if (n.nonManifoldVertices > 0 && n.nonManifoldEdges == 0 && n.boundaryEdges == 0)
  {
    problems.push_back(plural(n.nonManifoldVertices, "non-manifold vertex", "non-manifold vertices") +
      " (where separate sheets of the surface touch in a point), e.g. at " +
      at(s.points[firstVertex]));
    wrappable = true;
  }
  else
  {
    n.nonManifoldVertices = 0;
  }
}

bool InputPreparation::orient()
{
  OrientationResult oriented = orientShells(s);
  if (!oriented.ok)
  {
    problems.push_back(oriented.error);
    wrappable = true;
    return false;
  }
  out.orientation = oriented.report;
  out.orientation.mergedPoints = n.mergedPoints;
  out.orientation.droppedTriangles = n.collapsedTriangles + n.duplicateTriangles + n.zeroAreaTriangles;
  if (out.orientation.reorientedTriangles > 0 || out.orientation.invertedShells > 0)
  {
    std::ostringstream msg;
    msg << "orientation repaired: "
        << plural(out.orientation.reorientedTriangles, "triangle", "triangles")
        << " flipped to agree with their neighbours, "
        << plural(out.orientation.invertedShells, "inside-out shell", "inside-out shells")
        << " inverted";
    out.warnings.push_back(msg.str());
  }
  return true;
}

bool InputPreparation::checkSelfIntersections()
{
  if (options.checkSelfIntersections && s.triangles.size() <= options.selfIntersectionLimit)
  {
    const SelfIntersectionReport si = checkSelfIntersection(s, 1000);
    n.selfIntersectionChecked = si.checked;
    n.selfIntersectingPairs = si.pairs;
    if (!si.checked)
    {
      out.warnings.push_back("the self-intersection check could not run: " + si.note);
    }
    else if (si.intersects)
    {
      const Triangle& a = s.triangles[si.firstTriangle];
      std::ostringstream msg;
      msg << "the surface intersects itself: "
          << (si.pairs >= 1000 ? "at least " : "") << plural(si.pairs, "pair", "pairs")
          << " of triangles cross, e.g. input triangles " << source[si.firstTriangle] << " and "
          << source[si.secondTriangle] << " near " << at(s.points[a[0]]);
      problems.push_back(msg.str());
      wrappable = true;
      return false;
    }
  }
  else if (options.checkSelfIntersections)
  {
    std::ostringstream msg;
    msg << "self-intersections were not checked: the surface has " << s.triangles.size()
        << " triangles, more than the check's limit of " << options.selfIntersectionLimit;
    out.warnings.push_back(msg.str());
  }
  return true;
}

bool InputPreparation::measureVolume()
{
  double volume = 0;
  for (double v : out.orientation.shellVolume)
  {
    volume += v;
  }
  out.enclosedVolume = volume;
  if (!(volume > 0))
  {
    problems.push_back("the surface encloses no volume");
    return false;
  }
  return true;
}
} // namespace

PreparedSurface prepareInputSurface(const TriangleSurface& input, const InputCheckOptions& options)
{
  InputPreparation p(input, options);
  // -- what makes every later check meaningless
  if (!p.checkBasics())
  {
    return p.fail();
  }
  // -- safe repairs: merge, then drop collapsed, duplicated and zero-area triangles
  p.mergePoints();
  p.removeDegenerateTriangles();
  if (p.s.triangles.empty())
  {
    p.problems.push_back("no triangle is left after removing degenerate and duplicated ones");
    return p.fail();
  }
  p.dropUnusedPoints();
  // -- topology: boundary edges, non-manifold edges, non-manifold vertices
  const EdgeTable edges(p.s);
  p.checkEdges(edges);
  p.checkVertices(edges);
  if (!p.problems.empty())
  {
    return p.fail();
  }
  // -- orientation (repairable), then self-intersections (not)
  if (!p.orient() || !p.checkSelfIntersections() || !p.measureVolume())
  {
    return p.fail();
  }
  p.out.surface = std::move(p.s);
  p.out.sourceOfTriangle = std::move(p.source);
  p.out.ok = true;
  return std::move(p.out);
}
} // namespace ptm
