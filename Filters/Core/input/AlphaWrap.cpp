#include "AlphaWrap.h"

#include "CgalSurfaceMesh.h"
#include "SurfaceDistance.h"

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/alpha_wrap_3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <sstream>

namespace ptm
{
namespace
{
using Point = CgalKernel::Point_3;
using Face = std::array<std::size_t, 3>;

struct Soup
{
  std::vector<Point> points;
  std::vector<Face> faces;
  double area = 0;
};

// The usable triangles (finite points, three distinct indices in range).
Soup soupOf(const TriangleSurface& input, std::size_t& skipped)
{
  Soup soup;
  soup.points.reserve(input.points.size());
  for (const Vec3& p : input.points)
  {
    soup.points.emplace_back(p[0], p[1], p[2]);
  }
  const Index n = static_cast<Index>(input.points.size());
  skipped = 0;
  for (const Triangle& t : input.triangles)
  {
    const bool inRange = t[0] >= 0 && t[1] >= 0 && t[2] >= 0 && t[0] < n && t[1] < n && t[2] < n;
    if (!inRange || t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
    {
      ++skipped;
      continue;
    }
    soup.faces.push_back({ static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]),
      static_cast<std::size_t>(t[2]) });
    soup.area += 0.5 * norm(cross(input.points[t[1]] - input.points[t[0]], input.points[t[2]] - input.points[t[0]]));
  }
  return soup;
}

// Edges of exactly one face (by index): where the input is open.
std::size_t borderEdgeCount(const std::vector<Face>& faces)
{
  std::vector<std::array<std::size_t, 2>> edges;
  edges.reserve(3 * faces.size());
  for (const Face& f : faces)
  {
    for (int k = 0; k < 3; ++k)
    {
      edges.push_back({ std::min(f[k], f[(k + 1) % 3]), std::max(f[k], f[(k + 1) % 3]) });
    }
  }
  std::sort(edges.begin(), edges.end());
  std::size_t once = 0;
  for (std::size_t i = 0; i < edges.size();)
  {
    std::size_t j = i + 1;
    while (j < edges.size() && edges[j] == edges[i])
    {
      ++j;
    }
    once += j - i == 1 ? 1 : 0;
    i = j;
  }
  return once;
}

// "" if the wrap is a solid (see kSkinThicknessInOffsets), else what to say.
std::string skinMessage(const AlphaWrapResult& r)
{
  if (r.inputBorderEdges == 0 || !(r.meanThickness < kSkinThicknessInOffsets * r.offset))
  {
    return "";
  }
  std::ostringstream msg;
  msg << "the wrap is a hollow skin, not a solid: its mean thickness (2 x enclosed volume / area) is "
      << r.meanThickness << ", " << r.meanThickness / r.offset
      << " x the offset, so it wraps the surface from both sides: it went in through a hole of the open input ("
      << r.inputBorderEdges << " border edges) wider than alpha (" << r.alpha << ")";
  return msg.str();
}
} // namespace

AlphaWrapResult alphaWrapSurface(const TriangleSurface& input, const AlphaWrapOptions& options)
{
  AlphaWrapResult r;
  for (const Vec3& p : input.points)
  {
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      r.error = "the surface to wrap has a NaN or infinite coordinate";
      return r;
    }
  }
  if (!(options.relativeAlpha > 0) || !(options.relativeOffset > 0) || !std::isfinite(options.relativeAlpha) ||
    !std::isfinite(options.relativeOffset))
  {
    r.error = "the wrap's alpha and offset must be positive fractions of the bounding-box diagonal";
    return r;
  }
  Soup soup = soupOf(input, r.skippedTriangles);
  r.inputTriangles = soup.faces.size();
  r.inputBorderEdges = borderEdgeCount(soup.faces);
  const double diagonal = boundingBoxDiagonal(input.points);
  if (soup.faces.empty() || !(diagonal > 0) || !(soup.area > 0))
  {
    r.error = "there is nothing to wrap: the surface has no triangle with area";
    return r;
  }
  if (r.skippedTriangles > 0)
  {
    std::ostringstream msg;
    msg << "the wrap ignored " << r.skippedTriangles
        << " triangles with a repeated corner or a corner that does not exist";
    r.warnings.push_back(msg.str());
  }
  r.alpha = options.relativeAlpha * diagonal;
  r.offset = options.relativeOffset * diagonal;

  try
  {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    CgalMesh wrap;
    CGAL::alpha_wrap_3(soup.points, soup.faces, r.alpha, r.offset, wrap);
    const auto wrapped = Clock::now();
    r.wrapSeconds = std::chrono::duration<double>(wrapped - start).count();
    if (wrap.number_of_faces() == 0)
    {
      r.error = "the alpha wrap came out empty";
      return r;
    }
    namespace PMP = CGAL::Polygon_mesh_processing;
    r.meanThickness = 2.0 * PMP::volume(wrap) / PMP::area(wrap);
    const std::string skin = skinMessage(r);
    if (!skin.empty() && !options.allowSkin)
    {
      r.error = skin + ". Close the holes, or give an alpha wider than the widest hole (RelativeAlpha, "
                       "--wrap-alpha), or allow the skin (AllowSkin, --wrap-allow-skin) to mesh it as a thin solid";
      return r;
    }
    if (!skin.empty())
    {
      r.warnings.push_back(skin + " (allowed)");
    }
    r.surface = surfaceOfMesh(wrap);

    // Sample spacing: a tenth of alpha (the wrap's own resolution), or wider
    // for at most about 1.5e5 samples per surface: on the coarse OCCT bottle
    // (3,450 triangles, wrap of 19,940) 74,000 + 328,000 samples, measured in
    // 1.1 s against 3.0 s for the wrap itself; counting the area alone gave
    // 1.5 million samples and 3.9 s.
    const TwoSidedDistance d = sampledTwoSidedDistance(r.surface, input, r.alpha / 10.0, 1.5e5);
    r.wrapToInput = d.firstToSecond;
    r.inputToWrap = d.secondToFirst;
    r.sampleSpacing = d.sampleSpacing;
    r.distanceSeconds = std::chrono::duration<double>(Clock::now() - wrapped).count();
  }
  catch (const std::bad_alloc&)
  {
    r.error = "out of memory while wrapping (a larger WrapAlpha needs less)";
    return r;
  }
  catch (const std::exception& e)
  {
    r.error = std::string("the alpha wrap failed: ") + e.what();
    return r;
  }
  r.ok = true;
  return r;
}
} // namespace ptm
