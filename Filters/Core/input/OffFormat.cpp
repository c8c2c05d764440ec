#include "OffFormat.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <string_view>
#include <system_error>
#include <type_traits>

namespace ptm
{
namespace
{
// Splits the stream into lines, drops '#' comments and blank lines, and
// keeps the line numbers for the messages.
class OffLines
{
public:
  explicit OffLines(std::istream& in)
    : In(in)
  {
  }

  // The words of the next line that has any; false at the end of the stream.
  bool next(std::vector<std::string_view>& words)
  {
    while (std::getline(this->In, this->Line))
    {
      ++this->Number;
      const std::size_t hash = this->Line.find('#');
      if (hash != std::string::npos)
      {
        this->Line.erase(hash);
      }
      words.clear();
      const std::string_view line(this->Line);
      std::size_t i = 0;
      while (i < line.size())
      {
        while (i < line.size() && isSpace(line[i]))
        {
          ++i;
        }
        const std::size_t begin = i;
        while (i < line.size() && !isSpace(line[i]))
        {
          ++i;
        }
        if (i > begin)
        {
          words.push_back(line.substr(begin, i - begin));
        }
      }
      if (!words.empty())
      {
        ++this->NonBlank;
        return true;
      }
    }
    return false;
  }

  int number() const { return this->Number; }
  int nonBlankLines() const { return this->NonBlank; }
  bool failedToRead() const { return this->In.bad(); }

private:
  static bool isSpace(char c)
  {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
  }

