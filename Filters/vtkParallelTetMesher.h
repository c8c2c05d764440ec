/**
 * @class vtkParallelTetMesher
 * @brief Meshes every subdomain of the labeled complex with TetGen, concurrently on all ranks, into one conforming mesh with global ids.
 *
 * Stage 4 of the parallel tetrahedral mesher. Each rank extracts the closed
 * surface of every subdomain it owns (canonical form, see
 * ptm::extractSubdomainSurface), refines its outer part on the input surface
 * (ptm::refineSubdomainSurface; interfaces and contours unchanged) and meshes
 * it with TetGen (libtet) with that surface preserved (-pY: TetGen adds no
 * Steiner point on any subdomain surface), so neighbouring pieces match node
 * for node across interfaces. Ranks mesh
 * independently; only the counts are exchanged afterwards for the global
 * numbering, which follows subdomain order and so does not depend on the
 * number of ranks.
 *
 * Output port 0, vtkUnstructuredGrid with the rank's linear tetrahedra (a point
 * shared by two subdomains on this rank appears once):
 *  - point data: GlobalPointIds (vtkIdType, the global ids, 0..P-1 over the
 *    whole mesh); vtkGhostType with DUPLICATEPOINT on copies of points owned
 *    by another rank (owner: the rank of the lowest subdomain touching it);
 *  - cell data: GlobalCellIds (the global ids, 0..T-1), SubdomainId, Rank;
 *  - field data: NumberOfSubdomains, GlobalPointCount, GlobalCellCount,
 *    BoundaryPointsAdded (points the boundary refinement put on the input
 *    surface; they are numbered with their subdomain's interior points),
 *    BoundaryVolumeChange (relative) and BoundaryLargestDeviation (0 up to
 *    round-off unless CoplanarTolerance is set).
 * Output port 1, vtkPolyData: the outer boundary triangles of the rank's
 * subdomains with GlobalPointIds, SourceFaceId (the input triangle) and
 * SubdomainId, for boundary conditions.
 * Collective; a TetGen failure in any subdomain fails every rank with a
 * message naming the subdomain and TetGen's code.
 */
#ifndef vtkParallelTetMesher_h
#define vtkParallelTetMesher_h

#include "ParallelTetMesherFiltersModule.h"
#include "vtkUnstructuredGridAlgorithm.h"

#include <string>

class vtkMultiProcessController;

