#include "vtkParallelTetMesher.h"

#include "CADFaceIds.h"
#include "GlobalMeshNumbering.h"
#include "MemoryCheck.h"
#include "OffFormat.h"
#include "PhaseLog.h"
#include "PipelineRequests.h"
#include "PolyDataConversion.h"
#include "PropertyChecks.h"
#include "RankCollectives.h"
#include "SizeField.h"
#include "SizeFunction.h"
#include "StageRun.h"
#include "SubdomainSurface.h"
#include "SurfaceComplexArrays.h"
#include "SurfaceRefinement.h"
#include "TetGenProcess.h"
#include "TetGenSubdomainMesher.h"
#include "TetrahedronQuality.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <exception>
#include <limits>
#include <new>
#include <sstream>
#include <unordered_map>

namespace
{
// The mesh of each rank's subdomains against the memory of its machine
// (MemoryCheck.h).
std::string memoryShortfall(
  vtkMultiProcessController* controller, const ptm::ComplexPiece& piece, double maximumVolume)
{
  std::vector<double> regular; // of each subdomain
  for (double volume : piece.subdomainVolume)
  {
    regular.push_back(maximumVolume > 0 ? volume / maximumVolume : 0.0);
  }
  std::ostringstream requested;
  requested.precision(3);
  requested << "MaximumVolume " << maximumVolume;
  return ptm::memoryShortfall(controller,
    ptm::regularPerRank(regular, piece.subdomainRank, ptm::rankCount(controller)), requested.str());
}

// One subdomain refined (when asked) and meshed.
struct MeshedSubdomain
{
  ptm::TetMesh mesh;
  std::string error;
  std::vector<std::string> warnings;
  long long pointsAdded = 0;
  long long sliverPoints = 0; // put inside by the sliver repair (kept meshes only)
  double volumeChange = 0, deviation = 0;
};

// TetGen's edges come out about 1.3 x the -m size at the points (icosphere
// of edge 0.04, field 0.03-0.3: median edge 1.28 x the field, 69 % within
// 1.5 x; at 0.8 x: 1.07, 93 %; at 0.7 x: 0.95, 97 %), so it gets 0.75 x
// the field, which puts the median edge at the field.
constexpr double kTetGenSizeScale = 0.75;

// TetGen on `surface`, with the size field's values at its points when
// there is one.
ptm::TetMeshingResult meshWithSizes(const ptm::SubdomainSurface& surface, ptm::TetMeshingOptions options,
  const ptm::SizeField& field)
{
  if (field)
  {
    std::string error;
    if (!ptm::sizesAt(field, surface.surface.points, options.pointSizes, error))
    {
      ptm::TetMeshingResult r;
      r.error = error;
      return r;
    }
    for (double& h : options.pointSizes)
    {
      h *= kTetGenSizeScale;
    }
  }
  options.splittableTriangles.resize(surface.otherSide.size());
  std::transform(surface.otherSide.begin(), surface.otherSide.end(), options.splittableTriangles.begin(),
    [](int other) { return other < 0 ? 1 : 0; });
  return ptm::meshClosedSurface(surface.surface, options);
}

// Where TetGen split outer triangles of the subdomain (TetMeshingResult::
// splitTriangles), `surface` takes the faces that replace them, so the
// boundary output matches the tetrahedra; their new points are the mesh's,
// private to the subdomain like its interior points.
void takeSplitFaces(const ptm::TetMeshingResult& r, ptm::SubdomainSurface& surface)
{
  if (r.splitTriangles.empty())
  {
    return;
  }
  std::vector<char> split(surface.surface.triangles.size(), 0);
  for (ptm::Index t : r.splitTriangles)
  {
    split[t] = 1;
  }
  ptm::SubdomainSurface kept;
  kept.globalIds = surface.globalIds;
  kept.surface.points = r.mesh.points;
  for (std::size_t t = 0; t < split.size(); ++t)
  {
    if (!split[t])
    {
      kept.surface.triangles.push_back(surface.surface.triangles[t]);
      kept.sourceFaces.push_back(surface.sourceFaces[t]);
      kept.otherSide.push_back(surface.otherSide[t]);
    }
  }
  for (std::size_t f = 0; f < r.splitFaces.size(); ++f)
  {
    kept.surface.triangles.push_back(r.splitFaces[f]);
    kept.sourceFaces.push_back(surface.sourceFaces[r.splitFaceParents[f]]);
    kept.otherSide.push_back(-1);
  }
  surface = std::move(kept);
}

// The processor time a subdomain's TetGen calls have left: fixed by the
// first call that ran TetGen (its budget), then less what each call used.
class TetGenBudget
{
public:
  explicit TetGenBudget(const ptm::TetMeshingOptions& options)
    : Given(options)
  {
  }
  void Spend(const ptm::TetMeshingResult& r)
  {
    if (r.processorBudgetSeconds > 0)
    {
      this->Left = (this->Left < 0 ? r.processorBudgetSeconds : this->Left) - r.processorSeconds;
    }
  }
  // whether one more call could start a run (the kernel's limit counts
  // whole seconds); a call that would start none only replaces the error
  bool CanPay() const { return this->Left < 0 || this->Left >= ptm::kShortestRunSeconds; }
  ptm::TetMeshingOptions Options() const
  {
    ptm::TetMeshingOptions o = this->Given;
    if (this->Left >= 0)
    {
      o.processorBudgetSeconds = this->Left;
    }
    return o;
  }

private:
  ptm::TetMeshingOptions Given;
  double Left = -1; // < 0: no call has run TetGen yet
};

// Refines `surface` (unless `refinement` is null) and meshes it. Where
// TetGen fails on the refined surface, the surface as it came is meshed
// instead, with a warning: a subdomain TetGen can mesh must not fail because
// of the refinement (measured on CAD parts where TetGen stalls on some
// refined surfaces). `surface` ends as the boundary of the mesh: refined,
// and with the outer triangles TetGen split replaced (takeSplitFaces).
MeshedSubdomain meshSubdomain(ptm::SubdomainSurface& surface, const ptm::TetMeshingOptions& options,
  const ptm::SurfaceRefinementOptions* refinement, const ptm::SizeField& field)
{
  MeshedSubdomain m;
  const ptm::SubdomainSurface unrefined = refinement ? surface : ptm::SubdomainSurface{};
  if (refinement)
  {
    const ptm::SurfaceRefinementResult refined = ptm::refineSubdomainSurface(surface, *refinement);
    if (!refined.ok)
    {
      m.error = "boundary refinement: " + refined.error;
      return m;
    }
    m.warnings = refined.warnings;
    m.pointsAdded = static_cast<long long>(refined.pointsAdded);
    m.volumeChange = refined.volumeChange;
    m.deviation = refined.largestDeviation;
  }
  // the fall-backs below share the processor-time budget of the first call
  // that ran TetGen (TetMeshingOptions::processorBudgetSeconds): a surface on
  // which TetGen stalls fails in bounded time instead of stalling in each
  TetGenBudget budget(options);
  ptm::TetMeshingResult r = meshWithSizes(surface, options, field);
  budget.Spend(r);
  if (!r.ok && budget.CanPay() && refinement && m.pointsAdded > 0)
  {
    m.warnings.push_back("TetGen failed on the refined surface (" + r.error +
      "); meshed without boundary refinement");
    surface = unrefined;
    m.pointsAdded = 0;
    m.volumeChange = m.deviation = 0;
    r = meshWithSizes(surface, budget.Options(), field);
    budget.Spend(r);
  }
  if (!r.ok && budget.CanPay() && options.qualityRefinement)
  {
    // TetGen 1.5's crashes are mostly assertions in its quality refinement
    // (oblong, K = 64 parallel planes: signal 6 in all three point orders
    // for one subdomain); without -q it still recovers the surface and
    // bounds the volume, so the run ends with a mesh and a warning.
    ptm::TetMeshingOptions sizeOnly = budget.Options();
    sizeOnly.qualityRefinement = false;
    ptm::TetMeshingResult plain = meshWithSizes(surface, sizeOnly, field);
    if (plain.ok)
    {
      m.warnings.push_back("TetGen failed with quality refinement (" + r.error +
        "); meshed with the volume bound only (no -q), so this subdomain's tetrahedra are not "
        "quality-bounded");
      r = std::move(plain);
    }
  }
  if (!r.ok)
  {
    m.error = r.error;
    if (r.processorBudgetSeconds > 0) // TetGen ran: its surface tells why it was slow or failed
    {
      m.error += " (the surface TetGen was given: " + std::to_string(surface.surface.triangles.size()) +
        " triangles, " + std::to_string(m.pointsAdded) + " points added by the boundary refinement)";
    }
    return m;
  }
  if (!r.splitTriangles.empty())
  {
    m.warnings.push_back("TetGen could not keep " + std::to_string(r.splitTriangles.size()) +
      " triangles of the outer boundary and split them into " + std::to_string(r.splitFaces.size()) +
      " (with points on them; the interfaces are kept, so the mesh still conforms)");
    takeSplitFaces(r, surface);
  }
  if (r.recoveredThenRefined)
  {
    m.warnings.push_back("TetGen crashed or stalled meshing and refining in one run (in every input "
                         "order tried); meshed in two runs: " + r.switchesUsed);
  }
  else if (r.attempts > 1)
  {
    m.warnings.push_back("TetGen crashed, stalled, merged close points or changed the surface with the points and "
                         "facets in their canonical order and meshed them in another order (attempt " +
      std::to_string(r.attempts) + ", switches " + r.switchesUsed + ")");
  }
  m.sliverPoints = r.sliverRepairPoints;
  m.mesh = std::move(r.mesh);
  return m;
}
/// @name What a rank meshed, and how it becomes its piece
/// @{
struct OwnedSubdomains
{
  explicit OwnedSubdomains(const std::vector<int>& subdomains)
    : ids(subdomains)
    , surfaces(subdomains.size())
    , meshes(subdomains.size())
    , seconds(subdomains.size(), 0.0)
    , pointsAdded(subdomains.size(), 0)
    , sliverPoints(subdomains.size(), 0)
    , volumeChange(subdomains.size(), 0.0)
    , deviation(subdomains.size(), 0.0)
  {
  }
  std::vector<int> ids; // the subdomains, ascending
  std::vector<ptm::SubdomainSurface> surfaces;
  std::vector<ptm::TetMesh> meshes;
  std::vector<double> seconds;
  std::vector<long long> pointsAdded; // by the boundary refinement
  std::vector<long long> sliverPoints; // by TetGen's sliver repair
  std::vector<double> volumeChange, deviation;
};

// Every rank's figures, the same on every rank.
struct MeshTotals
{
  ptm::GlobalMeshOffsets offsets;
  std::vector<long long> tetrahedra; // per subdomain
  long long boundaryPointsAdded = 0;
  long long sliverRepairPoints = 0;
  double relativeVolumeChange = 0, largestDeviation = 0;
  ptm::DihedralQuality quality;
};

MeshTotals gatherTotals(
  vtkMultiProcessController* controller, const ptm::ComplexPiece& piece, const OwnedSubdomains& owned)
{
  const int K = piece.complex.subdomainCount;
  std::vector<long long> counts;
  std::vector<double> changes;
  for (std::size_t k = 0; k < owned.ids.size(); ++k)
  {
    // every point beyond the complex's own (the refinement's, TetGen's) is
    // private to the subdomain and numbered with it
    counts.insert(counts.end(), { owned.ids[k],
      static_cast<long long>(owned.meshes[k].points.size() - owned.surfaces[k].globalIds.size()),
      static_cast<long long>(owned.meshes[k].tets.size()), owned.pointsAdded[k], owned.sliverPoints[k] });
    changes.insert(changes.end(), { static_cast<double>(owned.ids[k]), owned.volumeChange[k], owned.deviation[k] });
  }
  MeshTotals totals;
  const std::vector<long long> allCounts = ptm::allGatherValues(controller, counts);
  std::vector<long long> interior(K, 0);
  totals.tetrahedra.assign(K, 0);
  for (std::size_t k = 0; k + 4 < allCounts.size(); k += 5)
  {
    interior[allCounts[k]] = allCounts[k + 1];
    totals.tetrahedra[allCounts[k]] = allCounts[k + 2];
    totals.boundaryPointsAdded += allCounts[k + 3];
    totals.sliverRepairPoints += allCounts[k + 4];
  }
  totals.offsets = ptm::globalMeshOffsets(piece.globalPointCount, interior, totals.tetrahedra);
  const std::vector<double> allChanges = ptm::allGatherValues(controller, changes);
  std::vector<double> subdomainChange(K, 0.0);
  for (std::size_t k = 0; k + 2 < allChanges.size(); k += 3)
  {
    subdomainChange[static_cast<int>(allChanges[k])] = allChanges[k + 1];
    totals.largestDeviation = std::max(totals.largestDeviation, allChanges[k + 2]);
  }
  double change = 0, volume = 0; // summed in subdomain order: the same on any number of ranks
  for (int s = 0; s < K; ++s)
  {
    change += subdomainChange[s];
    volume += piece.subdomainVolume[s];
  }
  totals.relativeVolumeChange = volume != 0 ? change / volume : 0.0;
  // quality in one pass over the tetrahedra this rank made, then reduced
  for (const ptm::TetMesh& mesh : owned.meshes)
  {
    const ptm::DihedralQuality q = ptm::dihedralQuality(mesh);
    totals.quality.below10Degrees += q.below10Degrees;
    totals.quality.minimumDihedralDegrees = std::min(totals.quality.minimumDihedralDegrees, q.minimumDihedralDegrees);
  }
  std::vector<double> below{ static_cast<double>(totals.quality.below10Degrees) }; // exact below 2^53
  ptm::allReduceSum(controller, below);
  std::vector<long long> minimum{ -std::llround(totals.quality.minimumDihedralDegrees * 1e9) };
  ptm::allReduceMax(controller, minimum);
  totals.quality.below10Degrees = std::llround(below[0]);
  // negated as an integer: a smallest angle under 5e-10 degrees rounds to 0,
  // and negating the double gave -0, printed as "-0.00 degrees"
  totals.quality.minimumDihedralDegrees = static_cast<double>(-minimum[0]) * 1e-9;
  totals.quality.tetrahedra = totals.offsets.tetrahedronCount;
  return totals;
}

// The lowest subdomain touching each complex point of this rank's
// subdomains, over all ranks: its rank owns the point. Settled by a
// rendezvous (minimumOverHolders): a rank sends only the points it holds.
// It was an all-reduce of a vector over every complex point, on every rank.
std::unordered_map<long long, long long> lowestSubdomainOfPoints(
  vtkMultiProcessController* controller, const ptm::ComplexPiece& piece, const OwnedSubdomains& owned)
{
  std::unordered_map<long long, long long> lowest;
  for (std::size_t k = 0; k < owned.ids.size(); ++k)
  {
    for (ptm::Index g : owned.surfaces[k].globalIds)
    {
      lowest.emplace(g, owned.ids[k]); // owned.ids ascend: the first subdomain to hold g is its lowest here
    }
  }
  std::vector<long long> keys, values;
  keys.reserve(lowest.size());
  values.reserve(lowest.size());
  for (const auto& [g, s] : lowest)
  {
    keys.push_back(g);
    values.push_back(s);
  }
  const std::vector<long long> overAll =
    ptm::minimumOverHolders(controller, static_cast<long long>(piece.globalPointCount), keys, values);
  for (std::size_t i = 0; i < keys.size(); ++i)
  {
    lowest[keys[i]] = overAll[i];
  }
  return lowest;
}

// The global id of point i of subdomain k's mesh: the complex's id for the
// surface points it came with, else one of the subdomain's own.
long long globalIdOf(const OwnedSubdomains& owned, const MeshTotals& totals, std::size_t k, std::size_t i)
{
  const std::size_t shared = owned.surfaces[k].globalIds.size();
  return i < shared ? static_cast<long long>(owned.surfaces[k].globalIds[i])
                    : totals.offsets.firstInteriorPoint[owned.ids[k]] + static_cast<long long>(i - shared);
}

vtkIdTypeArray* newIdArray(const char* name)
{
  vtkIdTypeArray* a = vtkIdTypeArray::New();
  a->SetName(name);
  return a;
}

vtkIntArray* newIntArray(const char* name)
{
  vtkIntArray* a = vtkIntArray::New();
  a->SetName(name);
  return a;
}

/// @name The rank's volume mesh as VTK arrays
/// @{
// Every array is sized once and written in place. Built with
// InsertNextValue and InsertNextCell, the output took 1.8 s of a rank's 45 s
// on the 10 M ball at 2 ranks (perf, session 35): a call per value, and
// each array grown by copying as it filled. Now 0.6 s, most of it the first
// touches of the new arrays' pages.

// The rank's points: a point shared by two of its subdomains appears once.
struct LocalPoints
{
  std::vector<std::vector<vtkIdType>> ofMesh;              // per subdomain k, per point of its mesh
  std::vector<long long> globalId;                         // per local point
  std::vector<std::pair<std::size_t, std::size_t>> first;  // (k, mesh point) where each local point was met first
};

LocalPoints numberLocalPoints(const OwnedSubdomains& owned, const MeshTotals& totals)
{
  LocalPoints l;
  l.ofMesh.resize(owned.ids.size());
  std::unordered_map<long long, vtkIdType> localOf;
  for (std::size_t k = 0; k < owned.ids.size(); ++k)
  {
    l.ofMesh[k].resize(owned.meshes[k].points.size());
    for (std::size_t i = 0; i < owned.meshes[k].points.size(); ++i)
    {
      const long long gid = globalIdOf(owned, totals, k, i);
      const auto inserted = localOf.emplace(gid, static_cast<vtkIdType>(l.globalId.size()));
      if (inserted.second)
      {
        l.globalId.push_back(gid);
        l.first.emplace_back(k, i);
      }
      l.ofMesh[k][i] = inserted.first->second;
    }
  }
  return l;
}

// The points, their global ids, and the ghost flag of those another rank owns.
void addPoints(const OwnedSubdomains& owned, const ptm::ComplexPiece& piece,
  const std::unordered_map<long long, long long>& lowest,
  int rank, const LocalPoints& l, vtkUnstructuredGrid* output)
{
  const vtkIdType count = static_cast<vtkIdType>(l.globalId.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(count);
  vtkDoubleArray* xyz = vtkArrayDownCast<vtkDoubleArray>(points->GetData());
  vtkSmartPointer<vtkIdTypeArray> pointIds = vtk::TakeSmartPointer(newIdArray("GlobalPointIds"));
  pointIds->SetNumberOfValues(count);
  vtkNew<vtkUnsignedCharArray> ghosts;
  ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
  ghosts->SetNumberOfValues(count);
  for (vtkIdType p = 0; p < count; ++p)
  {
    const auto [k, i] = l.first[static_cast<std::size_t>(p)];
    const long long gid = l.globalId[static_cast<std::size_t>(p)];
    const bool shared = i < owned.surfaces[k].globalIds.size();
    const int owner = shared ? ptm::owningRank(static_cast<int>(lowest.at(gid)), piece.subdomainRank) : rank;
    xyz->SetTypedTuple(p, owned.meshes[k].points[i].data());
    pointIds->SetValue(p, gid);
    ghosts->SetValue(p, owner == rank ? 0 : vtkDataSetAttributes::DUPLICATEPOINT);
  }
  output->SetPoints(points);
  output->GetPointData()->SetGlobalIds(pointIds);
  output->GetPointData()->AddArray(ghosts);
}

// The tetrahedra, their global ids, subdomains and rank. Each subdomain's
// own list is released as soon as its corners are copied, before the cell
// data arrays are made: the rank's own peak is at this step, and the list
// (32 bytes a tetrahedron) had lived beside all five arrays (56 bytes). On
// the 9.8 M ball at K = 2 rank 0's sampled peak went from 868 to 752 MB
// (session 36).
void addTetrahedra(OwnedSubdomains& owned, const MeshTotals& totals, int rank, const LocalPoints& l,
  vtkUnstructuredGrid* output)
{
  std::vector<vtkIdType> counts;
  vtkIdType count = 0;
  for (const ptm::TetMesh& mesh : owned.meshes)
  {
    counts.push_back(static_cast<vtkIdType>(mesh.tets.size()));
    count += counts.back();
  }
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfValues(count + 1);
  connectivity->SetNumberOfValues(4 * count);
  vtkIdType* offset = offsets->GetPointer(0);
  vtkIdType* corner = connectivity->GetPointer(0);
  vtkIdType c = 0;
  for (std::size_t k = 0; k < owned.ids.size(); ++k)
  {
    const std::vector<vtkIdType>& local = l.ofMesh[k];
    for (const std::array<ptm::Index, 4>& tet : owned.meshes[k].tets)
    {
      offset[c] = 4 * c;
      for (int j = 0; j < 4; ++j)
      {
        corner[4 * c + j] = local[static_cast<std::size_t>(tet[j])];
      }
      ++c;
    }
    std::vector<std::array<ptm::Index, 4>>().swap(owned.meshes[k].tets);
  }
  offset[count] = 4 * count;
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  output->SetCells(VTK_TETRA, cells);

  vtkSmartPointer<vtkIdTypeArray> cellIds = vtk::TakeSmartPointer(newIdArray("GlobalCellIds"));
  cellIds->SetNumberOfValues(count);
  vtkSmartPointer<vtkIntArray> subdomainIds = vtk::TakeSmartPointer(newIntArray("SubdomainId"));
  subdomainIds->SetNumberOfValues(count);
  vtkSmartPointer<vtkIntArray> ranks = vtk::TakeSmartPointer(newIntArray("Rank"));
  ranks->SetNumberOfValues(count);
  ranks->FillValue(rank);
  vtkIdType* cellId = cellIds->GetPointer(0);
  int* subdomain = subdomainIds->GetPointer(0);
  c = 0;
  for (std::size_t k = 0; k < owned.ids.size(); ++k)
  {
    const int s = owned.ids[k];
    for (vtkIdType t = 0; t < counts[k]; ++t, ++c)
    {
      cellId[c] = totals.offsets.firstTetrahedron[s] + t;
      subdomain[c] = s;
    }
  }
  output->GetCellData()->SetGlobalIds(cellIds);
  output->GetCellData()->AddArray(subdomainIds);
  output->GetCellData()->AddArray(ranks);
  output->GetCellData()->SetActiveScalars("SubdomainId");
}

// Releases the tetrahedra of `owned` (the points stay).
void assembleVolume(OwnedSubdomains& owned, const MeshTotals& totals, const ptm::ComplexPiece& piece,
  const std::unordered_map<long long, long long>& lowest, int rank, vtkUnstructuredGrid* output)
{
  const LocalPoints local = numberLocalPoints(owned, totals);
  output->Initialize();
  addPoints(owned, piece, lowest, rank, local, output);
  addTetrahedra(owned, totals, rank, local, output);
}
/// @}

// The outer boundary triangles (the refined surface) with their input triangle.
void assembleBoundary(const OwnedSubdomains& owned, const MeshTotals& totals, vtkPolyData* boundary)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkSmartPointer<vtkIdTypeArray> pointIds = vtk::TakeSmartPointer(newIdArray("GlobalPointIds"));
  vtkNew<vtkCellArray> cells;
  vtkSmartPointer<vtkIdTypeArray> sources = vtk::TakeSmartPointer(newIdArray(ptm::arrays::SourceFaceId));
  vtkSmartPointer<vtkIntArray> subdomains = vtk::TakeSmartPointer(newIntArray("SubdomainId"));
  std::unordered_map<long long, vtkIdType> localOf;
  for (std::size_t k = 0; k < owned.ids.size(); ++k)
  {
    const ptm::SubdomainSurface& surface = owned.surfaces[k];
    for (std::size_t t = 0; t < surface.surface.triangles.size(); ++t)
    {
      if (surface.otherSide[t] >= 0)
      {
        continue;
      }
      vtkIdType ids[3];
      for (int c = 0; c < 3; ++c)
      {
        const ptm::Index p = surface.surface.triangles[t][c];
        const long long gid = globalIdOf(owned, totals, k, static_cast<std::size_t>(p));
        auto it = localOf.find(gid);
        if (it == localOf.end())
        {
          it = localOf.emplace(gid, points->InsertNextPoint(surface.surface.points[p].data())).first;
          pointIds->InsertNextValue(gid);
        }
        ids[c] = it->second;
      }
      cells->InsertNextCell(3, ids);
      sources->InsertNextValue(surface.sourceFaces[t]);
      subdomains->InsertNextValue(owned.ids[k]);
    }
  }
  boundary->Initialize();
  boundary->SetPoints(points);
  boundary->SetPolys(cells);
  boundary->GetPointData()->SetGlobalIds(pointIds);
  boundary->GetCellData()->AddArray(sources);
  boundary->GetCellData()->AddArray(subdomains);
}

void addTotals(
  const ptm::ComplexPiece& piece, const OwnedSubdomains& owned, const MeshTotals& totals, vtkFieldData* fd)
{
  auto addCount = [&](const char* name, long long value) {
    vtkSmartPointer<vtkIdTypeArray> a = vtk::TakeSmartPointer(newIdArray(name));
    a->InsertNextValue(value);
    fd->AddArray(a);
  };
  auto addValue = [&](const char* name, double value) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->InsertNextValue(value);
    fd->AddArray(a);
  };
  const int K = piece.complex.subdomainCount;
  addCount(ptm::arrays::NumberOfSubdomains, K);
  addCount("GlobalPointCount", totals.offsets.pointCount);
  addCount("GlobalCellCount", totals.offsets.tetrahedronCount);
  addCount("BoundaryPointsAdded", totals.boundaryPointsAdded);
  addCount("SliverRepairPoints", totals.sliverRepairPoints);
  addValue("BoundaryVolumeChange", totals.relativeVolumeChange);
  addValue("BoundaryLargestDeviation", totals.largestDeviation);
  addCount("TetrahedraBelow10Degrees", totals.quality.below10Degrees);
  addValue("MinimumDihedralAngle", totals.quality.minimumDihedralDegrees);
  vtkSmartPointer<vtkIdTypeArray> perSubdomain = vtk::TakeSmartPointer(newIdArray("SubdomainTetrahedra"));
  for (long long t : totals.tetrahedra)
  {
    perSubdomain->InsertNextValue(t);
  }
  fd->AddArray(perSubdomain);
  vtkSmartPointer<vtkIntArray> subdomainRank = vtk::TakeSmartPointer(newIntArray("SubdomainRank"));
  for (int s = 0; s < K; ++s)
  {
    subdomainRank->InsertNextValue(piece.subdomainRank[s]);
  }
  fd->AddArray(subdomainRank);
  double seconds = 0;
  for (double t : owned.seconds)
  {
    seconds += t;
  }
  addValue("RankMeshingSeconds", seconds);
}
/// @}

