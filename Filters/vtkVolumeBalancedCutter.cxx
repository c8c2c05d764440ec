#include "vtkVolumeBalancedCutter.h"

#include "CADFaceIds.h"
#include "LocalThickness.h"
#include "MemoryCheck.h"
#include "PipelineRequests.h"
#include "PolyDataConversion.h"
#include "PropertyChecks.h"
#include "RankCollectives.h"
#include "PredictedCost.h"
#include "SizeField.h"
#include "SizeFunction.h"
#include "StageRun.h"
#include "SubdomainAssignment.h"
#include "SurfaceComplexArrays.h"
#include "VolumeBalancedDecomposition.h"

#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"

#include <cmath>
#include <exception>
#include <sstream>
#include <utility>

namespace
{
// The tetrahedra TetGen is expected to make in every subdomain
// (PredictedCost.h), by which the subdomains go to the ranks: for the size
// field no larger than the mesher's largest size (`maximumSize`, or the
// input's mean edge as the mesher's automatic MaximumVolume), or for that
// size alone without a field (predictUniformCost, a model fitted on real
// parts, counting the thickness cap where there is one); a field must be
// positive at every point of the complex. Every
// rank has the whole complex, so every rank gets the same costs, or the
// same error. Without a field the subdomains went by
// volume until session 22: on 10 real surfaces at K = 16 on 2 ranks the
// largest rank had 1.02-1.82 x the mean tetrahedra (1.26 on average).
bool predictedCosts(const ptm::DecompositionResult& result, const ptm::SizeField& field, double maximumSize,
  const ptm::SizeFunction& thicknessCap, ptm::PredictedCost& predicted, std::string& error)
{
  predicted = {};
  const double cap = maximumSize > 0 ? maximumSize : result.inputMeanEdgeLength;
  if (!field)
  {
    if (cap > 0)
    {
      predicted = ptm::predictUniformCost(result.complex, cap, thicknessCap);
    }
    return true;
  }
  std::vector<double> sizes;
  if (!ptm::sizesAt(field, result.complex.points, sizes, error))
  {
    return false;
  }
  predicted = ptm::predictCost(result.complex, ptm::cappedSize(field.size, cap));
  return true;
}

// x, y, z and the value of the point array `name` at every point of `source`
// (the SizeArray's samples on this rank); an error naming the array when
// it is missing or has more than one component.
std::vector<double> localSizeSamples(
  vtkDataSet* source, const char* what, const std::string& name, std::string& error)
{
  std::vector<double> xyzh;
  vtkDataArray* values = source ? source->GetPointData()->GetArray(name.c_str()) : nullptr;
  if (source && source->GetNumberOfPoints() > 0 && !values)
  {
    error = "SizeArray '" + name + "' is not a point array of the " + what;
    return xyzh;
  }
  if (values && values->GetNumberOfComponents() != 1)
  {
    error = "SizeArray '" + name + "' has " + std::to_string(values->GetNumberOfComponents()) +
      " components; a size is one number per point";
    return xyzh;
  }
  const vtkIdType n = source ? source->GetNumberOfPoints() : 0;
  xyzh.resize(4 * static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    source->GetPoint(i, &xyzh[4 * static_cast<std::size_t>(i)]);
    xyzh[4 * static_cast<std::size_t>(i) + 3] = values->GetComponent(i, 0);
  }
  return xyzh;
}

// Collective: the size field of the cutter (its SizeExpression, or the
// SizeArray's samples from `sizeSource` or else `input`, whole on every
// rank); false with this rank's error when it cannot be made (the caller
// agrees across ranks).
bool cutterSizeField(vtkMultiProcessController* controller, const std::string& expression,
  const std::string& arrayName, vtkDataSet* sizeSource, vtkPolyData* input, ptm::SizeSamples& samples,
  ptm::SizeField& field, std::string& error)
{
  if (arrayName.empty())
  {
    field = ptm::sizeFieldOf(expression, error); // the same on every rank
    return error.empty();
  }
  samples.arrayName = arrayName;
  const std::vector<double> local =
    localSizeSamples(sizeSource ? sizeSource : input, sizeSource ? "SizeSource" : "input surface",
      arrayName, error);
  // collective: every rank takes part, even one whose samples failed (the
  // caller then agrees to fail)
  samples.xyzh = ptm::wholeValuesOnEveryRank(controller, local);
  if (error.empty())
  {
    field = ptm::sizeFieldOfSamples(samples, error); // whole samples: the same on every rank
  }
  return error.empty();
}

// The core's options from the filter's properties (K = 0: one per rank).
ptm::DecompositionOptions decompositionOptions(vtkVolumeBalancedCutter* f, int ranks, const ptm::SizeField& size)
{
  ptm::DecompositionOptions options;
  options.numberOfSubdomains = f->GetNumberOfSubdomains() > 0 ? f->GetNumberOfSubdomains() : ranks;
  options.strategy = f->GetStrategy() == vtkVolumeBalancedCutter::PARALLEL_PLANES
    ? ptm::CutStrategy::ParallelPlanes
    : ptm::CutStrategy::RecursiveBisection;
  options.direction = static_cast<ptm::CutDirection>(f->GetDirection());
  options.criterion = static_cast<ptm::BalanceCriterion>(f->GetBalanceCriterion());
  options.costSize = size.size;
  options.costMaximumSize = f->GetMaximumSize();
  options.balanceTolerance = f->GetBalanceTolerance();
  options.alignmentAngleDegrees = f->GetPlaneAlignmentAngle();
  options.tiltDegrees = f->GetPlaneTiltAngle();
  options.minimumSlabThickness = f->GetMinimumSlabThickness();
  options.inputCheck.checkSelfIntersections = f->GetCheckSelfIntersections() != 0;
  options.removeFlatCrossings = f->GetRemoveFlatCrossings() != 0;
  options.inputCheck.selfIntersectionLimit = static_cast<std::size_t>(f->GetSelfIntersectionCheckLimit());
  return options;
}

/// @name The cut checks shared among ranks
/// @{
// Every rank cuts the whole surface; the self-crossing checks of each cut
// (most of the cutter's time on a ball at K = 64) are shared out: rank r
// checks the parts numbered r modulo the ranks (DecompositionOptions::
// checksPart; the two parts of a cut are numbered one after the other). Each
// collective carries {the largest verdict, whether a rank is still cutting},
// so that a rank that leaves the decomposition early (an exception) keeps
// answering the others' checks until every rank has left it
// (finishSharedCutChecks), and nobody waits.
void shareCutChecks(vtkMultiProcessController* controller, int rank, ptm::DecompositionOptions& options)
{
  const int ranks = ptm::rankCount(controller);
  if (ranks < 2)
  {
    return;
  }
  options.checksPart = [rank, ranks](int part) { return part % ranks == rank; };
  options.maxOverProcesses = [controller](int verdict) {
    std::vector<long long> v{ verdict, 1 };
    ptm::allReduceMax(controller, v);
    return static_cast<int>(v[0]);
  };
}

void finishSharedCutChecks(vtkMultiProcessController* controller, bool failed)
{
  if (ptm::rankCount(controller) < 2)
  {
    return;
  }
  for (;;)
  {
    std::vector<long long> v{ failed ? ptm::kCheckFailed : 0, 0 };
    ptm::allReduceMax(controller, v);
    if (v[1] == 0)
    {
      return;
    }
  }
}
/// @}

vtkSmartPointer<vtkDoubleArray> doubleArray(const char* name, const std::vector<double>& values)
{
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  for (double v : values)
  {
    a->InsertNextValue(v);
  }
  return a;
}

// The cutter's facts every later filter passes on: the balance criterion and
// how far it was met, the cuts the alignment turned or tilted, the contour
// points taken out of planar faces, what the input check repaired (as warned).
void addCutterFacts(vtkFieldData* fd, const ptm::DecompositionResult& result, const std::string& criterionName)
{
  vtkNew<vtkStringArray> criterion;
  criterion->SetName(ptm::arrays::BalanceCriterionName);
  criterion->InsertNextValue(criterionName);
  fd->AddArray(criterion);
  fd->AddArray(doubleArray(ptm::arrays::MaximumImbalance, { result.maximumImbalance }));
  vtkNew<vtkIntArray> aligned; // cuts turned parallel to an earlier line, and through it
  aligned->SetName(ptm::arrays::AlignedCuts);
  aligned->SetNumberOfComponents(2);
  const int alignedCounts[2] = { result.alignedNormals, result.alignedLines };
  aligned->InsertNextTypedTuple(alignedCounts);
  fd->AddArray(aligned);
  vtkNew<vtkIntArray> tilted;
  tilted->SetName(ptm::arrays::TiltedCuts);
  tilted->InsertNextValue(result.tiltedCuts);
  fd->AddArray(tilted);
  vtkNew<vtkIdTypeArray> flat; // FlatCrossingRemoval.h
  flat->SetName(ptm::arrays::FlatCrossingsRemoved);
  flat->InsertNextValue(static_cast<vtkIdType>(result.flatCrossingsRemoved));
  fd->AddArray(flat);
  vtkNew<vtkStringArray> repairs;
  repairs->SetName(ptm::arrays::InputRepairs);
  for (const std::string& warning : result.warnings)
  {
    repairs->InsertNextValue(warning);
  }
  fd->AddArray(repairs);
}
// This rank's block of the thickness rays: every rank has the whole
// surface, and rank r casts the rays of triangles n r / P .. n (r + 1) / P,
// so the blocks gathered in rank order are the samples of one serial call
// (LocalThickness.h), whatever the rank count. Blocks of equal triangle
// count are not of equal cost: Prusa's aq_bed (15,676 triangles, 2.3 M
// samples) took 7.9 s whole, 2.8 and 3.6 s in two blocks, 1.2-2.5 s in
// four (a small driver, beside a sweep).
std::string rayBlockSamples(vtkMultiProcessController* controller, const ptm::TriangleSurface& surface,
  double limit, std::vector<double>& samples)
{
  const std::size_t n = surface.triangles.size();
  const std::size_t rank = static_cast<std::size_t>(ptm::rankOf(controller));
  const std::size_t ranks = static_cast<std::size_t>(ptm::rankCount(controller));
  try
  {
    samples = ptm::thicknessSamples(surface, limit, n * rank / ranks, n * (rank + 1) / ranks);
  }
  catch (const std::exception& e)
  {
    return std::string("unexpected failure while measuring the thickness: ") + e.what();
  }
  return {};
}

// Collective: the whole input checked alike on every rank
// (prepareInputSurface: merged, cleaned, oriented outward); false when it is
// empty or refused (run reports why, agreed across ranks).
bool checkedInput(ptm::StageRun& run, const ptm::TriangleSurface& surface, const ptm::InputCheckOptions& options,
  ptm::PreparedSurface& prepared)
{
  std::string error;
  if (surface.triangles.empty())
  {
    error = "the input has no triangles (is the reader's file empty or not a surface?)";
  }
  else
  {
    try
    {
      prepared = ptm::prepareInputSurface(surface, options);
      error = prepared.ok ? "" : "the input surface cannot be meshed: " + prepared.error;
    }
    catch (const std::exception& e)
    {
      error = std::string("unexpected failure while checking the input: ") + e.what();
    }
  }
  return !run.FailedAnywhere(error);
}

// Why the tetrahedra MaximumSize asks for cannot fit in the machines'
// memory, or nothing, before any cut (MemoryCheck.h): the volume is shared
// evenly among the ranks, as the cuts will share it, and the size caps a
// size field, so the real mesh is no smaller. Nothing without a size.
std::string meshTooLarge(vtkMultiProcessController* controller, double maximumSize, double volume)
{
  if (!(maximumSize > 0))
  {
    return {};
  }
  const int ranks = ptm::rankCount(controller);
  std::ostringstream requested;
  requested.precision(3);
  requested << "MaximumSize " << maximumSize;
  const double regular = std::fabs(volume) / ranks / ptm::regularTetrahedronVolume(maximumSize);
  return ptm::memoryShortfall(controller, std::vector<double>(ranks, regular), requested.str());
}

// The same after the cuts, from the regular tetrahedra predicted for each
// rank's subdomains: this counts a size field (SizeExpression or
// SizeArray, capped at MaximumSize), which the size alone does not (a
// field of 0.001 on the unit ball went on to the interfaces and the
// mesher). Nothing where no cost was predicted.
std::string predictedMeshTooLarge(vtkMultiProcessController* controller, const ptm::PredictedCost& cost,
  const std::vector<int>& subdomainRank, const std::string& expression, const std::string& array,
  double maximumSize)
{
  const bool field = !expression.empty() || !array.empty();
  std::ostringstream requested;
  requested.precision(3);
  if (field)
  {
    requested << (expression.empty() ? "SizeArray '" + array : "SizeExpression '" + expression) << "'";
    if (maximumSize > 0)
    {
      requested << " capped at MaximumSize " << maximumSize;
    }
  }
  else if (maximumSize > 0)
  {
    requested << "MaximumSize " << maximumSize;
  }
  else
  {
    requested << "the automatic size, the input's mean edge";
  }
  // a field is floored at 1e-3 of the diagonal in the prediction
  return ptm::memoryShortfall(controller,
    ptm::regularPerRank(cost.regularTetrahedra, subdomainRank, ptm::rankCount(controller)), requested.str(), field);
}

// The complex of the cut as the next stage reads it, its subdomains
// assigned to ranks; the result's complex is moved out.
ptm::ComplexPiece cutPiece(ptm::DecompositionResult& result, const std::vector<int>& subdomainRank)
{
  ptm::ComplexPiece piece;
  piece.subdomainVolume = result.subdomainVolume;
  piece.subdomainMeasure = result.subdomainMeasure;
  piece.subdomainRank = subdomainRank;
  piece.globalPointCount = static_cast<ptm::Index>(result.complex.points.size());
  piece.inputMeanEdgeLength = result.inputMeanEdgeLength;
  piece.complex = std::move(result.complex);
  return piece;
}

// The whole surface's thickness samples on every rank: each rank casts the
// rays of its block (rayBlockSamples), a failure is agreed, and the blocks
// are gathered in rank order. False when a rank failed (run reports it).
bool measureThickness(vtkMultiProcessController* controller, ptm::StageRun& run, const ptm::TriangleSurface& surface,
  double limit, std::vector<double>& xyzt)
{
  std::vector<double> mine;
  if (run.FailedAnywhere(rayBlockSamples(controller, surface, limit, mine)))
  {
    return false;
  }
  xyzt = ptm::allGatherValues(controller, mine);
  return true;
}
} // namespace

