#include "BoundarySliverRepair.h"

#include "TetrahedronQuality.h"

#include <algorithm>
#include <functional>
#include <iterator>
#include <limits>
#include <numeric>

namespace ptm
{
namespace
{
// Below this fraction of its mean edge, an edge of a flat tetrahedron joins
// two surface points too close for a point between them to help.
constexpr double kTinyEdgeFraction = 0.1;
// How far above the flat tetrahedron the point goes, in its mean edges:
// half an edge makes the new tetrahedra on its surface faces about as high
// as they are wide. Above a tetrahedron with one face on the surface (a
// wedge) it goes at most halfway to the tetrahedron's circumsphere, since
// TetGen's flips remove the tetrahedron only if the point lies inside that
// sphere; not above one with two faces there (an ear), whose sphere may lie
// mostly outside. Measured at K = 16 with 2 ranks (smallest dihedral angle,
// share under 10 degrees): with every point at most halfway to the sphere,
// CGAL's eight (recursive bisection) stayed at 1.43 degrees and fandisk at
// 0.22; with none so bounded they rose to 3.18 and 2.97, but the triple
// torus (parallel planes) kept none of its new parts (0.241 %); bounding
// the wedges only gives 3.18, 3.04 and 0.239 %.
constexpr double kLiftFraction = 0.5;
// The third round (SliverKind::WithATinyEdge) takes only the flattest few
// of its tetrahedra in each subdomain: it is there for the subdomain's
// worst. Measured in session 38 with all of them (K = 16 on 2 ranks, the
// sweep's size): KiCad's fuse holder, whose boundary is mostly tiny edges,
// took 13.6 -> 23.3 s of volume meshing by bisection and 17.6 -> 26.6 s
// with planes, its smallest angle 0.00 degrees either way.
constexpr std::size_t kTinyEdgeRoundPoints = 4;

const int kFaceCorners[4][3] = { { 0, 1, 2 }, { 0, 1, 3 }, { 0, 2, 3 }, { 1, 2, 3 } };

// The sorted key of face f of tetrahedron t (kFaceCorners).
Triangle faceKey(const std::array<Index, 4>& t, int f)
{
  return sortedCorners(Triangle{ t[kFaceCorners[f][0]], t[kFaceCorners[f][1]], t[kFaceCorners[f][2]] });
}

// How many faces of the tetrahedron are surface triangles.
int surfaceFaceCount(const std::vector<Triangle>& surfaceKeys, const std::array<Index, 4>& t)
{
  int count = 0;
  for (int f = 0; f < 4; ++f)
  {
    count += std::binary_search(surfaceKeys.begin(), surfaceKeys.end(), faceKey(t, f)) ? 1 : 0;
  }
  return count;
}

// The mean inward unit normal of the tetrahedron's faces on the surface
// (inward: towards the corner off each face); returns how many faces are on
// the surface (0: none, their normals cancel, or two of them meet at an
// angle under `angleDegrees`).
int inwardNormal(const std::vector<Triangle>& surfaceKeys, const TetMesh& mesh, const std::array<Index, 4>& t,
  double angleDegrees, Vec3& inward)
{
  std::vector<Vec3> normals;
  for (int f = 0; f < 4; ++f)
  {
    const Triangle face{ t[kFaceCorners[f][0]], t[kFaceCorners[f][1]], t[kFaceCorners[f][2]] };
    if (!std::binary_search(surfaceKeys.begin(), surfaceKeys.end(), sortedCorners(face)))
    {
      continue;
    }
    const Vec3& a = mesh.points[face[0]];
    Vec3 n = cross(mesh.points[face[1]] - a, mesh.points[face[2]] - a);
    const double length = norm(n);
    if (!(length > 0))
    {
      continue;
    }
    const Vec3& off = mesh.points[t[6 - kFaceCorners[f][0] - kFaceCorners[f][1] - kFaceCorners[f][2]]];
    normals.push_back((dot(n, off - a) > 0 ? 1.0 : -1.0) / length * n);
  }
  // two surface faces at an angle under the bound: the surface itself is
  // that sharp there (a plane meeting the input at a shallow angle), and
  // every tetrahedron on that edge keeps the angle
  for (std::size_t i = 0; i < normals.size(); ++i)
  {
    for (std::size_t j = i + 1; j < normals.size(); ++j)
    {
      if (180.0 - std::acos(std::clamp(dot(normals[i], normals[j]), -1.0, 1.0)) * 180.0 / kPi < angleDegrees)
      {
        return 0;
      }
    }
  }
  Vec3 sum{ 0, 0, 0 };
  for (const Vec3& n : normals)
  {
    sum = sum + n;
  }
  const double length = norm(sum);
  if (!(length > 0))
  {
    return 0;
  }
  inward = (1.0 / length) * sum;
  return static_cast<int>(normals.size());
}

// How far from `from` along the unit vector `direction` the circumsphere of
// the tetrahedron a, b, c, d ends (`from` inside it); infinite for a flat
// one (no finite sphere).
double distanceToCircumsphere(
  const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& from, const Vec3& direction)
{
  const Vec3 ba = b - a, ca = c - a, da = d - a;
  const double denominator = 2.0 * dot(ba, cross(ca, da));
  if (denominator == 0.0)
  {
    return std::numeric_limits<double>::infinity();
  }
  const Vec3 centre = a +
    (1.0 / denominator) *
      (dot(ba, ba) * cross(ca, da) + dot(ca, ca) * cross(da, ba) + dot(da, da) * cross(ba, ca));
  const Vec3 offset = from - centre;
  const double radius2 = dot(a - centre, a - centre);
  const double along = dot(direction, offset);
  const double discriminant = along * along - (dot(offset, offset) - radius2);
  return -along + std::sqrt(std::max(discriminant, 0.0));
}

// The mean and the shortest of the tetrahedron's six edges.
void edgeLengths(const TetMesh& mesh, const std::array<Index, 4>& t, double& mean, double& shortest)
{
  double sum = 0;
  shortest = std::numeric_limits<double>::max();
  for (int a = 0; a < 4; ++a)
  {
    for (int b = a + 1; b < 4; ++b)
    {
      const double length = norm(mesh.points[t[a]] - mesh.points[t[b]]);
      sum += length;
      shortest = std::min(shortest, length);
    }
  }
  mean = sum / 6.0;
}

// Adds to the cavity every tetrahedron with a corner marked. One pass over
// the mesh instead of a table of the tetrahedra at every point, which
// would take 32 bytes per tetrahedron (a sixth of the mesh's own) for
// cavities of a few hundred.
void addTetrahedraAt(const TetMesh& mesh, const std::vector<char>& marked, std::vector<char>& inCavity)
{
  for (std::size_t k = 0; k < mesh.tets.size(); ++k)
  {
    const auto& t = mesh.tets[k];
    if (!inCavity[k] && std::any_of(t.begin(), t.end(), [&](Index v) { return marked[v] != 0; }))
    {
      inCavity[k] = 1;
    }
  }
}

// The faces of the tetrahedra `tets` used once, turned outward.
std::vector<Triangle> cavityBoundary(const TetMesh& mesh, const std::vector<Index>& tets)
{
  std::vector<Triangle> faces;
  for (Index k : tets)
  {
    const auto& t = mesh.tets[k];
    for (const Triangle& f : outwardTetrahedronFaces(t))
    {
      faces.push_back(f);
    }
  }
  std::vector<std::pair<Triangle, std::size_t>> keys(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f)
  {
    keys[f] = { sortedCorners(faces[f]), f };
  }
  std::sort(keys.begin(), keys.end());
  std::vector<Triangle> boundary;
  for (std::size_t i = 0; i < keys.size();)
  {
    std::size_t j = i + 1;
    while (j < keys.size() && keys[j].first == keys[i].first)
    {
      ++j;
    }
    if (j - i == 1)
    {
      boundary.push_back(faces[keys[i].second]);
    }
    i = j;
  }
  return boundary;
}

// Whether the faces around one point form a single fan (a disc, as on a
// closed manifold surface): joined across the edges at the point, they are
// one group, and every such edge has two of them.
bool singleFan(Index v, const std::vector<Triangle>& boundary, const std::vector<std::size_t>& around)
{
  std::vector<std::pair<Index, std::size_t>> spokes; // (the edge's other end, face)
  for (std::size_t f : around)
  {
    for (Index w : boundary[f])
    {
      if (w != v)
      {
        spokes.push_back({ w, f });
      }
    }
  }
  std::sort(spokes.begin(), spokes.end());
  std::vector<std::size_t> group(around.size());
  std::iota(group.begin(), group.end(), 0);
  auto slot = [&](std::size_t f) {
    return static_cast<std::size_t>(std::find(around.begin(), around.end(), f) - around.begin());
  };
  std::function<std::size_t(std::size_t)> root = [&](std::size_t i) {
    return group[i] == i ? i : group[i] = root(group[i]);
  };
  for (std::size_t i = 0; i < spokes.size();)
  {
    std::size_t j = i + 1;
    while (j < spokes.size() && spokes[j].first == spokes[i].first)
    {
      ++j;
    }
    if (j - i != 2)
    {
      return false;
    }
    group[root(slot(spokes[i].second))] = root(slot(spokes[i + 1].second));
    i = j;
  }
  std::size_t roots = 0;
  for (std::size_t i = 0; i < around.size(); ++i)
  {
    roots += root(i) == i ? 1 : 0;
  }
  return roots == 1;
}

// The points where the cavity's boundary is not a closed manifold surface
// (an edge with other than two faces, or two fans meeting at a point).
std::vector<Index> pinchedPoints(const std::vector<Triangle>& boundary)
{
  std::vector<std::pair<Index, std::size_t>> incidence;
  for (std::size_t f = 0; f < boundary.size(); ++f)
  {
    for (Index v : boundary[f])
    {
      incidence.push_back({ v, f });
    }
  }
  std::sort(incidence.begin(), incidence.end());
  std::vector<Index> pinched;
  std::vector<std::size_t> around;
  for (std::size_t i = 0; i < incidence.size();)
  {
    around.clear();
    std::size_t j = i;
    for (; j < incidence.size() && incidence[j].first == incidence[i].first; ++j)
    {
      around.push_back(incidence[j].second);
    }
    if (!singleFan(incidence[i].first, boundary, around))
    {
      pinched.push_back(incidence[i].first);
    }
    i = j;
  }
  return pinched;
}

// The cavity: the tetrahedra within two rings of a flat one of `points`
// (sharing a corner with one, or with a tetrahedron that does), grown by
// the tetrahedra at every point where its boundary is pinched; empty if it
// is still pinched after a few rounds. A pinched boundary is no closed
// surface for TetGen: with one ring and no growing, 4 of 17 cavities on
// CGAL's eight and fandisk at K = 16 were refused as self-intersecting.
// Rings, measured on eight at K = 16 (recursive bisection, 2 ranks): with
// one its worst part kept 1.43 degrees (4.09 came with one tetrahedron more
// under 10 degrees); with two it rose to 3.18; with three, 2.20.
constexpr int kCavityRounds = 4;
constexpr int kCavityRings = 2;

std::vector<Index> marked(const std::vector<char>& mask)
{
  std::vector<Index> tets;
  for (std::size_t k = 0; k < mask.size(); ++k)
  {
    if (mask[k])
    {
      tets.push_back(static_cast<Index>(k));
    }
  }
  return tets;
}

std::vector<char> cavityOf(const TetMesh& mesh, const std::vector<BoundarySliverPoint>& points)
{
  std::vector<char> inCavity(mesh.tets.size(), 0), corner(mesh.points.size(), 0);
  for (const auto& p : points)
  {
    for (Index v : mesh.tets[p.tetrahedron])
    {
      corner[v] = 1;
    }
  }
  addTetrahedraAt(mesh, corner, inCavity);
  for (int ring = 1; ring < kCavityRings; ++ring)
  {
    for (Index k : marked(inCavity))
    {
      for (Index v : mesh.tets[k])
      {
        corner[v] = 1;
      }
    }
    addTetrahedraAt(mesh, corner, inCavity);
  }
  for (int round = 0; round < kCavityRounds; ++round)
  {
    const std::vector<Index> pinched = pinchedPoints(cavityBoundary(mesh, marked(inCavity)));
    if (pinched.empty())
    {
      return inCavity;
    }
    std::fill(corner.begin(), corner.end(), 0);
    for (Index v : pinched)
    {
      corner[v] = 1;
    }
    addTetrahedraAt(mesh, corner, inCavity);
  }
  return pinchedPoints(cavityBoundary(mesh, marked(inCavity))).empty() ? inCavity : std::vector<char>{};
}

// One connected part of the cavity (tetrahedra joined through shared
// points), with the sliver points of its flat tetrahedra: each is meshed
// again, and kept or not, on its own.
struct CavityPart
{
  std::vector<Index> tets;
  std::vector<std::size_t> points; // into the sliver points
};

std::vector<CavityPart> cavityParts(
  const TetMesh& mesh, const std::vector<char>& inCavity, const std::vector<BoundarySliverPoint>& points)
{
  const std::vector<Index> tets = marked(inCavity);
  // tetrahedra sharing a point join: union-find over the cavity's own
  std::vector<std::size_t> group(tets.size());
  std::iota(group.begin(), group.end(), 0);
  std::function<std::size_t(std::size_t)> root = [&](std::size_t i) {
    return group[i] == i ? i : group[i] = root(group[i]);
  };
  std::vector<std::pair<Index, std::size_t>> corners; // (point, position in tets)
  for (std::size_t i = 0; i < tets.size(); ++i)
  {
    for (Index v : mesh.tets[tets[i]])
    {
      corners.push_back({ v, i });
    }
  }
  std::sort(corners.begin(), corners.end());
  for (std::size_t i = 1; i < corners.size(); ++i)
  {
    if (corners[i].first == corners[i - 1].first)
    {
      group[root(corners[i].second)] = root(corners[i - 1].second);
    }
  }
  std::vector<int> partOfRoot(tets.size(), -1);
  std::vector<CavityPart> parts;
  for (std::size_t i = 0; i < tets.size(); ++i)
  {
    int& id = partOfRoot[root(i)];
    if (id < 0)
    {
      id = static_cast<int>(parts.size());
      parts.emplace_back();
    }
    parts[id].tets.push_back(tets[i]); // ascending, as tets is
  }
  for (std::size_t p = 0; p < points.size(); ++p)
  {
    const auto i = static_cast<std::size_t>(
      std::lower_bound(tets.begin(), tets.end(), points[p].tetrahedron) - tets.begin());
    parts[partOfRoot[root(i)]].points.push_back(p);
  }
  return parts;
}

// The closed surface of a cavity: its boundary faces turned outward, on its
// boundary points in ascending order; `meshPoint` maps them back.
struct Cavity
{
  TriangleSurface surface;
  std::vector<Index> meshPoint;
};

Cavity cavitySurface(const TetMesh& mesh, const std::vector<Index>& tets)
{
  Cavity cavity;
  const std::vector<Triangle> boundary = cavityBoundary(mesh, tets);
  for (const auto& f : boundary)
  {
    cavity.meshPoint.insert(cavity.meshPoint.end(), f.begin(), f.end());
  }
  std::sort(cavity.meshPoint.begin(), cavity.meshPoint.end());
  cavity.meshPoint.erase(std::unique(cavity.meshPoint.begin(), cavity.meshPoint.end()), cavity.meshPoint.end());
  for (Index v : cavity.meshPoint)
  {
    cavity.surface.points.push_back(mesh.points[v]);
  }
  auto local = [&](Index v) {
    return static_cast<Index>(
      std::lower_bound(cavity.meshPoint.begin(), cavity.meshPoint.end(), v) - cavity.meshPoint.begin());
  };
  for (const auto& f : boundary)
  {
    cavity.surface.triangles.push_back({ local(f[0]), local(f[1]), local(f[2]) });
  }
  return cavity;
}

// The options for meshing a cavity again: those of the subdomain (its
// volume bound resolved by the caller), the sliver points inserted first,
// and with a size field the size at every boundary point of the cavity (a
// point inside the subdomain gets the mean of the cavity's surface points).
TetMeshingOptions cavityOptions(const TetMeshingOptions& options, const Cavity& cavity,
  const std::vector<Vec3>& insidePoints, std::size_t surfacePoints)
{
  TetMeshingOptions o = options;
  o.sliverRepairAngle = 0;
  o.splittableTriangles.clear();
  // a cavity TetGen stalls on costs a few seconds per order; two suffice to
  // step round the crashes of a canonical order
  o.inputOrders = std::min(options.inputOrders, 2);
  o.processorBudgetSeconds = 0; // the cavity's own, not what a subdomain's fall-back had left
  o.insidePoints = insidePoints;
  o.surfaceKnownValid = true; // faces of TetGen's mesh, and no point pinched (cavityOf)
  if (options.pointSizes.empty())
  {
    return o;
  }
  double sum = 0, count = 0;
  for (Index v : cavity.meshPoint)
  {
    if (static_cast<std::size_t>(v) < surfacePoints)
    {
      sum += options.pointSizes[v];
      count += 1;
    }
  }
  const double mean = count > 0 ? sum / count
                                 : std::accumulate(options.pointSizes.begin(), options.pointSizes.end(), 0.0) /
      static_cast<double>(options.pointSizes.size());
  o.pointSizes.clear();
  for (Index v : cavity.meshPoint)
  {
    o.pointSizes.push_back(static_cast<std::size_t>(v) < surfacePoints ? options.pointSizes[v] : mean);
  }
  return o;
}

// The cavity's parts meshed again in one TetGen run: the surface of all of them
// (vertex-disjoint closed shells), the new mesh, and the part of each of
// its tetrahedra; `kept` marks the tetrahedra of the parts whose new mesh
// is kept.
struct Remeshed
{
  Cavity cavity;
  TetMesh mesh; // on the cavity's surface points first, in the order of cavity.meshPoint
  std::vector<int> part;
  std::vector<char> kept;
};

// The tetrahedra of the kept parts replaced by their new ones. Points inside
// a part no longer used are dropped and the interior points renumbered in
// their order; the surface points keep their indices. The mesh is compacted
// in place (a kept item only moves to a lower index, so it is read before
// anything is written there): building a second mesh and moving it back
// took 0.6 s of a rank's 45 s on the 10 M ball at 2 ranks (perf, session
// 35), most of it in growing the copy.
void spliceParts(TetMesh& mesh, const std::vector<char>& replaced, const Remeshed& run, std::size_t surfacePoints)
{
  std::vector<char> kept(mesh.points.size(), 0);
  std::fill(kept.begin(), kept.begin() + static_cast<std::ptrdiff_t>(surfacePoints), 1);
  for (std::size_t k = 0; k < mesh.tets.size(); ++k)
  {
    if (!replaced[k])
    {
      for (Index v : mesh.tets[k])
      {
        kept[v] = 1;
      }
    }
  }
  std::vector<Index> newIndex(mesh.points.size(), -1);
  std::size_t points = 0;
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
  {
    if (kept[v])
    {
      newIndex[v] = static_cast<Index>(points);
      mesh.points[points++] = mesh.points[v];
    }
  }
  mesh.points.resize(points);
  std::size_t tets = 0;
  for (std::size_t k = 0; k < mesh.tets.size(); ++k)
  {
    if (!replaced[k])
    {
      const auto t = mesh.tets[k];
      mesh.tets[tets++] = { newIndex[t[0]], newIndex[t[1]], newIndex[t[2]], newIndex[t[3]] };
    }
  }
  mesh.tets.resize(tets);
  const std::size_t m = run.cavity.meshPoint.size();
  std::vector<Index> index(run.mesh.points.size(), -1);
  for (std::size_t k = 0; k < run.mesh.tets.size(); ++k)
  {
    if (!run.kept[k])
    {
      continue;
    }
    std::array<Index, 4> t;
    for (int c = 0; c < 4; ++c)
    {
      const Index v = run.mesh.tets[k][c];
      if (index[v] < 0 && static_cast<std::size_t>(v) < m)
      {
        index[v] = newIndex[run.cavity.meshPoint[v]]; // on a tetrahedron outside the part, so kept
      }
      else if (index[v] < 0)
      {
        index[v] = static_cast<Index>(mesh.points.size());
        mesh.points.push_back(run.mesh.points[v]);
      }
      t[c] = index[v];
    }
    mesh.tets.push_back(t);
  }
}

// The part of every tetrahedron of a new mesh of several parts: a boundary
// point's part is known; interior points take it from the tetrahedra they
// share with one, sweep by sweep.
std::vector<int> tetrahedronParts(const Remeshed& run, const std::vector<int>& pointPart)
{
  std::vector<int> point(run.mesh.points.size(), -1);
  std::copy(pointPart.begin(), pointPart.end(), point.begin());
  std::vector<int> part(run.mesh.tets.size(), -1);
  for (bool changed = true; changed;)
  {
    changed = false;
    for (std::size_t k = 0; k < run.mesh.tets.size(); ++k)
    {
      if (part[k] >= 0)
      {
        continue;
      }
      for (Index v : run.mesh.tets[k])
      {
        if (point[v] >= 0)
        {
          part[k] = point[v];
        }
      }
      if (part[k] >= 0)
      {
        changed = true;
        for (Index v : run.mesh.tets[k])
        {
          point[v] = part[k];
        }
      }
    }
  }
  return part;
}

// The cavity's parts meshed again in one run; marks kept the tetrahedra of
// every part whose new mesh has a larger smallest dihedral angle and either
// no more tetrahedra under 10 degrees than the part had or none under the
// repair angle, and returns how many sliver points those parts have. (The
// second way in, session 38: the graded ball of the size-field tests at
// K = 16 had a part go from 1.67 to 5.54 degrees with 7 tetrahedra under 10
// instead of 5, which the first alone refused; its run rose 1.67 -> 2.02.
// Tried and dropped: the parts not kept tried again with their points at
// 0.6 of the lift. It helped one part of CGAL's eight at K = 16, not its
// worst, for a third more repair time.)
int remeshParts(const TriangleSurface& surface, const TetMeshingOptions& options, const TetMesh& mesh,
  const std::vector<BoundarySliverPoint>& points, const std::vector<CavityPart>& parts, Remeshed& run)
{
  std::vector<Index> tets;
  std::vector<Vec3> inside;
  for (const CavityPart& part : parts)
  {
    tets.insert(tets.end(), part.tets.begin(), part.tets.end());
    for (std::size_t i : part.points)
    {
      inside.push_back(points[i].point);
    }
  }
  std::sort(tets.begin(), tets.end());
  run.cavity = cavitySurface(mesh, tets);
  TetMeshingResult r =
    meshClosedSurface(run.cavity.surface, cavityOptions(options, run.cavity, inside, surface.points.size()));
  if (!r.ok)
  {
    return 0;
  }
  run.mesh = std::move(r.mesh);
  std::vector<int> pointPart(run.cavity.meshPoint.size(), -1);
  for (std::size_t p = 0; p < parts.size(); ++p)
  {
    for (Index k : parts[p].tets)
    {
      for (Index v : mesh.tets[k])
      {
        const auto at = std::lower_bound(run.cavity.meshPoint.begin(), run.cavity.meshPoint.end(), v);
        if (at != run.cavity.meshPoint.end() && *at == v)
        {
          pointPart[at - run.cavity.meshPoint.begin()] = static_cast<int>(p);
        }
      }
    }
  }
  run.part = tetrahedronParts(run, pointPart);
  run.kept.assign(run.mesh.tets.size(), 0);
  std::vector<std::vector<Index>> newTetsOf(parts.size());
  for (std::size_t k = 0; k < run.mesh.tets.size(); ++k)
  {
    if (run.part[k] >= 0) // every part touches its boundary; a stray one is not kept
    {
      newTetsOf[run.part[k]].push_back(static_cast<Index>(k));
    }
  }
  int inserted = 0;
  for (std::size_t p = 0; p < parts.size(); ++p)
  {
    const std::vector<Index>& newTets = newTetsOf[p];
    const DihedralQuality before = dihedralQuality(mesh, parts[p].tets);
    const DihedralQuality after = dihedralQuality(run.mesh, newTets);
    if (after.minimumDihedralDegrees > before.minimumDihedralDegrees &&
      (after.below10Degrees <= before.below10Degrees || after.minimumDihedralDegrees >= options.sliverRepairAngle))
    {
      for (Index k : newTets)
      {
        run.kept[k] = 1;
      }
      inserted += static_cast<int>(parts[p].points.size());
    }
  }
  return inserted;
}
} // namespace

std::vector<BoundarySliverPoint> boundarySliverPoints(
  const TriangleSurface& surface, const TetMesh& mesh, double angleDegrees, SliverKind kind)
{
  std::vector<Triangle> surfaceKeys;
  surfaceKeys.reserve(surface.triangles.size());
  for (const auto& t : surface.triangles)
  {
    surfaceKeys.push_back(sortedCorners(t));
  }
  std::sort(surfaceKeys.begin(), surfaceKeys.end());
  const Index n = static_cast<Index>(surface.points.size());
  std::vector<BoundarySliverPoint> points;
  for (std::size_t k = 0; k < mesh.tets.size(); ++k)
  {
    const auto& t = mesh.tets[k];
    // only a tetrahedron with a corner on the surface is held by it: most
    // others are passed over without computing an angle
    const auto onSurface = std::count_if(t.begin(), t.end(), [n](Index v) { return v < n; });
    if (onSurface < (kind == SliverKind::OnTheSurface ? 3 : 1))
    {
      continue;
    }
    const Vec3 &a = mesh.points[t[0]], &b = mesh.points[t[1]], &c = mesh.points[t[2]], &d = mesh.points[t[3]];
    if (smallestDihedralDegrees(a, b, c, d) >= angleDegrees)
    {
      continue;
    }
    double mean = 0, shortest = 0;
    edgeLengths(mesh, t, mean, shortest);
    if ((shortest < kTinyEdgeFraction * mean) != (kind == SliverKind::WithATinyEdge))
    {
      continue;
    }
    const Vec3 centroid = 0.25 * (a + b + c + d);
    const bool held = onSurface < 3 || surfaceFaceCount(surfaceKeys, t) == 0;
    if (kind != SliverKind::WithATinyEdge && held != (kind == SliverKind::HeldByCorners))
    {
      continue;
    }
    if (held)
    {
      points.push_back({ centroid, static_cast<Index>(k) });
      continue;
    }
    Vec3 inward{ 0, 0, 0 };
    const int surfaceFaces = inwardNormal(surfaceKeys, mesh, t, angleDegrees, inward);
    if (surfaceFaces == 0)
    {
      continue;
    }
    double lift = kLiftFraction * mean;
    if (surfaceFaces == 1)
    {
      lift = std::min(lift, 0.5 * distanceToCircumsphere(a, b, c, d, centroid, inward));
    }
    points.push_back({ centroid + lift * inward, static_cast<Index>(k) });
  }
  return points;
}

namespace
{
// Keeps the `count` points whose tetrahedra have the smallest dihedral
// angles (ties by tetrahedron), in their order.
void keepTheFlattest(const TetMesh& mesh, std::size_t count, std::vector<BoundarySliverPoint>& points)
{
  if (points.size() <= count)
  {
    return;
  }
  std::vector<std::pair<double, std::size_t>> angles;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const auto& t = mesh.tets[points[i].tetrahedron];
    angles.emplace_back(
      smallestDihedralDegrees(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]], mesh.points[t[3]]), i);
  }
  std::sort(angles.begin(), angles.end());
  std::vector<char> keep(points.size(), 0);
  for (std::size_t k = 0; k < count; ++k)
  {
    keep[angles[k].second] = 1;
  }
  std::size_t kept = 0;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    if (keep[i])
    {
      points[kept++] = points[i];
    }
  }
  points.resize(kept);
}

