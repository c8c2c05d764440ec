#include "PolyDataConversion.h"

#include "SurfaceComplexArrays.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <map>
#include <unordered_map>

namespace ptm
{
void triangleSurfaceToPolyData(const TriangleSurface& s, vtkPolyData* output)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(s.points.size()));
  for (std::size_t i = 0; i < s.points.size(); ++i)
  {
    points->SetPoint(static_cast<vtkIdType>(i), s.points[i].data());
  }
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(static_cast<vtkIdType>(s.triangles.size()), 3 * s.triangles.size());
  for (const Triangle& t : s.triangles)
  {
    const vtkIdType ids[3] = { static_cast<vtkIdType>(t[0]), static_cast<vtkIdType>(t[1]),
      static_cast<vtkIdType>(t[2]) };
    polys->InsertNextCell(3, ids);
  }
  output->SetPoints(points);
  output->SetPolys(polys);
}

TriangleSurface triangleSurfaceFromPolyData(vtkPolyData* input)
{
  TriangleSurface s;
  if (!input || input->GetNumberOfPoints() == 0)
  {
    return s;
  }
  vtkSmartPointer<vtkPolyData> triangles = input;
  bool onlyTriangles = input->GetNumberOfStrips() == 0;
  if (onlyTriangles)
  {
    vtkCellArray* polys = input->GetPolys();
    onlyTriangles = polys->IsHomogeneous() == 3 || polys->GetNumberOfCells() == 0;
  }
  if (!onlyTriangles)
  {
    vtkNew<vtkPolyData> copy;
    copy->ShallowCopy(input);
    copy->SetVerts(nullptr);
    copy->SetLines(nullptr);
    vtkNew<vtkTriangleFilter> triangulate;
    triangulate->SetInputData(copy);
    triangulate->PassLinesOff();
    triangulate->PassVertsOff();
    triangulate->Update();
    triangles = triangulate->GetOutput();
  }
  const vtkIdType n = triangles->GetNumberOfPoints();
  s.points.resize(static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    triangles->GetPoint(i, s.points[i].data());
  }
  vtkCellArray* polys = triangles->GetPolys();
  vtkIdType npts = 0;
  const vtkIdType* pts = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(npts, pts);)
  {
    if (npts == 3)
    {
      s.triangles.push_back({ pts[0], pts[1], pts[2] });
    }
  }
  return s;
}

namespace
{
// The points and cells of the faces of a piece that are written, with the
// values of each kind of cell kept apart until all are made (VTK orders
// cell data: vertices, lines, polygons, strips).
struct ComplexCells
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkIdTypeArray> globalIds;
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkIntArray> polyPairs, linePairs, polyPlanes, linePlanes;
  vtkNew<vtkIdTypeArray> polySources, lineSources;
};

// The triangles, and the interface regions as closed poly-lines, whose pair
// contains a subdomain in `keep` (all if keep is empty).
void collectCells(const ComplexPiece& piece, const std::vector<int>& keep, ComplexCells& cells)
{
  const SurfaceComplex& c = piece.complex;
  std::vector<char> kept(static_cast<std::size_t>(std::max(c.subdomainCount, 1)), keep.empty());
  for (int s : keep)
  {
    if (s >= 0 && s < c.subdomainCount)
    {
      kept[s] = 1;
    }
  }
  auto wanted = [&](const SubdomainPair& pair) {
    return (pair[0] >= 0 && kept[pair[0]]) || (pair[1] >= 0 && kept[pair[1]]);
  };

  std::vector<vtkIdType> local(c.points.size(), -1);
  cells.points->SetDataTypeToDouble();
  cells.globalIds->SetName(arrays::GlobalPointIds);
  auto use = [&](Index p) {
    if (local[p] < 0)
    {
      local[p] = cells.points->InsertNextPoint(c.points[p].data());
      cells.globalIds->InsertNextValue(piece.globalIds.empty() ? p : piece.globalIds[p]);
    }
    return local[p];
  };

  cells.polyPairs->SetNumberOfComponents(2);
  cells.linePairs->SetNumberOfComponents(2);
  for (std::size_t i = 0; i < c.triangles.size(); ++i)
  {
    if (!wanted(c.trianglePairs[i]))
    {
      continue;
    }
    const vtkIdType ids[3] = { use(c.triangles[i][0]), use(c.triangles[i][1]), use(c.triangles[i][2]) };
    cells.polys->InsertNextCell(3, ids);
    cells.polyPairs->InsertNextTypedTuple(c.trianglePairs[i].data());
    cells.polySources->InsertNextValue(c.sourceFaces.empty() ? -1 : c.sourceFaces[i]);
    cells.polyPlanes->InsertNextValue(c.trianglePlanes.empty() ? -1 : c.trianglePlanes[i]);
  }
  for (const auto& region : c.interfaces)
  {
    if (!wanted(region.pair))
    {
      continue;
    }
    std::vector<std::vector<Index>> loops;
    chainLoops(region.edges, loops);
    for (const auto& loop : loops)
    {
      vtkNew<vtkIdList> ids;
      for (Index p : loop)
      {
        ids->InsertNextId(use(p));
      }
      ids->InsertNextId(use(loop.front()));
      cells.lines->InsertNextCell(ids);
      cells.linePairs->InsertNextTypedTuple(region.pair.data());
      cells.linePlanes->InsertNextValue(region.planeId);
      cells.lineSources->InsertNextValue(-1);
    }
  }
}