vtkStandardNewMacro(vtkVolumeBalancedCutter);
vtkCxxSetObjectMacro(vtkVolumeBalancedCutter, Controller, vtkMultiProcessController);

vtkVolumeBalancedCutter::vtkVolumeBalancedCutter()
{
  this->SetNumberOfInputPorts(2);
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

vtkVolumeBalancedCutter::~vtkVolumeBalancedCutter()
{
  this->SetController(nullptr);
}

int vtkVolumeBalancedCutter::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  ptm::announceAnyPiece(outputVector);
  return 1;
}

// Every rank asks its upstream for the whole surface (PipelineRequests.h says why).
int vtkVolumeBalancedCutter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  ptm::requestWholeInput(inputVector);
  ptm::requestWholeInput(inputVector, 1); // the SizeSource, when there is one
  return 1;
}

int vtkVolumeBalancedCutter::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  return this->Superclass::FillInputPortInformation(port, info);
}

std::string vtkVolumeBalancedCutter::PropertyError()
{
  ptm::PropertyChecks checks("VolumeBalancedCutter");
  checks.Require(this->NumberOfSubdomains >= 0 && this->NumberOfSubdomains <= 1000000,
    "NumberOfSubdomains", "be 0 (one per rank) or between 1 and 1000000", this->NumberOfSubdomains);
  checks.Require(this->BalanceTolerance >= 1e-6 && this->BalanceTolerance <= 0.5,
    "BalanceTolerance", "lie in [1e-6, 0.5]", this->BalanceTolerance);
  checks.Require(this->PlaneAlignmentAngle >= 0 && this->PlaneAlignmentAngle <= 45,
    "PlaneAlignmentAngle", "lie in [0, 45] degrees", this->PlaneAlignmentAngle);
  checks.Require(this->PlaneTiltAngle >= 0 && this->PlaneTiltAngle <= 30,
    "PlaneTiltAngle", "lie in [0, 30] degrees", this->PlaneTiltAngle);
  checks.Require(this->MinimumSlabThickness >= 0 && this->MinimumSlabThickness <= 1,
    "MinimumSlabThickness", "lie in [0, 1] (a fraction of the mesh size)", this->MinimumSlabThickness);
  checks.Require(this->MaximumSize >= 0 && std::isfinite(this->MaximumSize), "MaximumSize",
    "be 0 (automatic) or a positive length", this->MaximumSize);
  checks.Require(this->SelfIntersectionCheckLimit >= 0, "SelfIntersectionCheckLimit",
    "be a number of triangles, 0 or more", this->SelfIntersectionCheckLimit);
  checks.Require(this->SizeExpression.empty() || this->SizeArray.empty(), "SizeExpression",
    "be empty when SizeArray is set (one size field)", this->SizeExpression);
  return checks.Ok() ? "" : checks.Message();
}

