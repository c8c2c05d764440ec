/**
 * @class vtkOFFSurfaceReader
 * @brief Reads a surface in the Object File Format (.off) into vtkPolyData.
 *
 * Polygons with more than three corners are triangulated (ear clipping, so
 * non-convex polygons are right); cell data SourcePolygonId gives the face of
 * the file each triangle came from. Comments, blank lines, colours and the
 * COFF/NOFF/CNOFF/STOFF variants are accepted (ptm::readOff). A malformed
 * file gives an error naming the file, the line and the problem, and an
 * empty output (RequestData returns 0). In parallel, piece 0 reads the file
 * and holds the surface, and the other pieces are empty.
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

  /**
   * For ParaView's reader factory, which asks only about *.off files: 1 if
   * the file can be opened. It does not look at the content on purpose, so
   * that a malformed .off file is given to this reader, whose error says
   * what is wrong, instead of ParaView's "no reader found".
   */
  virtual int CanReadFile(VTK_FILEPATH const char* fileName);

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
