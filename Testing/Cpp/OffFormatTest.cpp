// The OFF parser: every accepted variant, polygon triangulation, every
// malformed case with its message, the file-level errors, and round trips.
#include "OffFormat.h"
#include "TestSurfaces.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <utility>

using namespace ptm;

namespace
{
OffReadResult parse(const std::string& text)
{
  std::istringstream in(text);
  return readOff(in);
}

// The cube's 8 corners, then the faces given.
std::string cube(const std::string& header, const std::string& faces)
{
  return header + "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n" + faces;
}

const std::string kCubeQuads = "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";

// Every edge is used exactly twice, once in each direction: closed, manifold
// and consistently oriented.
void expectClosedOriented(const TriangleSurface& s)
{
  std::map<std::pair<Index, Index>, int> directed;
  for (const Triangle& t : s.triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      ++directed[{ t[k], t[(k + 1) % 3] }];
    }
  }
  for (const auto& [edge, count] : directed)
  {
    EXPECT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second << " used " << count << " times";
    EXPECT_EQ(directed.count({ edge.second, edge.first }), 1u)
      << "edge " << edge.first << "-" << edge.second << " has no opposite";
  }
}

// Sum of the triangles' vector areas (equals the polygon's for a correct
// triangulation) and whether every triangle points along +normal.
double areaAlong(const TriangleSurface& s, std::size_t from, std::size_t to, const Vec3& normal,
  bool& allPositive)
{
  double area = 0;
  allPositive = true;
  for (std::size_t t = from; t < to; ++t)
  {
    const auto& tri = s.triangles[t];
    const auto& p = s.points;
    const double a = 0.5 * dot(cross(p[tri[1]] - p[tri[0]], p[tri[2]] - p[tri[0]]), normal);
    allPositive = allPositive && a > 0;
    area += a;
  }
  return area;
}
} // namespace

// ---------------------------------------------------------------- accepted

TEST(OffFormat, ReadsQuadsCommentsAndBlankLines)
{
  const OffReadResult r = parse("# leading comment\n\nOFF # the header\n# between\n8 6 12\n\n" +
    cube("", "") + "  # comment line with indentation\n" + kCubeQuads);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.data.surface.points.size(), 8u);
  EXPECT_EQ(r.data.surface.triangles.size(), 12u);
  EXPECT_EQ(r.data.polygonCount, 6u);
  ASSERT_EQ(r.data.sourcePolygon.size(), 12u);
  for (std::size_t t = 0; t < 12; ++t)
  {
    EXPECT_EQ(r.data.sourcePolygon[t], static_cast<Index>(t / 2)) << "triangle " << t;
  }
  EXPECT_NEAR(test::signedVolume(r.data.surface), 1.0, 1e-15);
  expectClosedOriented(r.data.surface);
}

TEST(OffFormat, CountsOnTheHeaderLineWithoutEdgeCount)
{
  const OffReadResult r = parse(cube("OFF 8 6\n", kCubeQuads));
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.data.surface.triangles.size(), 12u);
}

TEST(OffFormat, CrLfTabsAndPlusSigns)
{
  const OffReadResult r =
    parse("OFF\r\n3 1 0\r\n+0\t0 0\r\n1 0 0\r\n0 1.5e0 -0\r\n3\t0 1 2\r\n");
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.data.surface.points[2][1], 1.5);
}

TEST(OffFormat, UnderflowReadsAsZero)
{
  const OffReadResult r = parse("OFF\n3 1\n1e-999 -1e-400 0\n1 0 0\n0 1 4.9e-324\n3 0 1 2\n");
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.data.surface.points[0], (Vec3{ 0, 0, 0 }));
  EXPECT_GT(r.data.surface.points[2][2], 0);
}

TEST(OffFormat, VertexAndFaceColours)
{
  // COFF: RGBA per vertex; faces with no colour, RGB floats, RGBA ints, a colour-map index
  const OffReadResult r = parse("COFF 4 4 6\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n"
                                "0 1 0 0 0 255 255\n0 0 1 9 9 9 255\n"
                                "3 0 2 1 0.5 0.5 0.5\n3 0 1 3\n3 0 3 2 1 1 1 1\n3 1 2 3 7\n");
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.data.surface.points.size(), 4u);
  EXPECT_EQ(r.data.surface.triangles.size(), 4u);
  EXPECT_EQ(r.data.surface.points[3][2], 1.0);
  EXPECT_NEAR(test::signedVolume(r.data.surface), 1.0 / 6.0, 1e-15);
  expectClosedOriented(r.data.surface);
}

