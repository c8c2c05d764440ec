#ifndef PTM_SIZE_FIELD_H
#define PTM_SIZE_FIELD_H
// The size field of the filters (the edge length wanted at a point), as a
// ptm::SizeFunction for the core. It comes from one of two places:
// - an expression of x, y and z (VTK's function parser syntax, as in
//   ParaView's Calculator): the SizeExpression property of the cutter, the
//   triangulator and the mesher, the same string given to each;
// - samples, a point array of the input surface or of a background data set
//   (the cutter's SizeArray and SizeSource), interpolated between them. Only
//   the cutter sees those inputs, so it puts the samples in the field data of
//   the complex (SizeFieldSamples), every stage passes them on, and the
//   triangulator and the mesher build the same field from them.
// Either way every rank and both sides of every interface evaluate one
// deterministic function of position.
#include "SizeFunction.h"

#include <string>
#include <vector>

class vtkFieldData;

namespace ptm
{
// The function and what it was made of, for messages (empty when there is
// no field).
struct SizeField
{
  std::string source; // "SizeExpression '...'" or "SizeArray '...'"
  SizeFunction size;

  explicit operator bool() const { return static_cast<bool>(this->size); }
};

// An empty expression gives an empty field. Otherwise the expression is
// parsed once; on a syntax error or a non-scalar result the field is empty
// and `error` says why (the same on every rank, since every rank has the
// same property value).
SizeField sizeFieldOf(const std::string& expression, std::string& error);

// Samples of a size: x, y, z, h for every sample, and the array they came from.
struct SizeSamples
{
  std::string arrayName;
  std::vector<double> xyzh;
};

// The field interpolated between `samples` (SampledSize.h: Shepard's mean of
// the 8 nearest). Empty, with `error`, when there is no sample or a size is
// not positive and finite.
SizeField sizeFieldOfSamples(const SizeSamples& samples, std::string& error);

// The samples as field data of the complex, and back (no samples: empty).
void addSizeSamples(vtkFieldData* fieldData, const SizeSamples& samples);
SizeSamples sizeSamplesOf(vtkFieldData* fieldData);

// The field of a filter after the cutter: its own SizeExpression, or the
// samples in the complex's field data; an error when both are given.
SizeField complexSizeField(const std::string& expression, vtkFieldData* fieldData, std::string& error);

// The cutter's thickness samples (LocalThickness.h) as field data of the
// complex (ThicknessSamples, ThicknessLimit); nothing for no sample.
void addThicknessSamples(vtkFieldData* fieldData, const std::vector<double>& xyzt, double limit);

// The size the triangulator and the mesher put boundary points by: `field`
// capped by the complex's thickness samples, or `field` alone without them.
// Every rank reads the same samples, so both sides of an interface agree.
SizeFunction boundarySizeOf(const SizeField& field, vtkFieldData* fieldData);

// The field at `points`; false with `error` naming the first point where it
// is not a positive finite size.
bool sizesAt(const SizeField& field, const std::vector<Vec3>& points, std::vector<double>& sizes,
  std::string& error);
} // namespace ptm
#endif