// The cell arrays, lines first: VTK orders cell data: vertices, lines, polygons, strips.
void addCellData(const ComplexCells& cells, vtkPolyData* output)
{
  vtkNew<vtkIntArray> pairs;
  pairs->SetName(arrays::SubdomainPair);
  pairs->SetNumberOfComponents(2);
  pairs->SetComponentName(0, "Out");
  pairs->SetComponentName(1, "In");
  vtkNew<vtkIdTypeArray> sources;
  sources->SetName(arrays::SourceFaceId);
  vtkNew<vtkIntArray> planes;
  planes->SetName(arrays::PlaneId);
  for (vtkIdType i = 0; i < cells.lines->GetNumberOfCells(); ++i)
  {
    pairs->InsertNextTypedTuple(cells.linePairs->GetPointer(2 * i));
    sources->InsertNextValue(cells.lineSources->GetValue(i));
    planes->InsertNextValue(cells.linePlanes->GetValue(i));
  }
  for (vtkIdType i = 0; i < cells.polys->GetNumberOfCells(); ++i)
  {
    pairs->InsertNextTypedTuple(cells.polyPairs->GetPointer(2 * i));
    sources->InsertNextValue(cells.polySources->GetValue(i));
    planes->InsertNextValue(cells.polyPlanes->GetValue(i));
  }
  output->GetCellData()->AddArray(pairs);
  output->GetCellData()->AddArray(sources);
  output->GetCellData()->AddArray(planes);
  output->GetCellData()->SetActiveScalars(arrays::SubdomainPair);
}

// The piece's facts as field data: the cutting planes, the subdomains'
// count, ranks, volumes and measures, the global point count and the
// input's mean edge length.
void addFieldData(const ComplexPiece& piece, vtkFieldData* fd)
{
  const SurfaceComplex& c = piece.complex;
  vtkNew<vtkDoubleArray> planeArray;
  planeArray->SetName(arrays::CuttingPlanes);
  planeArray->SetNumberOfComponents(6);
  vtkNew<vtkIntArray> planeCounts;
  planeCounts->SetName(arrays::PlaneSubdomainCount);
  for (std::size_t k = 0; k < c.planes.size(); ++k)
  {
    const auto& p = c.planes[k];
    const double tuple[6] = { p.origin[0], p.origin[1], p.origin[2], p.normal[0], p.normal[1],
      p.normal[2] };
    planeArray->InsertNextTypedTuple(tuple);
    planeCounts->InsertNextValue(
      k < piece.planeSubdomainCount.size() ? piece.planeSubdomainCount[k] : p.cutSubdomainCount);
  }
  fd->AddArray(planeArray);
  fd->AddArray(planeCounts);
  vtkNew<vtkIntArray> count;
  count->SetName(arrays::NumberOfSubdomains);
  count->InsertNextValue(c.subdomainCount);
  fd->AddArray(count);
  vtkNew<vtkIntArray> ranks;
  ranks->SetName(arrays::SubdomainRank);
  for (int r : piece.subdomainRank)
  {
    ranks->InsertNextValue(r);
  }
  fd->AddArray(ranks);
  vtkNew<vtkDoubleArray> volumes;
  volumes->SetName(arrays::SubdomainVolume);
  for (double v : piece.subdomainVolume)
  {
    volumes->InsertNextValue(v);
  }
  fd->AddArray(volumes);
  vtkNew<vtkDoubleArray> measures;
  measures->SetName(arrays::SubdomainMeasure);
  for (double v : piece.subdomainMeasure)
  {
    measures->InsertNextValue(v);
  }
  fd->AddArray(measures);
  vtkNew<vtkIdTypeArray> total;
  total->SetName(arrays::GlobalPointCount);
  total->InsertNextValue(piece.globalPointCount);
  fd->AddArray(total);
  vtkNew<vtkDoubleArray> meanEdge;
  meanEdge->SetName(arrays::InputMeanEdgeLength);
  meanEdge->InsertNextValue(piece.inputMeanEdgeLength);
  fd->AddArray(meanEdge);
}
} // namespace