  std::istream& In;
  std::string Line; // the words point into it until the next call
  int Number = 0;
  int NonBlank = 0;
};

enum class Parsed
{
  Ok,
  NotANumber,
  OutOfRange
};

// Whole-word, locale-independent parsing ("+1" is accepted, "1x" is not).
template <typename T>
Parsed parseNumber(std::string_view word, T& value)
{
  if (word.size() > 1 && word[0] == '+' && word[1] != '-' && word[1] != '+')
  {
    word.remove_prefix(1);
  }
  const char* end = word.data() + word.size();
  std::from_chars_result r;
  if constexpr (std::is_floating_point_v<T>)
  {
    r = std::from_chars(word.data(), end, value, std::chars_format::general);
  }
  else
  {
    r = std::from_chars(word.data(), end, value, 10);
  }
  if (r.ec == std::errc::result_out_of_range && r.ptr == end)
  {
    if constexpr (std::is_floating_point_v<T>)
    {
      // Underflow (a magnitude below the smallest double) reads as zero;
      // only overflow is an error. The exponent, or the absence of any
      // non-zero digit before the decimal point, tells which.
      const std::size_t e = word.find_first_of("eE");
      const std::string_view mantissa = word.substr(0, e);
      const bool negativeExponent = e != std::string_view::npos && e + 1 < word.size() && word[e + 1] == '-';
      const bool noIntegerDigits =
        mantissa.substr(0, mantissa.find('.')).find_first_of("123456789") == std::string_view::npos;
      if (e == std::string_view::npos ? noIntegerDigits : negativeExponent)
      {
        value = (word[0] == '-') ? -0.0 : 0.0;
        return Parsed::Ok;
      }
    }
    return Parsed::OutOfRange;
  }
  return (r.ec == std::errc() && r.ptr == end && !word.empty()) ? Parsed::Ok : Parsed::NotANumber;
}

std::string quoted(std::string_view word)
{
  constexpr std::size_t kMax = 40;
  std::string s(word.substr(0, kMax));
  if (word.size() > kMax)
  {
    s += "...";
  }
  return "'" + s + "'";
}

std::string at(int line)
{
  return "line " + std::to_string(line) + ": ";
}

std::string plural(long long n, const char* word)
{
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

bool isKnownHeader(std::string_view w)
{
  // [ST][C][N]OFF in Geomview's order
  if (w.substr(0, 2) == "ST")
  {
    w.remove_prefix(2);
  }
  if (!w.empty() && w[0] == 'C')
  {
    w.remove_prefix(1);
  }
  if (!w.empty() && w[0] == 'N')
  {
    w.remove_prefix(1);
  }
  return w == "OFF";
}

OffReadResult failure(std::string message)
{
  OffReadResult r;
  r.error = std::move(message);
  return r;
}
constexpr long long kReserveLimit = 1 << 20; // a lying header must not allocate

// The reading of one OFF text, and what its steps share: the lines, the
// counts of the header and the surface being built. Each step returns the
// error, empty if there is none.
class OffParser
{
public:
  explicit OffParser(std::istream& in)
    : Lines(in)
  {
  }

  std::string readHeader();
  std::string readCounts();
  std::string readVertices();
  std::string readFaces();
  std::string checkEnd();
  OffReadResult& result() { return this->Result; }

private:
  std::string endOfFile(const std::string& message) const;
  std::string readVertex(long long i, Vec3& point) const;
  std::string readFace(long long f);
  std::string readCorners(const std::string& face, long long n);

  OffLines Lines;
  std::vector<std::string_view> Words;
  long long VertexCount = 0, FaceCount = 0;
  std::string CountsHint; // where the counts are and what they say, for the messages
  std::vector<Index> Corners;
  OffReadResult Result;
};

std::string OffParser::endOfFile(const std::string& message) const
{
  if (this->Lines.failedToRead())
  {
    return "reading failed after line " + std::to_string(this->Lines.number());
  }
  return message;
}

std::string OffParser::readHeader()
{
  if (!this->Lines.next(this->Words))
  {
    return endOfFile(this->Lines.number() > 0 ? "the file is empty (it has only comments and blank lines)"
                                              : "the file is empty");
  }
  if (!isKnownHeader(this->Words[0]))
  {
    const std::string_view w = this->Words[0];
    if (w.size() > 3 && w.substr(w.size() - 3) == "OFF")
    {
      return at(this->Lines.number()) + "the header " + quoted(w) +
        " is not supported (only OFF, COFF, NOFF, CNOFF and STOFF; no 4D or nOFF)";
    }
    return at(this->Lines.number()) + "expected the header OFF (or COFF, NOFF, CNOFF, STOFF) but found " +
      quoted(w) + ": this is not an OFF file";
  }
  if (this->Words.size() > 1 && this->Words[1] == "BINARY")
  {
    return at(this->Lines.number()) + "binary OFF files are not supported; save it as text OFF";
  }
  return {};
}

// The counts, on the header line or the next one.
std::string OffParser::readCounts()
{
  std::vector<std::string_view> counts(this->Words.begin() + 1, this->Words.end());
  if (counts.empty())
  {
    if (!this->Lines.next(this->Words))
    {
      return endOfFile("the file ends after the header, before the vertex and face counts");
    }
    counts = this->Words;
  }
  const int countsLine = this->Lines.number();
  if (counts.size() < 2 || counts.size() > 3)
  {
    return at(countsLine) + "expected the counts 'vertices faces [edges]' but found " +
      plural(static_cast<long long>(counts.size()), "value");
  }
  long long nv = 0, nf = 0, ne = 0;
  const char* names[3] = { "vertex", "face", "edge" };
  long long* values[3] = { &nv, &nf, &ne };
  for (std::size_t k = 0; k < counts.size(); ++k)
  {
    const Parsed p = parseNumber(counts[k], *values[k]);
    if (p != Parsed::Ok)
    {
      return at(countsLine) + "the " + names[k] + " count " + quoted(counts[k]) +
        (p == Parsed::OutOfRange ? " is too large" : " is not a whole number");
    }
    if (*values[k] < 0)
    {
      return at(countsLine) + "the " + names[k] + " count is negative (" + std::to_string(*values[k]) + ")";
    }
  }
  if (nv == 0)
  {
    return at(countsLine) + "header says 0 vertices: there is no surface";
  }
  if (nf == 0)
  {
    return at(countsLine) + "header says 0 faces: there is no surface";
  }
  this->VertexCount = nv;
  this->FaceCount = nf;
  this->CountsHint = " (line " + std::to_string(countsLine) + " says " + std::to_string(nv) +
    (nv == 1 ? " vertex" : " vertices") + " and " + plural(nf, "face") + ")";
  return {};
}

// Vertices, one per line; extra values (colour, normal, texture) are ignored.
std::string OffParser::readVertices()
{
  TriangleSurface& s = this->Result.data.surface;
  s.points.reserve(static_cast<std::size_t>(std::min(this->VertexCount, kReserveLimit)));
  for (long long i = 0; i < this->VertexCount; ++i)
  {
    if (!this->Lines.next(this->Words))
    {
      return endOfFile("expected " + std::to_string(this->VertexCount) + " vertices but the file ends after " +
        std::to_string(i) + this->CountsHint);
    }
    Vec3 point;
    const std::string error = readVertex(i, point);
    if (!error.empty())
    {
      return error;
    }
    s.points.push_back(point);
  }
  return {};
}

// Vertex i from the words of its line.
std::string OffParser::readVertex(long long i, Vec3& point) const
{
  const std::vector<std::string_view>& words = this->Words;
  if (words.size() < 3)
  {
    return at(this->Lines.number()) + "vertex " + std::to_string(i) + " has " +
      plural(static_cast<long long>(words.size()), "coordinate") + ", expected 3";
  }
  for (int k = 0; k < 3; ++k)
  {
    const Parsed p = parseNumber(words[k], point[k]);
    if (p == Parsed::OutOfRange)
    {
      return at(this->Lines.number()) + "vertex " + std::to_string(i) + " has a coordinate " +
        quoted(words[k]) + " out of the range of double precision";
    }
    if (p != Parsed::Ok)
    {
      return at(this->Lines.number()) + "vertex " + std::to_string(i) + " has a non-numeric coordinate " +
        quoted(words[k]);
    }
    if (std::isnan(point[k]))
    {
      return at(this->Lines.number()) + "vertex " + std::to_string(i) + " has a NaN coordinate";
    }
    if (!std::isfinite(point[k]))
    {
      return at(this->Lines.number()) + "vertex " + std::to_string(i) + " has an infinite coordinate";
    }
  }
  return {};
}

// Faces: n i1 .. in [colour: up to 4 values].
std::string OffParser::readFaces()
{
  TriangleSurface& s = this->Result.data.surface;
  s.triangles.reserve(static_cast<std::size_t>(std::min(this->FaceCount, kReserveLimit)));
  this->Result.data.sourcePolygon.reserve(s.triangles.capacity());
  for (long long f = 0; f < this->FaceCount; ++f)
  {
    if (!this->Lines.next(this->Words))
    {
      return endOfFile("expected " + std::to_string(this->FaceCount) + " faces but the file ends after " +
        std::to_string(f) + this->CountsHint);
    }
    const std::string error = readFace(f);
    if (!error.empty())
    {
      return error;
    }
  }
  return {};
}

// Face f from the words of its line: its triangles, or those of its polygon.
std::string OffParser::readFace(long long f)
{
  const std::vector<std::string_view>& words = this->Words;
  const std::string face = at(this->Lines.number()) + "face " + std::to_string(f);
  long long n = 0;
  if (parseNumber(words[0], n) != Parsed::Ok)
  {
    return face + " does not start with its number of corners (found " + quoted(words[0]) + ")" +
      this->CountsHint;
  }
  if (n < 3)
  {
    return face + " has " + plural(n, "corner") + "; a face needs at least 3" + this->CountsHint;
  }
  const long long listed = static_cast<long long>(words.size()) - 1;
  if (listed < n)
  {
    return face + " announces " + std::to_string(n) + " corners but lists " + std::to_string(listed) +
      " values" + this->CountsHint;
  }
  if (listed - n > 4)
  {
    return face + " announces " + std::to_string(n) + " corners but has " + std::to_string(listed) +
      " values after the count (at most 4 colour values may follow the corners)";
  }
  const std::string error = readCorners(face, n);
  if (!error.empty())
  {
    return error;
  }
  for (std::size_t k = static_cast<std::size_t>(n) + 1; k < words.size(); ++k)
  {
    double colour = 0;
    if (parseNumber(words[k], colour) == Parsed::NotANumber)
    {
      return face + " has a non-numeric colour value " + quoted(words[k]) + " after its corners";
    }
  }
  TriangleSurface& s = this->Result.data.surface;
  const std::vector<Index>& corners = this->Corners;
  const std::size_t before = s.triangles.size();
  if (n == 3)
  {
    s.triangles.push_back({ corners[0], corners[1], corners[2] });
  }
  else if (!triangulatePolygon(s.points, corners, s.triangles))
  {
    return face + " is a polygon of " + std::to_string(n) +
      " corners with zero area or crossing edges; it cannot be triangulated";
  }
  this->Result.data.sourcePolygon.insert(this->Result.data.sourcePolygon.end(), s.triangles.size() - before, f);
  return {};
}

// The n corners of a face, from the words after its count.
std::string OffParser::readCorners(const std::string& face, long long n)
{
  const long long nv = this->VertexCount;
  this->Corners.clear();
  for (long long k = 1; k <= n; ++k)
  {
    long long index = 0;
    const Parsed p = parseNumber(this->Words[static_cast<std::size_t>(k)], index);
    if (p != Parsed::Ok)
    {
      return face + " has a vertex index " + quoted(this->Words[static_cast<std::size_t>(k)]) +
        " that is not a whole number";
    }
    if (index < 0 || index >= nv)
    {
      return face + " refers to vertex " + std::to_string(index) + ", but there " +
        (nv == 1 ? "is only 1 vertex" : "are only " + std::to_string(nv) + " vertices") + " (numbered from 0)";
    }
    if (std::find(this->Corners.begin(), this->Corners.end(), index) != this->Corners.end())
    {
      return face + " uses vertex " + std::to_string(index) + " twice";
    }
    this->Corners.push_back(index);
  }
  return {};
}

// Nothing may follow: more lines mean the counts are wrong.
std::string OffParser::checkEnd()
{
  if (this->Lines.next(this->Words))
  {
    return at(this->Lines.number()) +
      "unexpected data after the last face; the file has more vertices or faces than its header says" +
      this->CountsHint;
  }
  if (this->Lines.failedToRead())
  {
    return "reading failed after line " + std::to_string(this->Lines.number());
  }
  this->Result.data.polygonCount = static_cast<std::size_t>(this->FaceCount);
  return {};
}
} // namespace

bool triangulatePolygon(
  const std::vector<Vec3>& points, const std::vector<Index>& corners, std::vector<Triangle>& out)
{
  const std::size_t n = corners.size();
  if (n < 3)
  {
    return false;
  }
  // Newell's normal (twice the vector area), relative to the first corner
  // for precision.
  const Vec3 origin = points[corners[0]];
  std::vector<Vec3> local(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    local[i] = points[corners[i]] - origin;
  }
  Vec3 normal{ 0, 0, 0 };
  for (std::size_t i = 0; i < n; ++i)
  {
    normal = normal + cross(local[i], local[(i + 1) % n]);
  }
  const double length = norm(normal);
  if (!(length > 0) || !std::isfinite(length))
  {
    return false;
  }
  // 2D coordinates in the plane of the normal: (e1, e2, normal) is right
  // handed, so the polygon runs counter-clockwise in (e1, e2).
  Vec3 e1, e2;
  planeBasis((1.0 / length) * normal, e1, e2);
  std::vector<std::array<double, 2>> p(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    p[i] = { dot(local[i], e1), dot(local[i], e2) };
  }
  auto orient = [&](std::size_t a, std::size_t b, std::size_t c) {
    return (p[b][0] - p[a][0]) * (p[c][1] - p[a][1]) - (p[b][1] - p[a][1]) * (p[c][0] - p[a][0]);
  };
  auto sameSpot = [&](std::size_t a, std::size_t b) { return p[a] == p[b]; };
  auto squaredLength = [&](std::size_t a, std::size_t b) {
    const double dx = p[b][0] - p[a][0], dy = p[b][1] - p[a][1];
    return dx * dx + dy * dy;
  };

  std::vector<std::size_t> ring(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    ring[i] = i;
  }
  std::vector<Triangle> triangles;
  triangles.reserve(n - 2);
  while (ring.size() > 3)
  {
    const std::size_t m = ring.size();
    // Among the ears (a strictly convex corner whose triangle holds no other
    // corner, not even on its boundary), clip the best shaped one; on large
    // polygons the first one, to stay near O(n^2).
    const bool firstEar = m > 64;
    std::size_t best = m;
    double bestShape = -1;
    for (std::size_t k = 0; k < m; ++k)
    {
      const std::size_t a = ring[(k + m - 1) % m], b = ring[k], c = ring[(k + 1) % m];
      const double area2 = orient(a, b, c);
      if (!(area2 > 0))
      {
        continue; // reflex or flat corner
      }
      bool empty = true;
      for (std::size_t j = 0; j < m && empty; ++j)
      {
        const std::size_t q = ring[j];
        if (q == a || q == b || q == c || sameSpot(q, a) || sameSpot(q, b) || sameSpot(q, c))
        {
          continue;
        }
        empty = !(orient(a, b, q) >= 0 && orient(b, c, q) >= 0 && orient(c, a, q) >= 0);
      }
      if (!empty)
      {
        continue;
      }
      const double longest =
        std::max({ squaredLength(a, b), squaredLength(b, c), squaredLength(c, a) });
      const double shape = area2 / longest;
      if (shape > bestShape)
      {
        bestShape = shape;
        best = k;
      }
      if (firstEar)
      {
        break;
      }
    }
    if (best == m)
    {
      return false; // self-intersecting (or numerically degenerate) polygon
    }
    const std::size_t a = ring[(best + m - 1) % m], b = ring[best], c = ring[(best + 1) % m];
    triangles.push_back({ corners[a], corners[b], corners[c] });
    ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(best));
  }
  if (!(orient(ring[0], ring[1], ring[2]) > 0))
  {
    return false;
  }
  triangles.push_back({ corners[ring[0]], corners[ring[1]], corners[ring[2]] });
  out.insert(out.end(), triangles.begin(), triangles.end());
  return true;
}

OffReadResult readOff(std::istream& in)
{
  OffParser parser(in);
  for (auto step : { &OffParser::readHeader, &OffParser::readCounts, &OffParser::readVertices,
         &OffParser::readFaces, &OffParser::checkEnd })
  {
    std::string error = (parser.*step)();
    if (!error.empty())
    {
      return failure(std::move(error));
    }
  }
  parser.result().ok = true;
  return std::move(parser.result());
}

OffReadResult readOffFile(const std::string& path)
{
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
  {
    return failure(path + ": is a directory, not an OFF file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    const int code = errno;
    return failure(path + ": cannot open the file (" +
      (code ? std::string(std::strerror(code)) : std::string("unknown reason")) + ")");
  }
  OffReadResult r = readOff(in);
  if (!r.ok)
  {
    r.error = path + ": " + r.error;
  }
  return r;
}

void writeOff(std::ostream& out, const TriangleSurface& surface, const std::string& comment)
{
  const auto precision = out.precision(std::numeric_limits<double>::max_digits10);
  out << "OFF\n";
  if (!comment.empty())
  {
    std::string oneLine = comment;
    std::replace(oneLine.begin(), oneLine.end(), '\n', ' ');
    out << "# " << oneLine << "\n";
  }
  out << surface.points.size() << " " << surface.triangles.size() << " 0\n";
  for (const Vec3& p : surface.points)
  {
    out << p[0] << " " << p[1] << " " << p[2] << "\n";
  }
  for (const Triangle& t : surface.triangles)
  {
    out << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
  }
  out.precision(precision);
}
} // namespace ptm
