/**
 * @class vtkVolumeBalancedCutter
 * @brief Splits a closed surface into subdomains of equal volume by cutting planes.
 *
 * Stage 1 of the parallel tetrahedral mesher. The input surface (any
 * polygonal data, possibly spread over ranks; ParaView's readers put it all
 * on rank 0) is gathered, merged and oriented, then cut by planes into
 * NumberOfSubdomains subdomains of equal measure (see ptm::decomposeVolumeBalanced).
 * Every rank computes the same decomposition; each rank outputs the labeled
 * surface complex of the subdomains it owns: triangles with SubdomainPair and
 * SourceFaceId, closed interface loops as poly-lines with SubdomainPair and
 * PlaneId, GlobalPointIds, and the planes and subdomain facts as field data
 * (SurfaceComplexArrays.h). Colour by SubdomainPair to see the partition.
 *
 * Collective: every rank must execute it. Failure on any rank (bad input,
 * impossible request) is reported by all ranks from the same update.
 */
#ifndef vtkVolumeBalancedCutter_h
#define vtkVolumeBalancedCutter_h

#include "ParallelTetMesherFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <string>

class vtkMultiProcessController;

class PARALLELTETMESHERFILTERS_EXPORT vtkVolumeBalancedCutter : public vtkPolyDataAlgorithm
{
public:
  static vtkVolumeBalancedCutter* New();
  vtkTypeMacro(vtkVolumeBalancedCutter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum StrategyType
  {
    PARALLEL_PLANES = 0,
    RECURSIVE_BISECTION = 1
  };
  enum DirectionType
  {
    X = 0,
    Y = 1,
    Z = 2,
    LONGEST_EXTENT = 3,
    INERTIA = 4
  };
  enum BalanceCriterionType
  {
    VOLUME = 0,
    BOUNDARY_FACETS = 1,
    NODES = 2,
    PREDICTED_COST = 3
  };

  ///@{
  /// Number of subdomains K; 0 (default) means one per MPI rank. More than
  /// the ranks is over-decomposition: subdomains are then assigned to ranks
  /// so that each rank's total measure is balanced.
  vtkSetMacro(NumberOfSubdomains, int);
  vtkGetMacro(NumberOfSubdomains, int);
  ///@}

  ///@{
  /// ParallelPlanes (0) or RecursiveBisection (1, default).
  vtkSetClampMacro(Strategy, int, PARALLEL_PLANES, RECURSIVE_BISECTION);
  vtkGetMacro(Strategy, int);
  ///@}

  ///@{
  /// Plane normal: X, Y, Z, LongestExtent, or Inertia (default: the long
  /// principal axis of the node inertia matrix, per part in recursive bisection).
  vtkSetClampMacro(Direction, int, X, INERTIA);
  vtkGetMacro(Direction, int);
  ///@}

  ///@{
  /// What is balanced: Volume (default), BoundaryFacets, Nodes, or
  /// PredictedCost: the tetrahedra the size field (SizeExpression or
  /// SizeArray, capped at MaximumSize) predicts, estimated on a grid of cost
  /// samples inside the surface; without a size field it balances volume.
  vtkSetClampMacro(BalanceCriterion, int, VOLUME, PREDICTED_COST);
  vtkGetMacro(BalanceCriterion, int);
  ///@}

  ///@{
  /// Allowed relative deviation of a subdomain from its target (default 0.01).
  vtkSetMacro(BalanceTolerance, double);
  vtkGetMacro(BalanceTolerance, double);
  ///@}

  ///@{
  /// Recursive bisection: a plane whose line on an interface runs within
  /// this angle of a line an earlier plane drew there turns to run parallel
  /// to it, and through it where the balance allows, instead of crossing it
  /// at a sliver (default 15 degrees; 0 turns this off).
  vtkSetMacro(PlaneAlignmentAngle, double);
  vtkGetMacro(PlaneAlignmentAngle, double);
  ///@}

  ///@{
  /// Recursive bisection: a plane that would pass a hair off vertices or
  /// cross faces at a shallow angle may tilt by up to this angle to a
  /// clearer, still balanced position (default 10 degrees; 0 turns this off).
  vtkSetMacro(PlaneTiltAngle, double);
  vtkGetMacro(PlaneTiltAngle, double);
  ///@}

  ///@{
  /// ParallelPlanes: refuse, before any cut, a K whose thinnest slab would be
  /// thinner than this fraction of the mesh size (MaximumSize, or the input's
  /// mean edge), naming the largest K that is not (default 0.25,
  /// ptm::kMinimumSlabThickness; 0 never refuses). Thinner slabs are meshed
  /// far finer than asked, with poor tetrahedra. Slabs under the size but
  /// above this fraction are cut with a warning, and with a size field all
  /// of them are.
  vtkSetMacro(MinimumSlabThickness, double);
  vtkGetMacro(MinimumSlabThickness, double);
  ///@}

  ///@{
  /// After the cuts (with ParallelPlanes after every cut), take out the
  /// contour points that only mark where a plane crossed an edge inside a
  /// planar face (default on; field data
  /// FlatCrossingsRemoved). Off keeps every crossing, as before session 17.
  vtkSetMacro(RemoveFlatCrossings, vtkTypeBool);
  vtkGetMacro(RemoveFlatCrossings, vtkTypeBool);
  vtkBooleanMacro(RemoveFlatCrossings, vtkTypeBool);
  ///@}

  ///@{
  /// Check the input for self-intersections with CGAL's exact predicates
  /// before cutting (default on). Other input checks always run.
  vtkSetMacro(CheckSelfIntersections, vtkTypeBool);
  vtkGetMacro(CheckSelfIntersections, vtkTypeBool);
  vtkBooleanMacro(CheckSelfIntersections, vtkTypeBool);
  ///@}

  ///@{
  /// Above this many input triangles the self-intersection check is skipped
  /// with a warning (default 2,000,000).
  vtkSetMacro(SelfIntersectionCheckLimit, vtkIdType);
  vtkGetMacro(SelfIntersectionCheckLimit, vtkIdType);
  ///@}

  ///@{
  /// A size field (the edge length wanted at x, y, z, in the syntax of
  /// ParaView's Calculator), the one given to InterfaceTriangulator and
  /// ParallelTetMesher. Empty (default): the subdomains go to the ranks by
  /// their balance measure. Set: by the tetrahedra the field predicts in
  /// each (the field data SubdomainPredictedTetrahedra), so a rank meshing
  /// a finely sized region gets fewer subdomains; with BalanceCriterion
  /// PredictedCost the cuts balance that cost too.
  vtkSetMacro(SizeExpression, std::string);
  vtkGetMacro(SizeExpression, std::string);
  ///@}

  ///@{
  /// A size field given as samples instead (leave SizeExpression empty):
  /// the name of a point array of the SizeSource (input port 1, any data
  /// set, e.g. a background mesh or an earlier solution) or, without one,
  /// of the input surface. Between samples the size is interpolated
  /// (SizeField.h); the samples travel in the complex's field data
  /// (SizeFieldSamples), so the triangulator and the mesher follow them
  /// without being told. Empty (default): no array.
  vtkSetMacro(SizeArray, std::string);
  vtkGetMacro(SizeArray, std::string);
  ///@}

  ///@{
  /// With SizeExpression or SizeArray: the largest size the mesher will use, as its
  /// MaximumVolume sets it (the edge of that regular tetrahedron); 0
  /// (default) is the mesher's automatic size, the input's mean edge. The
  /// predicted cost takes the field no larger than this.
  vtkSetMacro(MaximumSize, double);
  vtkGetMacro(MaximumSize, double);
  ///@}

  ///@{
  /// Measure the input's local thickness (LocalThickness.h: a ray along each
  /// triangle's inward normal) where it is under the size (MaximumSize, or
  /// the input's mean edge), and put the samples in the complex's field data
  /// (ThicknessSamples), so the contour split, the interface triangulation
  /// and the mesher's boundary refinement make edges no longer than a wall
  /// is thick. On (default); off: the size alone sets them.
  vtkSetMacro(SizeByThickness, vtkTypeBool);
  vtkGetMacro(SizeByThickness, vtkTypeBool);
  vtkBooleanMacro(SizeByThickness, vtkTypeBool);
  ///@}

  ///@{
  /// The controller (default: the global one).
  void SetController(vtkMultiProcessController*);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

protected:
  vtkVolumeBalancedCutter();
  ~vtkVolumeBalancedCutter() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  // The message naming the first nonsense property value; empty when all are fine.
  std::string PropertyError();

  int NumberOfSubdomains = 0;
  int Strategy = RECURSIVE_BISECTION;
  int Direction = INERTIA;
  int BalanceCriterion = VOLUME;
  double BalanceTolerance = 0.01;
  double PlaneAlignmentAngle = 15.0;
  double PlaneTiltAngle = 10.0;
  double MinimumSlabThickness = 0.25;
  vtkTypeBool CheckSelfIntersections = 1;
  vtkTypeBool RemoveFlatCrossings = 1;
  vtkIdType SelfIntersectionCheckLimit = 2000000;
  std::string SizeExpression;
  std::string SizeArray;
  double MaximumSize = 0.0;
  vtkTypeBool SizeByThickness = 1;
  vtkMultiProcessController* Controller = nullptr;

private:
  vtkVolumeBalancedCutter(const vtkVolumeBalancedCutter&) = delete;
  void operator=(const vtkVolumeBalancedCutter&) = delete;
};

#endif