class PARALLELTETMESHERFILTERS_EXPORT vtkParallelTetMesher : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkParallelTetMesher* New();
  vtkTypeMacro(vtkParallelTetMesher, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// TetGen's radius-edge ratio bound (-q), default 2.0; must exceed 1.
  vtkSetMacro(RadiusEdgeRatio, double);
  vtkGetMacro(RadiusEdgeRatio, double);
  ///@}

  ///@{
  /// Largest tetrahedron volume (-a); 0 (default) = automatic: the volume of a
  /// regular tetrahedron whose edge is the mean edge length of the input
  /// surface (recorded by the cutter), the same for every subdomain, so the
  /// mesh density does not depend on the number of subdomains.
  vtkSetMacro(MaximumVolume, double);
  vtkGetMacro(MaximumVolume, double);
  ///@}

  ///@{
  /// Smallest dihedral angle TetGen should aim for (degrees, the second -q
  /// value); 0 = TetGen's own default (none). Default 10: with the surface
  /// kept (-Y) TetGen cannot split a boundary face to remove a sliver, but it
  /// still removes most interior and near-boundary ones (corpus, 2 ranks,
  /// K = 16: joint 1.16 % -> 0.57 % of tetrahedra under 10 degrees for 12 %
  /// more tetrahedra, 3torus 0.60 % -> 0.27 % for 7 %).
  vtkSetMacro(MinimumDihedralAngle, double);
  vtkGetMacro(MinimumDihedralAngle, double);
  ///@}

  ///@{
  /// Flat tetrahedra TetGen leaves on the kept surface (degrees; default 5,
  /// 0 = off): where a subdomain's mesh has a tetrahedron with a face on its
  /// surface and a dihedral angle under this, TetGen refines the mesh again
  /// (-ri) with one point inside above each such tetrahedron; the new mesh
  /// is kept if its smallest dihedral angle is larger and its share under 10
  /// degrees not. The surface is never touched (see ptm::boundarySliverPoints).
  /// The points of the kept meshes are the field data SliverRepairPoints.
  vtkSetMacro(SliverRepairAngle, double);
  vtkGetMacro(SliverRepairAngle, double);
  ///@}

  ///@{
  /// Processor seconds one TetGen run may use (default 0: automatic, 2 s
  /// plus about 30 us per expected tetrahedron and 0.4 ms per surface
  /// triangle). A run over it is stopped and tried in another input order;
  /// all runs of one subdomain together may use 4 x this limit, then the
  /// filter fails, naming the subdomain and what to do. Raise it for a
  /// surface of long, nearly flat triangles on which TetGen is merely slow.
  vtkSetMacro(TetGenTimeLimit, double);
  vtkGetMacro(TetGenTimeLimit, double);
  ///@}

  ///@{
  /// Boundary refinement before TetGen (default on; see
  /// ptm::refineSubdomainSurface): the outer part of every subdomain surface
  /// is meshed anew on the input surface, with edges near the target size
  /// (the edge of a regular tetrahedron of MaximumVolume) and triangles of at
  /// least BoundaryMinimumAngle, the interfaces and contours unchanged, so
  /// tetrahedra next to the boundary are not held to the input's slivers.
  vtkSetMacro(BoundaryRefinement, bool);
  vtkGetMacro(BoundaryRefinement, bool);
  vtkBooleanMacro(BoundaryRefinement, bool);
  vtkSetMacro(BoundaryMinimumAngle, double);
  vtkGetMacro(BoundaryMinimumAngle, double);
  /// The shortest spacing the refinement splits an input edge at beside a
  /// thin input triangle, as a fraction of the local size, in [1/1024, 1]
  /// (default 1/8): lower follows thin strips of CAD exports down to their
  /// width, with better tetrahedra there and many more of them.
  vtkSetMacro(BoundarySpacingFloor, double);
  vtkGetMacro(BoundarySpacingFloor, double);
  ///@}

  ///@{
  /// Degrees; 0 (default) keeps the geometry exactly: only exactly coplanar
  /// input triangles are meshed anew together. Above 0, input triangles
  /// whose normals differ by less than this join one facet, as TetGen -p
  /// merges nearly coplanar facets: far better triangles on CAD files whose
  /// flat faces are flat only to the file's 6-7 digits, at the price of a
  /// small change of the surface, reported as the field data
  /// BoundaryVolumeChange (relative) and BoundaryLargestDeviation.
  vtkSetMacro(CoplanarTolerance, double);
  vtkGetMacro(CoplanarTolerance, double);
  ///@}

  ///@{
  /// A size field: the edge length wanted at (x, y, z), as an expression in
  /// the syntax of ParaView's Calculator (e.g. "0.02 + 0.1 * abs(z)"). Empty
  /// (default): none. It sets the boundary refinement's local target and,
  /// at every subdomain surface point, TetGen's sizing (-m), which TetGen
  /// interpolates inside; MaximumVolume still bounds every tetrahedron.
  /// Give InterfaceTriangulator the same expression. Sizes must be positive
  /// at every surface point, or the filter fails with the point named.
  vtkSetMacro(SizeExpression, std::string);
  vtkGetMacro(SizeExpression, std::string);
  ///@}

  ///@{
  /// Extra TetGen switches for experts (validated: nothing that breaks the surface contract).
  vtkSetMacro(ExtraSwitches, std::string);
  vtkGetMacro(ExtraSwitches, std::string);
  ///@}

  void SetController(vtkMultiProcessController*);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);

protected:
  vtkParallelTetMesher();
  ~vtkParallelTetMesher() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  // The message naming the first nonsense property value; empty when all are fine.
  std::string PropertyError();
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double RadiusEdgeRatio = 2.0;
  double MaximumVolume = 0.0;
  double MinimumDihedralAngle = 10.0;
  double SliverRepairAngle = 5.0;
  double TetGenTimeLimit = 0.0;
  std::string ExtraSwitches;
  std::string SizeExpression;
  bool BoundaryRefinement = true;
  double BoundaryMinimumAngle = 20.7;
  double BoundarySpacingFloor = 0.125; // the core's default (checked in the .cxx) and the XML's
  double CoplanarTolerance = 0.0;
  vtkMultiProcessController* Controller = nullptr;

private:
  vtkParallelTetMesher(const vtkParallelTetMesher&) = delete;
  void operator=(const vtkParallelTetMesher&) = delete;
};

#endif
