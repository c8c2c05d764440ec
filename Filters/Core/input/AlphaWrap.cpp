#include "AlphaWrap.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/alpha_wrap_3.h>

#include <chrono>
#include <cmath>
#include <exception>
#include <iterator>
#include <sstream>

namespace ptm
{
namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Face = std::array<std::size_t, 3>;
using CgalTriangle = Kernel::Triangle_3;
using TriangleIterator = std::vector<CgalTriangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, TriangleIterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
namespace PMP = CGAL::Polygon_mesh_processing;

// About this many samples per surface (CGAL's grid sampling gives up to
// twice the estimate): on the coarse OCCT bottle (3,450 triangles, wrap of
// 19,940) 74,000 + 328,000 samples, measured in 1.1 s against 3.0 s for the
// wrap itself; counting the area alone gave 1.5 million samples and 3.9 s.
constexpr double kMaximumSamples = 1.5e5;


// Area and total edge length (every triangle's three edges): CGAL's grid
// sampling puts about area / h^2 samples in the faces and length / h on the
// edges (the CAD tessellations' long thin triangles make the second term the
// larger: 1.5 million samples on the coarse OCCT bottle when only the area
// was counted).
struct Extent
{
  double area = 0;
  double edges = 0;
};

Extent extentOf(const std::vector<CgalTriangle>& triangles)
{
  Extent e;
  for (const CgalTriangle& t : triangles)
  {
    e.area += std::sqrt(std::max(0.0, t.squared_area()));
    for (int k = 0; k < 3; ++k)
    {
      e.edges += std::sqrt(CGAL::squared_distance(t.vertex(k), t.vertex(k + 1)));
    }
  }
  return e;
}

// The spacing h at which area / h^2 + edges / h = samples.
double spacingFor(const Extent& e, double samples)
{
  const double x = (-e.edges + std::sqrt(e.edges * e.edges + 4 * e.area * samples)) / (2 * e.area);
  return x > 0 ? 1.0 / x : 0.0;
}

struct Soup
{
  std::vector<Point> points;
  std::vector<Face> faces;
  std::vector<CgalTriangle> triangles;
  Extent extent;
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
    soup.triangles.emplace_back(soup.points[t[0]], soup.points[t[1]], soup.points[t[2]]);
  }
  soup.extent = extentOf(soup.triangles);
  return soup;
}

// Largest distance from the samples to the triangles of the tree.
double largestDistance(const std::vector<Point>& samples, const std::vector<CgalTriangle>& triangles)
{
  Tree tree(triangles.begin(), triangles.end());
  tree.accelerate_distance_queries();
  double worst = 0;
  for (const Point& p : samples)
  {
    worst = std::max(worst, tree.squared_distance(p));
  }
  return std::sqrt(worst);
}

TriangleSurface surfaceOf(Mesh& mesh, std::vector<CgalTriangle>& triangles)
{
  mesh.collect_garbage();
  TriangleSurface s;
  s.points.reserve(mesh.number_of_vertices());
  for (Mesh::Vertex_index v : mesh.vertices())
  {
    const Point& p = mesh.point(v);
    s.points.push_back({ p.x(), p.y(), p.z() });
  }
  for (Mesh::Face_index f : mesh.faces())
  {
    Triangle t{};
    int k = 0;
    for (Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
    {
      if (k < 3)
      {
        t[k] = static_cast<Index>(v.idx());
      }
      ++k;
    }
    if (k == 3)
    {
      s.triangles.push_back(t);
      triangles.emplace_back(mesh.point(Mesh::Vertex_index(static_cast<Mesh::size_type>(t[0]))),
        mesh.point(Mesh::Vertex_index(static_cast<Mesh::size_type>(t[1]))),
        mesh.point(Mesh::Vertex_index(static_cast<Mesh::size_type>(t[2]))));
    }
  }
  return s;
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
  const double diagonal = boundingBoxDiagonal(input.points);
  if (soup.faces.empty() || !(diagonal > 0) || !(soup.extent.area > 0))
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
    Mesh wrap;
    CGAL::alpha_wrap_3(soup.points, soup.faces, r.alpha, r.offset, wrap);
    const auto wrapped = Clock::now();
    r.wrapSeconds = std::chrono::duration<double>(wrapped - start).count();
    if (wrap.number_of_faces() == 0)
    {
      r.error = "the alpha wrap came out empty";
      return r;
    }
    std::vector<CgalTriangle> wrapTriangles;
    r.surface = surfaceOf(wrap, wrapTriangles);

    // Sample spacing: a tenth of alpha (the wrap's own resolution), widened
    // so that neither surface gets more than about kMaximumSamples samples.
    r.sampleSpacing = std::max({ r.alpha / 10.0, spacingFor(soup.extent, kMaximumSamples),
      spacingFor(extentOf(wrapTriangles), kMaximumSamples) });
    const auto sampling =
      CGAL::parameters::use_grid_sampling(true).grid_spacing(r.sampleSpacing);
    std::vector<Point> onWrap, onInput;
    PMP::sample_triangle_mesh(wrap, std::back_inserter(onWrap), sampling);
    PMP::sample_triangle_soup(soup.points, soup.faces, std::back_inserter(onInput), sampling);
    r.wrapToInput = largestDistance(onWrap, soup.triangles);
    r.inputToWrap = largestDistance(onInput, wrapTriangles);
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
