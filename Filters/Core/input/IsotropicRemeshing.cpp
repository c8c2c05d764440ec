#include "IsotropicRemeshing.h"

#include "CgalSurfaceMesh.h"
#include "SelfIntersectionCheck.h"
#include "SurfaceDistance.h"

#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <chrono>
#include <cmath>
#include <exception>
#include <sstream>

namespace ptm
{
namespace
{
namespace PMP = CGAL::Polygon_mesh_processing;
using Vertex = CgalMesh::Vertex_index;
using Edge = CgalMesh::Edge_index;
using Face = CgalMesh::Face_index;

// The input as a CGAL mesh; empty with `error` set if it is not a closed
// oriented manifold one.
bool meshOf(const TriangleSurface& input, CgalMesh& mesh, std::string& error)
{
  std::vector<CgalKernel::Point_3> points;
  points.reserve(input.points.size());
  for (const Vec3& p : input.points)
  {
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      error = "the surface to remesh has a NaN or infinite coordinate";
      return false;
    }
    points.emplace_back(p[0], p[1], p[2]);
  }
  std::vector<std::vector<std::size_t>> polygons;
  polygons.reserve(input.triangles.size());
  const Index n = static_cast<Index>(input.points.size());
  for (const Triangle& t : input.triangles)
  {
    if (t[0] < 0 || t[1] < 0 || t[2] < 0 || t[0] >= n || t[1] >= n || t[2] >= n)
    {
      error = "the surface to remesh has a triangle with a corner that does not exist";
      return false;
    }
    polygons.push_back({ static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]),
      static_cast<std::size_t>(t[2]) });
  }
  if (polygons.empty() || !PMP::is_polygon_soup_a_polygon_mesh(polygons))
  {
    error = "the surface to remesh is not an oriented, edge- and vertex-manifold triangle mesh (a soup, "
            "or triangles with a repeated corner); wrap it first (AlphaWrap, tetmesh.py --wrap)";
    return false;
  }
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  if (!CGAL::is_closed(mesh))
  {
    error = "the surface to remesh is open (it has boundary edges); wrap it first (AlphaWrap, tetmesh.py --wrap)";
    return false;
  }
  return true;
}

// Corners: vertices where a number of sharp edges other than two meet, or
// where the sharp polyline through them turns by more than the feature
// angle. They do not move; the other vertices of sharp edges slide along
// them.
std::size_t markCorners(const CgalMesh& mesh, const CgalMesh::Property_map<Edge, bool>& sharp,
  double featureAngleDegrees, CgalMesh::Property_map<Vertex, bool>& corner)
{
  std::size_t corners = 0;
  const double cosTurn = std::cos(featureAngleDegrees * kPi / 180.0);
  for (Vertex v : mesh.vertices())
  {
    std::vector<Vec3> out;
    for (auto h : CGAL::halfedges_around_target(v, mesh))
    {
      if (sharp[mesh.edge(h)])
      {
        const auto& a = mesh.point(v);
        const auto& b = mesh.point(mesh.source(h));
        out.push_back(normalized(Vec3{ b.x() - a.x(), b.y() - a.y(), b.z() - a.z() }));
      }
    }
    // a straight polyline has its two edges opposite: -dot = cos(turn)
    const bool isCorner = (!out.empty() && out.size() != 2) || (out.size() == 2 && -dot(out[0], out[1]) < cosTurn);
    corner[v] = isCorner;
    corners += isCorner ? 1 : 0;
  }
  return corners;
}

// The labels on the faces (in the order of the input's triangles, as
// polygon_soup_to_polygon_mesh added them), and every edge between two
// labels kept like a sharp one.
void keepLabelBorders(const CgalMesh& mesh, const std::vector<long long>& labels,
  CgalMesh::Property_map<Face, long long>& label, CgalMesh::Property_map<Edge, bool>& sharp)
{
  std::size_t i = 0;
  for (Face f : mesh.faces())
  {
    label[f] = i < labels.size() ? labels[i] : -1;
    ++i;
  }
  for (Edge e : mesh.edges())
  {
    const auto h = mesh.halfedge(e);
    if (label[mesh.face(h)] != label[mesh.face(mesh.opposite(h))])
    {
      sharp[e] = true;
    }
  }
}

