#include "vtkCADSurfaceReader.h"

#include "CADTessellation.h"
#include "PipelineRequests.h"
#include "PolyDataConversion.h"
#include "SurfaceComplexArrays.h"

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

vtkStandardNewMacro(vtkCADSurfaceReader);

vtkCADSurfaceReader::vtkCADSurfaceReader()
{
  this->SetNumberOfInputPorts(0);
}

int vtkCADSurfaceReader::CanReadFile(const char* fileName)
{
  return ptm::fileOpens(fileName);
}

int vtkCADSurfaceReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  ptm::announceAnyPiece(outputVector);
  return 1;
}

int vtkCADSurfaceReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();
  this->LastError.clear();
  const int piece = ptm::requestedPiece(outInfo);
  if (piece > 0)
  {
    return 1; // the whole surface lives on piece 0
  }
  if (this->FileName.empty())
  {
    this->LastError = "no file name was given";
    vtkErrorMacro(<< this->LastError);
    return 0;
  }
  ptm::CADReadOptions options;
  options.relativeLinearDeflection = this->RelativeLinearDeflection;
  options.linearDeflection = this->LinearDeflection;
  options.angularDeflection = this->AngularDeflection;
  options.solid = this->SolidIndex;
  ptm::CADSurface r;
  try
  {
    r = ptm::readCADSurface(this->FileName, options);
  }
  catch (const std::exception& e) // std::bad_alloc; OCCT's own failures are caught inside
  {
    r = ptm::CADSurface();
    r.error = this->FileName + ": " + e.what();
  }
  if (!r.ok)
  {
    this->LastError = r.error;
    vtkErrorMacro(<< r.error);
    return 0;
  }
  for (const std::string& w : r.warnings)
  {
    vtkWarningMacro(<< w);
  }

  ptm::triangleSurfaceToPolyData(r.surface, output);
  vtkNew<vtkIdTypeArray> faces;
  faces->SetName(ptm::arrays::CADFaceId);
  faces->SetNumberOfTuples(static_cast<vtkIdType>(r.faceId.size()));
  for (std::size_t t = 0; t < r.faceId.size(); ++t)
  {
    faces->SetValue(static_cast<vtkIdType>(t), static_cast<vtkIdType>(r.faceId[t]));
  }
  output->GetCellData()->AddArray(faces);
  output->GetCellData()->SetActiveScalars(ptm::arrays::CADFaceId);
  return 1;
}

void vtkCADSurfaceReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "RelativeLinearDeflection: " << this->RelativeLinearDeflection << "\n";
  os << indent << "LinearDeflection: " << this->LinearDeflection << "\n";
  os << indent << "AngularDeflection: " << this->AngularDeflection << "\n";
  os << indent << "SolidIndex: " << this->SolidIndex << "\n";
  os << indent << "LastError: " << this->LastError << "\n";
}
