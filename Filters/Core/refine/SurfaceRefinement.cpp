#include "SurfaceRefinement.h"

#include "InterfaceTriangulation.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <unordered_map>
#include <cstdint>
#include <sstream>

namespace ptm
{
namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
/// @name The surface's adjacency
/// @{
// across[t][k]: the triangle on the other side of edge k (from corner k to
// corner k + 1) of triangle t. The surface is closed and edge-manifold (the
// extraction checked it), so every edge has exactly one.
std::vector<std::array<Index, 3>> triangleNeighbours(const std::vector<Triangle>& triangles)
{
  struct Use
  {
    UndirectedEdge edge;
    Index triangle;
    int corner;
  };
  std::vector<Use> uses;
  uses.reserve(3 * triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      uses.push_back({ undirected(triangles[t][k], triangles[t][(k + 1) % 3]), static_cast<Index>(t), k });
    }
  }
  std::sort(uses.begin(), uses.end(), [](const Use& x, const Use& y) {
    return x.edge < y.edge || (x.edge == y.edge && x.triangle < y.triangle);
  });
  std::vector<std::array<Index, 3>> across(triangles.size(), { -1, -1, -1 });
  for (std::size_t i = 0; i + 1 < uses.size(); i += 2)
  {
    across[uses[i].triangle][uses[i].corner] = uses[i + 1].triangle;
    across[uses[i + 1].triangle][uses[i + 1].corner] = uses[i].triangle;
  }
  return across;
}

Kernel::Point_3 cgalPoint(const Vec3& p)
{
  return { p[0], p[1], p[2] };
}

Vec3 triangleNormal(const std::vector<Vec3>& points, const Triangle& t)
{
  return cross(points[t[1]] - points[t[0]], points[t[2]] - points[t[0]]);
}

// Whether outer triangle u may join the facet grown from triangle `seed`:
// facing the same way and, with no tolerance, in its plane (CGAL's exact
// predicate on all three corners, or within round-off); with a tolerance, a normal within
// that angle of the seed's, so a facet cannot drift around a curved surface
// one small step at a time.
bool joinsFacet(
  const SubdomainSurface& s, Index seed, Index u, double cosTolerance, bool exact, double roundOff)
{
  const auto& pts = s.surface.points;
  const Triangle& a = s.surface.triangles[seed];
  const Triangle& b = s.surface.triangles[u];
  const Vec3 na = normalized(triangleNormal(pts, a)), nb = normalized(triangleNormal(pts, b));
  if (!(dot(na, nb) > 0))
  {
    return false;
  }
  if (!exact)
  {
    return dot(na, nb) >= cosTolerance;
  }
  for (Index p : b)
  {
    if (CGAL::orientation(cgalPoint(pts[a[0]]), cgalPoint(pts[a[1]]), cgalPoint(pts[a[2]]), cgalPoint(pts[p])) !=
        CGAL::COPLANAR &&
      !(std::fabs(dot(pts[p] - pts[a[0]], na)) <= roundOff))
    {
      return false;
    }
  }
  return true;
}

// Facet of every outer triangle (-1 on interface triangles), grown across
// edges from the lowest unlabeled triangle; facets are numbered in the order
// of their first triangle, so the same surface always gives the same facets.
std::vector<int> facetLabels(
  const SubdomainSurface& s, const std::vector<std::array<Index, 3>>& across, double toleranceDegrees)
{
  const auto& tris = s.surface.triangles;
  const bool exact = !(toleranceDegrees > 0);
  const double cosTolerance = std::cos(toleranceDegrees * kPi / 180.0);
  // The pieces of one input triangle cut by a plane are coplanar but for the
  // round-off of the cut points (about 1e-16 of the coordinates): such a
  // piece still joins, as everything within 1e-13 of the subdomain's
  // bounding-box diagonal does (or 100 roundings of its coordinates, far
  // from the origin: roundOffTolerance), far below the 1e-12 a point may
  // lie off the input surface.
  const double roundOff = roundOffTolerance(s.surface.points, 1e-13);
  std::vector<int> label(tris.size(), -1);
  int facets = 0;
  std::vector<Index> stack;
  for (std::size_t seed = 0; seed < tris.size(); ++seed)
  {
    if (s.otherSide[seed] >= 0 || label[seed] >= 0)
    {
      continue;
    }
    label[seed] = facets;
    stack.assign(1, static_cast<Index>(seed));
    while (!stack.empty())
    {
      const Index t = stack.back();
      stack.pop_back();
      for (Index u : across[t])
      {
        if (s.otherSide[u] < 0 && label[u] < 0 &&
          joinsFacet(s, static_cast<Index>(seed), u, cosTolerance, exact, roundOff))
        {
          label[u] = facets;
          stack.push_back(u);
        }
      }
    }
    ++facets;
  }
  return label;
}
/// @}

