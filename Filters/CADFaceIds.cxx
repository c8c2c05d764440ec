#include "CADFaceIds.h"

#include "RankCollectives.h"
#include "SurfaceComplexArrays.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkPolyData.h"

#include <vector>

namespace ptm
{
namespace
{
// The input's CADFaceId per triangle as triangleSurfaceFromPolyData numbers
// them (the polygons, in order), when the polygons are all triangles; else
// -1 everywhere (a reader of CAD files gives triangles only).
std::vector<long long> localTable(vtkPolyData* input, std::size_t localTriangles, bool& has)
{
  std::vector<long long> table(localTriangles, -1);
  vtkDataArray* ids = input ? input->GetCellData()->GetArray(arrays::CADFaceId) : nullptr;
  has = ids != nullptr;
  if (!ids || input->GetNumberOfStrips() > 0 ||
    input->GetNumberOfPolys() != static_cast<vtkIdType>(localTriangles))
  {
    return table;
  }
  const vtkIdType first = input->GetNumberOfVerts() + input->GetNumberOfLines();
  for (std::size_t t = 0; t < localTriangles; ++t)
  {
    table[t] = static_cast<long long>(ids->GetTuple1(first + static_cast<vtkIdType>(t)));
  }
  return table;
}
} // namespace

vtkSmartPointer<vtkIdTypeArray> gatherCADFaceTable(vtkMultiProcessController* controller,
  vtkPolyData* input, std::size_t localTriangles, std::size_t wholeTriangles)
{
  bool has = false;
  const std::vector<long long> local = localTable(input, localTriangles, has);
  std::vector<long long> anyHas = { has ? 1 : 0 };
  allReduceMax(controller, anyHas);
  if (anyHas[0] == 0)
  {
    return nullptr; // the same decision on every rank
  }
  // wholeSurfaceOnEveryRank keeps a rank's own surface when every rank holds
  // the same one, else concatenates the pieces in rank order: the table
  // follows the same choice (the concatenation has the whole surface's
  // length only in the second case, or with one rank, where both agree).
  const std::vector<long long> all = allGatherValues(controller, local);
  const std::vector<long long>* chosen =
    all.size() == wholeTriangles ? &all : (local.size() == wholeTriangles ? &local : nullptr);
  auto table = vtkSmartPointer<vtkIdTypeArray>::New();
  table->SetName(arrays::SourceFaceCADFaceId);
  table->SetNumberOfTuples(static_cast<vtkIdType>(wholeTriangles));
  for (std::size_t t = 0; t < wholeTriangles; ++t)
  {
    table->SetValue(static_cast<vtkIdType>(t), chosen ? (*chosen)[t] : -1);
  }
  return table;
}

void addBoundaryCADFaceIds(vtkPolyData* complex, vtkPolyData* boundary)
{
  auto* table = complex
    ? vtkIdTypeArray::SafeDownCast(complex->GetFieldData()->GetAbstractArray(arrays::SourceFaceCADFaceId))
    : nullptr;
  vtkDataArray* sources = boundary ? boundary->GetCellData()->GetArray(arrays::SourceFaceId) : nullptr;
  if (!table || !sources)
  {
    return;
  }
  const vtkIdType n = table->GetNumberOfTuples();
  auto faces = vtkSmartPointer<vtkIdTypeArray>::New();
  faces->SetName(arrays::CADFaceId);
  faces->SetNumberOfTuples(sources->GetNumberOfTuples());
  for (vtkIdType c = 0; c < sources->GetNumberOfTuples(); ++c)
  {
    const auto s = static_cast<vtkIdType>(sources->GetTuple1(c));
    faces->SetValue(c, s >= 0 && s < n ? table->GetValue(s) : -1);
  }
  boundary->GetCellData()->AddArray(faces);
}
} // namespace ptm
