#include "SizeExpression.h"

#include "vtkFunctionParser.h"
#include "vtkSmartPointer.h"

#include <cmath>
#include <memory>
#include <sstream>

namespace ptm
{
SizeField sizeFieldOf(const std::string& expression, std::string& error)
{
  error.clear();
  SizeField field;
  field.expression = expression;
  if (expression.empty())
  {
    return field;
  }
  auto parser = vtkSmartPointer<vtkFunctionParser>::New();
  parser->SetFunction(expression.c_str());
  for (const char* name : { "x", "y", "z" })
  {
    parser->SetScalarVariableValue(name, 0.0);
  }
  // parses; VTK prints the position of a syntax error itself
  if (!parser->IsScalarResult())
  {
    error = "SizeExpression '" + expression +
      "' is not a scalar expression of x, y and z (the syntax of ParaView's Calculator, e.g. "
      "0.02 + 0.1 * abs(z))";
    return field;
  }
  // the parser keeps state between calls: one per function, used by one thread
  field.size = [parser](const Vec3& p) {
    parser->SetScalarVariableValue("x", p[0]);
    parser->SetScalarVariableValue("y", p[1]);
    parser->SetScalarVariableValue("z", p[2]);
    return parser->GetScalarResult();
  };
  return field;
}

bool sizesAt(const SizeField& field, const std::vector<Vec3>& points, std::vector<double>& sizes,
  std::string& error)
{
  sizes.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    sizes[i] = field.size(points[i]);
    if (!(sizes[i] > 0) || !std::isfinite(sizes[i]))
    {
      std::ostringstream msg;
      msg.precision(9);
      msg << "SizeExpression '" << field.expression << "' gives " << sizes[i] << " at (" << points[i][0]
          << ", " << points[i][1] << ", " << points[i][2] << "); sizes must be positive and finite";
      error = msg.str();
      return false;
    }
  }
  return true;
}
} // namespace ptm
