// The CAD reader's core on the sample files Debian's occt-misc ships
// (/usr/share/opencascade/data, LGPL-2.1 with the OCCT exception): the
// tessellation must be one closed surface the input check accepts, with a
// CAD face for every triangle; bad files must be refused by name.
#include "CADTessellation.h"
#include "SurfaceInputCheck.h"

#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>

#include <cstdio>
#include <fstream>
#include <algorithm>
#include <set>

namespace
{
using namespace ptm;

const std::string kData = "/usr/share/opencascade/data/";

bool present(const std::string& path)
{
  return std::ifstream(path).is_open();
}

#define REQUIRE_FILE(path)                                                                          \
  if (!present(path))                                                                               \
  GTEST_SKIP() << path << " is missing: install occt-misc (Scripts/install-deps.sh)"

void expectClosedWithFaces(const std::string& path, int minimumFaces, std::size_t warnings = 0)
{
  const CADSurface r = readCADSurface(path, CADReadOptions());
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.warnings.size(), warnings) << (r.warnings.empty() ? "" : r.warnings.front());
  for (const std::string& w : r.warnings)
  {
    std::printf("warning: %s\n", w.c_str());
  }
  ASSERT_EQ(r.faceId.size(), r.surface.triangles.size());
  std::set<Index> used(r.faceId.begin(), r.faceId.end());
  EXPECT_GE(*used.begin(), 0);
  EXPECT_LT(*used.rbegin(), r.faces);
  EXPECT_GE(static_cast<int>(used.size()), minimumFaces);
  const PreparedSurface checked = prepareInputSurface(r.surface, InputCheckOptions());
  ASSERT_TRUE(checked.ok) << checked.error;
  // merged by exact coordinates, oriented by the faces: nothing to repair
  EXPECT_EQ(checked.counts.mergedPoints, 0u);
  EXPECT_EQ(checked.orientation.reorientedTriangles, 0u);
  EXPECT_EQ(checked.orientation.invertedShells, 0u);
  std::printf("%s: %d solids, %d faces (%zu with triangles), %zu points, %zu triangles, volume %g, "
              "deflection %g\n",
    path.c_str(), r.solids, r.faces, used.size(), r.surface.points.size(), r.surface.triangles.size(),
    checked.enclosedVolume, r.linearDeflection);
}

TEST(CADTessellation, StepScrewIsClosed)
{
  REQUIRE_FILE(kData + "step/screw.step");
  expectClosedWithFaces(kData + "step/screw.step", 10);
}

TEST(CADTessellation, BrepPumpNutIsClosed)
{
  REQUIRE_FILE(kData + "occ/Pump_Nut.brep");
  expectClosedWithFaces(kData + "occ/Pump_Nut.brep", 10);
}

TEST(CADTessellation, IgesHammerFacesAreSewnIntoSolids)
{
  // hammer.iges holds trimmed faces and no solid: they are sewn, with a warning
  REQUIRE_FILE(kData + "iges/hammer.iges");
  expectClosedWithFaces(kData + "iges/hammer.iges", 10, 1);
}

TEST(CADTessellation, IgesBearingDoesNotClose)
{
  // bearing.iges: faces that leave open shells (the corpus's 3758 boundary edges)
  REQUIRE_FILE(kData + "iges/bearing.iges");
  const CADSurface r = readCADSurface(kData + "iges/bearing.iges", CADReadOptions());
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("213 faces do not sew into a closed shell"), std::string::npos) << r.error;
}

TEST(CADTessellation, BrepOfOneOpenFaceSaysSo)
{
  // MAT.brep: a single face and no solid
  REQUIRE_FILE(kData + "occ/MAT.brep");
  const CADSurface r = readCADSurface(kData + "occ/MAT.brep", CADReadOptions());
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("its one face does not close into a shell"), std::string::npos) << r.error;
}

TEST(CADTessellation, FinerDeflectionGivesMoreTriangles)
{
  REQUIRE_FILE(kData + "step/screw.step");
  CADReadOptions fine;
  fine.relativeLinearDeflection = 2e-4;
  const CADSurface coarse = readCADSurface(kData + "step/screw.step", CADReadOptions());
  const CADSurface dense = readCADSurface(kData + "step/screw.step", fine);
  ASSERT_TRUE(coarse.ok && dense.ok);
  EXPECT_GT(dense.surface.triangles.size(), coarse.surface.triangles.size());
  EXPECT_NEAR(dense.linearDeflection, coarse.linearDeflection / 5, 1e-9 * coarse.linearDeflection);
}

