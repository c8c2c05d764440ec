#ifndef PTM_SURFACE_COMPLEX_ARRAYS_H
#define PTM_SURFACE_COMPLEX_ARRAYS_H
// Names of the arrays of the labeled surface complex as vtkPolyData (the
// output of VolumeBalancedCutter, InterfaceTriangulator and SurfaceRelaxer).
// README.md, section "The labeled surface complex", documents them.
namespace ptm::arrays
{
// point data
constexpr const char* GlobalPointIds = "GlobalPointIds"; // vtkIdType, set as the global ids
// cell data
constexpr const char* SubdomainPair = "SubdomainPair"; // int x2: normal points out of [0] into [1]
constexpr const char* SourceFaceId = "SourceFaceId";   // vtkIdType: input triangle, -1 on interfaces
constexpr const char* PlaneId = "PlaneId";             // int: cutting plane, -1 on the input surface
// field data
constexpr const char* CuttingPlanes = "CuttingPlanes";             // double x6 per plane: origin, normal
constexpr const char* PlaneSubdomainCount = "PlaneSubdomainCount"; // int per plane: subdomains in the part it cut
constexpr const char* NumberOfSubdomains = "NumberOfSubdomains";   // int
constexpr const char* SubdomainRank = "SubdomainRank";             // int per subdomain: the rank that owns it
constexpr const char* SubdomainVolume = "SubdomainVolume";         // double per subdomain
constexpr const char* SubdomainMeasure = "SubdomainMeasure";       // double per subdomain, by the balance criterion
constexpr const char* SubdomainPredictedTetrahedra = "SubdomainPredictedTetrahedra"; // double per subdomain, with a size field
constexpr const char* GlobalPointCount = "GlobalPointCount";       // vtkIdType: points of the whole complex
constexpr const char* BalanceCriterionName = "BalanceCriterion";   // string
constexpr const char* MaximumImbalance = "MaximumImbalance";       // double
constexpr const char* InputRepairs = "InputRepairs";               // strings: repairs of the input check
constexpr const char* AlignedCuts = "AlignedCuts";                 // 2 ints: cuts turned parallel to an earlier line, and through it
constexpr const char* TiltedCuts = "TiltedCuts";                   // int: cuts tilted to a clearer plane
constexpr const char* FlatCrossingsRemoved = "FlatCrossingsRemoved"; // vtkIdType: contour points inside planar faces taken out
constexpr const char* InputMeanEdgeLength = "InputMeanEdgeLength"; // double: the input surface's resolution
// the cutter's SizeArray (SizeField.h): double x4 per sample (x, y, z, size), and the array's name
constexpr const char* SizeFieldSamples = "SizeFieldSamples";
constexpr const char* SizeFieldArray = "SizeFieldArray"; // string
// the cutter's SizeByThickness (LocalThickness.h): double x4 per sample (x, y,
// z, thickness), and the size they were measured under (double, one value)
constexpr const char* ThicknessSamples = "ThicknessSamples";
constexpr const char* ThicknessLimit = "ThicknessLimit";

// CAD input (vtkCADSurfaceReader): the CAD face every triangle came from
constexpr const char* CADFaceId = "CADFaceId"; // cell data, vtkIdType: index in the TopExp face map
// field data of the complex, vtkIdType per input triangle (by SourceFaceId):
// its CADFaceId, carried by every stage so the mesher can put CADFaceId on
// its boundary port
constexpr const char* SourceFaceCADFaceId = "SourceFaceCADFaceId";

// the interface triangulator's figures (vtkIdType each, the last a double)
constexpr const char* ContourPointsAdded = "ContourPointsAdded";
constexpr const char* InterfacesTriangulatedAgain = "InterfacesTriangulatedAgain"; // bent ones that crossed the surface
// times contour subdivision was undone because a subdomain crossed itself
// (2: in the end no edge split), and the regions whose edges were kept whole
constexpr const char* ContourSubdivisionRetries = "ContourSubdivisionRetries";
constexpr const char* InterfacesKeptWhole = "InterfacesKeptWhole";
constexpr const char* InterfaceNewPoints = "InterfaceNewPoints";
constexpr const char* InterfaceTrianglesBelowMinimumAngle = "InterfaceTrianglesBelowMinimumAngle";
constexpr const char* InterfaceTrianglesBelowMinimumAngleAwayFromBoundary =
  "InterfaceTrianglesBelowMinimumAngleAwayFromBoundary";
constexpr const char* EncroachedBoundarySegments = "EncroachedBoundarySegments";
constexpr const char* InterfaceMinimumAngle = "InterfaceMinimumAngle";

// The facts of earlier stages that every later stage copies from its input's
// field data to its output's (PolyDataConversion.h: passOnFieldData).
constexpr const char* PassedOn[] = { BalanceCriterionName, MaximumImbalance, SourceFaceCADFaceId,
  SizeFieldSamples, SizeFieldArray, ThicknessSamples, ThicknessLimit, ContourPointsAdded, ContourSubdivisionRetries, InterfacesKeptWhole,
  InterfacesTriangulatedAgain, InterfaceNewPoints,
  InterfaceTrianglesBelowMinimumAngle, InterfaceTrianglesBelowMinimumAngleAwayFromBoundary,
  EncroachedBoundarySegments, InterfaceMinimumAngle };

// field data of vtkAlphaWrapFilter's output (absolute lengths)
constexpr const char* WrapAlpha = "WrapAlpha";
constexpr const char* WrapOffset = "WrapOffset";
constexpr const char* WrapToInputDistance = "WrapToInputDistance"; // largest, wrap to input
constexpr const char* InputToWrapDistance = "InputToWrapDistance"; // largest, input to wrap
constexpr const char* WrapSampleSpacing = "WrapSampleSpacing";     // the distances are exact to within this
constexpr const char* WrapSeconds = "WrapSeconds";                 // wrapping and measuring, on rank 0
constexpr const char* WrapMeanThickness = "WrapMeanThickness";     // 2 x enclosed volume / area (AlphaWrap.h)

// field data of vtkSurfaceRemesher's output (absolute lengths)
constexpr const char* RemeshEdgeLength = "RemeshEdgeLength";           // the target edge length used
constexpr const char* RemeshToInputDistance = "RemeshToInputDistance"; // largest, remeshed to input
constexpr const char* InputToRemeshDistance = "InputToRemeshDistance"; // largest, input to remeshed
constexpr const char* RemeshSampleSpacing = "RemeshSampleSpacing";     // the distances are exact to within this
constexpr const char* RemeshVolumeChange = "RemeshVolumeChange";       // (V remeshed - V input) / V input
constexpr const char* RemeshFeatureEdges = "RemeshFeatureEdges";       // input edges kept as feature lines
constexpr const char* RemeshCorners = "RemeshCorners";                 // input points that did not move
constexpr const char* RemeshSeconds = "RemeshSeconds";                 // remeshing and measuring, on rank 0
} // namespace ptm::arrays
#endif