TEST(OffFormat, HeaderVariantsIgnoreExtraVertexValues)
{
  const std::string faces = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  const std::map<std::string, std::string> variants{
    { "NOFF", "0 0 0 0 0 1\n1 0 0 1 0 0\n0 1 0 0 1 0\n0 0 1 0 0 1\n" },
    { "CNOFF", "0 0 0 0 0 1 1 0 0 1\n1 0 0 1 0 0 1 0 0 1\n0 1 0 0 1 0 1 0 0 1\n0 0 1 0 0 1 1 0 0 1\n" },
    { "STOFF", "0 0 0 0.1 0.2\n1 0 0 0.3 0.4\n0 1 0 0.5 0.6\n0 0 1 0.7 0.8\n" },
    { "OFF", "0 0 0\n1 0 0\n0 1 0\n0 0 1\n" },
  };
  for (const auto& [header, vertices] : variants)
  {
    const OffReadResult r = parse(header + "\n4 4 6\n" + vertices + faces);
    ASSERT_TRUE(r.ok) << header << ": " << r.error;
    EXPECT_EQ(r.data.surface.points[1], (Vec3{ 1, 0, 0 })) << header;
    EXPECT_NEAR(test::signedVolume(r.data.surface), 1.0 / 6.0, 1e-15) << header;
  }
}

TEST(OffFormat, ConvexPentagonBecomesThreeTriangles)
{
  // a regular pentagon in the tilted plane x + y + z = 1, counter-clockwise about (1,1,1)
  const Vec3 n = normalized({ 1, 1, 1 });
  Vec3 e1, e2;
  planeBasis(n, e1, e2);
  std::ostringstream text;
  text << "OFF\n5 1 0\n";
  text.precision(17);
  for (int k = 0; k < 5; ++k)
  {
    const double a = 2 * kPi * k / 5;
    const Vec3 p = (1.0 / 3.0) * Vec3{ 1, 1, 1 } + std::cos(a) * e1 + std::sin(a) * e2;
    text << p[0] << " " << p[1] << " " << p[2] << "\n";
  }
  text << "5 0 1 2 3 4 0.2 0.3 0.4\n";
  const OffReadResult r = parse(text.str());
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_EQ(r.data.surface.triangles.size(), 3u);
  bool positive = false;
  const double area = areaAlong(r.data.surface, 0, 3, n, positive);
  EXPECT_TRUE(positive);
  EXPECT_NEAR(area, 2.5 * std::sin(2 * kPi / 5), 1e-13);
  EXPECT_EQ(r.data.sourcePolygon, (std::vector<Index>{ 0, 0, 0 }));
}

TEST(OffFormat, NonConvexPolygonsAreTriangulatedInside)
{
  // An L-shaped hexagon (area 3) in z = 2 facing +z, and a comb with three
  // teeth (area 11) in x = 1 facing -x (its (u, v) = (z, y)) that starts at
  // a reflex corner: a fan from the first corner would leave the polygon.
  const std::vector<std::array<double, 2>> comb{ { 4, 1 }, { 3, 1 }, { 3, 3 }, { 2, 3 }, { 2, 1 },
    { 1, 1 }, { 1, 3 }, { 0, 3 }, { 0, 0 }, { 5, 0 }, { 5, 3 }, { 4, 3 } };
  std::ostringstream text;
  text << "OFF\n18 2 0\n0 0 2\n2 0 2\n2 1 2\n1 1 2\n1 2 2\n0 2 2\n";
  for (const auto& uv : comb)
  {
    text << "1 " << uv[1] << " " << uv[0] << "\n";
  }
  text << "6 0 1 2 3 4 5\n12 6 7 8 9 10 11 12 13 14 15 16 17\n";
  const OffReadResult r = parse(text.str());
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_EQ(r.data.surface.triangles.size(), 4u + 10u);
  bool positive = false;
  EXPECT_NEAR(areaAlong(r.data.surface, 0, 4, { 0, 0, 1 }, positive), 3.0, 1e-14);
  EXPECT_TRUE(positive) << "a triangle of the L is flipped or degenerate";
  EXPECT_NEAR(areaAlong(r.data.surface, 4, 14, { -1, 0, 0 }, positive), 11.0, 1e-14);
  EXPECT_TRUE(positive) << "a triangle of the comb is flipped or degenerate";
  for (std::size_t t = 0; t < 14; ++t)
  {
    EXPECT_EQ(r.data.sourcePolygon[t], t < 4 ? 0 : 1);
  }
}