/// @name Segment splitting
/// @{
// The points put on one segment, from its smaller to its larger end.
using SegmentPoints = std::map<UndirectedEdge, std::vector<Index>>;

// The spacing a segment is split at: the target size, or less where a
// corner of one of its two facets lies closer to the segment than that and
// the facet is poor (a triangle under the angle bound: a thin facet, whose
// corner across a long edge is near), so the triangles across a thin facet
// can be well shaped, as TetGen -q splits encroached segments. Corners of
// good facets do not count: splitting the slightly long edge of a good
// triangle only makes worse ones (a gmsh fillet from the corpus, K = 1: 0.33 %
// of the tetrahedra under 10 degrees instead of 0.14 %). Never below an
// eighth of the size (kDefaultSegmentSpacingFloor): a floor of size / 32 split the
// long input edges beside the slivers a cut leaves into 121,000 points on
// CGAL's joint at K = 16 (804,000 tetrahedra, 1.29 % under 10 degrees, where
// K = 2 makes 86,000); size / 8 gave 295,000 and 1.44 %. The price is on
// very thin input strips: OpenSCAD's CSG example, K = 1, 7.3 % under 10
// degrees instead of 6.1 % with size / 32. A corner on a contour counts
// down to kThinPieceSpacingFraction of the size only (SizeFunction.h), the
// floor the contour beside a thin cut piece is split at, so the piece gets
// points at one spacing on both sides. The quarter for every corner cost
// the OpenSCAD and gmsh exports (their thin input triangles): at K = 2
// OpenSCAD example005 went from 1.65 % to 2.53 % under 10 degrees.
// A floor of size / 64 for input corners (contour corners still at a
// quarter) was measured again at K = 1 on the corpus sizes and not taken,
// as it helps only some parts: CGAL's cheese (thin triangles on coarse
// spherical holes) 31.4 % -> 2.2 % under 10 degrees (serial tetgen -pq
// 2.8 %; 65,000 -> 590,000 tetrahedra), gmsh's lever 9.3 % -> 5.6 %, but
// CGAL's joint 0.22 % -> 0.32 %, OCCT linkrods 1.79 % -> 1.95 %, OpenSCAD
// example002 2.86 % -> 3.21 %.
// Splitting again every segment a facet triangle encroaches (obtuse across
// a piece; up to three rounds, each segment halved again, the facets meshed
// anew) was measured on the ball with the size field 0.03*10^((z+1)/2),
// 2 ranks, and not taken: minimum dihedral 2.08 -> 0.30 degrees at K = 4,
// 2.30 -> 1.31 at K = 8, 2.02 -> 0.36 at K = 16; under 10 degrees 0.071 ->
// 0.185 % at K = 4. The obtuse triangle beside a bent input edge seemed to
// cause the worst tetrahedron (four boundary points, two faces on the
// boundary), but the shorter pieces made more such places than they removed.
// Splitting the two segments of a sharp facet corner (the tip of a needle)
// at a ladder of distances shrinking 1.5 x towards the tip, so the strips
// near the tip shrink with their width, was measured at K = 1 and not
// taken: the worst tetrahedra stand on the shortest strip edge whatever its
// length, since TetGen -Y keeps its points out of the neighbouring facets'
// larger diametral balls; CGAL's pinion 0.33 -> 0.11 degrees minimum
// dihedral, CGAL's joint 0.62 -> 0.09, OpenSCAD example001 0.27 -> 0.01.
// Session 23 measured lower floors once more, at K = 2 by bisection on the
// 22 surfaces with thin walls (6 of the corpus, 16 unseen), against serial
// TetGen -pq's goals (share under 10 degrees at most 1.5 x, minimum
// dihedral at least half): size / 8 met the share goal on 16 and the angle
// goal on 16 (2.52 M tetrahedra, 40,470 under 10 degrees); size / 64 on 17
// and 14 (3.92 M, 58,900); size / 1000, about the input's own strip
// widths, on 19 and 15 (6.78 M, 65,930). The finest floor is what serial
// TetGen does (4,005 of its points lie within 0.01 of one 0.001-wide strip
// of Cura's tronxy bed, whose minimum dihedral then rises 0.06 -> 3.52
// degrees, serial 4.44), but it made Prusa's ender3 bed 2.62 M tetrahedra
// (serial 0.22 M) and lowered femur's minimum 0.19 -> 0.00 degrees and
// rr-vc-300's 1.21 -> 0.01.
// Session 26, KiCad's heat sink HS-125 (kicad-packages3d, tessellated by
// OCCT; the size 7.766, K = 1): 14,854 of its 104,920 boundary triangles
// had angles of 5.2 degrees, strips 0.056 wide split at the floor, and
// 24,052 of 289,318 tetrahedra (8.31 %) were under 10 degrees (serial
// TetGen -pq2.0: 1.245 % of 535,722). With a floor of 1/64: 0.089 % of
// 1,182,366 and 1.91 degrees (serial 4.21), but the volume meshing took
// 660 s instead of 32 s (on a loaded machine). So the floor is the
// SurfaceRefinementOptions::segmentSpacingFloor a user may lower.
// Session 29 split the segment beside a thin cut piece between the feet of
// the piece's contour points, never right across from one (where a contour
// point and a point on the segment, as far apart as the piece is thin, stood
// under the worst tetrahedra of the graded ball of issue #22): the ball at
// K = 16 rose from 2.02 to 2.51 degrees, at K = 32 from 2.31 to 3.17, but
// on 32 corpus runs at K = 16 the minimum fell on 14 and rose on 11 (CGAL's
// rotor by bisection 0.38 -> 0.00), for 2.4 % fewer tetrahedra under 10
// degrees. Not kept (Testing/Corpus/results/sliver-round2-session29.md).