// TetGen's options from the filter's properties; the automatic volume bound
// is a regular tetrahedron with the input surface's mean edge, the same for
// every subdomain, so the density does not depend on K.
ptm::TetMeshingOptions meshingOptions(vtkParallelTetMesher* filter, const ptm::ComplexPiece& piece)
{
  ptm::TetMeshingOptions options;
  options.radiusEdgeRatio = filter->GetRadiusEdgeRatio();
  options.maximumVolume = filter->GetMaximumVolume() > 0 || !(piece.inputMeanEdgeLength > 0)
    ? filter->GetMaximumVolume()
    : ptm::regularTetrahedronVolume(piece.inputMeanEdgeLength);
  options.minimumDihedralAngle = filter->GetMinimumDihedralAngle();
  options.sliverRepairAngle = filter->GetSliverRepairAngle();
  options.timeLimitSeconds = filter->GetTetGenTimeLimit();
  options.extraSwitches = filter->GetExtraSwitches();
  return options;
}

// Where the environment names a folder (PTM_FAILED_SURFACE_DIR), a subdomain
// surface TetGen could not mesh in any way is written there as
// subdomain-ID.off, as it came to the mesher (before the boundary
// refinement), so the failure can be run again with tetgen alone, and
// subdomain-ID.sides, per triangle the subdomain across (-1: outer); the
// note for the error message, or "".
std::string keepFailedSurface(const ptm::SubdomainSurface& surface, long long id)
{
  const char* dir = std::getenv("PTM_FAILED_SURFACE_DIR");
  if (!dir || !*dir)
  {
    return "";
  }
  const std::string base = std::string(dir) + "/subdomain-" + std::to_string(id);
  const std::string path = base + ".off";
  std::ofstream out(path);
  ptm::writeOff(out, surface.surface);
  std::ofstream sides(base + ".sides");
  for (const auto other : surface.otherSide)
  {
    sides << other << "\n";
  }
  return out && sides ? " (its surface: " + path + ")" : " (its surface could not be written to " + path + ")";
}