TEST(OffFormat, PolygonWithCollinearCornersHasNoDegenerateTriangle)
{
  // a square with a corner in the middle of every edge
  const OffReadResult r = parse("OFF\n8 1 0\n0 0 0\n1 0 0\n2 0 0\n2 1 0\n2 2 0\n1 2 0\n0 2 0\n0 1 0\n"
                                "8 0 1 2 3 4 5 6 7\n");
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_EQ(r.data.surface.triangles.size(), 6u);
  bool positive = false;
  EXPECT_NEAR(areaAlong(r.data.surface, 0, 6, { 0, 0, 1 }, positive), 4.0, 1e-14);
  EXPECT_TRUE(positive);
}

TEST(OffFormat, TriangulatePolygonRejectsSelfIntersectionAndZeroArea)
{
  const std::vector<Vec3> points{ { 0, 0, 0 }, { 1, 1, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 2, 2, 0 } };
  std::vector<Triangle> out;
  EXPECT_FALSE(triangulatePolygon(points, { 0, 1, 2, 3 }, out)); // bow tie: zero net area
  EXPECT_FALSE(triangulatePolygon(points, { 0, 1, 4 }, out));    // collinear
  EXPECT_TRUE(out.empty());
  EXPECT_TRUE(triangulatePolygon(points, { 0, 2, 1, 3 }, out));
  EXPECT_EQ(out.size(), 2u);
}

// ---------------------------------------------------------------- malformed

struct MalformedCase
{
  const char* name;
  std::string text;
  std::string message; // a fragment the error must contain
};

class MalformedOff : public ::testing::TestWithParam<MalformedCase>
{
};

TEST_P(MalformedOff, IsAnErrorThatSaysWhatIsWrong)
{
  const MalformedCase& c = GetParam();
  const OffReadResult r = parse(c.text);
  EXPECT_FALSE(r.ok) << "accepted:\n" << c.text;
  EXPECT_NE(r.error.find(c.message), std::string::npos)
    << "expected '" << c.message << "' in: " << r.error;
  EXPECT_TRUE(r.data.surface.points.empty());
  EXPECT_TRUE(r.data.surface.triangles.empty());
  EXPECT_TRUE(r.data.sourcePolygon.empty());
}

const std::string kTet = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
const std::string kTetFaces = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

