#ifndef PTM_SURFACE_COMPLEX_H
#define PTM_SURFACE_COMPLEX_H
// The labeled surface complex: the contract between the four stages.
//
// A closed input surface cut by planes into subdomains 0..K-1 is described by
//  * surface triangles, each with a SubdomainPair {inside, -1}: the triangle's
//    normal points out of subdomain `inside` into the outside (-1);
//  * interface regions: planar pieces of a cutting plane between two
//    subdomains {a, b}. The region's normal points out of a into b; its
//    boundary is a set of directed edges with the region on the LEFT when
//    seen from that normal (outer loops counter-clockwise, holes clockwise);
//  * after interface triangulation, interface triangles with the pair {a, b}
//    oriented like the region (normal out of a into b).
// Taking every triangle whose pair contains s, flipped where s is the second
// entry, gives subdomain s a closed, outward-oriented surface.
// Point indices are global: the same index means the same point, with the
// same coordinates, everywhere.
#include "TriangleSurface.h"

#include <array>
#include <vector>

namespace ptm
{
using SubdomainPair = std::array<int, 2>;
using DirectedEdge = std::array<Index, 2>;

struct CuttingPlane
{
  Vec3 origin;
  Vec3 normal; // unit; the subdomains below (normal . (x - origin) < 0) were split from those above
  int cutSubdomainCount = 0; // how many final subdomains the part cut by this plane holds
};

struct InterfaceRegion
{
  int planeId = -1;
  SubdomainPair pair{ -1, -1 };
  std::vector<DirectedEdge> edges;
};

struct SurfaceComplex
{
  std::vector<Vec3> points;

  std::vector<Triangle> triangles;
  std::vector<SubdomainPair> trianglePairs;
  std::vector<Index> sourceFaces; // input triangle each piece came from; -1 on interface triangles
  std::vector<int> trianglePlanes; // plane of each interface triangle, -1 on surface triangles;
                                   // may be empty while there are no interface triangles

  std::vector<InterfaceRegion> interfaces;
  std::vector<CuttingPlane> planes;

  int subdomainCount = 0;
};

// Closed loops (each a list of point indices, first not repeated at the end)
// chained from directed edges in which every point has as many outgoing as
// incoming edges. Deterministic: loops start at the smallest unused edge.
// Returns false if the edges do not form closed loops.
bool chainLoops(const std::vector<DirectedEdge>& edges, std::vector<std::vector<Index>>& loops);

// Signed volume of every subdomain by the divergence theorem over its closed
// boundary: surface triangles, interface triangles and interface regions
// (a region contributes (origin - o) . vectorArea / 3 with its plane's
// origin). A label far from (0, 0, 0) has it taken about its own lowest
// corner o, so a part far from the origin keeps its volume
// (sixTimesVolumeAbout; SurfaceComplex.cpp says where "far" begins).
std::vector<double> subdomainVolumes(const SurfaceComplex& complex);

// Signed volume enclosed by the faces carrying one label (a subdomain, or a
// part during decomposition), by the same rule as subdomainVolumes.
double labelVolume(const SurfaceComplex& complex, int label);

// The points of a region's boundary, each once, in increasing index order.
std::vector<Index> regionPoints(const InterfaceRegion& region);

// The largest |coordinate| of a region's boundary points: a point computed
// on its plane lies on it up to about eps times this.
double largestCoordinateOf(const SurfaceComplex& complex, const InterfaceRegion& region);

// Vector area (1/2 sum (p - about) x (q - about)) of a set of directed
// boundary edges; for closed loops the same about any point, but accurate
// only about one near them.
Vec3 vectorArea(
  const std::vector<Vec3>& points, const std::vector<DirectedEdge>& edges, const Vec3& about = Vec3{ 0, 0, 0 });

// The closed surface of subdomain s: its triangles, oriented outward (only
// triangles; call after the interfaces are triangulated). Point indices stay
// global.
std::vector<Triangle> subdomainTriangles(const SurfaceComplex& complex, int s);
} // namespace ptm
#endif
