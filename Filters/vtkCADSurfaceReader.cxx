#include "vtkCADSurfaceReader.h"

#include "CADTessellation.h"
#include "LibraryFolder.h"
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

#include <dlfcn.h>

#include <fstream>
#include <string>

namespace
{
// ptmReadCADSurface from libptmcad.so (CADTessellation.h: why it is not
// linked), opened once per process: beside the plugin, else where the build
// made it. Null, with `error` naming both places, if neither opens.
ptm::ReadCADSurfaceFunction cadLibraryReader(std::string& error)
{
  static std::string failure;
  static const ptm::ReadCADSurfaceFunction read = [] {
    std::string tried;
    for (const std::string& path : { ptm::folderOfThisLibrary() + "libptmcad.so", std::string(PTM_CAD_LIBRARY) })
    {
      if (void* library = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL))
      {
        if (void* f = ::dlsym(library, ptm::kReadCADSurfaceSymbol))
        {
          return reinterpret_cast<ptm::ReadCADSurfaceFunction>(f);
        }
      }
      const char* why = ::dlerror(); // names the file
      tried += (tried.empty() ? "" : "; ") + (why ? std::string(why) : path + " has no " + ptm::kReadCADSurfaceSymbol);
    }
    failure = "the CAD reader's library (libptmcad.so, built beside the plugin) could not be opened: " + tried;
    return ptm::ReadCADSurfaceFunction(nullptr);
  }();
  error = failure;
  return read;
}
} // namespace

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
  if (const ptm::ReadCADSurfaceFunction read = cadLibraryReader(r.error))
  {
    read(this->FileName.c_str(), &options, &r);
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