// Meshes every subdomain of `owned` in turn (progress and warnings on
// `filter`); the first failure, naming its subdomain, or "".
std::string meshOwnedSubdomains(vtkParallelTetMesher* filter, const ptm::ComplexPiece& piece,
  const ptm::TetMeshingOptions& options, const ptm::SurfaceRefinementOptions* refinement,
  const ptm::SizeField& field, OwnedSubdomains& owned)
{
  const std::string forked = owned.ids.empty() ? "" : ptm::tetgenForkReason();
  if (!forked.empty())
  {
    vtkWarningWithObjectMacro(filter, << forked);
  }
  for (std::size_t k = 0; k < owned.ids.size(); ++k)
  {
    const std::string where = "subdomain " + std::to_string(owned.ids[k]) + ": ";
    std::string error;
    if (!ptm::extractSubdomainSurface(piece.complex, piece.globalIds, owned.ids[k], owned.surfaces[k], error))
    {
      return error;
    }
    filter->SetProgressText(("Meshing " + where).c_str());
    const auto start = std::chrono::steady_clock::now();
    try
    {
      const ptm::SubdomainSurface asCut =
        std::getenv("PTM_FAILED_SURFACE_DIR") ? owned.surfaces[k] : ptm::SubdomainSurface{};
      MeshedSubdomain m = meshSubdomain(owned.surfaces[k], options, refinement, field);
      for (const std::string& w : m.warnings)
      {
        vtkWarningWithObjectMacro(filter, << where << w);
      }
      if (!m.error.empty())
      {
        return where + m.error + keepFailedSurface(asCut, owned.ids[k]);
      }
      owned.pointsAdded[k] = m.pointsAdded;
      owned.sliverPoints[k] = m.sliverPoints;
      owned.volumeChange[k] = m.volumeChange;
      owned.deviation[k] = m.deviation;
      owned.meshes[k] = std::move(m.mesh);
    }
    catch (const std::bad_alloc&)
    {
      return where + "out of memory while meshing";
    }
    catch (const std::exception& e)
    {
      return where + e.what();
    }
    owned.seconds[k] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    filter->UpdateProgress(0.05 + 0.8 * static_cast<double>(k + 1) / owned.ids.size());
  }
  return "";
}
} // namespace

