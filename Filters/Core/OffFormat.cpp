#include "OffFormat.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>

namespace ptm
{
namespace
{
// Splits the stream into lines, dropping comments and blank lines, and keeps
// the line numbers for messages.
class OffLines
{
public:
  explicit OffLines(std::istream& in)
    : In(in)
  {
  }

  // The next non-blank line's words; false at the end.
  bool next(std::vector<std::string>& words)
  {
    std::string line;
    while (std::getline(this->In, line))
    {
      ++this->Number;
      const std::size_t hash = line.find('#');
      if (hash != std::string::npos)
      {
        line.erase(hash);
      }
      std::istringstream split(line);
      words.clear();
      std::string word;
      while (split >> word)
      {
        words.push_back(word);
      }
      if (!words.empty())
      {
        return true;
      }
    }
    return false;
  }

  int number() const { return this->Number; }

private:
  std::istream& In;
  int Number = 0;
};

bool parseDouble(const std::string& word, double& value)
{
  const char* begin = word.c_str();
  char* end = nullptr;
  errno = 0;
  value = std::strtod(begin, &end);
  return end != begin && *end == '\0';
}

bool parseIndex(const std::string& word, long long& value)
{
  const char* begin = word.c_str();
  char* end = nullptr;
  errno = 0;
  value = std::strtoll(begin, &end, 10);
  return end != begin && *end == '\0' && errno == 0;
}

std::string at(int line)
{
  return "line " + std::to_string(line) + ": ";
}
} // namespace

bool triangulatePolygon(
  const std::vector<Vec3>& points, const std::vector<Index>& corners, std::vector<Triangle>& out)
{
  const std::size_t n = corners.size();
  Vec3 normal{ 0, 0, 0 };
  for (std::size_t i = 0; i < n; ++i)
  {
    const Vec3& a = points[corners[i]];
    const Vec3& b = points[corners[(i + 1) % n]];
    normal = normal + Vec3{ (a[1] - b[1]) * (a[2] + b[2]), (a[2] - b[2]) * (a[0] + b[0]),
                        (a[0] - b[0]) * (a[1] + b[1]) };
  }
  if (!(norm(normal) > 0))
  {
    return false;
  }
  // 2D coordinates in the plane of the normal
  const int drop = std::fabs(normal[0]) >= std::fabs(normal[1])
    ? (std::fabs(normal[0]) >= std::fabs(normal[2]) ? 0 : 2)
    : (std::fabs(normal[1]) >= std::fabs(normal[2]) ? 1 : 2);
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  const double sign = normal[drop] > 0 ? 1.0 : -1.0;
  std::vector<std::array<double, 2>> p(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    p[i] = { points[corners[i]][u], sign * points[corners[i]][v] };
  }
  auto orient = [&](std::size_t a, std::size_t b, std::size_t c) {
    return (p[b][0] - p[a][0]) * (p[c][1] - p[a][1]) - (p[b][1] - p[a][1]) * (p[c][0] - p[a][0]);
  };
  std::vector<std::size_t> ring(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    ring[i] = i;
  }
  std::vector<Triangle> triangles;
  while (ring.size() > 3)
  {
    const std::size_t m = ring.size();
    bool clipped = false;
    for (std::size_t k = 0; k < m && !clipped; ++k)
    {
      const std::size_t a = ring[(k + m - 1) % m], b = ring[k], c = ring[(k + 1) % m];
      if (orient(a, b, c) <= 0)
      {
        continue; // reflex or flat corner
      }
      bool empty = true;
      for (std::size_t j = 0; j < m && empty; ++j)
      {
        const std::size_t q = ring[j];
        if (q == a || q == b || q == c)
        {
          continue;
        }
        empty = !(orient(a, b, q) >= 0 && orient(b, c, q) >= 0 && orient(c, a, q) >= 0);
      }
      if (empty)
      {
        triangles.push_back({ corners[a], corners[b], corners[c] });
        ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(k));
        clipped = true;
      }
    }
    if (!clipped)
    {
      return false; // self-intersecting or degenerate polygon
    }
  }
  triangles.push_back({ corners[ring[0]], corners[ring[1]], corners[ring[2]] });
  for (const Triangle& t : triangles)
  {
    out.push_back(t);
  }
  return true;
}

