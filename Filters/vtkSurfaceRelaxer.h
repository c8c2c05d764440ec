/**
 * @class vtkSurfaceRelaxer
 * @brief Improves the triangles of the labeled complex near the cuts by moving nodes only.
 *
 * Stage 3 of the parallel tetrahedral mesher (see ptm::relaxSurfaceComplex).
 * Mode KeepSurface (default): the surface of every subdomain stays the same
 * point set (volumes change by round-off only): a node moves only within a
 * plane its whole star lies in (exact predicates), or along a straight line
 * where exactly two such planes meet; every other node stays put.
 * Mode SmoothSurface: smoothing with every node projected back onto its
 * geometry (input-surface nodes on the input surface and its feature lines,
 * contour nodes on their contour, interface nodes in their plane, corners
 * fixed), which cuts the corners of curved surfaces; moves that would put the
 * surface farther than MaximumSurfaceDeviation from the input are rejected.
 * A move is kept only if no triangle inverts and the worst
 * angle around the node does not get worse. Topology, node count, global
 * ids and SubdomainPair are unchanged. The whole complex is gathered and
 * relaxed identically on every rank, so a node shared by ranks ends at
 * bit-identical coordinates everywhere and the result does not depend on
 * the number of ranks; each rank outputs the faces of its own subdomains.
 * Field data: minimum angle and share of triangles under 10 and 20 degrees,
 * before and after; the relative volume change (whole, largest per
 * subdomain) and the largest sampled distance between the surfaces before
 * and after, both ways, relative to the bounding-box diagonal.
 */
#ifndef vtkSurfaceRelaxer_h
#define vtkSurfaceRelaxer_h

#include "ParallelTetMesherFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <string>

class vtkMultiProcessController;

class PARALLELTETMESHERFILTERS_EXPORT vtkSurfaceRelaxer : public vtkPolyDataAlgorithm
{
public:
  static vtkSurfaceRelaxer* New();
  vtkTypeMacro(vtkSurfaceRelaxer, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ModeType
  {
    KEEP_SURFACE = 0,
    SMOOTH_SURFACE = 1
  };

  enum RegionType
  {
    NEAR_CUTS = 0,
    EVERYWHERE = 1
  };

  ///@{
  /// KeepSurface (default): the surface stays the same point set; SmoothSurface: may move it.
  vtkSetMacro(Mode, int);
  vtkGetMacro(Mode, int);
  ///@}

  ///@{
  /// SmoothSurface: largest distance allowed between the surfaces before and
  /// after, relative to the bounding-box diagonal (default 0.01).
  vtkSetMacro(MaximumSurfaceDeviation, double);
  vtkGetMacro(MaximumSurfaceDeviation, double);
  ///@}

  ///@{
  /// Smoothing sweeps over the nodes (default 10; 0 passes the complex through).
  vtkSetMacro(NumberOfIterations, int);
  vtkGetMacro(NumberOfIterations, int);
  ///@}

  ///@{
  /// Fraction of the way to the neighbours' centroid a node moves per sweep (default 0.5).
  vtkSetMacro(RelaxationFactor, double);
  vtkGetMacro(RelaxationFactor, double);
  ///@}

  ///@{
  /// SmoothSurface: surface edges whose normals differ by more than this (degrees, default 30) are feature lines.
  vtkSetMacro(FeatureAngle, double);
  vtkGetMacro(FeatureAngle, double);
  ///@}

  ///@{
  /// NearCuts (default): the three rings of nodes around contours and interfaces; Everywhere.
  vtkSetMacro(Region, int);
  vtkGetMacro(Region, int);
  ///@}

  void SetController(vtkMultiProcessController*);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);

protected:
  vtkSurfaceRelaxer();
  ~vtkSurfaceRelaxer() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  // The clauses naming every nonsense property value; empty when all are fine.
  std::string PropertyError();

  int Mode = KEEP_SURFACE;
  double MaximumSurfaceDeviation = 0.01;
  int NumberOfIterations = 10;
  double RelaxationFactor = 0.5;
  double FeatureAngle = 30.0;
  int Region = NEAR_CUTS;
  vtkMultiProcessController* Controller = nullptr;

private:
  vtkSurfaceRelaxer(const vtkSurfaceRelaxer&) = delete;
  void operator=(const vtkSurfaceRelaxer&) = delete;
};

#endif