void complexToPolyData(const ComplexPiece& piece, const std::vector<int>& keep, vtkPolyData* output)
{
  ComplexCells cells;
  collectCells(piece, keep, cells);
  output->Initialize();
  output->SetPoints(cells.points);
  output->SetPolys(cells.polys);
  output->SetLines(cells.lines);
  output->GetPointData()->SetGlobalIds(cells.globalIds);
  addCellData(cells, output);
  addFieldData(piece, output->GetFieldData());
}

bool complexFromPolyData(vtkPolyData* input, ComplexPiece& piece, std::string& error)
{
  piece = ComplexPiece();
  if (!input)
  {
    error = "no input";
    return false;
  }
  vtkFieldData* fd = input->GetFieldData();
  auto* planes = vtkDoubleArray::SafeDownCast(fd->GetAbstractArray(arrays::CuttingPlanes));
  auto* count = vtkIntArray::SafeDownCast(fd->GetAbstractArray(arrays::NumberOfSubdomains));
  auto* ranks = vtkIntArray::SafeDownCast(fd->GetAbstractArray(arrays::SubdomainRank));
  auto* total = vtkIdTypeArray::SafeDownCast(fd->GetAbstractArray(arrays::GlobalPointCount));
  auto* pairs = vtkIntArray::SafeDownCast(input->GetCellData()->GetAbstractArray(arrays::SubdomainPair));
  auto* sources =
    vtkIdTypeArray::SafeDownCast(input->GetCellData()->GetAbstractArray(arrays::SourceFaceId));
  auto* planeIds = vtkIntArray::SafeDownCast(input->GetCellData()->GetAbstractArray(arrays::PlaneId));
  auto* globalIds =
    vtkIdTypeArray::SafeDownCast(input->GetPointData()->GetAbstractArray(arrays::GlobalPointIds));
  const char* missing = !planes ? arrays::CuttingPlanes
    : !count                    ? arrays::NumberOfSubdomains
    : !ranks                    ? arrays::SubdomainRank
    : !total                    ? arrays::GlobalPointCount
    : !pairs                    ? arrays::SubdomainPair
    : !sources                  ? arrays::SourceFaceId
    : !planeIds                 ? arrays::PlaneId
    : !globalIds                ? arrays::GlobalPointIds
                                : nullptr;
  if (missing)
  {
    error = std::string("the input is not a labeled surface complex (array '") + missing +
      "' is missing): connect the output of VolumeBalancedCutter";
    return false;
  }
  SurfaceComplex& c = piece.complex;
  c.subdomainCount = count->GetValue(0);
  for (vtkIdType k = 0; k < planes->GetNumberOfTuples(); ++k)
  {
    double t[6];
    planes->GetTypedTuple(k, t);
    CuttingPlane p;
    p.origin = { t[0], t[1], t[2] };
    p.normal = { t[3], t[4], t[5] };
    c.planes.push_back(p);
  }
  if (auto* pc = vtkIntArray::SafeDownCast(fd->GetAbstractArray(arrays::PlaneSubdomainCount)))
  {
    for (vtkIdType k = 0; k < pc->GetNumberOfTuples(); ++k)
    {
      piece.planeSubdomainCount.push_back(pc->GetValue(k));
      if (k < static_cast<vtkIdType>(c.planes.size()))
      {
        c.planes[k].cutSubdomainCount = pc->GetValue(k);
      }
    }
  }
  for (vtkIdType s = 0; s < ranks->GetNumberOfTuples(); ++s)
  {
    piece.subdomainRank.push_back(ranks->GetValue(s));
  }
  if (static_cast<int>(piece.subdomainRank.size()) != c.subdomainCount)
  {
    error = "the SubdomainRank field array does not have one entry per subdomain";
    return false;
  }
  if (auto* v = vtkDoubleArray::SafeDownCast(fd->GetAbstractArray(arrays::SubdomainVolume)))
  {
    for (vtkIdType s = 0; s < v->GetNumberOfTuples(); ++s)
    {
      piece.subdomainVolume.push_back(v->GetValue(s));
    }
  }
  if (auto* v = vtkDoubleArray::SafeDownCast(fd->GetAbstractArray(arrays::SubdomainMeasure)))
  {
    for (vtkIdType s = 0; s < v->GetNumberOfTuples(); ++s)
    {
      piece.subdomainMeasure.push_back(v->GetValue(s));
    }
  }
  piece.globalPointCount = total->GetValue(0);
  if (auto* meanEdge = vtkDoubleArray::SafeDownCast(fd->GetAbstractArray(arrays::InputMeanEdgeLength)))
  {
    piece.inputMeanEdgeLength = meanEdge->GetNumberOfTuples() ? meanEdge->GetValue(0) : 0.0;
  }

  const vtkIdType n = input->GetNumberOfPoints();
  c.points.resize(static_cast<std::size_t>(n));
  piece.globalIds.resize(static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    input->GetPoint(i, c.points[i].data());
    piece.globalIds[i] = globalIds->GetValue(i);
  }
  // Cell data runs over vertices, lines, polygons, strips in that order.
  const vtkIdType verts = input->GetNumberOfVerts();
  vtkIdType cellId = verts;
  std::map<std::pair<int, SubdomainPair>, std::size_t> regionOf;
  vtkIdType npts = 0;
  const vtkIdType* pts = nullptr;
  vtkCellArray* lines = input->GetLines();
  for (lines->InitTraversal(); lines->GetNextCell(npts, pts); ++cellId)
  {
    SubdomainPair pair;
    pairs->GetTypedTuple(cellId, pair.data());
    const int plane = planeIds->GetValue(cellId);
    if (plane < 0 || plane >= static_cast<int>(c.planes.size()))
    {
      error = "an interface loop refers to a cutting plane that does not exist";
      return false;
    }
    if (npts < 4 || pts[0] != pts[npts - 1])
    {
      error = "an interface loop is not closed";
      return false;
    }
    auto key = std::make_pair(plane, pair);
    auto it = regionOf.find(key);
    if (it == regionOf.end())
    {
      it = regionOf.emplace(key, c.interfaces.size()).first;
      InterfaceRegion region;
      region.planeId = plane;
      region.pair = pair;
      c.interfaces.push_back(region);
    }
    auto& edges = c.interfaces[it->second].edges;
    for (vtkIdType k = 0; k + 1 < npts; ++k)
    {
      edges.push_back({ pts[k], pts[k + 1] });
    }
  }
  vtkCellArray* polys = input->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(npts, pts); ++cellId)
  {
    if (npts != 3)
    {
      error = "the labeled surface complex must contain only triangles";
      return false;
    }
    SubdomainPair pair;
    pairs->GetTypedTuple(cellId, pair.data());
    c.triangles.push_back({ pts[0], pts[1], pts[2] });
    c.trianglePairs.push_back(pair);
    c.sourceFaces.push_back(sources->GetValue(cellId));
    c.trianglePlanes.push_back(planeIds->GetValue(cellId));
  }
  for (auto& region : c.interfaces)
  {
    std::sort(region.edges.begin(), region.edges.end());
  }
  return true;
}
void passOnFieldData(vtkPolyData* input, vtkFieldData* output)
{
  if (!input)
  {
    return;
  }
  for (const char* name : arrays::PassedOn)
  {
    if (vtkAbstractArray* a = input->GetFieldData()->GetAbstractArray(name))
    {
      output->AddArray(a);
    }
  }
}
} // namespace ptm
