#include "vtkOFFSurfaceReader.h"

#include "OffFormat.h"
#include "PipelineRequests.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <exception>
#include <fstream>

vtkStandardNewMacro(vtkOFFSurfaceReader);

vtkOFFSurfaceReader::vtkOFFSurfaceReader()
{
  this->SetNumberOfInputPorts(0);
}

int vtkOFFSurfaceReader::CanReadFile(const char* fileName)
{
  return ptm::fileOpens(fileName);
}

int vtkOFFSurfaceReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  // Any number of pieces: piece 0 gets the surface, the others stay empty.
  ptm::announceAnyPiece(outputVector);
  return 1;
}

int vtkOFFSurfaceReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();
  this->LastError.clear();

  const int piece = ptm::requestedPiece(outInfo);
  if (piece > 0)
  {
    return 1; // the whole surface lives on piece 0; this piece is empty
  }
  if (this->FileName.empty())
  {
    this->LastError = "no file name was given";
    vtkErrorMacro(<< this->LastError);
    return 0;
  }

  ptm::OffReadResult r;
  try
  {
    r = ptm::readOffFile(this->FileName);
  }
  catch (const std::exception& e) // only std::bad_alloc is expected here
  {
    r = ptm::OffReadResult();
    r.error = this->FileName + ": " + e.what();
  }
  if (!r.ok)
  {
    this->LastError = r.error;
    vtkErrorMacro(<< r.error);
    return 0;
  }

  const ptm::TriangleSurface& s = r.data.surface;
  const vtkIdType numberOfPoints = static_cast<vtkIdType>(s.points.size());
  const vtkIdType numberOfTriangles = static_cast<vtkIdType>(s.triangles.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(numberOfPoints);
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    points->SetPoint(i, s.points[static_cast<std::size_t>(i)].data());
  }
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(numberOfTriangles, 3 * numberOfTriangles);
  vtkNew<vtkIdTypeArray> source;
  source->SetName("SourcePolygonId");
  source->SetNumberOfTuples(numberOfTriangles);
  for (vtkIdType t = 0; t < numberOfTriangles; ++t)
  {
    const ptm::Triangle& tri = s.triangles[static_cast<std::size_t>(t)];
    const vtkIdType ids[3] = { static_cast<vtkIdType>(tri[0]), static_cast<vtkIdType>(tri[1]),
      static_cast<vtkIdType>(tri[2]) };
    polys->InsertNextCell(3, ids);
    source->SetValue(t, static_cast<vtkIdType>(r.data.sourcePolygon[static_cast<std::size_t>(t)]));
  }
  output->SetPoints(points);
  output->SetPolys(polys);
  output->GetCellData()->AddArray(source);
  return 1;
}

void vtkOFFSurfaceReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "LastError: " << this->LastError << "\n";
}