class SegmentSpacing
{
public:
  SegmentSpacing(const std::vector<Vec3>& points, const std::vector<Triangle>& triangles,
    const std::vector<int>& label, double size, const SizeFunction& sizeAt, double boundRadians, double floor)
    : Points(points)
    , Size(size)
    , Floor(floor)
    , SizeAt(sizeAt)
    , FacetsOf(points.size())
    , OnInterface(points.size(), 0)
  {
    for (std::size_t t = 0; t < triangles.size(); ++t)
    {
      for (Index p : triangles[t])
      {
        OnInterface[p] = OnInterface[p] || label[t] < 0;
      }
    }
    int facets = 0;
    for (int l : label)
    {
      facets = std::max(facets, l + 1);
    }
    std::vector<char> poor(facets, 0);
    for (std::size_t t = 0; t < triangles.size(); ++t)
    {
      const Triangle& tri = triangles[t];
      if (label[t] >= 0 && triangleMinimumAngle(points[tri[0]], points[tri[1]], points[tri[2]]) < boundRadians)
      {
        poor[label[t]] = 1;
      }
    }
    for (std::size_t t = 0; t < triangles.size(); ++t)
    {
      for (Index p : triangles[t])
      {
        if (label[t] >= 0 && poor[label[t]] &&
          std::find(FacetsOf[p].begin(), FacetsOf[p].end(), label[t]) == FacetsOf[p].end())
        {
          if (FacetsOf[p].empty())
          {
            this->Cells[this->KeyOf(this->CellOf(points[p]))].push_back(p);
          }
          FacetsOf[p].push_back(label[t]);
        }
      }
    }
  }