std::string optionError(const RemeshOptions& o)
{
  if (!(o.targetEdgeLength >= 0) || !std::isfinite(o.targetEdgeLength))
  {
    return "the remeshing target edge length must be 0 (automatic) or positive";
  }
  if (!(o.featureAngleDegrees >= 0 && o.featureAngleDegrees <= 180))
  {
    return "the remeshing feature angle must lie in [0, 180] degrees";
  }
  if (o.iterations < 1 || o.iterations > 100)
  {
    return "the remeshing iterations must lie in [1, 100]";
  }
  if (!(o.distanceSamples >= 1) || !std::isfinite(o.distanceSamples))
  {
    return "the remeshing distance samples must be at least 1";
  }
  if (!(o.maximumVolumeChange >= 0) || !std::isfinite(o.maximumVolumeChange))
  {
    return "the remeshing maximum volume change must be 0 (not bounded) or positive";
  }
  if (!(o.maximumDeviation >= 0) || !std::isfinite(o.maximumDeviation))
  {
    return "the remeshing maximum deviation must be 0 (not bounded) or positive";
  }
  return "";
}

// The checks the remeshed surface must pass before it is handed on (a
// smaller edge length may pass them all).
std::string resultError(const RemeshResult& r, const RemeshOptions& o)
{
  std::ostringstream msg;
  const double worst = std::max(r.remeshToInput, r.inputToRemesh);
  if (o.maximumDeviation > 0 && worst > o.maximumDeviation * r.boundingBoxDiagonal)
  {
    msg << "remeshing at edge length " << o.targetEdgeLength << " moved the surface by at least " << worst << " ("
        << worst / r.boundingBoxDiagonal << " of the bounding-box diagonal; remeshed to input " << r.remeshToInput
        << ", input to remeshed " << r.inputToRemesh << "), more than MaximumDeviation " << o.maximumDeviation
        << ": the input has features smaller than the edge length; give a smaller target edge length, or allow "
           "more deviation";
    return msg.str();
  }
  const SelfIntersectionReport crossing = checkSelfIntersection(r.surface);
  if (crossing.checked && crossing.intersects)
  {
    msg << "remeshing at edge length " << o.targetEdgeLength << " made the surface cross itself (triangles "
        << crossing.firstTriangle << " and " << crossing.secondTriangle
        << " of the remeshed surface): walls or gaps thinner than about the edge length; give a smaller "
           "target edge length";
    return msg.str();
  }
  return "";
}