TEST(CADTessellation, RefusesWithTheProblemNamed)
{
  CADSurface r = readCADSurface("/nonexistent/part.step", CADReadOptions());
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("cannot open"), std::string::npos) << r.error;

  const std::string garbage = testing::TempDir() + "garbage.step";
  std::ofstream(garbage) << "this is not ISO-10303-21\n";
  r = readCADSurface(garbage, CADReadOptions());
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("cannot read it as a STEP file"), std::string::npos) << r.error;

  const std::string text = testing::TempDir() + "part.txt";
  std::ofstream(text) << "x\n";
  r = readCADSurface(text, CADReadOptions());
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("unknown CAD extension 'txt'"), std::string::npos) << r.error;

  REQUIRE_FILE(kData + "occ/face.brep");
  r = readCADSurface(kData + "occ/face.brep", CADReadOptions());
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("no solid"), std::string::npos) << r.error;

  REQUIRE_FILE(kData + "occ/asahi.brep"); // curves, no faces
  r = readCADSurface(kData + "occ/asahi.brep", CADReadOptions());
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("no faces either"), std::string::npos) << r.error;

  CADReadOptions beyond;
  beyond.solid = 7;
  r = readCADSurface(kData + "occ/Pump_Nut.brep", beyond);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("solid 7 does not exist"), std::string::npos) << r.error;
}
TEST(CADTessellation, RefusesASolidWithAnOpenShell)
{
  // a box whose shell lacks its last face, written as a BREP solid
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(1.0, 2.0, 3.0).Shape();
  BRep_Builder builder;
  TopoDS_Shell shell;
  builder.MakeShell(shell);
  int faces = 0;
  for (TopExp_Explorer e(box, TopAbs_FACE); e.More(); e.Next())
  {
    if (++faces < 6)
    {
      builder.Add(shell, e.Current());
    }
  }
  TopoDS_Solid solid;
  builder.MakeSolid(solid);
  builder.Add(solid, shell);
  const std::string path = testing::TempDir() + "open_box.brep";
  ASSERT_TRUE(BRepTools::Write(solid, path.c_str()));
  const CADSurface r = readCADSurface(path, CADReadOptions());
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("solid 0 has an open shell"), std::string::npos) << r.error;

  // the whole box is read, closed
  const std::string closed = testing::TempDir() + "box.brep";
  ASSERT_TRUE(BRepTools::Write(box, closed.c_str()));
  const CADSurface good = readCADSurface(closed, CADReadOptions());
  ASSERT_TRUE(good.ok) << good.error;
  EXPECT_EQ(good.surface.triangles.size(), 12u);
  const PreparedSurface checked = prepareInputSurface(good.surface, InputCheckOptions());
  ASSERT_TRUE(checked.ok) << checked.error;
  EXPECT_NEAR(checked.enclosedVolume, 6.0, 1e-12);
}
} // namespace

namespace
{
using namespace ptm;

TEST(CADTessellation, ChoosesOneSolidOrTakesAll)
{
  // the bearing axis: solids that share faces; all of them together are
  // non-manifold (a warning), each one alone is a closed solid
  const std::string path = kData + "occ/Axis_of_bearing.brep";
  REQUIRE_FILE(path);
  const CADSurface all = readCADSurface(path, CADReadOptions());
  ASSERT_TRUE(all.ok) << all.error;
  ASSERT_GT(all.solids, 1);
  // solid 14 of its 18 has no shell at all
  ASSERT_EQ(all.warnings.size(), 2u);
  EXPECT_NE(all.warnings[0].find("left out 1 empty solids (no faces), e.g. solid 14"), std::string::npos)
    << all.warnings[0];
  EXPECT_NE(all.warnings[1].find("not shared by exactly two triangles"), std::string::npos) << all.warnings[1];
  std::size_t triangles = 0;
  for (int s = 0; s < all.solids; ++s)
  {
    CADReadOptions one;
    one.solid = s;
    const CADSurface r = readCADSurface(path, one);
    if (s == 14)
    {
      EXPECT_FALSE(r.ok);
      EXPECT_NE(r.error.find("solid 14 is empty (no faces)"), std::string::npos) << r.error;
      continue;
    }
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_TRUE(r.warnings.empty()) << "solid " << s << ": " << r.warnings.front();
    const PreparedSurface checked = prepareInputSurface(r.surface, InputCheckOptions());
    EXPECT_TRUE(checked.ok) << "solid " << s << ": " << checked.error;
    // face ids index the whole file's face map, whichever solid is read
    EXPECT_LT(*std::max_element(r.faceId.begin(), r.faceId.end()), all.faces);
    triangles += r.surface.triangles.size();
  }
  std::printf("%s: %d solids, %zu triangles together, %zu one by one\n", path.c_str(), all.solids,
    all.surface.triangles.size(), triangles);
  EXPECT_EQ(triangles, all.surface.triangles.size());
}
} // namespace