  double Spacing(Index a, Index b, int facetA, int facetB) const
  {
    const Vec3 pa = this->Points[a], d = this->Points[b] - pa;
    const double local = this->LocalSize(pa + 0.5 * d);
    double spacing = local;
    std::array<long long, 3> lo = this->CellOf(pa), hi = lo;
    for (const std::array<long long, 3>& c : { this->CellOf(this->Points[b]) })
    {
      for (int i = 0; i < 3; ++i)
      {
        lo[i] = std::min(lo[i], c[i]) - 1;
        hi[i] = std::max(hi[i], c[i]) + 1;
      }
    }
    for (long long i = lo[0]; i <= hi[0]; ++i)
      for (long long j = lo[1]; j <= hi[1]; ++j)
        for (long long k = lo[2]; k <= hi[2]; ++k)
        {
          auto it = this->Cells.find(this->KeyOf({ i, j, k }));
          if (it == this->Cells.end())
          {
            continue;
          }
          for (Index v : it->second)
          {
            const auto& f = this->FacetsOf[v];
            if (v == a || v == b ||
              (std::find(f.begin(), f.end(), facetA) == f.end() && std::find(f.begin(), f.end(), facetB) == f.end()))
            {
              continue;
            }
            const double floor =
              this->OnInterface[v] ? std::max(kThinPieceSpacingFraction, this->Floor) : this->Floor;
            spacing = std::min(spacing, std::max(floor * local, distanceToSegment(this->Points[v], pa, this->Points[b])));
          }
        }
    return spacing;
  }

private:
  double LocalSize(const Vec3& p) const { return cappedSizeAt(this->SizeAt, this->Size, p); }
  std::array<long long, 3> CellOf(const Vec3& p) const
  {
    return { static_cast<long long>(std::floor(p[0] / this->Size)),
      static_cast<long long>(std::floor(p[1] / this->Size)), static_cast<long long>(std::floor(p[2] / this->Size)) };
  }
  static std::uint64_t KeyOf(const std::array<long long, 3>& c)
  {
    // cells that share a key only add candidates
    return static_cast<std::uint64_t>(c[0]) * 73856093ULL ^ static_cast<std::uint64_t>(c[1]) * 19349663ULL ^
      static_cast<std::uint64_t>(c[2]) * 83492791ULL;
  }

  const std::vector<Vec3>& Points;
  double Size;
  double Floor; // of the spacing beside a poor facet's corner, a fraction of the local size
  const SizeFunction& SizeAt;
  std::vector<std::vector<int>> FacetsOf; // the facets each point is a corner of a poor triangle of
  std::vector<char> OnInterface;          // a point of an interface triangle (a contour point)
  std::unordered_map<std::uint64_t, std::vector<Index>> Cells;
};

// Splits every edge between two different outer facets into equal parts at
// most its SegmentSpacing long (rounded to the nearer count); the new points
// are appended to `points` in the order of the triangles and their corners,
// so the same surface always numbers them alike. Edges next to an interface
// are contours, which the neighbouring subdomain has too: never split here.
SegmentPoints splitSegments(SubdomainSurface& s, const std::vector<std::array<Index, 3>>& across,
  const std::vector<int>& label, const SurfaceRefinementOptions& options)
{
  SegmentPoints split;
  auto& pts = s.surface.points;
  const auto& tris = s.surface.triangles;
  // the spacing looks at the input's corners only, so the new points are
  // appended after every segment is measured
  const SegmentSpacing spacing(pts, tris, label, options.size, options.sizeAt,
    options.minimumAngleDegrees * kPi / 180.0, options.segmentSpacingFloor);
  std::vector<Vec3> added;
  for (std::size_t t = 0; t < tris.size(); ++t)
  {
    for (int k = 0; k < 3 && label[t] >= 0; ++k)
    {
      const Index u = across[t][k];
      if (u < static_cast<Index>(t) || label[u] < 0 || label[u] == label[t])
      {
        continue;
      }
      const UndirectedEdge e = undirected(tris[t][k], tris[t][(k + 1) % 3]);
      const Vec3 a = pts[e[0]], d = pts[e[1]] - pts[e[0]];
      const double parts = std::round(norm(d) / spacing.Spacing(e[0], e[1], label[t], label[u]));
      if (!(parts >= 2))
      {
        continue;
      }
      std::vector<Index>& onSegment = split[e];
      for (int i = 1; i < static_cast<int>(parts); ++i)
      {
        onSegment.push_back(static_cast<Index>(pts.size() + added.size()));
        added.push_back(a + (static_cast<double>(i) / parts) * d);
      }
    }
  }
  pts.insert(pts.end(), added.begin(), added.end());
  return split;
}
/// @}

/// @name Facet meshing
/// @{
struct Facet
{
  std::vector<Index> triangles;
  bool hasSplitSegment = false;
};