// One remeshing of `mesh` (a copy of the input, enclosing `inputVolume`) at
// options.targetEdgeLength, measured and checked; r.error set on a failure.
// Returns whether a smaller edge length may help (a bound or a crossing, not
// an exception).
bool remeshOnce(
  CgalMesh mesh, const TriangleSurface& input, double inputVolume, const RemeshOptions& options, RemeshResult& r)
{
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  r.targetEdgeLength = options.targetEdgeLength;
  try
  {
    auto sharp = mesh.add_property_map<Edge, bool>("e:ptm_sharp", false).first;
    auto corner = mesh.add_property_map<Vertex, bool>("v:ptm_corner", false).first;
    auto label = mesh.add_property_map<Face, long long>("f:ptm_label", -1).first;
    PMP::detect_sharp_edges(mesh, options.featureAngleDegrees, sharp);
    const bool labelled = !options.faceLabels.empty();
    if (labelled)
    {
      keepLabelBorders(mesh, options.faceLabels, label, sharp);
    }
    r.featureEdges = 0;
    for (Edge e : mesh.edges())
    {
      r.featureEdges += sharp[e] ? 1 : 0;
    }
    r.corners = markCorners(mesh, sharp, options.featureAngleDegrees, corner);
    // Sliding the points of sharp edges along them (relax_constraints) moved
    // a CAD cylinder's rims inwards: 0.056 off the input at edge 0.25 on
    // radius 1, against 0.012 with them left where splits put them.
    const auto parameters = CGAL::parameters::number_of_iterations(static_cast<unsigned int>(options.iterations))
                              .edge_is_constrained_map(sharp)
                              .vertex_is_constrained_map(corner)
                              .relax_constraints(false);
    if (labelled)
    {
      PMP::isotropic_remeshing(faces(mesh), options.targetEdgeLength, mesh, parameters.face_patch_map(label));
    }
    else
    {
      PMP::isotropic_remeshing(faces(mesh), options.targetEdgeLength, mesh, parameters);
    }
    r.surface = surfaceOfMesh(mesh); // garbage collected: faces in the order of its triangles
    r.faceLabels.clear();
    if (labelled)
    {
      for (Face f : mesh.faces())
      {
        r.faceLabels.push_back(label[f]);
      }
    }
    mesh.remove_property_map(sharp);
    mesh.remove_property_map(corner);
    mesh.remove_property_map(label);
  }
  catch (const std::bad_alloc&)
  {
    r.error = "out of memory while remeshing (a larger target edge length needs less)";
    return false;
  }
  catch (const std::exception& e)
  {
    r.error = std::string("the isotropic remeshing failed: ") + e.what();
    return false;
  }
  const auto remeshed = Clock::now();
  r.remeshSeconds += std::chrono::duration<double>(remeshed - start).count();
  r.volumeChange = inputVolume != 0 ? (enclosedVolume(r.surface) - inputVolume) / inputVolume : 0;
  r.remeshToInput = r.inputToRemesh = r.sampleSpacing = 0;
  if (options.maximumVolumeChange > 0 && std::fabs(r.volumeChange) > options.maximumVolumeChange)
  {
    // known before any distance is measured
    std::ostringstream msg;
    msg << "remeshing at edge length " << options.targetEdgeLength << " changed the enclosed volume by "
        << r.volumeChange << " (relative), more than MaximumVolumeChange " << options.maximumVolumeChange
        << ": give a smaller target edge length, or allow more change";
    r.error = msg.str();
    return true;
  }
  // More samples than the wrap's 1.5e5: the bound is checked on these
  // figures, and a CAD input's many short edges take most of the samples.
  // OCCT's Pump_Nut at edge 0.5 with 1.5e5: samples 0.78 apart, the remeshed
  // surface "1.3e-13" from the input (only its points were hit); with 1e6,
  // 0.15 apart and 0.068. A remeshing beyond the bound stops measuring at
  // the first sample that shows it.
  const double bound = options.maximumDeviation > 0 ? options.maximumDeviation * r.boundingBoxDiagonal : HUGE_VAL;
  const TwoSidedDistance d =
    sampledTwoSidedDistance(r.surface, input, options.targetEdgeLength / 10.0, options.distanceSamples, bound);
  r.remeshToInput = d.firstToSecond;
  r.inputToRemesh = d.secondToFirst;
  r.sampleSpacing = d.sampleSpacing;
  r.distanceSeconds += std::chrono::duration<double>(Clock::now() - remeshed).count();
  r.error = resultError(r, options);
  return true;
}
} // namespace

RemeshResult remeshSurface(const TriangleSurface& input, const RemeshOptions& given)
{
  RemeshResult r;
  r.error = optionError(given);
  CgalMesh mesh;
  if (!r.error.empty() || !meshOf(input, mesh, r.error))
  {
    return r;
  }
  if (!given.faceLabels.empty() && given.faceLabels.size() != input.triangles.size())
  {
    r.error = "the remeshing was given face labels for another number of triangles";
    return r;
  }
  RemeshOptions options = given;
  if (options.targetEdgeLength == 0)
  {
    // the size the mesher's volume bound defaults to. (The edge of the mean
    // triangle area was tried first: on OCCT's Pump_Nut.brep, whose needles
    // have almost no area, it asked for 0.64 and made 45,512 triangles.)
    options.targetEdgeLength = meanEdgeLength(input);
  }
  r.boundingBoxDiagonal = boundingBoxDiagonal(input.points);
  const double inputVolume = enclosedVolume(input);
  for (r.attempts = 1;; ++r.attempts, options.targetEdgeLength /= 2)
  {
    r.error.clear();
    const bool retryable = remeshOnce(mesh, input, inputVolume, options, r);
    if (r.error.empty() || r.attempts > options.halvings || !retryable)
    {
      break;
    }
  }
  r.ok = r.error.empty();
  if (!r.ok && r.attempts > 1)
  {
    std::ostringstream msg;
    msg << " (after halving the edge length " << r.attempts - 1 << " times from " << r.targetEdgeLength * std::pow(2.0, r.attempts - 1) << ")";
    r.error += msg.str();
  }
  return r;
}
} // namespace ptm
