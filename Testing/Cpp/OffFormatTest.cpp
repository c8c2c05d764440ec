#include "OffFormat.h"
#include "TestSurfaces.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

using namespace ptm;

namespace
{
OffReadResult parse(const std::string& text)
{
  std::istringstream in(text);
  return readOff(in);
}

const char* const kCubeWithQuads = R"(OFF
# a unit cube with quad faces
8 6 12

0 0 0
1 0 0
1 1 0
0 1 0
0 0 1
1 0 1
1 1 1
0 1 1
4 0 3 2 1
4 4 5 6 7   # top
4 0 1 5 4
4 1 2 6 5
4 2 3 7 6
4 3 0 4 7
)";

void expectError(const std::string& text, const std::string& fragment)
{
  const OffReadResult r = parse(text);
  EXPECT_FALSE(r.ok) << "accepted: " << text;
  EXPECT_NE(r.error.find(fragment), std::string::npos) << "message: " << r.error;
}
} // namespace

TEST(OffFormat, ReadsQuadsCommentsAndBlankLines)
{
  const OffReadResult r = parse(kCubeWithQuads);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.data.surface.points.size(), 8u);
  EXPECT_EQ(r.data.surface.triangles.size(), 12u);
  EXPECT_EQ(r.data.polygonCount, 6u);
  ASSERT_EQ(r.data.sourcePolygon.size(), 12u);
  EXPECT_EQ(r.data.sourcePolygon[0], 0);
  EXPECT_EQ(r.data.sourcePolygon[11], 5);
  EXPECT_NEAR(test::signedVolume(r.data.surface), 1.0, 1e-15);
}

TEST(OffFormat, CountsOnTheHeaderLineAndColours)
{
  const OffReadResult r = parse("COFF 4 4 6\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n"
                                "0 1 0 0 0 255 255\n0 0 1 9 9 9 255\n"
                                "3 0 2 1 0.5 0.5 0.5\n3 0 1 3\n3 0 3 2 1 1 1 1\n3 1 2 3\n");
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.data.surface.points.size(), 4u);
  EXPECT_EQ(r.data.surface.triangles.size(), 4u);
  EXPECT_NEAR(test::signedVolume(r.data.surface), 1.0 / 6.0, 1e-15);
}

TEST(OffFormat, NonConvexPolygonIsTriangulatedInside)
{
  // an L-shaped hexagon (area 3) in the plane z = 2, and a pentagon
  const OffReadResult r = parse("OFF\n11 2 0\n0 0 2\n2 0 2\n2 1 2\n1 1 2\n1 2 2\n0 2 2\n"
                                "0 0 0\n1 0 0\n1.5 0.8 0\n0.5 1.5 0\n-0.5 0.8 0\n"
                                "6 0 1 2 3 4 5\n5 6 7 8 9 10\n");
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_EQ(r.data.surface.triangles.size(), 4u + 3u);
  double area = 0;
  for (int t = 0; t < 4; ++t)
  {
    const auto& tri = r.data.surface.triangles[t];
    const auto& p = r.data.surface.points;
    const Vec3 n = cross(p[tri[1]] - p[tri[0]], p[tri[2]] - p[tri[0]]);
    EXPECT_GT(n[2], 0) << "triangle " << t << " flipped or degenerate";
    area += 0.5 * n[2];
  }
  EXPECT_NEAR(area, 3.0, 1e-14);
}

TEST(OffFormat, EveryMalformedCaseNamesTheProblem)
{
  expectError("", "empty");
  expectError("# only a comment\n\n", "empty");
  expectError("PLY\n3 1 0\n", "OFF header");
  expectError("OFF\n", "ends after the header");
  expectError("OFF\nthree 1 0\n", "counts");
  expectError("OFF\n0 0 0\n", "no surface");
  expectError("OFF\n4 1 0\n0 0 0\n1 0 0\n", "expected 4 vertices but the file ends after 2");
  expectError("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "expected 2 faces but the file ends after 1");
  expectError("OFF\n3 1 0\n0 0 0\n1 abc 0\n0 1 0\n3 0 1 2\n", "line 4: vertex 1 has a non-numeric coordinate 'abc'");
  expectError("OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", "vertex 1 has a NaN coordinate");
  expectError("OFF\n3 1 0\n0 0 0\n1 inf 0\n0 1 0\n3 0 1 2\n", "infinite");
  expectError("OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n", "fewer than 3 coordinates");
  expectError("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", "refers to vertex 7, but there are only 3 vertices");
  expectError("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n", "refers to vertex -1");
  expectError("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", "at least 3");
  expectError("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n", "announces 4 corners but lists 3");
  expectError("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1\n", "repeats vertex 1");
  expectError("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1.5 2\n", "non-integer corner");
  expectError("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 red\n", "non-numeric value 'red'");
  expectError("OFF\n4 1 0\n0 0 0\n1 0 0\n2 0 0\n3 0 0\n4 0 1 2 3\n", "degenerate");
  expectError("OFF BINARY\n", "binary");
}

TEST(OffFormat, FileErrorsNameTheFile)
{
  const OffReadResult missing = readOffFile("/nonexistent/dir/x.off");
  EXPECT_FALSE(missing.ok);
  EXPECT_NE(missing.error.find("/nonexistent/dir/x.off"), std::string::npos);
  const std::string path = ::testing::TempDir() + "truncated.off";
  {
    std::ofstream out(path);
    out << "OFF\n8 6 12\n0 0 0\n1 0 0\n";
  }
  const OffReadResult truncated = readOffFile(path);
  EXPECT_FALSE(truncated.ok);
  EXPECT_NE(truncated.error.find(path + ": expected 8 vertices"), std::string::npos)
    << truncated.error;
  std::remove(path.c_str());
}