std::vector<Facet> collectFacets(const SubdomainSurface& s, const std::vector<std::array<Index, 3>>& across,
  const std::vector<int>& label, const SegmentPoints& split)
{
  int count = 0;
  for (int l : label)
  {
    count = std::max(count, l + 1);
  }
  std::vector<Facet> facets(count);
  for (std::size_t t = 0; t < label.size(); ++t)
  {
    if (label[t] < 0)
    {
      continue;
    }
    Facet& f = facets[label[t]];
    f.triangles.push_back(static_cast<Index>(t));
    for (int k = 0; k < 3; ++k)
    {
      const Triangle& tri = s.surface.triangles[t];
      f.hasSplitSegment = f.hasSplitSegment ||
        (label[across[t][k]] != label[t] && split.count(undirected(tri[k], tri[(k + 1) % 3])));
    }
  }
  return facets;
}

// The facet as a planar region: every corner of its triangles (the inner ones
// stay as fixed vertices), its boundary edges in the triangles' direction
// (region on the left seen from the outward normal) with the points of split
// segments in between. `surfaceIndex` gives each region point's index in the
// surface.
PlanarRegion facetRegion(const SubdomainSurface& s, const std::vector<Vec3>& pts, const Facet& facet,
  const std::vector<std::array<Index, 3>>& across, const std::vector<int>& label,
  const SegmentPoints& split, std::vector<Index>& surfaceIndex)
{
  PlanarRegion region;
  std::map<Index, Index> localOf;
  auto local = [&](Index p) {
    auto it = localOf.emplace(p, static_cast<Index>(surfaceIndex.size()));
    if (it.second)
    {
      surfaceIndex.push_back(p);
      region.points.push_back(pts[p]);
    }
    return it.first->second;
  };
  Vec3 normal{ 0, 0, 0 };
  for (Index t : facet.triangles)
  {
    const Triangle& tri = s.surface.triangles[t];
    normal = normal + triangleNormal(pts, tri);
    for (int k = 0; k < 3; ++k)
    {
      local(tri[k]);
    }
  }
  for (Index t : facet.triangles)
  {
    const Triangle& tri = s.surface.triangles[t];
    for (int k = 0; k < 3; ++k)
    {
      if (label[across[t][k]] == label[t])
      {
        continue;
      }
      std::vector<Index> chain{ tri[k] };
      auto it = split.find(undirected(tri[k], tri[(k + 1) % 3]));
      if (it != split.end())
      {
        if (tri[k] < tri[(k + 1) % 3])
        {
          chain.insert(chain.end(), it->second.begin(), it->second.end());
        }
        else
        {
          chain.insert(chain.end(), it->second.rbegin(), it->second.rend());
        }
      }
      chain.push_back(tri[(k + 1) % 3]);
      for (std::size_t i = 0; i + 1 < chain.size(); ++i)
      {
        region.edges.push_back({ local(chain[i]), local(chain[i + 1]) });
      }
    }
  }
  region.normal = normalized(normal);
  region.origin = region.points.front();
  return region;
}

