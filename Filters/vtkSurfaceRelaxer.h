/**
 * @class vtkSurfaceRelaxer
 * @brief Improves the triangles of the labeled complex near the cuts by moving nodes only.
 *
 * Stage 3 of the parallel tetrahedral mesher (see ptm::relaxSurfaceComplex):
 * smoothing with every node kept on its geometry: input-surface nodes on the
 * input surface and its feature lines, contour nodes on their contour,
 * interface nodes in their plane, nodes on plane-plane lines on the line,
 * corners fixed. A move is kept only if no triangle inverts and the worst
 * angle around the node does not get worse. Topology, node count, global
 * ids and SubdomainPair are unchanged. The whole complex is gathered and
 * relaxed identically on every rank, so a node shared by ranks ends at
 * bit-identical coordinates everywhere and the result does not depend on
 * the number of ranks; each rank outputs the faces of its own subdomains.
 * Field data: minimum angle and share of triangles under 10 and 20 degrees,
 * before and after.
 */
#ifndef vtkSurfaceRelaxer_h
#define vtkSurfaceRelaxer_h

#include "ParallelTetMesherFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class vtkMultiProcessController;

class PARALLELTETMESHERFILTERS_EXPORT vtkSurfaceRelaxer : public vtkPolyDataAlgorithm
{
public:
  static vtkSurfaceRelaxer* New();
  vtkTypeMacro(vtkSurfaceRelaxer, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum RegionType
  {
    NEAR_CUTS = 0,
    EVERYWHERE = 1
  };

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
  /// Surface edges whose normals differ by more than this (degrees, default 30) are feature lines.
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
