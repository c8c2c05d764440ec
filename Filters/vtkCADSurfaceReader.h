/**
 * @class vtkCADSurfaceReader
 * @brief Reads the solids of a STEP, IGES or BREP file into one closed
 * triangle surface, with the CAD face of every triangle (OpenCASCADE 7.6).
 *
 * The solids (one chosen by SolidIndex, or all as separate shells) are
 * tessellated by BRepMesh_IncrementalMesh within LinearDeflection (absolute,
 * or RelativeLinearDeflection x bounding-box diagonal when 0) and
 * AngularDeflection; shared edges give shared nodes, merged into one surface
 * oriented outward (ptm::readCADSurface). Cell data CADFaceId is the index of
 * the triangle's face in the file's TopExp face map; it flows through the
 * mesher's stages to its boundary port. An unreadable file, no solid, a
 * solid index out of range or an open shell gives an error naming the file
 * and the problem, and an empty output. As the OFF reader: piece 0 reads the
 * file and holds the surface, other pieces are empty (the cutter asks every
 * rank for piece 0, so every rank reads and fails alike).
 */
#ifndef vtkCADSurfaceReader_h
#define vtkCADSurfaceReader_h

#include "ParallelTetMesherFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <string>

class PARALLELTETMESHERFILTERS_EXPORT vtkCADSurfaceReader : public vtkPolyDataAlgorithm
{
public:
  static vtkCADSurfaceReader* New();
  vtkTypeMacro(vtkCADSurfaceReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The .step, .stp, .iges, .igs or .brep file to read.
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

  ///@{
  /// Largest distance between a triangle and its face as a fraction of the
  /// bounding-box diagonal (default 1e-3), used when LinearDeflection is 0.
  vtkSetMacro(RelativeLinearDeflection, double);
  vtkGetMacro(RelativeLinearDeflection, double);
  ///@}

  ///@{
  /// Largest distance between a triangle and its face, in model units; 0
  /// (default) takes RelativeLinearDeflection.
  vtkSetMacro(LinearDeflection, double);
  vtkGetMacro(LinearDeflection, double);
  ///@}

  ///@{
  /// Largest angle between neighbouring triangle normals on a face, in
  /// radians (default 0.5).
  vtkSetMacro(AngularDeflection, double);
  vtkGetMacro(AngularDeflection, double);
  ///@}

  ///@{
  /// The solid to read (0-based, in the file's order), or -1 (default) for
  /// all of them as separate shells.
  vtkSetMacro(SolidIndex, int);
  vtkGetMacro(SolidIndex, int);
  ///@}

  /// The message of the last failed read ("" after a good one).
  const char* GetLastError() const { return this->LastError.c_str(); }

  /// For ParaView's reader factory: 1 if the file can be opened (the content
  /// is not looked at, so that a broken file gets this reader's message).
  virtual int CanReadFile(VTK_FILEPATH const char* fileName);

protected:
  vtkCADSurfaceReader();
  ~vtkCADSurfaceReader() override = default;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  std::string FileName;
  std::string LastError;
  double RelativeLinearDeflection = 1e-3;
  double LinearDeflection = 0.0;
  double AngularDeflection = 0.5;
  int SolidIndex = -1;

private:
  vtkCADSurfaceReader(const vtkCADSurfaceReader&) = delete;
  void operator=(const vtkCADSurfaceReader&) = delete;
};

#endif
