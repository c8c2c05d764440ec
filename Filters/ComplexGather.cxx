#include "ComplexGather.h"

#include "RankCollectives.h"

#include <algorithm>
#include <cstring>
#include <tuple>

namespace ptm
{
bool allGatherComplex(vtkMultiProcessController* controller, const ComplexPiece& local,
  ComplexPiece& whole, std::string& error)
{
  const SurfaceComplex& c = local.complex;
  if (!c.interfaces.empty())
  {
    error = "the complex still has untriangulated interface loops: run InterfaceTriangulator first";
    return false;
  }
  std::vector<double> coordinates;
  std::vector<long long> pointIds;
  for (std::size_t i = 0; i < c.points.size(); ++i)
  {
    pointIds.push_back(local.globalIds[i]);
    coordinates.insert(coordinates.end(), c.points[i].begin(), c.points[i].end());
  }
  std::vector<long long> faces; // 7 per triangle: ids (rotated), pair, source, plane
  for (std::size_t t = 0; t < c.triangles.size(); ++t)
  {
    std::array<long long, 3> g{ local.globalIds[c.triangles[t][0]], local.globalIds[c.triangles[t][1]],
      local.globalIds[c.triangles[t][2]] };
    std::rotate(g.begin(), std::min_element(g.begin(), g.end()), g.end());
    faces.insert(faces.end(), g.begin(), g.end());
    faces.push_back(c.trianglePairs[t][0]);
    faces.push_back(c.trianglePairs[t][1]);
    faces.push_back(c.sourceFaces.empty() ? -1 : c.sourceFaces[t]);
    faces.push_back(c.trianglePlanes.empty() ? -1 : c.trianglePlanes[t]);
  }
  const std::vector<long long> allIds = allGatherValues(controller, pointIds);
  const std::vector<double> allCoordinates = allGatherValues(controller, coordinates);
  std::vector<long long> allFaces = allGatherValues(controller, faces);

  whole = ComplexPiece();
  whole.subdomainRank = local.subdomainRank;
  whole.subdomainVolume = local.subdomainVolume;
  whole.subdomainMeasure = local.subdomainMeasure;
  whole.planeSubdomainCount = local.planeSubdomainCount;
  whole.globalPointCount = local.globalPointCount;
  whole.inputMeanEdgeLength = local.inputMeanEdgeLength;
  SurfaceComplex& w = whole.complex;
  w.planes = c.planes;
  w.subdomainCount = c.subdomainCount;
  const long long n = local.globalPointCount;
  w.points.assign(static_cast<std::size_t>(n), Vec3{ 0, 0, 0 });
  std::vector<char> seen(static_cast<std::size_t>(n), 0);
  for (std::size_t i = 0; i < allIds.size(); ++i)
  {
    const long long g = allIds[i];
    if (g < 0 || g >= n)
    {
      error = "a global point id lies outside the complex's GlobalPointCount";
      return false;
    }
    const Vec3 p{ allCoordinates[3 * i], allCoordinates[3 * i + 1], allCoordinates[3 * i + 2] };
    if (seen[g] && std::memcmp(&w.points[g], &p, sizeof(Vec3)) != 0)
    {
      error = "two ranks hold different coordinates for the same global point";
      return false;
    }
    w.points[g] = p;
    seen[g] = 1;
  }
  std::vector<std::array<long long, 7>> records(allFaces.size() / 7);
  for (std::size_t k = 0; k < records.size(); ++k)
  {
    std::copy_n(&allFaces[7 * k], 7, records[k].begin());
  }
  std::sort(records.begin(), records.end());
  records.erase(std::unique(records.begin(), records.end()), records.end());
  for (const auto& r : records)
  {
    w.triangles.push_back({ r[0], r[1], r[2] });
    w.trianglePairs.push_back({ static_cast<int>(r[3]), static_cast<int>(r[4]) });
    w.sourceFaces.push_back(r[5]);
    w.trianglePlanes.push_back(static_cast<int>(r[6]));
  }
  whole.globalIds.resize(static_cast<std::size_t>(n));
  for (long long g = 0; g < n; ++g)
  {
    whole.globalIds[g] = g;
  }
  return true;
}
} // namespace ptm
