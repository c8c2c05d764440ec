/**
 * @class vtkInterfaceTriangulator
 * @brief Fills every interface loop of the labeled complex with a quality 2D constrained Delaunay triangulation.
 *
 * Stage 2 of the parallel tetrahedral mesher. Input: the labeled surface
 * complex from vtkVolumeBalancedCutter. Every interface region (the loops of
 * one plane between one pair of subdomains) is triangulated in its plane with
 * CGAL's constrained Delaunay triangulation and refined inside only, with a
 * minimum angle and a maximum edge length. Before that, every loop edge longer
 * than the size is split into equal parts, and the surface triangles on it
 * with it (SubdivideContours; the same points on every rank, since the rule
 * reads only the edge); the triangulation itself adds no point on a loop. A rank triangulates the regions of
 * its own subdomains from canonically ordered input, so two ranks sharing an
 * interface produce bit-identical triangles; the new points get global ids
 * after the complex's points, region by region in (plane, pair) order, which
 * does not depend on the number of ranks.
 *
 * Output: the same complex with the loops replaced by interface triangles
 * (SubdomainPair oriented out of the first subdomain, SourceFaceId -1,
 * PlaneId of the plane); field data adds InterfaceTrianglesBelowMinimumAngle,
 * InterfaceTrianglesBelowMinimumAngleAwayFromBoundary (0 expected),
 * EncroachedBoundarySegments, InterfaceMinimumAngle, InterfaceNewPoints and
 * ContourPointsAdded (the points SubdivideContours put on the loops first),
 * ContourSubdivisionRetries and InterfacesKeptWhole (after the splits a
 * region bent at a snapped vertex whose triangles cross the surface keeps
 * its edges whole, and every subdomain surface is checked whole for
 * self-intersection; the regions of one that crosses itself keep their
 * edges whole; the stage is redone after either, and after a second
 * crossing subdomain no edge is split).
 * Collective: every rank must execute it; a failure anywhere fails all.
 */
#ifndef vtkInterfaceTriangulator_h
#define vtkInterfaceTriangulator_h

#include "ParallelTetMesherFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <string>

class vtkMultiProcessController;

class PARALLELTETMESHERFILTERS_EXPORT vtkInterfaceTriangulator : public vtkPolyDataAlgorithm
{
public:
  static vtkInterfaceTriangulator* New();
  vtkTypeMacro(vtkInterfaceTriangulator, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Smallest angle allowed in an interface triangle, in degrees (default
  /// 20.7, the bound with guaranteed termination; up to about 30 works).
  /// Contour subdivision splits a contour finer next to a surface triangle
  /// with an angle under it (ContourSubdivision.h).
  vtkSetMacro(MinimumAngle, double);
  vtkGetMacro(MinimumAngle, double);
  ///@}

  ///@{
  /// Longest edge allowed; 0 (default) derives it from the spacing of the
  /// loop's own points, so interface triangles match the surface resolution
  /// and grade smoothly inward.
  vtkSetMacro(MaximumEdgeLength, double);
  vtkGetMacro(MaximumEdgeLength, double);
  ///@}

  ///@{
  /// A size field: the edge length wanted at (x, y, z), an expression in the
  /// syntax of ParaView's Calculator. Empty (default): none. When set it
  /// replaces the automatic sizing (MaximumEdgeLength still caps it); give
  /// ParallelTetMesher the same expression.
  vtkSetMacro(SizeExpression, std::string);
  vtkGetMacro(SizeExpression, std::string);
  ///@}

  ///@{
  /// Split every edge of the interfaces' boundaries (the contours, where a
  /// plane crosses the surface, and the lines where two planes meet) into
  /// equal parts at most the size long before triangulating (default on):
  /// MaximumEdgeLength, or the input's mean edge when that is 0, or the size
  /// field where it is smaller. Both neighbours get the same points, which
  /// lie on the input surface and in the plane.
  vtkSetMacro(SubdivideContours, vtkTypeBool);
  vtkGetMacro(SubdivideContours, vtkTypeBool);
  vtkBooleanMacro(SubdivideContours, vtkTypeBool);
  ///@}

  void SetController(vtkMultiProcessController*);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);

protected:
  vtkInterfaceTriangulator();
  ~vtkInterfaceTriangulator() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  // The clauses naming every nonsense property value; empty when all are fine.
  std::string PropertyError();

  double MinimumAngle = 20.7;
  double MaximumEdgeLength = 0.0;
  std::string SizeExpression;
  vtkTypeBool SubdivideContours = 1;
  vtkMultiProcessController* Controller = nullptr;

private:
  vtkInterfaceTriangulator(const vtkInterfaceTriangulator&) = delete;
  void operator=(const vtkInterfaceTriangulator&) = delete;
};

#endif
