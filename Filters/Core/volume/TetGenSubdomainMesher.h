#ifndef PTM_TETGEN_SUBDOMAIN_MESHER_H
#define PTM_TETGEN_SUBDOMAIN_MESHER_H
// Stage 4 of the method: the volume mesh of one closed subdomain surface by
// TetGen (libtet), with the surface preserved exactly.
//
// Contract: the surface points come out first, in the same order and with
// bit-identical coordinates, followed by TetGen's interior points; every
// input triangle is the face of exactly one tetrahedron and the boundary of
// the tetrahedra is exactly the input surface (switch Y: no Steiner point on
// the boundary), so neighbouring subdomains meshed apart match node for node.
// The one exception: triangles the caller marks splittable (a subdomain's
// outer boundary) may come out split, where TetGen cannot keep them, into
// faces on them (TetMeshingResult::splitFaces).
// Shells with negative enclosed volume (cavities) get a hole point so TetGen
// leaves them empty. TetGen's failures (it throws an int) become ok = false
// with the code and its meaning. TetGen 1.5 sometimes aborts on an
// assertion, or loops for ever in boundary recovery, for an input it meshes
// when the points come in another order: then (a crash, or a run over its
// processor-time limit, which is stopped) it runs again with the points
// reversed, then shuffled, then with the facets shuffled too (fixed seeds;
// six orders, and six more where none stalled), all within one
// processor-time budget per surface. A run stopped after it had recovered
// the boundary (its phase lines say so) was refining: other orders would be
// as slow, so it ends the runs. If all of them fail, the surface
// is recovered in one run without refinement and the mesh refined in a
// second (-rY). Flat tetrahedra TetGen leaves on the surface are then
// repaired in small cavities meshed again (TetMeshingOptions::
// sliverRepairAngle, BoundarySliverRepair.h). The same input and options
// give the same mesh.
#include "TriangleSurface.h"

#include <string>

