#include "SizeField.h"

#include "LocalThickness.h"
#include "SampledSize.h"
#include "SurfaceComplexArrays.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFunctionParser.h"
#include "vtkSmartPointer.h"
#include "vtkNew.h"
#include "vtkStringArray.h"

#include <cmath>
#include <sstream>

namespace ptm
{
SizeField sizeFieldOf(const std::string& expression, std::string& error)
{
  error.clear();
  SizeField field;
  if (expression.empty())
  {
    return field;
  }
  field.source = "SizeExpression '" + expression + "'";
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

SizeField sizeFieldOfSamples(const SizeSamples& samples, std::string& error)
{
  SizeField field;
  field.source = "SizeArray '" + samples.arrayName + "'";
  field.size = sampledSize(samples.xyzh, field.source, error);
  if (!error.empty())
  {
    field.size = nullptr;
  }
  return field;
}

void addSizeSamples(vtkFieldData* fieldData, const SizeSamples& samples)
{
  vtkNew<vtkDoubleArray> values;
  values->SetName(arrays::SizeFieldSamples);
  values->SetNumberOfComponents(4);
  values->SetNumberOfTuples(static_cast<vtkIdType>(samples.xyzh.size() / 4));
  std::copy(samples.xyzh.begin(), samples.xyzh.end(), values->GetPointer(0));
  fieldData->AddArray(values);
  vtkNew<vtkStringArray> name;
  name->SetName(arrays::SizeFieldArray);
  name->InsertNextValue(samples.arrayName);
  fieldData->AddArray(name);
}

SizeSamples sizeSamplesOf(vtkFieldData* fieldData)
{
  SizeSamples samples;
  auto* values = fieldData
    ? vtkDoubleArray::SafeDownCast(fieldData->GetAbstractArray(arrays::SizeFieldSamples))
    : nullptr;
  if (!values || values->GetNumberOfComponents() != 4)
  {
    return samples;
  }
  const double* v = values->GetPointer(0);
  samples.xyzh.assign(v, v + 4 * values->GetNumberOfTuples());
  auto* name = vtkStringArray::SafeDownCast(fieldData->GetAbstractArray(arrays::SizeFieldArray));
  samples.arrayName = name && name->GetNumberOfValues() > 0 ? name->GetValue(0) : "";
  return samples;
}

SizeField complexSizeField(const std::string& expression, vtkFieldData* fieldData, std::string& error)
{
  const SizeSamples samples = sizeSamplesOf(fieldData);
  if (samples.xyzh.empty())
  {
    return sizeFieldOf(expression, error);
  }
  if (!expression.empty())
  {
    error = "both a SizeExpression ('" + expression + "') and the cutter's SizeArray ('" +
      samples.arrayName + "') give a size field; set one of them";
    return SizeField{};
  }
  return sizeFieldOfSamples(samples, error);
}

void addThicknessSamples(vtkFieldData* fieldData, const std::vector<double>& xyzt, double limit)
{
  if (xyzt.empty())
  {
    return;
  }
  vtkNew<vtkDoubleArray> values;
  values->SetName(arrays::ThicknessSamples);
  values->SetNumberOfComponents(4);
  values->SetNumberOfTuples(static_cast<vtkIdType>(xyzt.size() / 4));
  std::copy(xyzt.begin(), xyzt.end(), values->GetPointer(0));
  fieldData->AddArray(values);
  vtkNew<vtkDoubleArray> bound;
  bound->SetName(arrays::ThicknessLimit);
  bound->InsertNextValue(limit);
  fieldData->AddArray(bound);
}

SizeFunction boundarySizeOf(const SizeField& field, vtkFieldData* fieldData)
{
  auto* values =
    fieldData ? vtkDoubleArray::SafeDownCast(fieldData->GetAbstractArray(arrays::ThicknessSamples)) : nullptr;
  auto* bound =
    fieldData ? vtkDoubleArray::SafeDownCast(fieldData->GetAbstractArray(arrays::ThicknessLimit)) : nullptr;
  if (!values || values->GetNumberOfComponents() != 4 || !bound || bound->GetNumberOfTuples() != 1)
  {
    return field.size;
  }
  const double* v = values->GetPointer(0);
  return thicknessCappedSize(field.size, std::vector<double>(v, v + 4 * values->GetNumberOfTuples()),
    bound->GetValue(0));
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
      msg << field.source << " gives " << sizes[i] << " at (" << points[i][0] << ", " << points[i][1]
          << ", " << points[i][2] << "); sizes must be positive and finite";
      error = msg.str();
      return false;
    }
  }
  return true;
}
} // namespace ptm