// Which input triangle of a facet lies under a point (seen along the facet's
// normal), looked up in a grid over the facet's plane.
class SourceLocator
{
public:
  SourceLocator(const SubdomainSurface& s, const Facet& facet, const Vec3& normal)
    : Surface(s)
  {
    planeBasis(normal, E1, E2);
    double lo[2] = { std::numeric_limits<double>::max(), std::numeric_limits<double>::max() };
    double hi[2] = { -lo[0], -lo[1] };
    for (Index t : facet.triangles)
    {
      for (Index p : s.surface.triangles[t])
      {
        const auto q = this->To2D(s.surface.points[p]);
        for (int c = 0; c < 2; ++c)
        {
          lo[c] = std::min(lo[c], q[c]);
          hi[c] = std::max(hi[c], q[c]);
        }
      }
    }
    this->Cells = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(facet.triangles.size()))));
    for (int c = 0; c < 2; ++c)
    {
      this->Low[c] = lo[c];
      this->Step[c] = std::max((hi[c] - lo[c]) / this->Cells, 1e-300);
    }
    this->Grid.resize(static_cast<std::size_t>(this->Cells) * this->Cells);
    for (Index t : facet.triangles)
    {
      int from[2] = { this->Cells, this->Cells }, to[2] = { -1, -1 };
      for (Index p : s.surface.triangles[t])
      {
        const auto q = this->To2D(s.surface.points[p]);
        for (int c = 0; c < 2; ++c)
        {
          from[c] = std::min(from[c], this->CellOf(q[c], c));
          to[c] = std::max(to[c], this->CellOf(q[c], c));
        }
      }
      for (int i = from[0]; i <= to[0]; ++i)
      {
        for (int j = from[1]; j <= to[1]; ++j)
        {
          this->Grid[i * this->Cells + j].push_back(t);
        }
      }
    }
  }

  // The facet triangle under point x (the nearest by barycentric excess
  // where round-off puts x just outside every one).
  Index TriangleUnder(const Vec3& x) const
  {
    const auto q = this->To2D(x);
    const auto& candidates = this->Grid[this->CellOf(q[0], 0) * this->Cells + this->CellOf(q[1], 1)];
    Index best = -1;
    double bestExcess = std::numeric_limits<double>::infinity();
    for (Index t : candidates)
    {
      const Triangle& tri = this->Surface.surface.triangles[t];
      const auto a = this->To2D(this->Surface.surface.points[tri[0]]);
      const auto b = this->To2D(this->Surface.surface.points[tri[1]]);
      const auto c = this->To2D(this->Surface.surface.points[tri[2]]);
      const double area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
      const double l[3] = { ((b[0] - q[0]) * (c[1] - q[1]) - (b[1] - q[1]) * (c[0] - q[0])) / area,
        ((c[0] - q[0]) * (a[1] - q[1]) - (c[1] - q[1]) * (a[0] - q[0])) / area,
        ((a[0] - q[0]) * (b[1] - q[1]) - (a[1] - q[1]) * (b[0] - q[0])) / area };
      const double excess = -std::min({ l[0], l[1], l[2], 0.0 });
      if (excess < bestExcess)
      {
        bestExcess = excess;
        best = t;
      }
    }
    return best;
  }

private:
  std::array<double, 2> To2D(const Vec3& p) const { return { dot(p, E1), dot(p, E2) }; }
  int CellOf(double v, int c) const
  {
    return std::clamp(static_cast<int>((v - this->Low[c]) / this->Step[c]), 0, this->Cells - 1);
  }

  const SubdomainSurface& Surface;
  Vec3 E1, E2;
  double Low[2] = { 0, 0 }, Step[2] = { 1, 1 };
  int Cells = 1;
  std::vector<std::vector<Index>> Grid;
};

// The outer triangles' share of the enclosed volume (divergence theorem);
// the interface triangles do not change, so its difference is the change of
// the subdomain's volume.
double outerVolume(const SubdomainSurface& s)
{
  if (s.surface.points.empty())
  {
    return 0.0;
  }
  std::vector<Index> outer;
  for (std::size_t t = 0; t < s.surface.triangles.size(); ++t)
  {
    if (s.otherSide[t] < 0)
    {
      outer.push_back(static_cast<Index>(t));
    }
  }
  // about the first point, which the refinement keeps (new points go after)
  return volumeAbout(s.surface.points[0], s.surface.points, s.surface.triangles, outer);
}

double outerMinimumAngle(const SubdomainSurface& s)
{
  double smallest = kPi;
  for (std::size_t t = 0; t < s.surface.triangles.size(); ++t)
  {
    if (s.otherSide[t] < 0)
    {
      const Triangle& tri = s.surface.triangles[t];
      smallest = std::min(smallest,
        triangleMinimumAngle(s.surface.points[tri[0]], s.surface.points[tri[1]], s.surface.points[tri[2]]));
    }
  }
  return smallest * 180.0 / kPi;
}

// Where the line through x along `direction` meets the plane of triangle t.
Vec3 ontoTrianglePlane(const std::vector<Vec3>& pts, const Triangle& t, const Vec3& x, const Vec3& direction)
{
  const Vec3 n = triangleNormal(pts, t);
  const double along = dot(direction, n);
  return along != 0 ? x + (dot(pts[t[0]] - x, n) / along) * direction : x;
}

