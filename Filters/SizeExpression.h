#ifndef PTM_SIZE_EXPRESSION_H
#define PTM_SIZE_EXPRESSION_H
// The size field of the filters' SizeExpression property: an expression of
// x, y and z (VTK's function parser syntax, as in ParaView's Calculator)
// giving the edge length wanted at a point, as a ptm::SizeFunction for the
// core. Shared by InterfaceTriangulator and ParallelTetMesher, so both sides
// of every interface and every stage read the same field.
#include "InterfaceTriangulation.h" // ptm::SizeFunction

#include <string>
#include <vector>

namespace ptm
{
// The expression and the function made of it (empty when the expression is).
struct SizeField
{
  std::string expression;
  SizeFunction size;

  explicit operator bool() const { return static_cast<bool>(this->size); }
};

// An empty expression gives an empty field. Otherwise the expression is
// parsed once; on a syntax error or a non-scalar result the field is empty
// and `error` says why (the same on every rank, since every rank has the
// same property value).
SizeField sizeFieldOf(const std::string& expression, std::string& error);

// The field at `points`; false with `error` naming the first point where it
// is not a positive finite size.
bool sizesAt(const SizeField& field, const std::vector<Vec3>& points, std::vector<double>& sizes,
  std::string& error);
} // namespace ptm
#endif
