#include "TetrahedronQuality.h"

namespace ptm
{
namespace
{
// The cosine of the angle between the two outward unit face normals of the
// tetrahedron that point most apart (-1 if it is flat). Its smallest
// dihedral angle is pi minus that angle, at the edge the two faces share.
double mostOpposedNormals(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
  const std::array<Vec3, 4> p{ a, b, c, d };
  // outward unit normal of the face opposite each vertex
  std::array<Vec3, 4> normal;
  for (int f = 0; f < 4; ++f)
  {
    const Vec3& x = p[(f + 1) % 4];
    const Vec3& y = p[(f + 2) % 4];
    const Vec3& z = p[(f + 3) % 4];
    Vec3 n = cross(y - x, z - x);
    if (dot(n, p[f] - x) > 0)
    {
      n = -1.0 * n;
    }
    const double length = norm(n);
    if (!(length > 0))
    {
      return -1.0;
    }
    normal[f] = (1.0 / length) * n;
  }
  double lowest = 1.0;
  for (int f = 0; f < 4; ++f)
  {
    for (int g = f + 1; g < 4; ++g)
    {
      lowest = std::min(lowest, dot(normal[f], normal[g]));
    }
  }
  return std::max(lowest, -1.0);
}

double degreesOf(double mostOpposed)
{
  return (kPi - std::acos(mostOpposed)) * 180.0 / kPi;
}

// A smallest dihedral angle under 10 degrees is one whose normals are more
// than 170 degrees apart: a tetrahedron is counted by comparing cosines,
// and the angle is taken once, of the most opposed normals of all (an acos
// per tetrahedron was about 5 % of the quality pass, perf, session 35).
const double kCosine170Degrees = std::cos(170.0 * kPi / 180.0);

struct Counter
{
  const TetMesh& mesh;
  long long tetrahedra = 0, below10Degrees = 0;
  double mostOpposed = 1.0;

  void count(const std::array<Index, 4>& t)
  {
    const double cosine =
      mostOpposedNormals(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]], mesh.points[t[3]]);
    ++tetrahedra;
    below10Degrees += cosine < kCosine170Degrees ? 1 : 0;
    mostOpposed = std::min(mostOpposed, cosine);
  }

  DihedralQuality quality() const { return { tetrahedra, below10Degrees, degreesOf(mostOpposed) }; }
};
} // namespace

double smallestDihedralDegrees(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
  return degreesOf(mostOpposedNormals(a, b, c, d));
}

DihedralQuality dihedralQuality(const TetMesh& mesh)
{
  Counter counter{ mesh };
  for (const auto& t : mesh.tets)
  {
    counter.count(t);
  }
  return counter.quality();
}

DihedralQuality dihedralQuality(const TetMesh& mesh, const std::vector<Index>& tets)
{
  Counter counter{ mesh };
  for (Index k : tets)
  {
    counter.count(mesh.tets[k]);
  }
  return counter.quality();
}
} // namespace ptm
