#ifndef PTM_SIZE_FUNCTION_H
#define PTM_SIZE_FUNCTION_H
// The type every stage takes a size field as.
#include "Vec3.h"

#include <functional>

namespace ptm
{
// A size field: the edge length wanted at a point in space. Empty: none.
using SizeFunction = std::function<double(const Vec3&)>;
} // namespace ptm
#endif