INSTANTIATE_TEST_SUITE_P(OffFormat, MalformedOff,
  ::testing::Values(
    MalformedCase{ "Empty", "", "the file is empty" },
    MalformedCase{ "OnlyCommentsAndBlankLines", "# nothing\n\n   \n# here\n", "the file is empty" },
    MalformedCase{ "NotOff", "ply\nformat ascii 1.0\n", "line 1: expected the header OFF" },
    MalformedCase{ "FourDimensional", "4OFF\n1 1 0\n", "line 1: the header '4OFF' is not supported" },
    MalformedCase{ "Binary", "OFF BINARY\n", "binary OFF files are not supported" },
    MalformedCase{ "NoCounts", "OFF\n# the end\n", "the file ends after the header" },
    MalformedCase{ "OneCount", "OFF\n4\n" + kTet, "line 2: expected the counts 'vertices faces [edges]' but found 1 value" },
    MalformedCase{ "NonNumericCount", "OFF\nfour 4 6\n" + kTet, "line 2: the vertex count 'four' is not a whole number" },
    MalformedCase{ "FractionalCount", "OFF 4 4.5 6\n" + kTet, "line 1: the face count '4.5' is not a whole number" },
    MalformedCase{ "NegativeCount", "OFF\n-4 4 6\n" + kTet, "line 2: the vertex count is negative (-4)" },
    MalformedCase{ "HugeCount", "OFF\n99999999999999999999 4 6\n", "the vertex count '99999999999999999999' is too large" },
    MalformedCase{ "ZeroVertices", "OFF\n0 0 0\n", "line 2: header says 0 vertices" },
    MalformedCase{ "ZeroFaces", "OFF\n4 0 0\n" + kTet, "line 2: header says 0 faces" },
    MalformedCase{ "TruncatedVertices", "OFF\n8 6 12\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n",
      "expected 8 vertices but the file ends after 5 (line 2 says 8 vertices and 6 faces)" },
    MalformedCase{ "TruncatedFaces", "OFF\n4 4 6\n" + kTet + "3 0 2 1\n3 0 1 3\n",
      "expected 4 faces but the file ends after 2" },
    MalformedCase{ "TooFewVerticesInHeader", "OFF\n3 4 6\n" + kTet + kTetFaces,
      "line 6: face 0 has 0 corners; a face needs at least 3 (line 2 says 3 vertices and 4 faces)" },
    MalformedCase{ "VertexLineReadAsFace", "OFF\n3 4 6\n0 0 0\n1 0 0\n0 1 0\n0.5 0.5 1\n" + kTetFaces,
      "line 6: face 0 does not start with its number of corners (found '0.5')" },
    MalformedCase{ "TooFewFacesInHeader", "OFF\n4 3 6\n" + kTet + kTetFaces,
      "line 10: unexpected data after the last face; the file has more vertices or faces than its header says (line 2 says 4 vertices and 3 faces)" },
    MalformedCase{ "NonNumericCoordinate", "OFF\n4 4 6\n0 0 0\n1 abc 0\n0 1 0\n0 0 1\n" + kTetFaces,
      "line 4: vertex 1 has a non-numeric coordinate 'abc'" },
    MalformedCase{ "CoordinateWithTrailingGarbage", "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1x\n" + kTetFaces,
      "line 6: vertex 3 has a non-numeric coordinate '1x'" },
    MalformedCase{ "CommaDecimal", "OFF\n4 4 6\n0 0 0\n1,5 0 0\n0 1 0\n0 0 1\n" + kTetFaces,
      "vertex 1 has a non-numeric coordinate '1,5'" },
    MalformedCase{ "NaNCoordinate", "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 nan\n" + kTetFaces,
      "line 6: vertex 3 has a NaN coordinate" },
    MalformedCase{ "InfiniteCoordinate", "OFF\n4 4 6\n0 0 0\n-inf 0 0\n0 1 0\n0 0 1\n" + kTetFaces,
      "line 4: vertex 1 has an infinite coordinate" },
    MalformedCase{ "OverflowingCoordinate", "OFF\n4 4 6\n0 0 0\n1e999 0 0\n0 1 0\n0 0 1\n" + kTetFaces,
      "vertex 1 has a coordinate '1e999' out of the range" },
    MalformedCase{ "TwoCoordinates", "OFF\n4 4 6\n0 0 0\n1 0\n0 1 0\n0 0 1\n" + kTetFaces,
      "line 4: vertex 1 has 2 coordinates, expected 3" },
    MalformedCase{ "IndexOutOfRange", "OFF\n4 4 6\n" + kTet + "3 0 2 1\n3 0 1 3\n3 0 12 2\n3 1 2 3\n",
      "line 9: face 2 refers to vertex 12, but there are only 4 vertices" },
    MalformedCase{ "NegativeIndex", "OFF\n4 4 6\n" + kTet + "3 0 2 -1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n",
      "face 0 refers to vertex -1" },
    MalformedCase{ "FractionalIndex", "OFF\n4 4 6\n" + kTet + "3 0 2 1.5\n3 0 1 3\n3 0 3 2\n3 1 2 3\n",
      "face 0 has a vertex index '1.5' that is not a whole number" },
    MalformedCase{ "TwoCorners", "OFF\n4 4 6\n" + kTet + "2 0 2\n3 0 1 3\n3 0 3 2\n3 1 2 3\n",
      "line 7: face 0 has 2 corners; a face needs at least 3" },
    MalformedCase{ "FewerIndicesThanAnnounced", "OFF\n4 4 6\n" + kTet + "3 0 2 1\n4 0 1 3\n3 0 3 2\n3 1 2 3\n",
      "line 8: face 1 announces 4 corners but lists 3 values" },
    MalformedCase{ "MoreIndicesThanAnnounced", "OFF\n8 1 0\n" + kTet + kTet + "3 0 1 2 3 4 5 6 7\n",
      "face 0 announces 3 corners but has 8 values" },
    MalformedCase{ "RepeatedVertex", "OFF\n4 4 6\n" + kTet + "3 0 2 1\n3 0 1 1\n3 0 3 2\n3 1 2 3\n",
      "line 8: face 1 uses vertex 1 twice" },
    MalformedCase{ "NonNumericColour", "OFF\n4 4 6\n" + kTet + "3 0 2 1 red\n3 0 1 3\n3 0 3 2\n3 1 2 3\n",
      "face 0 has a non-numeric colour value 'red'" },
    MalformedCase{ "ZeroAreaPolygon", "OFF\n4 1 0\n0 0 0\n1 0 0\n2 0 0\n3 0 0\n4 0 1 2 3\n",
      "line 7: face 0 is a polygon of 4 corners with zero area or crossing edges" },
    MalformedCase{ "SelfIntersectingPolygon", "OFF\n5 1 0\n0 0 0\n2 2 0\n2 0 0\n0 2 0\n0 1 0\n5 0 1 2 3 4\n",
      "face 0 is a polygon of 5 corners with zero area or crossing edges" }),
  [](const ::testing::TestParamInfo<MalformedCase>& info) { return std::string(info.param.name); });

