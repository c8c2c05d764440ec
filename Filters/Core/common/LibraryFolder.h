#ifndef PTM_LIBRARY_FOLDER_H
#define PTM_LIBRARY_FOLDER_H
// Where the code runs from, to find the files built beside it.
#include <string>

namespace ptm
{
// The folder, with a trailing slash, of the shared library or program this
// core is linked into (the plugin's folder inside ParaView; the test
// program's in the unit tests); empty if the loader cannot tell.
std::string folderOfThisLibrary();
} // namespace ptm
#endif