// One round of the repair: the flat tetrahedra of one kind, their cavities
// meshed again in one TetGen run, the parts that got better spliced in.
// Returns the points of the kept parts.
int repairRound(const TriangleSurface& surface, const TetMeshingOptions& options, SliverKind kind, TetMesh& mesh)
{
  std::vector<BoundarySliverPoint> points = boundarySliverPoints(surface, mesh, options.sliverRepairAngle, kind);
  if (kind == SliverKind::WithATinyEdge)
  {
    keepTheFlattest(mesh, kTinyEdgeRoundPoints, points);
  }
  const std::vector<char> inCavity = points.empty() ? std::vector<char>{} : cavityOf(mesh, points);
  if (inCavity.empty())
  {
    return 0;
  }
  const std::vector<CavityPart> parts = cavityParts(mesh, inCavity, points);
  Remeshed run;
  const int inserted = remeshParts(surface, options, mesh, points, parts, run);
  if (inserted > 0)
  {
    std::vector<char> partKept(parts.size(), 0), replaced(mesh.tets.size(), 0);
    for (std::size_t k = 0; k < run.mesh.tets.size(); ++k)
    {
      if (run.kept[k])
      {
        partKept[run.part[k]] = 1;
      }
    }
    for (std::size_t p = 0; p < parts.size(); ++p)
    {
      for (Index t : parts[p].tets)
      {
        replaced[t] = partKept[p];
      }
    }
    spliceParts(mesh, replaced, run, surface.points.size());
  }
  return inserted;
}
} // namespace

int repairBoundarySlivers(const TriangleSurface& surface, const TetMeshingOptions& options, TetMesh& mesh)
{
  if (!(options.sliverRepairAngle > 0) || !options.qualityRefinement)
  {
    return 0;
  }
  return repairRound(surface, options, SliverKind::OnTheSurface, mesh) +
    repairRound(surface, options, SliverKind::HeldByCorners, mesh) +
    repairRound(surface, options, SliverKind::WithATinyEdge, mesh);
}
} // namespace ptm
