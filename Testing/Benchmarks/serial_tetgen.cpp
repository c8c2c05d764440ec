// Serial TetGen on a whole closed surface, through the same library call and
// switches the ParallelTetMesher uses per subdomain (ptm::meshClosedSurface):
// the reference the parallel pipeline is measured against.
//
//   serial_tetgen SURFACE.off [radius-edge-ratio] [maximum-volume] [MESH.vtk]
//
// Prints one JSON object: tetrahedra, points, seconds (TetGen alone) and the
// seconds of every step from reading to writing, the peak resident memory of
// this process and of the TetGen process, minimum dihedral angle and share of
// tetrahedra under 10 degrees. With MESH.vtk the tetrahedra are written as a
// binary legacy VTK file, so the benchmark driver can measure every peer's
// output with the same code (mesh_quality.py) and the time covers reading to
// written output, like the pipeline's.
#include "OffFormat.h"
#include "SurfaceOrientation.h"
#include "TetGenSubdomainMesher.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

namespace
{
double minimumDihedral(const ptm::TetMesh& m, const std::array<ptm::Index, 4>& t)
{
  using namespace ptm; // the Vec3 operators
  const Vec3 p[4] = { m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]] };
  static const int faces[4][3] = { { 1, 2, 3 }, { 0, 2, 3 }, { 0, 1, 3 }, { 0, 1, 2 } };
  Vec3 n[4];
  for (int f = 0; f < 4; ++f)
  {
    // outward normal of the face opposite vertex f
    Vec3 v = ptm::cross(p[faces[f][1]] - p[faces[f][0]], p[faces[f][2]] - p[faces[f][0]]);
    if (ptm::dot(v, p[f] - p[faces[f][0]]) > 0)
    {
      v = -1.0 * v;
    }
    n[f] = ptm::normalized(v);
  }
  double smallest = 180;
  for (int i = 0; i < 4; ++i)
  {
    for (int j = i + 1; j < 4; ++j)
    {
      const double c = std::clamp(-ptm::dot(n[i], n[j]), -1.0, 1.0);
      smallest = std::min(smallest, std::acos(c) * 180.0 / 3.14159265358979323846);
    }
  }
  return smallest;
}

// Binary legacy VTK is big-endian whatever the machine.
template <typename T>
void writeBigEndian(std::ofstream& out, T value)
{
  static const std::uint16_t one = 1;
  static const bool littleEndian = *reinterpret_cast<const unsigned char*>(&one) == 1;
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  if (littleEndian)
  {
    std::reverse(bytes, bytes + sizeof(T));
  }
  out.write(bytes, sizeof(T));
}

bool writeLegacyVtk(const std::string& path, const ptm::TetMesh& m)
{
  std::ofstream out(path, std::ios::binary);
  out << "# vtk DataFile Version 3.0\nserial_tetgen\nBINARY\nDATASET UNSTRUCTURED_GRID\n";
  out << "POINTS " << m.points.size() << " double\n";
  for (const auto& p : m.points)
  {
    for (int c = 0; c < 3; ++c)
    {
      writeBigEndian<double>(out, p[c]);
    }
  }
  out << "\nCELLS " << m.tets.size() << " " << 5 * m.tets.size() << "\n";
  for (const auto& t : m.tets)
  {
    writeBigEndian<std::int32_t>(out, 4);
    for (int c = 0; c < 4; ++c)
    {
      writeBigEndian<std::int32_t>(out, static_cast<std::int32_t>(t[c]));
    }
  }
  out << "\nCELL_TYPES " << m.tets.size() << "\n";
  for (std::size_t i = 0; i < m.tets.size(); ++i)
  {
    writeBigEndian<std::int32_t>(out, 10); // VTK_TETRA
  }
  out << "\n";
  return static_cast<bool>(out);
}

double secondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
} // namespace

int main(int argc, char** argv)
{
  if (argc < 2)
  {
    std::fprintf(stderr, "usage: serial_tetgen SURFACE.off [radius-edge-ratio] [maximum-volume] [MESH.vtk]\n");
    return 2;
  }
  const auto readStart = std::chrono::steady_clock::now();
  ptm::OffReadResult in = ptm::readOffFile(argv[1]);
  if (!in.ok)
  {
    std::fprintf(stderr, "serial_tetgen: %s\n", in.error.c_str());
    return 1;
  }
  const double readSeconds = secondsSince(readStart);
  const auto orientStart = std::chrono::steady_clock::now();
  ptm::TriangleSurface surface = in.data.surface;
  std::size_t dropped = 0;
  std::vector<ptm::Index> source;
  ptm::mergeDuplicatePoints(surface, dropped, source);
  const ptm::OrientationResult oriented = ptm::orientShells(surface);
  if (!oriented.ok)
  {
    std::fprintf(stderr, "serial_tetgen: %s\n", oriented.error.c_str());
    return 1;
  }
  const double orientSeconds = secondsSince(orientStart);
  ptm::TetMeshingOptions options;
  if (argc > 2)
  {
    options.radiusEdgeRatio = std::atof(argv[2]);
  }
  if (argc > 3)
  {
    options.maximumVolume = std::atof(argv[3]);
  }
  const auto start = std::chrono::steady_clock::now();
  const ptm::TetMeshingResult r = ptm::meshClosedSurface(surface, options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!r.ok)
  {
    std::fprintf(stderr, "serial_tetgen: %s\n", r.error.c_str());
    return 1;
  }
  double writeSeconds = 0;
  if (argc > 4)
  {
    const auto writeStart = std::chrono::steady_clock::now();
    if (!writeLegacyVtk(argv[4], r.mesh))
    {
      std::fprintf(stderr, "serial_tetgen: cannot write %s\n", argv[4]);
      return 1;
    }
    writeSeconds = secondsSince(writeStart);
  }
  double smallest = 180;
  std::size_t below10 = 0;
  for (const auto& t : r.mesh.tets)
  {
    const double a = minimumDihedral(r.mesh, t);
    smallest = std::min(smallest, a);
    below10 += a < 10 ? 1 : 0;
  }
  rusage self{}, children{};
  getrusage(RUSAGE_SELF, &self);
  getrusage(RUSAGE_CHILDREN, &children);
  std::printf("{\"tetrahedra\": %zu, \"points\": %zu, \"seconds\": %.3f, \"switches\": \"%s\", "
              "\"read_seconds\": %.3f, \"orient_seconds\": %.3f, \"write_seconds\": %.3f, "
              "\"peak_rss_mb_driver\": %.1f, \"peak_rss_mb_tetgen\": %.1f, "
              "\"minimum_dihedral_angle_degrees\": %.3f, \"share_below_10_degrees\": %.6f}\n",
    r.mesh.tets.size(), r.mesh.points.size(), seconds, r.switchesUsed.c_str(), readSeconds, orientSeconds,
    writeSeconds, self.ru_maxrss / 1024.0,
    children.ru_maxrss / 1024.0, smallest, static_cast<double>(below10) / std::max<std::size_t>(1, r.mesh.tets.size()));
  return 0;
}