double distanceToTrianglePlane(const std::vector<Vec3>& pts, const Triangle& t, const Vec3& x)
{
  return std::fabs(dot(x - pts[t[0]], normalized(triangleNormal(pts, t))));
}

// Meshes one facet of `s` anew and appends its triangles (and new points) to
// `out`, whose points already hold the split segments' points; false with
// `error` set where the facet mesher refuses its boundary. A facet that is
// only nearly planar (a coplanar tolerance) has its new points lifted onto
// the input triangles under them; `deviation` grows to the largest distance
// of a new triangle's centroid from the input surface.
bool meshFacet(const SubdomainSurface& s, const Facet& facet, const std::vector<std::array<Index, 3>>& across,
  const std::vector<int>& label, const SegmentPoints& split, const InterfaceTriangulationOptions& options,
  bool nearlyPlanar, SubdomainSurface& out, double& deviation, std::string& error)
{
  std::vector<Index> surfaceIndex;
  const PlanarRegion region = facetRegion(s, out.surface.points, facet, across, label, split, surfaceIndex);
  const InterfaceTriangulationResult r = triangulateInterface(region, options);
  if (!r.ok)
  {
    error = r.error;
    return false;
  }
  std::map<Index, Index> sources;
  for (Index t : facet.triangles)
  {
    sources.emplace(s.sourceFaces[t], t);
  }
  std::optional<SourceLocator> locator;
  if (sources.size() > 1 || nearlyPlanar)
  {
    locator.emplace(s, facet, region.normal);
  }
  const auto& inputPoints = s.surface.points;
  const Index firstNew = static_cast<Index>(out.surface.points.size());
  for (const Vec3& x : r.triangulation.newPoints)
  {
    out.surface.points.push_back(nearlyPlanar
        ? ontoTrianglePlane(inputPoints, s.surface.triangles[locator->TriangleUnder(x)], x, region.normal)
        : x);
  }
  const Index n = static_cast<Index>(surfaceIndex.size());
  for (const Triangle& t : r.triangulation.triangles)
  {
    Triangle mapped;
    for (int c = 0; c < 3; ++c)
    {
      mapped[c] = t[c] < n ? surfaceIndex[t[c]] : firstNew + (t[c] - n);
    }
    out.surface.triangles.push_back(mapped);
    Index under = facet.triangles.front();
    if (locator)
    {
      const Vec3 centroid = (1.0 / 3.0) *
        (out.surface.points[mapped[0]] + out.surface.points[mapped[1]] + out.surface.points[mapped[2]]);
      under = locator->TriangleUnder(centroid);
      if (nearlyPlanar)
      {
        deviation = std::max(deviation, distanceToTrianglePlane(inputPoints, s.surface.triangles[under], centroid));
      }
    }
    out.sourceFaces.push_back(s.sourceFaces[under]);
    out.otherSide.push_back(-1);
  }
  return true;
}
/// @}

// The tetrahedra the volume bound (a regular tetrahedron of edge `size`)
// predicts for the closed surface `s`: 2 x its volume / the bound.
double expectedTetrahedra(const SubdomainSurface& s, double size)
{
  return 2.0 * std::fabs(enclosedVolume(s.surface)) / regularTetrahedronVolume(size);
}

// The most points the refinement may put on one subdomain's segments, per
// predicted tetrahedron and surface point: kMostPointsAddedPerExpected at
// the default floor, more for a lower one (a strip is split at the floor,
// so its points grow as 1 / floor).
double mostPointsFactor(double floor)
{
  return kMostPointsAddedPerExpected * kDefaultSegmentSpacingFloor / floor;
}

std::string tooManyPointsWarning(
  std::size_t onSegments, double factor, double expected, const SubdomainSurface& s)
{
  const std::size_t thin = trianglesWithAngleUnder(s.surface, 10.0 * kPi / 180.0);
  std::ostringstream msg;
  msg << "boundary refinement skipped: it would put " << onSegments << " points on the edges of the outer "
      << "boundary, more than " << factor << " x the " << static_cast<long long>(expected)
      << " tetrahedra the size predicts here plus the " << s.surface.points.size() << " surface points ("
      << thin << " of its triangles have an angle under 10 degrees: long thin input triangles are split "
      << "at their width); the surface is meshed as it is. Remeshing the input (--remesh) avoids this";
  return msg.str();
}