OffReadResult readOff(std::istream& in)
{
  OffReadResult r;
  OffLines lines(in);
  std::vector<std::string> words;
  if (!lines.next(words))
  {
    r.error = "the file is empty";
    return r;
  }
  static const std::set<std::string> headers{ "OFF", "COFF", "NOFF", "CNOFF", "STOFF", "STCOFF",
    "STNOFF", "STCNOFF" };
  if (!headers.count(words[0]))
  {
    r.error = at(lines.number()) + "the file does not start with an OFF header (found '" +
      words[0] + "'; 4OFF and nOFF are not supported)";
    return r;
  }
  if (words.size() > 1 && words[1] == "BINARY")
  {
    r.error = at(lines.number()) + "binary OFF files are not supported; save it as text OFF";
    return r;
  }
  std::vector<std::string> counts(words.begin() + 1, words.end());
  if (counts.empty() && !lines.next(counts))
  {
    r.error = "the file ends after the header, before the vertex and face counts";
    return r;
  }
  long long nv = -1, nf = -1, ne = 0;
  if (counts.size() < 2 || !parseIndex(counts[0], nv) || !parseIndex(counts[1], nf) ||
    (counts.size() > 2 && !parseIndex(counts[2], ne)))
  {
    r.error = at(lines.number()) + "expected the counts 'vertices faces edges'";
    return r;
  }
  if (nv < 0 || nf < 0)
  {
    r.error = at(lines.number()) + "negative vertex or face count";
    return r;
  }
  if (nv == 0 || nf == 0)
  {
    r.error = at(lines.number()) + "the header says " + std::to_string(nv) + " vertices and " +
      std::to_string(nf) + " faces: there is no surface";
    return r;
  }
  auto& s = r.data.surface;
  s.points.reserve(static_cast<std::size_t>(std::min<long long>(nv, 100000000)));
  for (long long i = 0; i < nv; ++i)
  {
    if (!lines.next(words))
    {
      r.error = "expected " + std::to_string(nv) + " vertices but the file ends after " +
        std::to_string(i);
      return r;
    }
    if (words.size() < 3)
    {
      r.error = at(lines.number()) + "vertex " + std::to_string(i) + " has fewer than 3 coordinates";
      return r;
    }
    Vec3 p;
    for (int k = 0; k < 3; ++k)
    {
      if (!parseDouble(words[k], p[k]))
      {
        r.error = at(lines.number()) + "vertex " + std::to_string(i) +
          " has a non-numeric coordinate '" + words[k] + "'";
        return r;
      }
      if (!std::isfinite(p[k]))
      {
        r.error = at(lines.number()) + "vertex " + std::to_string(i) + " has a " +
          (std::isnan(p[k]) ? "NaN" : "infinite") + " coordinate";
        return r;
      }
    }
    s.points.push_back(p);
  }
  for (long long f = 0; f < nf; ++f)
  {
    if (!lines.next(words))
    {
      r.error = "expected " + std::to_string(nf) + " faces but the file ends after " +
        std::to_string(f);
      return r;
    }
    long long n = 0;
    if (!parseIndex(words[0], n))
    {
      r.error = at(lines.number()) + "face " + std::to_string(f) +
        " does not start with its number of corners (found '" + words[0] + "')";
      return r;
    }
    if (n < 3)
    {
      r.error = at(lines.number()) + "face " + std::to_string(f) + " has " + std::to_string(n) +
        " corners; a face needs at least 3";
      return r;
    }
    if (static_cast<long long>(words.size()) < n + 1)
    {
      r.error = at(lines.number()) + "face " + std::to_string(f) + " announces " +
        std::to_string(n) + " corners but lists " + std::to_string(words.size() - 1);
      return r;
    }
    std::vector<Index> corners;
    for (long long k = 1; k <= n; ++k)
    {
      long long index = 0;
      if (!parseIndex(words[k], index))
      {
        r.error = at(lines.number()) + "face " + std::to_string(f) + " has a non-integer corner '" +
          words[k] + "'";
        return r;
      }
      if (index < 0 || index >= nv)
      {
        r.error = at(lines.number()) + "face " + std::to_string(f) + " refers to vertex " +
          std::to_string(index) + ", but there are only " + std::to_string(nv) + " vertices";
        return r;
      }
      for (Index c : corners)
      {
        if (c == index)
        {
          r.error = at(lines.number()) + "face " + std::to_string(f) + " repeats vertex " +
            std::to_string(index);
          return r;
        }
      }
      corners.push_back(index);
    }
    for (std::size_t k = static_cast<std::size_t>(n) + 1; k < words.size(); ++k)
    {
      double colour = 0;
      if (!parseDouble(words[k], colour))
      {
        r.error = at(lines.number()) + "face " + std::to_string(f) + " has a non-numeric value '" +
          words[k] + "' after its corners";
        return r;
      }
    }
    const std::size_t before = s.triangles.size();
    if (n == 3)
    {
      s.triangles.push_back({ corners[0], corners[1], corners[2] });
    }
    else if (!triangulatePolygon(s.points, corners, s.triangles))
    {
      r.error = at(lines.number()) + "face " + std::to_string(f) + " is a degenerate or " +
        "self-intersecting polygon and cannot be triangulated";
      return r;
    }
    r.data.sourcePolygon.insert(r.data.sourcePolygon.end(), s.triangles.size() - before, f);
  }
  r.data.polygonCount = static_cast<std::size_t>(nf);
  r.ok = true;
  return r;
}

OffReadResult readOffFile(const std::string& path)
{
  std::ifstream in(path);
  if (!in)
  {
    OffReadResult r;
    r.error = path + ": cannot open the file (" + std::strerror(errno) + ")";
    return r;
  }
  OffReadResult r = readOff(in);
  if (!r.ok)
  {
    r.error = path + ": " + r.error;
  }
  return r;
}
} // namespace ptm
