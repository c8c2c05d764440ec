#include "LibraryFolder.h"

#include <dlfcn.h>

namespace ptm
{
std::string folderOfThisLibrary()
{
  Dl_info info{};
  if (::dladdr(reinterpret_cast<void*>(&folderOfThisLibrary), &info) == 0 || !info.dli_fname)
  {
    return "";
  }
  const std::string path = info.dli_fname;
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? "" : path.substr(0, slash + 1);
}
} // namespace ptm