static_assert(ptm::kDefaultSegmentSpacingFloor == 0.125, "BoundarySpacingFloor's default in the header and XML");
vtkStandardNewMacro(vtkParallelTetMesher);
vtkCxxSetObjectMacro(vtkParallelTetMesher, Controller, vtkMultiProcessController);

vtkParallelTetMesher::vtkParallelTetMesher()
{
  this->SetNumberOfOutputPorts(2);
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

vtkParallelTetMesher::~vtkParallelTetMesher()
{
  this->SetController(nullptr);
}

int vtkParallelTetMesher::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkParallelTetMesher::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkUnstructuredGrid" : "vtkPolyData");
  return 1;
}

int vtkParallelTetMesher::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  ptm::announceAnyPiece(outputVector);
  return 1;
}

std::string vtkParallelTetMesher::PropertyError()
{
  ptm::PropertyChecks checks("ParallelTetMesher");
  checks.Require(this->RadiusEdgeRatio >= 1.0 && this->RadiusEdgeRatio <= 100.0,
    "RadiusEdgeRatio", "lie in [1, 100]", this->RadiusEdgeRatio);
  checks.Require(this->MaximumVolume >= 0.0 && std::isfinite(this->MaximumVolume),
    "MaximumVolume", "be 0 (automatic) or a positive volume", this->MaximumVolume);
  checks.Require(this->MinimumDihedralAngle >= 0.0 && this->MinimumDihedralAngle <= 30.0,
    "MinimumDihedralAngle", "lie in [0, 30] degrees", this->MinimumDihedralAngle);
  checks.Require(this->SliverRepairAngle >= 0.0 && this->SliverRepairAngle <= 30.0,
    "SliverRepairAngle", "lie in [0, 30] degrees", this->SliverRepairAngle);
  checks.Require(this->TetGenTimeLimit >= 0.0 && this->TetGenTimeLimit <= 1e6,
    "TetGenTimeLimit", "be 0 (automatic) or a number of seconds up to 1e6", this->TetGenTimeLimit);
  checks.Require(this->CoplanarTolerance >= 0.0 && this->CoplanarTolerance <= 10.0,
    "CoplanarTolerance", "lie in [0, 10] degrees", this->CoplanarTolerance);
  checks.Require(this->BoundaryMinimumAngle > 0.0 && this->BoundaryMinimumAngle <= 34.0,
    "BoundaryMinimumAngle", "lie in (0, 34] degrees", this->BoundaryMinimumAngle);
  checks.Require(this->BoundarySpacingFloor >= ptm::kSmallestSegmentSpacingFloor && this->BoundarySpacingFloor <= 1.0,
    "BoundarySpacingFloor", "lie in [1/1024, 1] (a fraction of the local size)", this->BoundarySpacingFloor);
  return checks.Ok() ? "" : checks.Message();
}