namespace ptm
{
// How many input orders TetMeshingOptions::inputOrders allows (see there),
// and how many are tried once a run has stalled: a stall costs the whole
// processor-time limit, a crash (an assertion in boundary recovery) a
// fraction of a second. The measurements are at runInOrders.
constexpr int kInputOrders = 12;
constexpr int kInputOrdersAfterAStall = 6;
// What all TetGen runs of one surface may use together, in per-run
// processor-time limits, unless TetMeshingOptions::processorBudgetSeconds
// says otherwise. Before the budget a surface on which TetGen stalls went
// through six orders, the two-run fall-back and the caller's fall-backs
// (about 20 stopped runs): OpenFOAM's NACA0012 wing (long span-wise
// strips, 99 % of its triangles under 10 degrees) at K = 7 on 3 ranks gave
// no message in 15 minutes, each TetGen process over 1 GB. Four is two
// more than the documented stall that another order mends needs
// (tetgen_stall_in_canonical_order.off: stopped once, then meshed).
constexpr double kBudgetInRunLimits = 4.0;
// No TetGen run is started with less processor time than this: the
// kernel's limit (RLIMIT_CPU) counts whole seconds.
constexpr double kShortestRunSeconds = 1.0;

struct TetMeshingOptions
{
  double radiusEdgeRatio = 2.0;      // -q bound, > 1
  double minimumDihedralAngle = 0.0; // second -q value in degrees; 0: TetGen's default
  double maximumVolume = 0.0;        // -a; 0: regular tetrahedron of the mean surface edge
  // false: no -q, only the volume bound refines (the last resort of the
  // mesher for a subdomain where TetGen's quality refinement crashes)
  bool qualityRefinement = true;
  // optional size field at the surface points (edge length wanted, > 0, one
  // per point): TetGen -m, which interpolates it inside; the volume bound
  // still applies. Empty: none.
  std::vector<double> pointSizes;
  std::string extraSwitches;         // only O, S, T, V with numbers (what cannot break the contract)
  // per surface triangle, nonzero where TetGen may split it if it cannot
  // keep it (the outer boundary of a subdomain, which no neighbour shares;
  // see TetMeshingResult::splitTriangles). Empty: the surface is kept exactly.
  // TetGen 1.5 can also be told to refine these (a per-facet -Y: with -Y it
  // splits a facet, and a segment all of whose facets, that has a facet
  // constraint of nonzero area; checked on a cube). Measured and not used:
  // with the outer triangles so marked, the ball with a size field at K = 8
  // (2 ranks) went from 2.30 to 1.93 degrees minimum dihedral and 0.091 to
  // 0.099 % under 10 degrees, and CGAL's cheese at K = 4 from 3.75 to 66.8 s
  // of volume meshing (TetGen split 8,555 triangles into 87,057 faces on one
  // subdomain and crashed in all six orders on two others), 28.0 to 30.3 %
  // under 10 degrees. The boundary is refined before TetGen instead
  // (SurfaceRefinement.h). Two more ways were measured on CGAL's pinion at
  // K = 1 (0.33 degrees with -pY) and not kept: a second run with the outer
  // triangles so marked, only where the first mesh has a tetrahedron under
  // 5 degrees, ran over its 7 s limit (the first took 1 s); and the points
  // of a -pq run without -Y (8.8 degrees) put back on the input triangles
  // they came 2.6e-8 off (TetGen merged facets within 0.1 degrees) and the
  // facets meshed again with them: 0.009 degrees, since its points ignore
  // the edges between the facets it merged. Told not to merge (-M), TetGen
  // -pq on that surface itself gives 0.0 degrees and 4.7 x the tetrahedra.
  std::vector<char> splittableTriangles;
  // per TetGen run, processor time; 0: 2 s + 30 us per expected tetrahedron
  // (about 6x TetGen's speed) + 0.4 ms per surface triangle. A run is also
  // stopped after 60 s + 10x this + 10 us per expected tetrahedron of wall time.
  double timeLimitSeconds = 0.0;
  // processor time of all TetGen runs of this surface together (every input
  // order and fall-back); when less than a second of it is left no run is
  // started and the result says so (TetMeshingResult::outOfTime). 0:
  // kBudgetInRunLimits x the per-run processor-time limit. A caller with
  // fall-backs of its own passes on what the first call left.
  double processorBudgetSeconds = 0.0;
  // input orders tried after a crash, a stall or a mesh that changed the
  // surface (meshClosedSurface), before the two-run fall-back,
  // 1..kInputOrders: the points as given, reversed, shuffled, then points
  // and facets shuffled (fixed seeds, so the same mesh on any rank); at
  // most kInputOrdersAfterAStall once a run has stalled. Fewer orders fail
  // sooner on a surface TetGen cannot mesh.
  int inputOrders = kInputOrders;
  // Flat tetrahedra left on the surface: where the mesh has a tetrahedron
  // with a face on the surface and a dihedral angle under this many degrees,
  // the tetrahedra around it are meshed again with a point inside above it
  // (BoundarySliverRepair.h), kept if better. 0: never.
  double sliverRepairAngle = 5.0;
  // points TetGen inserts inside the surface first (-i; points outside are
  // passed over). Empty: none.
  std::vector<Vec3> insidePoints;
  // true: the surface is known not to cross itself (faces of a valid mesh,
  // as the sliver repair's cavities), so CGAL's check before TetGen is not
  // made
  bool surfaceKnownValid = false;
};

struct TetMesh
{
  std::vector<Vec3> points;               // surface points first, then interior points
  std::vector<std::array<Index, 4>> tets; // positive volume (VTK_TETRA order)
};

// The four faces of a positively oriented tetrahedron, each turned outward.
inline std::array<Triangle, 4> outwardTetrahedronFaces(const std::array<Index, 4>& t)
{
  return { Triangle{ t[1], t[2], t[3] }, Triangle{ t[0], t[3], t[2] }, Triangle{ t[0], t[1], t[3] },
    Triangle{ t[0], t[2], t[1] } };
}

struct TetMeshingResult
{
  bool ok = false;
  int tetgenCode = 0; // TetGen's exit code on failure, 0 otherwise
  std::string error;
  TetMesh mesh;
  std::string switchesUsed;
  int attempts = 0; // TetGen runs: more than 1 if it crashed, stalled or broke the contract in the first order
  // true if TetGen crashed or stalled meshing and refining in one run, and
  // the mesh comes from two: the surface recovered (-pY), then refined (-rY)
  bool recoveredThenRefined = false;
  // processor time TetGen's runs used (the sliver repair's excluded), the
  // budget they had, and whether it ran out before a mesh was found (then
  // `error` says so, with the runs and what to do)
  double processorSeconds = 0.0;
  double processorBudgetSeconds = 0.0;
  bool outOfTime = false;
  // points the sliver repair put inside (TetMeshingOptions::sliverRepairAngle;
  // 0: it left the mesh as TetGen made it)
  int sliverRepairPoints = 0;
  // The splittable triangles TetGen split, ascending, and the faces that
  // replace them: outward, indexing mesh.points (new points on the split
  // triangles come after the surface's), each with the split triangle it
  // lies on. Empty where the boundary is exactly the surface.
  std::vector<Index> splitTriangles;
  std::vector<Triangle> splitFaces;
  std::vector<Index> splitFaceParents;
};

TetMeshingResult meshClosedSurface(const TriangleSurface& surface, const TetMeshingOptions& options);

// The size of a mesh before it is made, to refuse a request that cannot fit
// in memory instead of being killed half-way. With a volume bound TetGen's
// quality mesh has about 2 x volume / maximumVolume tetrahedra (measured:
// ball 2.0, bracket 2.3); a rank running the pipeline in pvbatch peaks at
// about 190 bytes per tetrahedron (TetGen's process plus the VTK
// output: 3.9 GB per rank for 41.6 M tetrahedra on 2 ranks), so the
// estimate counts 220.
struct TetMeshEstimate
{
  double tetrahedra = 0;
  double bytes = 0;
};
TetMeshEstimate estimateTetMesh(double volume, double maximumVolume);
// The same from the regular tetrahedra of the size (volume / maximumVolume,
// or PredictedCost::regularTetrahedra under a size field).
TetMeshEstimate estimateTetMeshOfRegular(double regularTetrahedra);

// Physical memory of this machine in bytes (0 if unknown).
double physicalMemoryBytes();

// A number that is the same for the processes of one machine and (almost
// surely) different between machines: a hash of the host name.
long long machineIdentity();

// What TetGen 1.5's exit codes mean.
std::string describeTetGenError(int code);
} // namespace ptm
#endif
