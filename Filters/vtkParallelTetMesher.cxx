#include "vtkParallelTetMesher.h"

#include "GlobalMeshNumbering.h"
#include "PolyDataConversion.h"
#include "PropertyChecks.h"
#include "RankCollectives.h"
#include "SubdomainSurface.h"
#include "SurfaceComplexArrays.h"
#include "SurfaceRefinement.h"
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
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <exception>
#include <limits>
#include <new>
#include <sstream>
#include <unordered_map>

namespace
{
// Why the requested size cannot fit, or nothing: the estimated meshes of the
// ranks that share a machine against that machine's memory, the same
// decision on every rank (all of it is gathered).
std::string memoryShortfall(
  vtkMultiProcessController* controller, const ptm::ComplexPiece& piece, double maximumVolume)
{
  const int K = piece.complex.subdomainCount;
  const int ranks = ptm::rankCount(controller);
  std::vector<double> rankVolume(ranks, 0.0);
  for (int s = 0; s < K; ++s)
  {
    if (piece.subdomainRank[s] >= 0 && piece.subdomainRank[s] < ranks)
    {
      rankVolume[piece.subdomainRank[s]] += piece.subdomainVolume[s];
    }
  }
  const std::vector<long long> machine =
    ptm::allGatherValues(controller, std::vector<long long>{ ptm::machineIdentity() });
  const std::vector<long long> memory = ptm::allGatherValues(
    controller, std::vector<long long>{ static_cast<long long>(ptm::physicalMemoryBytes()) });
  std::map<long long, std::vector<int>> ranksOfMachine;
  for (int r = 0; r < static_cast<int>(machine.size()); ++r)
  {
    ranksOfMachine[machine[r]].push_back(r);
  }
  for (const auto& [id, onIt] : ranksOfMachine)
  {
    double tetrahedra = 0, bytes = 0, available = 0;
    for (int r : onIt)
    {
      const ptm::TetMeshEstimate estimate = ptm::estimateTetMesh(rankVolume[r], maximumVolume);
      tetrahedra += estimate.tetrahedra;
      bytes += estimate.bytes;
      const double reported = static_cast<double>(memory[r]);
      available = available > 0 && reported > 0 ? std::min(available, reported) : reported;
    }
    if (available > 0 && bytes > available)
    {
      std::ostringstream why;
      why.precision(3);
      why << "the requested size (MaximumVolume " << maximumVolume << ") would give about "
          << tetrahedra << " tetrahedra on the " << onIt.size() << " rank" << (onIt.size() > 1 ? "s" : "")
          << " of one machine (rank";
      for (std::size_t k = 0; k < onIt.size() && k < 8; ++k)
      {
        why << (k ? ", " : " ") << onIt[k];
      }
      why << (onIt.size() > 8 ? ", ..." : "") << "), about " << bytes / 1e9 << " GB, more than its "
          << available / 1e9 << " GB of memory; use a larger size or more machines";
      return why.str();
    }
  }
  return {};
}

// The edge of the regular tetrahedron of volume v: the target size of the
// boundary refinement, so that surface and volume are sized alike.
double regularTetrahedronEdge(double v)
{
  return std::cbrt(6.0 * std::sqrt(2.0) * v);
}
} // namespace

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
  for (int port = 0; port < 2; ++port)
  {
    outputVector->GetInformationObject(port)->Set(
      vtkAlgorithm::CAN_HANDLE_PIECE_REQUEST(), 1);
  }
  return 1;
}

