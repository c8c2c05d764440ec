// The cutter alone on one OFF surface, then every subdomain checked for
// self-intersection with every interface triangulated as the unit tests do
// (Testing/Cpp/TestSurfaces.h, triangulateAllInterfaces): prints OK, CROSS
// (with the count and the first crossing subdomain), CUTFAIL or READFAIL, the
// cut's seconds and the flat crossings taken out. Figures, not a test.
//   crossing_diagnostic FILE.off K PP|RB [vol|cost][keep]
// Build (from the source root, after building libptmcore):
//   g++ -O2 -std=c++17 -IFilters/Core/common -IFilters/Core/cut -IFilters/Core/input \
//     -IFilters/Core/interface -IFilters/Core/refine -IFilters/Core/volume -ITesting/Cpp \
//     -DPTM_DATA_DIR='"x"' Testing/Corpus/crossing_diagnostic.cpp Testing/Cpp/TestSurfaces.cpp \
//     build/lib/libptmcore.a -lgmp -lmpfr -ltet -o crossing_diagnostic
#include "OffFormat.h"
#include "SelfIntersectionCheck.h"
#include "SurfaceInputCheck.h"
#include "TestSurfaces.h"
#include "VolumeBalancedDecomposition.h"
#include <chrono>
#include <iostream>
using namespace ptm;
int main(int argc, char** argv)
{
  auto r = readOffFile(argv[1]);
  if (!r.ok) { std::cout << "READFAIL " << r.error << "\n"; return 0; }
  DecompositionOptions o;
  o.numberOfSubdomains = std::atoi(argv[2]);
  o.strategy = std::string(argv[3]) == "PP" ? CutStrategy::ParallelPlanes : CutStrategy::RecursiveBisection;
  o.direction = CutDirection::Inertia;
  std::string mode = argc > 4 ? argv[4] : "";
  if (mode.find("keep") != std::string::npos) o.removeFlatCrossings = false;
  if (mode.find("cost") != std::string::npos) o.criterion = BalanceCriterion::PredictedCost;
  auto t0 = std::chrono::steady_clock::now();
  PreparedSurface p = prepareInputSurface(r.data.surface, o.inputCheck);
  DecompositionResult d = decomposeVolumeBalanced(std::move(p), o);
  double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!d.ok) { std::cout << "CUTFAIL " << sec << " " << d.error << "\n"; return 0; }
  SurfaceComplex c = d.complex;
  auto f = test::triangulateAllInterfaces(c);
  if (!f.ok) { std::cout << "TRIFAIL " << f.error << "\n"; return 0; }
  int bad = 0, first = -1;
  for (int s = 0; s < c.subdomainCount; ++s)
    if (checkSelfIntersection(TriangleSurface{ c.points, subdomainTriangles(c, s) }).intersects) { ++bad; if (first < 0) first = s; }
  std::cout << (bad ? "CROSS " : "OK ") << sec << " removed=" << d.flatCrossingsRemoved << " bad=" << bad << " first=" << first;
  for (auto& w : d.warnings) if (w.find("cut again") != std::string::npos || w.find("kept") != std::string::npos || w.find("not parallel") != std::string::npos) std::cout << " [" << w.substr(0, 400) << "]";
  std::cout << "\n";
}