int vtkParallelTetMesher::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  vtkPolyData* boundary = vtkPolyData::GetData(outputVector, 1);
  vtkMultiProcessController* controller = this->Controller;
  // StageRun.h; PhaseLog.h: the last phase is "end": writing
  ptm::StageRun run(this, controller, "ParallelTetMesher", "volume meshing", { output, boundary });
  ptm::ComplexPiece piece;
  if (run.PropertiesRefused(this->PropertyError()) || !run.ReadPiece(input, piece))
  {
    return run.Failure();
  }
  run.Step(0.02, "Extracting subdomain surfaces");
  const ptm::TetMeshingOptions options = meshingOptions(this, piece);
  std::string localError;
  const ptm::SizeField field = ptm::complexSizeField(
    this->SizeExpression, input ? input->GetFieldData() : nullptr, localError);
  if (run.FailedAnywhere(localError) ||
    // a size that cannot fit: the same decision on every rank
    run.FailedAnywhere(memoryShortfall(controller, piece, options.maximumVolume)))
  {
    return run.Failure();
  }

  // Independent meshing of every owned subdomain.
  OwnedSubdomains owned(ptm::ownedSubdomains(piece, run.Rank()));
  ptm::SurfaceRefinementOptions refinement;
  // the edge of the volume bound's regular tetrahedron: surface and volume sized alike
  refinement.size = ptm::regularTetrahedronEdge(options.maximumVolume);
  refinement.minimumAngleDegrees = this->BoundaryMinimumAngle;
  refinement.segmentSpacingFloor = this->BoundarySpacingFloor;
  refinement.coplanarToleranceDegrees = this->CoplanarTolerance;
  refinement.sizeAt = ptm::boundarySizeOf(field, input ? input->GetFieldData() : nullptr); // thickness-capped
  const bool refine = this->BoundaryRefinement && options.maximumVolume > 0;
  localError = meshOwnedSubdomains(this, piece, options, refine ? &refinement : nullptr, field, owned);
  if (run.FailedAnywhere(localError))
  {
    return run.Failure();
  }
  if (run.AbortedAnywhere())
  {
    return run.Aborted();
  }

  run.Step(0.9, "Numbering");
  ptm::phases::setPhase(controller, "numbering and assembly");
  const MeshTotals totals = gatherTotals(controller, piece, owned);
  const std::unordered_map<long long, long long> lowest = lowestSubdomainOfPoints(controller, piece, owned);
  run.Step(0.95, "Assembling");
  assembleVolume(owned, totals, piece, lowest, run.Rank(), output);
  assembleBoundary(owned, totals, boundary);
  ptm::addBoundaryCADFaceIds(input, boundary); // CAD face of every boundary triangle
  addTotals(piece, owned, totals, output->GetFieldData());
  // the same totals on the small boundary port, so a summary can be fetched
  // without gathering the volume mesh onto one process
  boundary->GetFieldData()->ShallowCopy(output->GetFieldData());
  return run.Done();
}

void vtkParallelTetMesher::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RadiusEdgeRatio: " << this->RadiusEdgeRatio << "\n";
  os << indent << "MaximumVolume: " << this->MaximumVolume << "\n";
  os << indent << "MinimumDihedralAngle: " << this->MinimumDihedralAngle << "\n";
  os << indent << "SliverRepairAngle: " << this->SliverRepairAngle << "\n";
  os << indent << "TetGenTimeLimit: " << this->TetGenTimeLimit << "\n";
  os << indent << "ExtraSwitches: " << this->ExtraSwitches << "\n";
  os << indent << "SizeExpression: " << this->SizeExpression << "\n";
  os << indent << "BoundaryRefinement: " << this->BoundaryRefinement << "\n";
  os << indent << "BoundaryMinimumAngle: " << this->BoundaryMinimumAngle << "\n";
  os << indent << "BoundarySpacingFloor: " << this->BoundarySpacingFloor << "\n";
  os << indent << "CoplanarTolerance: " << this->CoplanarTolerance << "\n";
}