// `result` for a surface left as it was.
SurfaceRefinementResult unrefined(SurfaceRefinementResult& result)
{
  result.minimumAngleAfter = result.minimumAngleBefore;
  result.facetsMeshed = 0;
  result.segmentsSplit = 0;
  result.pointsAdded = 0;
  result.largestDeviation = 0;
  result.ok = true;
  return result;
}
} // namespace

SurfaceRefinementResult refineSubdomainSurface(
  SubdomainSurface& surface, const SurfaceRefinementOptions& options)
{
  SurfaceRefinementResult result;
  if (!(options.size > 0) || !std::isfinite(options.size) ||
    !(options.minimumAngleDegrees > 0 && options.minimumAngleDegrees <= 34) ||
    !(options.coplanarToleranceDegrees >= 0 && options.coplanarToleranceDegrees <= 10) ||
    !(options.segmentSpacingFloor >= kSmallestSegmentSpacingFloor && options.segmentSpacingFloor <= 1))
  {
    result.error = "invalid options: the size must be positive, the minimum angle lie in (0, 34] degrees, "
                   "the coplanar tolerance in [0, 10] degrees and the segment spacing floor in [1/1024, 1]";
    return result;
  }
  result.minimumAngleBefore = outerMinimumAngle(surface);
  const auto across = triangleNeighbours(surface.surface.triangles);
  const std::vector<int> label = facetLabels(surface, across, options.coplanarToleranceDegrees);
  const double volumeBefore = outerVolume(surface);

  SubdomainSurface refined = surface; // the work copy: the input stays intact for a fallback
  const SegmentPoints split = splitSegments(refined, across, label, options);
  const double expected = expectedTetrahedra(surface, options.size);
  const double factor = mostPointsFactor(options.segmentSpacingFloor);
  const std::size_t most =
    static_cast<std::size_t>(factor * (expected + static_cast<double>(surface.surface.points.size())));
  const std::size_t onSegments = refined.surface.points.size() - surface.surface.points.size();
  if (onSegments > most)
  {
    result.warnings.push_back(tooManyPointsWarning(onSegments, factor, expected, surface));
    return unrefined(result);
  }
  const std::vector<Facet> facets = collectFacets(surface, across, label, split);
  result.facets = facets.size();
  result.segmentsSplit = split.size();
  refined.surface.triangles.clear();
  refined.sourceFaces.clear();
  refined.otherSide.clear();
  for (std::size_t t = 0; t < surface.surface.triangles.size(); ++t)
  {
    // interface triangles, and the facets that stay as they are, first
    const bool keep = label[t] < 0 ||
      (facets[label[t]].triangles.size() == 1 && !facets[label[t]].hasSplitSegment);
    if (keep)
    {
      refined.surface.triangles.push_back(surface.surface.triangles[t]);
      refined.sourceFaces.push_back(surface.sourceFaces[t]);
      refined.otherSide.push_back(surface.otherSide[t]);
    }
  }
  InterfaceTriangulationOptions facetOptions;
  facetOptions.minimumAngleDegrees = options.minimumAngleDegrees;
  facetOptions.maximumEdgeLength = options.size;
  facetOptions.sizeAt = options.sizeAt;
  facetOptions.keepIsolatedPoints = true;
  for (std::size_t f = 0; f < facets.size(); ++f)
  {
    if (facets[f].triangles.size() == 1 && !facets[f].hasSplitSegment)
    {
      continue;
    }
    std::string why;
    if (!meshFacet(surface, facets[f], across, label, split, facetOptions, options.coplanarToleranceDegrees > 0,
          refined, result.largestDeviation, why))
    {
      std::ostringstream msg;
      msg << "boundary refinement skipped: a planar facet of " << facets[f].triangles.size()
          << " triangles could not be meshed (" << why << "); the surface is meshed as it is";
      result.warnings.push_back(msg.str());
      return unrefined(result);
    }
    ++result.facetsMeshed;
  }
  result.pointsAdded = refined.surface.points.size() - surface.surface.points.size();
  surface = std::move(refined);
  result.minimumAngleAfter = outerMinimumAngle(surface);
  result.volumeChange = outerVolume(surface) - volumeBefore;
  result.ok = true;
  return result;
}
} // namespace ptm
