#ifndef PTM_FUZZ_CHECK_H
#define PTM_FUZZ_CHECK_H
// Invariant checks inside fuzz targets. A violated invariant prints what was
// expected and what was found, then calls abort(): libFuzzer reports that as
// a crash and keeps the input, exactly as it does for a sanitizer finding.
// (gtest assertions are not usable here, and assert() vanishes under NDEBUG.)
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

namespace ptm::fuzz
{
[[noreturn]] inline void invariantViolated(
  const char* condition, const std::string& details, const char* file, int line)
{
  std::fprintf(stderr, "%s:%d: fuzz invariant violated: %s\n  %s\n", file, line, condition,
    details.c_str());
  std::fflush(stderr);
  std::abort();
}
} // namespace ptm::fuzz

// PTM_FUZZ_CHECK(volume > 0, "volume " << volume);
#define PTM_FUZZ_CHECK(condition, details)                                                       \
  do                                                                                             \
  {                                                                                              \
    if (!(condition))                                                                            \
    {                                                                                            \
      std::ostringstream ptmFuzzDetails;                                                         \
      ptmFuzzDetails << details;                                                                 \
      ::ptm::fuzz::invariantViolated(#condition, ptmFuzzDetails.str(), __FILE__, __LINE__);      \
    }                                                                                            \
  } while (false)
#endif
