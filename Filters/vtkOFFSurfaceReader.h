/**
 * @class vtkOFFSurfaceReader
 * @brief Reads a surface in the Object File Format (.off) into vtkPolyData.
 *
 * Polygons with more than three corners are triangulated (ear clipping, so
 * non-convex polygons are right); cell data SourcePolygonId gives the face of
 * the file each triangle came from. Comments, blank lines, colours and the
 * COFF/NOFF/CNOFF/STOFF variants are accepted (ptm::readOff). A malformed
 * file gives an error naming the file, the line and the problem, and an
 * empty output. In parallel, piece 0 holds the surface and the other pieces
 * are empty.
 */
#ifndef vtkOFFSurfaceReader_h
#define vtkOFFSurfaceReader_h

#include "ParallelTetMesherFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <string>

class PARALLELTETMESHERFILTERS_EXPORT vtkOFFSurfaceReader : public vtkPolyDataAlgorithm
{
public:
  static vtkOFFSurfaceReader* New();
  vtkTypeMacro(vtkOFFSurfaceReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The .off file to read.
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

  /// The message of the last failed read ("" after a good one).
  const char* GetLastError() const { return this->LastError.c_str(); }

  /// True if the file starts with an OFF header (for the reader factory).
  static bool CanReadFile(const char* fileName);

protected:
  vtkOFFSurfaceReader();
  ~vtkOFFSurfaceReader() override = default;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  std::string FileName;
  std::string LastError;

private:
  vtkOFFSurfaceReader(const vtkOFFSurfaceReader&) = delete;
  void operator=(const vtkOFFSurfaceReader&) = delete;
};

#endif