int vtkParallelTetMesher::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  vtkPolyData* boundary = vtkPolyData::GetData(outputVector, 1);
  vtkMultiProcessController* controller = this->Controller;
  const int rank = ptm::rankOf(controller);
  std::string message, localError;
  auto fail = [&](const std::string& text) {
    vtkErrorMacro("ParallelTetMesher failed: " << text);
    output->Initialize();
    boundary->Initialize();
    return 0;
  };

  this->UpdateProgress(0.0);
  // nonsense property values (the same on every rank, so every rank stops)
  ptm::PropertyChecks checks("ParallelTetMesher");
  checks.Require(this->RadiusEdgeRatio >= 1.0 && this->RadiusEdgeRatio <= 100.0,
    "RadiusEdgeRatio", "lie in [1, 100]", this->RadiusEdgeRatio);
  checks.Require(this->MaximumVolume >= 0.0 && std::isfinite(this->MaximumVolume),
    "MaximumVolume", "be 0 (automatic) or a positive volume", this->MaximumVolume);
  checks.Require(this->MinimumDihedralAngle >= 0.0 && this->MinimumDihedralAngle <= 30.0,
    "MinimumDihedralAngle", "lie in [0, 30] degrees", this->MinimumDihedralAngle);
  checks.Require(this->CoplanarTolerance >= 0.0 && this->CoplanarTolerance <= 10.0,
    "CoplanarTolerance", "lie in [0, 10] degrees", this->CoplanarTolerance);
  checks.Require(this->BoundaryMinimumAngle > 0.0 && this->BoundaryMinimumAngle <= 34.0,
    "BoundaryMinimumAngle", "lie in (0, 34] degrees", this->BoundaryMinimumAngle);
  if (!checks.Ok())
  {
    vtkErrorMacro(<< checks.Message());
    output->Initialize();
    boundary->Initialize();
    return 0;
  }
  this->SetProgressText("Extracting subdomain surfaces");
  ptm::ComplexPiece piece;
  if (!ptm::complexFromPolyData(input, piece, localError))
  {
    localError = "ParallelTetMesher: " + localError;
  }
  if (!ptm::agreeAllSucceeded(controller, localError.empty(), localError, message))
  {
    return fail(message);
  }
  const int K = piece.complex.subdomainCount;
  std::vector<int> mine;
  for (int s = 0; s < K; ++s)
  {
    if (piece.subdomainRank[s] == rank)
    {
      mine.push_back(s);
    }
  }

  // Independent meshing of every owned subdomain.
  ptm::TetMeshingOptions options;
  options.radiusEdgeRatio = this->RadiusEdgeRatio;
  // automatic size: a regular tetrahedron with the input surface's mean edge,
  // the same for every subdomain, so the density does not depend on K
  options.maximumVolume = this->MaximumVolume > 0 || !(piece.inputMeanEdgeLength > 0)
    ? this->MaximumVolume
    : std::pow(piece.inputMeanEdgeLength, 3) / (6.0 * std::sqrt(2.0));
  options.minimumDihedralAngle = this->MinimumDihedralAngle;
  options.extraSwitches = this->ExtraSwitches;

  // Refuse a size that cannot fit, the same decision on every rank.
  const std::string tooLarge = memoryShortfall(controller, piece, options.maximumVolume);
  if (!tooLarge.empty())
  {
    return fail(tooLarge);
  }
  std::vector<ptm::SubdomainSurface> surfaces(mine.size());
  std::vector<ptm::TetMesh> meshes(mine.size());
  std::vector<double> seconds(mine.size(), 0.0);
  std::vector<long long> added(mine.size(), 0); // points the boundary refinement put on the surface
  std::vector<double> volumeChange(mine.size(), 0.0), deviation(mine.size(), 0.0); // and how it moved it
  for (std::size_t k = 0; k < mine.size() && localError.empty(); ++k)
  {
    const int s = mine[k];
    std::ostringstream where;
    where << "subdomain " << s << ": ";
    if (!ptm::extractSubdomainSurface(piece.complex, piece.globalIds, s, surfaces[k], localError))
    {
      break;
    }
    this->SetProgressText(("Meshing " + where.str()).c_str());
    const auto start = std::chrono::steady_clock::now();
    try
    {
      if (this->BoundaryRefinement && options.maximumVolume > 0)
      {
        ptm::SurfaceRefinementOptions refinement;
        refinement.size = regularTetrahedronEdge(options.maximumVolume);
        refinement.minimumAngleDegrees = this->BoundaryMinimumAngle;
        refinement.coplanarToleranceDegrees = this->CoplanarTolerance;
        const ptm::SurfaceRefinementResult refined = ptm::refineSubdomainSurface(surfaces[k], refinement);
        if (!refined.ok)
        {
          localError = where.str() + "boundary refinement: " + refined.error;
          break;
        }
        for (const std::string& w : refined.warnings)
        {
          vtkWarningMacro(<< where.str() << w);
        }
        added[k] = static_cast<long long>(refined.pointsAdded);
        volumeChange[k] = refined.volumeChange;
        deviation[k] = refined.largestDeviation;
      }
      ptm::TetMeshingResult r = ptm::meshClosedSurface(surfaces[k].surface, options);
      if (!r.ok)
      {
        localError = where.str() + r.error;
        break;
      }
      if (r.attempts > 1)
      {
        vtkWarningMacro(<< where.str() << "TetGen crashed or stalled with the points in their "
                        << "canonical order and meshed them in another order (attempt " << r.attempts
                        << ")");
      }
      meshes[k] = std::move(r.mesh);
    }
    catch (const std::bad_alloc&)
    {
      localError = where.str() + "out of memory while meshing";
      break;
    }
    catch (const std::exception& e)
    {
      localError = where.str() + e.what();
      break;
    }
    seconds[k] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    this->UpdateProgress(0.05 + 0.8 * static_cast<double>(k + 1) / mine.size());
  }
  if (!ptm::agreeAllSucceeded(controller, localError.empty(), localError, message))
  {
    return fail(message);
  }
  if (ptm::agreeAnyAborted(controller, this))
  {
    output->Initialize();
    boundary->Initialize();
    return 1;
  }

  // Global numbering from every subdomain's counts.
  this->SetProgressText("Numbering");
  std::vector<long long> counts;
  for (std::size_t k = 0; k < mine.size(); ++k)
  {
    counts.push_back(mine[k]);
    // every point beyond the complex's own (the refinement's, TetGen's) is
    // private to the subdomain and numbered with it
    counts.push_back(static_cast<long long>(meshes[k].points.size() - surfaces[k].globalIds.size()));
    counts.push_back(static_cast<long long>(meshes[k].tets.size()));
    counts.push_back(added[k]);
  }
  const std::vector<long long> allCounts = ptm::allGatherValues(controller, counts);
  std::vector<double> changes;
  ptm::DihedralQuality quality; // this rank's, then every rank's
  for (std::size_t k = 0; k < mine.size(); ++k)
  {
    changes.insert(changes.end(), { static_cast<double>(mine[k]), volumeChange[k], deviation[k] });
    const ptm::DihedralQuality q = ptm::dihedralQuality(meshes[k]);
    quality.below10Degrees += q.below10Degrees;
    quality.minimumDihedralDegrees = std::min(quality.minimumDihedralDegrees, q.minimumDihedralDegrees);
  }
  {
    std::vector<double> below{ static_cast<double>(quality.below10Degrees) }; // exact below 2^53
    ptm::allReduceSum(controller, below);
    std::vector<long long> minimum{ -std::llround(quality.minimumDihedralDegrees * 1e9) };
    ptm::allReduceMax(controller, minimum);
    quality.below10Degrees = std::llround(below[0]);
    quality.minimumDihedralDegrees = -static_cast<double>(minimum[0]) * 1e-9;
  }
  const std::vector<double> allChanges = ptm::allGatherValues(controller, changes);
  std::vector<double> subdomainChange(K, 0.0);
  double largestDeviation = 0;
  for (std::size_t k = 0; k + 2 < allChanges.size(); k += 3)
  {
    subdomainChange[static_cast<int>(allChanges[k])] = allChanges[k + 1];
    largestDeviation = std::max(largestDeviation, allChanges[k + 2]);
  }
  double totalChange = 0, totalVolume = 0; // summed in subdomain order: the same on any number of ranks
  for (int s = 0; s < K; ++s)
  {
    totalChange += subdomainChange[s];
    totalVolume += piece.subdomainVolume[s];
  }
  std::vector<long long> interior(K, 0), tets(K, 0);
  long long boundaryPointsAdded = 0;
  for (std::size_t k = 0; k + 3 < allCounts.size(); k += 4)
  {
    interior[allCounts[k]] = allCounts[k + 1];
    tets[allCounts[k]] = allCounts[k + 2];
    boundaryPointsAdded += allCounts[k + 3];
  }
  const ptm::GlobalMeshOffsets offsets =
    ptm::globalMeshOffsets(piece.globalPointCount, interior, tets);

  // Owner of every surface point: the rank of the lowest subdomain touching it.
  std::vector<long long> lowest(static_cast<std::size_t>(piece.globalPointCount),
    std::numeric_limits<long long>::max());
  for (std::size_t k = 0; k < mine.size(); ++k)
  {
    for (ptm::Index g : surfaces[k].globalIds)
    {
      lowest[g] = std::min<long long>(lowest[g], mine[k]);
    }
  }
  ptm::allReduceMin(controller, lowest);

  // Assemble this rank's piece.
  this->SetProgressText("Assembling");
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkIdTypeArray> pointIds;
  pointIds->SetName("GlobalPointIds");
  vtkNew<vtkUnsignedCharArray> ghosts;
  ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
  std::unordered_map<long long, vtkIdType> localOf;
  auto addPoint = [&](long long gid, const ptm::Vec3& x, int owner) {
    auto it = localOf.find(gid);
    if (it != localOf.end())
    {
      return it->second;
    }
    const vtkIdType id = points->InsertNextPoint(x.data());
    pointIds->InsertNextValue(gid);
    ghosts->InsertNextValue(owner == rank ? 0 : vtkDataSetAttributes::DUPLICATEPOINT);
    localOf.emplace(gid, id);
    return id;
  };
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkIdTypeArray> cellIds;
  cellIds->SetName("GlobalCellIds");
  vtkNew<vtkIntArray> subdomainIds;
  subdomainIds->SetName("SubdomainId");
  vtkNew<vtkIntArray> ranks;
  ranks->SetName("Rank");
  vtkNew<vtkPoints> boundaryPoints;
  boundaryPoints->SetDataTypeToDouble();
  vtkNew<vtkIdTypeArray> boundaryPointIds;
  boundaryPointIds->SetName("GlobalPointIds");
  std::unordered_map<long long, vtkIdType> boundaryLocalOf;
  vtkNew<vtkCellArray> boundaryCells;
  vtkNew<vtkIdTypeArray> boundarySources;
  boundarySources->SetName(ptm::arrays::SourceFaceId);
  vtkNew<vtkIntArray> boundarySubdomains;
  boundarySubdomains->SetName("SubdomainId");
  for (std::size_t k = 0; k < mine.size(); ++k)
  {
    const int s = mine[k];
    const ptm::SubdomainSurface& surface = surfaces[k];
    const ptm::TetMesh& mesh = meshes[k];
    const std::size_t nShared = surface.globalIds.size(); // the complex's points, maybe shared
    auto globalIdOf = [&](std::size_t i) {
      return i < nShared ? static_cast<long long>(surface.globalIds[i])
                         : offsets.firstInteriorPoint[s] + static_cast<long long>(i - nShared);
    };
    std::vector<vtkIdType> local(mesh.points.size());
    for (std::size_t i = 0; i < mesh.points.size(); ++i)
    {
      const long long gid = globalIdOf(i);
      const int owner = i < nShared ? ptm::owningRank(static_cast<int>(lowest[gid]), piece.subdomainRank) : rank;
      local[i] = addPoint(gid, mesh.points[i], owner);
    }
    for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    {
      const vtkIdType ids[4] = { local[mesh.tets[t][0]], local[mesh.tets[t][1]],
        local[mesh.tets[t][2]], local[mesh.tets[t][3]] };
      cells->InsertNextCell(4, ids);
      cellIds->InsertNextValue(offsets.firstTetrahedron[s] + static_cast<long long>(t));
      subdomainIds->InsertNextValue(s);
      ranks->InsertNextValue(rank);
    }
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
        const long long gid = globalIdOf(static_cast<std::size_t>(p));
        auto it = boundaryLocalOf.find(gid);
        if (it == boundaryLocalOf.end())
        {
          it = boundaryLocalOf.emplace(gid, boundaryPoints->InsertNextPoint(surface.surface.points[p].data())).first;
          boundaryPointIds->InsertNextValue(gid);
        }
        ids[c] = it->second;
      }
      boundaryCells->InsertNextCell(3, ids);
      boundarySources->InsertNextValue(surface.sourceFaces[t]);
      boundarySubdomains->InsertNextValue(s);
    }
  }
  output->Initialize();
  output->SetPoints(points);
  output->SetCells(VTK_TETRA, cells);
  output->GetPointData()->SetGlobalIds(pointIds);
  output->GetPointData()->AddArray(ghosts);
  output->GetCellData()->SetGlobalIds(cellIds);
  output->GetCellData()->AddArray(subdomainIds);
  output->GetCellData()->AddArray(ranks);
  output->GetCellData()->SetActiveScalars("SubdomainId");
  vtkFieldData* fd = output->GetFieldData();
  auto addCount = [&](vtkFieldData* to, const char* name, long long value) {
    vtkNew<vtkIdTypeArray> a;
    a->SetName(name);
    a->InsertNextValue(value);
    to->AddArray(a);
  };
  addCount(fd, ptm::arrays::NumberOfSubdomains, K);
  addCount(fd, "GlobalPointCount", offsets.pointCount);
  addCount(fd, "GlobalCellCount", offsets.tetrahedronCount);
  addCount(fd, "BoundaryPointsAdded", boundaryPointsAdded);
  auto addValue = [&](const char* name, double value) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->InsertNextValue(value);
    fd->AddArray(a);
  };
  addValue("BoundaryVolumeChange", totalVolume != 0 ? totalChange / totalVolume : 0.0);
  addValue("BoundaryLargestDeviation", largestDeviation);
  addCount(fd, "TetrahedraBelow10Degrees", quality.below10Degrees);
  addValue("MinimumDihedralAngle", quality.minimumDihedralDegrees);
  vtkNew<vtkIdTypeArray> perSubdomain;
  perSubdomain->SetName("SubdomainTetrahedra");
  for (long long t : tets)
  {
    perSubdomain->InsertNextValue(t);
  }
  fd->AddArray(perSubdomain);
  vtkNew<vtkIntArray> subdomainRank;
  subdomainRank->SetName("SubdomainRank");
  for (int s = 0; s < K; ++s)
  {
    subdomainRank->InsertNextValue(piece.subdomainRank[s]);
  }
  fd->AddArray(subdomainRank);
  vtkNew<vtkDoubleArray> times;
  times->SetName("RankMeshingSeconds");
  double total = 0;
  for (double t : seconds)
  {
    total += t;
  }
  times->InsertNextValue(total);
  fd->AddArray(times);

  boundary->Initialize();
  boundary->SetPoints(boundaryPoints);
  boundary->SetPolys(boundaryCells);
  boundary->GetPointData()->SetGlobalIds(boundaryPointIds);
  boundary->GetCellData()->AddArray(boundarySources);
  boundary->GetCellData()->AddArray(boundarySubdomains);
  // the same totals on the small boundary port, so a summary can be fetched
  // without gathering the volume mesh onto one process
  boundary->GetFieldData()->ShallowCopy(fd);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkParallelTetMesher::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RadiusEdgeRatio: " << this->RadiusEdgeRatio << "\n";
  os << indent << "MaximumVolume: " << this->MaximumVolume << "\n";
  os << indent << "MinimumDihedralAngle: " << this->MinimumDihedralAngle << "\n";
  os << indent << "ExtraSwitches: " << this->ExtraSwitches << "\n";
  os << indent << "BoundaryRefinement: " << this->BoundaryRefinement << "\n";
  os << indent << "BoundaryMinimumAngle: " << this->BoundaryMinimumAngle << "\n";
  os << indent << "CoplanarTolerance: " << this->CoplanarTolerance << "\n";
}
