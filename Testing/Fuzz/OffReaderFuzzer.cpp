// Fuzz target for the OFF parser (OffFormat.h): any bytes at all.
//
// Contract: no crash, hang, sanitizer report or exception (readOff promises
// not to throw for malformed input); the result is either an error message or
// a surface. An accepted surface must be well formed (indices in range, no
// repeated corner, finite coordinates, one source polygon per triangle) and
// must come back unchanged through writeOff and readOff: writeOff prints
// round-trip precision, so any difference is a parser or writer bug.
#include "FuzzCheck.h"

#include "OffFormat.h"

#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>

using namespace ptm;

namespace
{
void checkSurface(const OffReadResult& r)
{
  const TriangleSurface& s = r.data.surface;
  const Index n = static_cast<Index>(s.points.size());
  PTM_FUZZ_CHECK(r.error.empty(), "accepted with the error '" << r.error << "'");
  PTM_FUZZ_CHECK(n > 0 && !s.triangles.empty(), n << " points, " << s.triangles.size() << " triangles");
  PTM_FUZZ_CHECK(r.data.sourcePolygon.size() == s.triangles.size(),
    r.data.sourcePolygon.size() << " source polygons for " << s.triangles.size() << " triangles");
  PTM_FUZZ_CHECK(r.data.polygonCount > 0 && r.data.polygonCount <= s.triangles.size(),
    r.data.polygonCount << " polygons, " << s.triangles.size() << " triangles");
  for (const Vec3& p : s.points)
  {
    PTM_FUZZ_CHECK(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]), "a non-finite point");
  }
  Index previousSource = 0;
  for (std::size_t i = 0; i < s.triangles.size(); ++i)
  {
    const Triangle& t = s.triangles[i];
    for (Index v : t)
    {
      PTM_FUZZ_CHECK(v >= 0 && v < n, "triangle " << i << " refers to point " << v << " of " << n);
    }
    PTM_FUZZ_CHECK(t[0] != t[1] && t[1] != t[2] && t[2] != t[0], "triangle " << i << " repeats a corner");
    const Index source = r.data.sourcePolygon[i];
    PTM_FUZZ_CHECK(source >= previousSource &&
        source < static_cast<Index>(r.data.polygonCount),
      "triangle " << i << " comes from polygon " << source);
    previousSource = source;
  }
}

void checkRoundTrip(const TriangleSurface& s)
{
  std::stringstream text;
  writeOff(text, s, "round trip\nof a fuzz input");
  const OffReadResult back = readOff(text);
  PTM_FUZZ_CHECK(back.ok, "the written surface does not read back: " << back.error);
  PTM_FUZZ_CHECK(back.data.surface.triangles == s.triangles, "triangles changed in the round trip");
  PTM_FUZZ_CHECK(back.data.surface.points.size() == s.points.size(), "point count changed");
  for (std::size_t i = 0; i < s.points.size(); ++i)
  {
    const Vec3 &a = s.points[i], &b = back.data.surface.points[i];
    // bitwise, so that -0 stays -0 and no digit is lost
    PTM_FUZZ_CHECK(a == b && std::signbit(a[0]) == std::signbit(b[0]) &&
        std::signbit(a[1]) == std::signbit(b[1]) && std::signbit(a[2]) == std::signbit(b[2]),
      "point " << i << " changed in the round trip");
  }
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  const OffReadResult r = readOff(in);
  if (!r.ok)
  {
    PTM_FUZZ_CHECK(!r.error.empty(), "refused without a message");
    return 0;
  }
  checkSurface(r);
  checkRoundTrip(r.data.surface);
  return 0;
}
