#include "CADTessellation.h"

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepLib.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Poly_Triangulation.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TopAbs.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shape.hxx>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <exception>
#include <fstream>
#include <map>
#include <sstream>
#include <unordered_map>

namespace ptm
{
namespace
{
std::string lowerExtension(const std::string& fileName)
{
  const std::size_t dot = fileName.find_last_of('.');
  if (dot == std::string::npos || fileName.find_first_of("/\\", dot) != std::string::npos)
  {
    return "";
  }
  std::string ext = fileName.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// The shape of the file, or an error naming the file and what went wrong.
bool readShape(const std::string& fileName, TopoDS_Shape& shape, std::string& error)
{
  if (!std::ifstream(fileName).is_open())
  {
    error = fileName + ": cannot open the file";
    return false;
  }
  const std::string ext = lowerExtension(fileName);
  if (ext == "brep")
  {
    BRep_Builder builder;
    if (!BRepTools::Read(shape, fileName.c_str(), builder) || shape.IsNull())
    {
      error = fileName + ": OpenCASCADE cannot read it as a BREP file";
      return false;
    }
    return true;
  }
  const bool step = ext == "step" || ext == "stp";
  const bool iges = ext == "iges" || ext == "igs";
  if (!step && !iges)
  {
    error = fileName + ": unknown CAD extension '" + ext + "' (expected .step, .stp, .iges, .igs or .brep)";
    return false;
  }
  STEPControl_Reader stepReader;
  IGESControl_Reader igesReader;
  XSControl_Reader& reader = step ? static_cast<XSControl_Reader&>(stepReader) : igesReader;
  if (reader.ReadFile(fileName.c_str()) != IFSelect_RetDone)
  {
    error = fileName + ": OpenCASCADE cannot read it as a " + (step ? "STEP" : "IGES") + " file";
    return false;
  }
  reader.TransferRoots();
  shape = reader.OneShape();
  if (shape.IsNull())
  {
    error = fileName + ": the file holds no shape OpenCASCADE can transfer";
    return false;
  }
  return true;
}

double diagonalOf(const TopoDS_Shape& shape)
{
  Bnd_Box box;
  BRepBndLib::AddOptimal(shape, box, false, false);
  return box.IsVoid() ? 0.0 : std::sqrt(box.SquareExtent());
}

// IGES files mostly hold trimmed faces, not solids (OCCT's hammer.iges: 0
// solids): sew the faces and make a solid of every closed shell. Returns the
// compound of those solids (empty when no shell closes); `openShells` counts
// the shells that stay open.
TopoDS_Shape solidsBySewing(const TopoDS_Shape& shape, double diagonal, int& openShells)
{
  // 1e-5 x diagonal: OCCT's hammer.iges (diagonal 4e4) stays open at 1e-6
  // and closes from 1e-5 on; bearing.iges stays open up to 1e-3 (measured)
  BRepBuilderAPI_Sewing sewing(1e-5 * diagonal);
  sewing.Add(shape);
  sewing.Perform();
  BRep_Builder builder;
  TopoDS_Compound solids;
  builder.MakeCompound(solids);
  openShells = 0;
  for (TopExp_Explorer e(sewing.SewedShape(), TopAbs_SHELL); e.More(); e.Next())
  {
    if (!BRep_Tool::IsClosed(e.Current()))
    {
      ++openShells;
      continue;
    }
    BRepBuilderAPI_MakeSolid make(TopoDS::Shell(e.Current()));
    TopoDS_Solid solid = make.Solid();
    BRepLib::OrientClosedSolid(solid); // outward, whatever the faces' order
    builder.Add(solids, solid);
  }
  return solids;
}

struct PointKey
{
  double x, y, z;
  bool operator==(const PointKey& o) const { return x == o.x && y == o.y && z == o.z; }
};
struct PointKeyHash
{
  std::size_t operator()(const PointKey& k) const
  {
    const std::hash<double> h;
    return h(k.x) * 73856093u ^ h(k.y) * 19349663u ^ h(k.z) * 83492791u;
  }
};

// Appends the triangles of one solid's faces; nodes merged by exact coordinates.
bool appendSolid(const TopoDS_Shape& solid, int solidIndex, const TopTools_IndexedMapOfShape& faceMap,
  std::unordered_map<PointKey, Index, PointKeyHash>& merged, CADSurface& out, std::string& error)
{
  for (TopExp_Explorer e(solid, TopAbs_FACE); e.More(); e.Next())
  {
    const TopoDS_Face& face = TopoDS::Face(e.Current());
    const Index id = faceMap.FindIndex(face) - 1;
    TopLoc_Location location;
    const Handle(Poly_Triangulation) mesh = BRep_Tool::Triangulation(face, location);
    if (mesh.IsNull())
    {
      std::ostringstream msg;
      msg << "face " << id << " of solid " << solidIndex << " could not be tessellated";
      error = msg.str();
      return false;
    }
    std::vector<Index> node(static_cast<std::size_t>(mesh->NbNodes()) + 1, -1);
    for (int i = 1; i <= mesh->NbNodes(); ++i)
    {
      const gp_Pnt p = mesh->Node(i).Transformed(location.Transformation());
      const PointKey key{ p.X(), p.Y(), p.Z() };
      auto it = merged.find(key);
      if (it == merged.end())
      {
        it = merged.emplace(key, static_cast<Index>(out.surface.points.size())).first;
        out.surface.points.push_back({ p.X(), p.Y(), p.Z() });
      }
      node[i] = it->second;
    }
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    for (int t = 1; t <= mesh->NbTriangles(); ++t)
    {
      int a = 0, b = 0, c = 0;
      mesh->Triangle(t).Get(a, b, c);
      if (reversed)
      {
        std::swap(b, c);
      }
      if (node[a] == node[b] || node[b] == node[c] || node[c] == node[a])
      {
        continue; // collapsed at a degenerate edge (a cone's apex, a sphere's pole)
      }
      out.surface.triangles.push_back({ node[a], node[b], node[c] });
      out.faceId.push_back(id);
    }
  }
  return true;
}

// Edges used other than twice after merging: the tessellation is not closed.
std::size_t unpairedEdges(const TriangleSurface& s)
{
  std::map<std::pair<Index, Index>, int> uses;
  for (const Triangle& t : s.triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Index a = t[k], b = t[(k + 1) % 3];
      ++uses[{ std::min(a, b), std::max(a, b) }];
    }
  }
  std::size_t bad = 0;
  for (const auto& [edge, n] : uses)
  {
    bad += n != 2 ? 1 : 0;
  }
  return bad;
}
} // namespace

CADSurface readCADSurface(const std::string& fileName, const CADReadOptions& options)
{
  CADSurface out;
  if (!(options.angularDeflection > 0) || !(options.relativeLinearDeflection > 0) ||
    !(options.linearDeflection >= 0))
  {
    out.error = "the deflections must be positive";
    return out;
  }
  TopoDS_Shape shape;
  try
  {
    if (!readShape(fileName, shape, out.error))
    {
      return out;
    }
    TopTools_IndexedMapOfShape faceMap, solidMap;
    TopExp::MapShapes(shape, TopAbs_SOLID, solidMap);
    const double diagonal = diagonalOf(shape);
    if (solidMap.Extent() == 0)
    {
      TopExp::MapShapes(shape, TopAbs_FACE, faceMap);
      const int fileFaces = faceMap.Extent();
      int openShells = 0;
      if (fileFaces > 0)
      {
        shape = solidsBySewing(shape, diagonal, openShells);
        TopExp::MapShapes(shape, TopAbs_SOLID, solidMap);
      }
      if (solidMap.Extent() == 0)
      {
        std::ostringstream msg;
        msg << fileName << ": no solid in the file, and ";
        if (fileFaces == 0)
        {
          // OCCT's asahi.brep: curves only
          msg << "no faces either (only curves or points): nothing encloses a volume";
        }
        else if (fileFaces == 1)
        {
          // OCCT's MAT.brep: one open face
          msg << "its one face does not close into a shell (faces are missing; close them in a CAD tool)";
        }
        else
        {
          msg << "its " << fileFaces << " faces do not sew into a closed shell (" << openShells
              << " open shells: faces missing or apart; close them in a CAD tool)";
        }
        out.error = msg.str();
        return out;
      }
      std::ostringstream msg;
      msg << fileName << ": no solid in the file; sewed its " << fileFaces << " faces into "
          << solidMap.Extent() << " closed shells made solids";
      if (openShells > 0)
      {
        msg << " (" << openShells << " open shells left out)";
      }
      out.warnings.push_back(msg.str());
      faceMap.Clear();
    }
    // face ids of the shape that is tessellated (the sewn one for IGES faces)
    TopExp::MapShapes(shape, TopAbs_FACE, faceMap);
    out.faces = faceMap.Extent();
    out.solids = solidMap.Extent();
    if (options.solid < -1 || options.solid >= out.solids)
    {
      std::ostringstream msg;
      msg << fileName << ": solid " << options.solid << " does not exist (the file has " << out.solids
          << " solids, 0 to " << out.solids - 1 << "; -1 takes all)";
      out.error = msg.str();
      return out;
    }
    // Empty solids exist (OCCT's Axis_of_bearing.brep: solid 14 of 18 has no
    // shell): refused when chosen alone, left out with a warning from all.
    std::vector<int> chosen, empty;
    for (int s = 0; s < out.solids; ++s)
    {
      if (options.solid == -1 || options.solid == s)
      {
        (TopExp_Explorer(solidMap(s + 1), TopAbs_FACE).More() ? chosen : empty).push_back(s);
      }
    }
    if (chosen.empty())
    {
      std::ostringstream msg;
      msg << fileName << ": " << (options.solid >= 0 ? "solid " + std::to_string(options.solid) + " is"
                                                     : std::string("all solids are"))
          << " empty (no faces)";
      out.error = msg.str();
      return out;
    }
    if (!empty.empty())
    {
      std::ostringstream msg;
      msg << fileName << ": left out " << empty.size() << " empty solids (no faces), e.g. solid "
          << empty.front();
      out.warnings.push_back(msg.str());
    }
    for (int s : chosen)
    {
      const TopoDS_Shape& solid = solidMap(s + 1);
      for (TopExp_Explorer e(solid, TopAbs_SHELL); e.More(); e.Next())
      {
        if (!BRep_Tool::IsClosed(e.Current()))
        {
          std::ostringstream msg;
          msg << fileName << ": solid " << s << " has an open shell (free edges: a face is missing or "
              << "not sewn to its neighbours)";
          out.error = msg.str();
          return out;
        }
      }
    }
    out.linearDeflection =
      options.linearDeflection > 0 ? options.linearDeflection : options.relativeLinearDeflection * diagonal;
    // not in parallel: the same triangles on every rank and every run
    BRepMesh_IncrementalMesh mesher(shape, out.linearDeflection, false, options.angularDeflection, false);
    std::unordered_map<PointKey, Index, PointKeyHash> merged;
    for (int s : chosen)
    {
      std::string error;
      if (!appendSolid(solidMap(s + 1), s, faceMap, merged, out, error))
      {
        out.error = fileName + ": " + error;
        return out;
      }
    }
  }
  catch (const Standard_Failure& e)
  {
    out.error = fileName + ": OpenCASCADE failed: " + e.GetMessageString();
    return out;
  }
  // Not an error here: solids that share faces or edges (an assembly) are
  // non-manifold as a whole, which the cutter refuses with its own message
  // and the alpha wrap repairs; the reader must still deliver them.
  const std::size_t unpaired = unpairedEdges(out.surface);
  if (unpaired > 0)
  {
    std::ostringstream msg;
    msg << fileName << ": " << unpaired
        << " edges of the tessellation are not shared by exactly two triangles (solids that touch, "
           "or faces tessellated apart along an edge)";
    out.warnings.push_back(msg.str());
  }
  out.ok = true;
  return out;
}
} // namespace ptm

extern "C" void ptmReadCADSurface(
  const char* fileName, const ptm::CADReadOptions* options, ptm::CADSurface* result)
{
  try
  {
    *result = ptm::readCADSurface(fileName, *options);
  }
  catch (const std::exception& e) // std::bad_alloc; OCCT's own failures are caught inside
  {
    *result = ptm::CADSurface();
    result->error = std::string(fileName) + ": " + e.what();
  }
}