int vtkVolumeBalancedCutter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkMultiProcessController* controller = this->Controller;
  ptm::StageRun run(this, controller, "VolumeBalancedCutter", "cut", { output }); // StageRun.h
  if (run.PropertiesRefused(this->PropertyError()))
  {
    return run.Failure();
  }
  ptm::SizeSamples samples;
  ptm::SizeField size;
  std::string localError;
  cutterSizeField(controller, this->SizeExpression, this->SizeArray, vtkDataSet::GetData(inputVector[1], 0),
    input, samples, size, localError);
  if (run.FailedAnywhere(localError))
  {
    return run.Failure();
  }
  run.Step(0.02, "Gathering the surface");
  const ptm::TriangleSurface local = ptm::triangleSurfaceFromPolyData(input);
  const ptm::TriangleSurface surface = ptm::wholeSurfaceOnEveryRank(controller, local);
  // the CAD face of every input triangle, for the mesher's boundary (CADFaceIds.h)
  const vtkSmartPointer<vtkIdTypeArray> cadFaces =
    ptm::gatherCADFaceTable(controller, input, local.triangles.size(), surface.triangles.size());
  if (run.AbortedAnywhere())
  {
    return run.Aborted();
  }

  run.Step(0.04, "Checking the surface");
  ptm::DecompositionOptions options = decompositionOptions(this, ptm::rankCount(controller), size);
  ptm::PreparedSurface prepared;
  if (!checkedInput(run, surface, options.inputCheck, prepared) ||
    run.FailedAnywhere(meshTooLarge(controller, this->MaximumSize, prepared.enclosedVolume)))
  {
    return run.Failure();
  }

  // Measured on the checked surface (outward, as the rays need) before the
  // cuts, so the cost they balance counts the finer walls (PredictedCost.h:
  // predictUniformCost).
  std::vector<double> thickness;
  const double thicknessLimit = this->MaximumSize > 0 ? this->MaximumSize : ptm::meanEdgeLength(prepared.surface);
  if (this->SizeByThickness)
  {
    run.Step(0.05, "Measuring the thickness");
    if (!measureThickness(controller, run, prepared.surface, thicknessLimit, thickness))
    {
      return run.Failure();
    }
  }

  run.Step(0.1, "Cutting");
  if (!thickness.empty())
  {
    // one lattice for the cuts, their measure and the assignment
    const ptm::SizeFunction cap = ptm::thicknessCappedSize(nullptr, thickness, thicknessLimit);
    options.costThicknessCap = ptm::onLattice(
      [cap, thicknessLimit](const ptm::Vec3& p) { return std::min(thicknessLimit, cap(p)); },
      prepared.surface.points, 0.5 * thicknessLimit);
  }
  shareCutChecks(controller, run.Rank(), options);
  if (cadFaces)
  {
    // contour points between two CAD faces stay, so each piece keeps its face
    options.faceGroups.resize(static_cast<std::size_t>(cadFaces->GetNumberOfValues()));
    for (vtkIdType i = 0; i < cadFaces->GetNumberOfValues(); ++i)
    {
      options.faceGroups[i] = cadFaces->GetValue(i);
    }
  }
  ptm::DecompositionResult result;
  bool threw = false;
  try
  {
    result = ptm::decomposeVolumeBalanced(std::move(prepared), options);
    localError = result.ok          ? ""
      : result.refusedBeforeCutting ? "the cut is refused: " + result.error
      : result.failedInCuts         ? "the cut failed (the input surface is sound; another K, strategy or "
                                      "Direction cuts it otherwise): " + result.error
                                    : "the input surface cannot be meshed: " + result.error;
  }
  catch (const std::exception& e)
  {
    localError = std::string("unexpected failure while cutting: ") + e.what();
    threw = true;
  }
  finishSharedCutChecks(controller, threw);
  ptm::PredictedCost cost;
  if (localError.empty())
  {
    predictedCosts(result, size, this->MaximumSize, options.costThicknessCap, cost, localError);
  }
  if (run.FailedAnywhere(localError))
  {
    return run.Failure();
  }
  const std::vector<double>& predicted = cost.tetrahedra;
  const std::vector<int> subdomainRank =
    ptm::assignSubdomainsToRanks(predicted.empty() ? result.subdomainMeasure : predicted, ptm::rankCount(controller));
  if (run.FailedAnywhere(predictedMeshTooLarge(controller, cost, subdomainRank, this->SizeExpression,
        this->SizeArray, this->MaximumSize)))
  {
    return run.Failure();
  }
  for (const std::string& warning : result.warnings)
  {
    if (run.Rank() == 0)
    {
      vtkWarningMacro(<< warning);
    }
  }
  const std::size_t subdomains = result.subdomainVolume.size();
  const std::size_t ranks = static_cast<std::size_t>(ptm::rankCount(controller));
  if (run.Rank() == 0 && subdomains < ranks)
  {
    // a run that silently leaves ranks idle looks like a slow machine
    const std::size_t idle = ranks - subdomains;
    vtkWarningMacro(<< "NumberOfSubdomains " << subdomains << " is less than the " << ranks << " ranks: " << idle
                    << (idle == 1 ? " rank gets no subdomain and stays idle" : " ranks get no subdomain and stay idle")
                    << " while the others mesh (give at least one subdomain per rank, or 0 for one each)");
  }
  if (run.AbortedAnywhere())
  {
    return run.Aborted();
  }

  run.Step(0.8, "Writing the complex");
  ptm::writeOwnedFaces(cutPiece(result, subdomainRank), run.Rank(), output);
  vtkFieldData* fd = output->GetFieldData();
  addCutterFacts(fd, result, ptm::toString(options.criterion));
  if (!predicted.empty())
  {
    fd->AddArray(doubleArray(ptm::arrays::SubdomainPredictedTetrahedra, predicted));
  }
  if (cadFaces)
  {
    fd->AddArray(cadFaces);
  }
  if (!samples.xyzh.empty())
  {
    ptm::addSizeSamples(fd, samples); // for the triangulator and the mesher (SizeField.h)
  }
  if (this->SizeByThickness)
  {
    ptm::addThicknessSamples(fd, thickness, thicknessLimit);
  }
  return run.Done();
}

