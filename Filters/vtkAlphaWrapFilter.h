/**
 * @class vtkAlphaWrapFilter
 * @brief Wraps a dirty surface (open, non-manifold, self-intersecting) into a
 * closed one the mesher accepts, with CGAL's 3D alpha wrapping.
 *
 * Put it between a reader and vtkVolumeBalancedCutter when the cutter's input
 * check refuses the surface. The output is a closed, 2-manifold,
 * non-self-intersecting surface at about RelativeOffset x diagonal outside the
 * input, that does not enter gaps narrower than about RelativeAlpha x diagonal
 * (ptm::alphaWrapSurface). How far the wrap strays from the input is measured
 * in both directions and put in field data (WrapToInputDistance,
 * InputToWrapDistance), with the absolute WrapAlpha and WrapOffset used and
 * the wrap's WrapMeanThickness. A wrap that is a hollow skin around an open
 * input is refused unless AllowSkin is on.
 *
 * Collective, as ptm::runWholeSurfaceStage runs it: rank 0 alone wraps
 * the whole surface and sends the wrap to the others, so the output does not
 * depend on the number of ranks; piece 0 of a request gets the whole wrap;
 * a re-execution with the same input and properties reuses the last wrap.
 */
#ifndef vtkAlphaWrapFilter_h
#define vtkAlphaWrapFilter_h

#include "ParallelTetMesherFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class vtkMultiProcessController;
namespace ptm
{
struct WholeSurfaceCache;
}

class PARALLELTETMESHERFILTERS_EXPORT vtkAlphaWrapFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkAlphaWrapFilter* New();
  vtkTypeMacro(vtkAlphaWrapFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Alpha as a fraction of the input's bounding-box diagonal (default 1/100):
  /// gaps and cavities narrower than about alpha are not entered.
  vtkSetMacro(RelativeAlpha, double);
  vtkGetMacro(RelativeAlpha, double);
  ///@}

  ///@{
  /// Offset of the wrap from the input, as a fraction of the bounding-box
  /// diagonal (default 1/3000).
  vtkSetMacro(RelativeOffset, double);
  vtkGetMacro(RelativeOffset, double);
  ///@}

  ///@{
  /// Whether a wrap that is a hollow skin (an open input whose holes are
  /// wider than alpha, wrapped from both sides; ptm::AlphaWrapOptions) is
  /// output with a warning instead of refused (default off).
  vtkSetMacro(AllowSkin, vtkTypeBool);
  vtkGetMacro(AllowSkin, vtkTypeBool);
  vtkBooleanMacro(AllowSkin, vtkTypeBool);
  ///@}

  ///@{
  /// The controller (default: the global one).
  void SetController(vtkMultiProcessController*);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

protected:
  vtkAlphaWrapFilter();
  ~vtkAlphaWrapFilter() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double RelativeAlpha = 1.0 / 100.0;
  double RelativeOffset = 1.0 / 3000.0;
  vtkTypeBool AllowSkin = 0;
  vtkMultiProcessController* Controller = nullptr;

private:
  // The last wrap and what it was made from (WholeSurfaceStage.h).
  ptm::WholeSurfaceCache* Cache = nullptr;

  vtkAlphaWrapFilter(const vtkAlphaWrapFilter&) = delete;
  void operator=(const vtkAlphaWrapFilter&) = delete;
};

#endif
