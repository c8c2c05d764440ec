#include "vtkOFFSurfaceReader.h"

#include "OffFormat.h"

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
#include <sstream>

vtkStandardNewMacro(vtkOFFSurfaceReader);

vtkOFFSurfaceReader::vtkOFFSurfaceReader()
{
  this->SetNumberOfInputPorts(0);
}

bool vtkOFFSurfaceReader::CanReadFile(const char* fileName)
{
  std::ifstream in(fileName ? fileName : "");
  std::string word;
  while (in >> word)
  {
    if (word[0] == '#')
    {
      std::getline(in, word);
      continue;
    }
    return word.size() >= 3 && word.compare(word.size() - 3, 3, "OFF") == 0;
  }
  return false;
}

int vtkOFFSurfaceReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  outputVector->GetInformationObject(0)->Set(vtkAlgorithm::CAN_HANDLE_PIECE_REQUEST(), 1);
  return 1;
}

int vtkOFFSurfaceReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();
  this->LastError.clear();
  if (this->FileName.empty())
  {
    this->LastError = "no file name was given";
    vtkErrorMacro("OFF reader: " << this->LastError);
    return 0;
  }
  const int piece = outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER())
    ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER())
    : 0;
  if (piece > 0)
  {
    return 1; // the whole surface lives on piece 0
  }
  ptm::OffReadResult r;
  try
  {
    r = ptm::readOffFile(this->FileName);
  }
  catch (const std::exception& e)
  {
    r.ok = false;
    r.error = this->FileName + ": " + e.what();
  }
  if (!r.ok)
  {
    this->LastError = r.error;
    vtkErrorMacro("OFF reader: " << r.error);
    return 0;
  }
  const ptm::TriangleSurface& s = r.data.surface;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(s.points.size()));
  for (std::size_t i = 0; i < s.points.size(); ++i)
  {
    points->SetPoint(static_cast<vtkIdType>(i), s.points[i].data());
  }
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(static_cast<vtkIdType>(s.triangles.size()), 3 * static_cast<vtkIdType>(s.triangles.size()));
  vtkNew<vtkIdTypeArray> source;
  source->SetName("SourcePolygonId");
  source->SetNumberOfTuples(static_cast<vtkIdType>(s.triangles.size()));
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
  {
    const vtkIdType ids[3] = { s.triangles[t][0], s.triangles[t][1], s.triangles[t][2] };
    polys->InsertNextCell(3, ids);
    source->SetValue(static_cast<vtkIdType>(t), r.data.sourcePolygon[t]);
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
}