// ---------------------------------------------------------------- files

TEST(OffFormat, FileErrorsNameTheFile)
{
  const OffReadResult missing = readOffFile("/nonexistent/dir/x.off");
  EXPECT_FALSE(missing.ok);
  EXPECT_NE(missing.error.find("/nonexistent/dir/x.off: cannot open the file (No such file"),
    std::string::npos)
    << missing.error;

  const OffReadResult directory = readOffFile(::testing::TempDir());
  EXPECT_FALSE(directory.ok);
  EXPECT_NE(directory.error.find("is a directory"), std::string::npos) << directory.error;

  const std::string path = ::testing::TempDir() + "ptm_truncated.off";
  {
    std::ofstream out(path);
    out << "OFF\n8 6 12\n0 0 0\n1 0 0\n";
  }
  const OffReadResult truncated = readOffFile(path);
  EXPECT_FALSE(truncated.ok);
  EXPECT_NE(truncated.error.find(path + ": expected 8 vertices but the file ends after 2"),
    std::string::npos)
    << truncated.error;

  {
    std::ofstream out(path, std::ios::trunc);
  }
  const OffReadResult empty = readOffFile(path);
  EXPECT_FALSE(empty.ok);
  EXPECT_EQ(empty.error, path + ": the file is empty");
  std::remove(path.c_str());
}

TEST(OffFormat, RoundTripKeepsCountsAndCoordinates)
{
  for (const auto& named : { test::NamedSurface{ "ball", test::icosphere({ 0.1, -0.2, 0.3 }, 1.0, 3) },
         test::NamedSurface{ "box", test::subdividedBox({ 0, 0, 0 }, { 2, 1, 1 }, 4) },
         test::NamedSurface{ "torus", test::torus({ 0, 0, 0 }, 2.0, 0.7, 24, 12) } })
  {
    std::stringstream text;
    writeOff(text, named.surface, "round trip of " + named.name);
    const OffReadResult r = readOff(text);
    ASSERT_TRUE(r.ok) << named.name << ": " << r.error;
    EXPECT_EQ(r.data.surface.points, named.surface.points) << named.name;
    EXPECT_EQ(r.data.surface.triangles, named.surface.triangles) << named.name;
    EXPECT_EQ(r.data.polygonCount, named.surface.triangles.size());
    // and once more: the text is a fixed point
    std::stringstream again;
    writeOff(again, r.data.surface, "round trip of " + named.name);
    EXPECT_EQ(again.str(), text.str());
  }
}

TEST(OffFormat, BundledSurfacesAreClosedAndOriented)
{
  // counts from the files' headers; the quads of cube.off give 12 triangles
  const struct
  {
    const char* file;
    std::size_t points, triangles, polygons;
  } files[] = { { "cube.off", 8, 12, 6 }, { "ball.off", 1136, 2268, 2268 },
    { "bracket.off", 2483, 4970, 4970 }, { "two_bodies.off", 2076, 4144, 4144 } };
  for (const auto& f : files)
  {
    const OffReadResult r = readOffFile(std::string(PTM_DATA_DIR) + "/" + f.file);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.data.surface.points.size(), f.points) << f.file;
    EXPECT_EQ(r.data.surface.triangles.size(), f.triangles) << f.file;
    EXPECT_EQ(r.data.polygonCount, f.polygons) << f.file;
    expectClosedOriented(r.data.surface);
    EXPECT_GT(test::signedVolume(r.data.surface), 0) << f.file << " is not outward oriented";
  }
}
