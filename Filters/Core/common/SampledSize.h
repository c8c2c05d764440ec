#ifndef PTM_SAMPLED_SIZE_H
#define PTM_SAMPLED_SIZE_H
// A size field given by samples (points with a size each), interpolated:
// at a sample its own size; elsewhere Shepard's mean of the 8 nearest
// samples weighted by the inverse square distance, found with CGAL's kd-tree.
// A point inside a body lies between surface samples, so a field given on
// the surface alone reaches the interior (there it follows the nearest
// surface). Deterministic: the same samples give the same function on every
// rank, so both sides of an interface get the same sizes.
#include "SizeFunction.h"

#include <string>
#include <vector>

namespace ptm
{
// `xyzh`: x, y, z and the size of every sample. Empty, with `error`, when
// there is no sample or a size is not positive and finite (`name` names
// the samples in the message). The function shares the tree; calls are
// safe from one thread at a time.
SizeFunction sampledSize(const std::vector<double>& xyzh, const std::string& name, std::string& error);
} // namespace ptm
#endif
