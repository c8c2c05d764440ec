/**
 * @class vtkSurfaceRemesher
 * @brief Remeshes a closed surface into triangles of about one edge length
 * with CGAL's isotropic remeshing, keeping its sharp edges: an explicit mode
 * that moves the surface, for CAD exports full of long thin triangles.
 *
 * Put it between a reader and vtkVolumeBalancedCutter. The default pipeline
 * keeps every input triangle exactly, so on CAD tessellations (needles a
 * thousandth as wide as long on cylinders and fillets) every cut leaves
 * contour edges as short as a needle is wide, and TetGen meets them with
 * flat tetrahedra or fails. This filter replaces the triangles by ones of
 * about TargetEdgeLength (ptm::remeshSurface): sharp edges (FeatureAngle)
 * stay as polylines, their corners do not move, new points are projected
 * onto the input. How far the result strays from the input is measured in
 * both directions and with the enclosed volume, put in field data
 * (RemeshToInputDistance, InputToRemeshDistance, RemeshVolumeChange, ...),
 * and bounded: beyond MaximumDeviation or MaximumVolumeChange, or where the result crosses itself
 * (walls thinner than the edge length), the edge length is halved and the
 * input remeshed again (at most 6 times), then the filter fails and says why.
 *
 * The input's cell data CADFaceId survives: borders between CAD faces are
 * kept like sharp edges and every new triangle takes its face's id.
 *
 * Collective, as ptm::runWholeSurfaceStage runs it: rank 0 alone remeshes
 * the whole surface and sends the result to the others, so the output does
 * not depend on the number of ranks; piece 0 of a request gets the whole
 * surface; a re-execution with the same input and properties reuses it.
 */
#ifndef vtkSurfaceRemesher_h
#define vtkSurfaceRemesher_h

#include "ParallelTetMesherFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class vtkMultiProcessController;
namespace ptm
{
struct WholeSurfaceCache;
}

class PARALLELTETMESHERFILTERS_EXPORT vtkSurfaceRemesher : public vtkPolyDataAlgorithm
{
public:
  static vtkSurfaceRemesher* New();
  vtkTypeMacro(vtkSurfaceRemesher, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Edge length wanted (absolute). 0 (the default): the input's mean edge
  /// length, the size the mesher's volume bound defaults to.
  vtkSetMacro(TargetEdgeLength, double);
  vtkGetMacro(TargetEdgeLength, double);
  ///@}

  ///@{
  /// Edges whose two faces' normals differ by more than this (degrees,
  /// default 30) are kept as feature lines.
  vtkSetMacro(FeatureAngle, double);
  vtkGetMacro(FeatureAngle, double);
  ///@}

  ///@{
  /// CGAL's rounds of splits, collapses, flips and smoothing (default 3).
  vtkSetMacro(Iterations, int);
  vtkGetMacro(Iterations, int);
  ///@}

  ///@{
  /// Largest distance allowed between the remeshed surface and the input, in
  /// either direction, as a fraction of the bounding-box diagonal (default
  /// 0.005); 0: not bounded.
  vtkSetMacro(MaximumDeviation, double);
  vtkGetMacro(MaximumDeviation, double);
  ///@}

  ///@{
  /// Largest change of the enclosed volume allowed, relative (default
  /// 0.002); 0: not bounded. Beyond it the edge length is halved as for
  /// MaximumDeviation.
  vtkSetMacro(MaximumVolumeChange, double);
  vtkGetMacro(MaximumVolumeChange, double);
  ///@}

  ///@{
  /// The controller (default: the global one).
  void SetController(vtkMultiProcessController*);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

protected:
  vtkSurfaceRemesher();
  ~vtkSurfaceRemesher() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double TargetEdgeLength = 0.0;
  double FeatureAngle = 30.0;
  int Iterations = 3;
  double MaximumDeviation = 0.005;
  double MaximumVolumeChange = 0.002;
  vtkMultiProcessController* Controller = nullptr;

private:
  ptm::WholeSurfaceCache* Cache = nullptr; // the last result (WholeSurfaceStage.h)

  vtkSurfaceRemesher(const vtkSurfaceRemesher&) = delete;
  void operator=(const vtkSurfaceRemesher&) = delete;
};

#endif