void vtkVolumeBalancedCutter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfSubdomains: " << this->NumberOfSubdomains << "\n";
  os << indent << "Strategy: " << this->Strategy << "\n";
  os << indent << "Direction: " << this->Direction << "\n";
  os << indent << "BalanceCriterion: " << this->BalanceCriterion << "\n";
  os << indent << "BalanceTolerance: " << this->BalanceTolerance << "\n";
  os << indent << "PlaneAlignmentAngle: " << this->PlaneAlignmentAngle << "\n";
  os << indent << "PlaneTiltAngle: " << this->PlaneTiltAngle << "\n";
  os << indent << "MinimumSlabThickness: " << this->MinimumSlabThickness << "\n";
  os << indent << "CheckSelfIntersections: " << this->CheckSelfIntersections << "\n";
  os << indent << "RemoveFlatCrossings: " << this->RemoveFlatCrossings << "\n";
  os << indent << "SizeByThickness: " << this->SizeByThickness << "\n";
  os << indent << "SelfIntersectionCheckLimit: " << this->SelfIntersectionCheckLimit << "\n";
  os << indent << "SizeExpression: " << this->SizeExpression << "\n";
  os << indent << "SizeArray: " << this->SizeArray << "\n";
  os << indent << "MaximumSize: " << this->MaximumSize << "\n";
  os << indent << "Controller: " << this->Controller << "\n";
}
