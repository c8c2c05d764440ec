#include "SizeField.h"

#include "SurfaceComplexArrays.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFunctionParser.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStaticPointLocator.h"
#include "vtkStringArray.h"

#include <cmath>
#include <memory>
#include <sstream>

namespace ptm
{
namespace
{
// Shepard's interpolation over this many nearest samples: enough that the
// field is smooth between surface samples, few enough to stay local.
constexpr int kNeighbours = 8;

std::string pointText(const double* p)
{
  std::ostringstream s;
  s.precision(9);
  s << "(" << p[0] << ", " << p[1] << ", " << p[2] << ")";
  return s.str();
}

// The locator and its scratch list: one per field, used by one thread (as
// the expression's parser).
struct Interpolator
{
  vtkNew<vtkPolyData> cloud;
  vtkNew<vtkStaticPointLocator> locator;
  vtkNew<vtkIdList> nearest;
  std::vector<double> sizes;

  double operator()(const Vec3& p)
  {
    this->locator->FindClosestNPoints(kNeighbours, p.data(), this->nearest);
    double weighted = 0.0;
    double total = 0.0;
    for (vtkIdType k = 0; k < this->nearest->GetNumberOfIds(); ++k)
    {
      const vtkIdType id = this->nearest->GetId(k);
      double q[3];
      this->cloud->GetPoint(id, q);
      const double d2 = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
        (p[2] - q[2]) * (p[2] - q[2]);
      if (d2 == 0.0)
      {
        return this->sizes[static_cast<std::size_t>(id)];
      }
      weighted += this->sizes[static_cast<std::size_t>(id)] / d2;
      total += 1.0 / d2;
    }
    return weighted / total;
  }
};
} // namespace

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
  error.clear();
  SizeField field;
  const std::size_t n = samples.xyzh.size() / 4;
  if (n == 0)
  {
    error = "SizeArray '" + samples.arrayName + "' has no values (the size source has no points)";
    return field;
  }
  auto state = std::make_shared<Interpolator>();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(n));
  state->sizes.resize(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const double* s = &samples.xyzh[4 * i];
    if (!(s[3] > 0) || !std::isfinite(s[3]))
    {
      std::ostringstream msg;
      msg << "SizeArray '" << samples.arrayName << "' is " << s[3] << " at " << pointText(s)
          << "; sizes must be positive and finite";
      error = msg.str();
      return field;
    }
    points->SetPoint(static_cast<vtkIdType>(i), s);
    state->sizes[i] = s[3];
  }
  state->cloud->SetPoints(points);
  state->locator->SetDataSet(state->cloud);
  state->locator->BuildLocator();
  field.source = "SizeArray '" + samples.arrayName + "'";
  field.size = [state](const Vec3& p) { return (*state)(p); };
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
      msg << field.source << " gives " << sizes[i] << " at " << pointText(points[i].data())
          << "; sizes must be positive and finite";
      error = msg.str();
      return false;
    }
  }
  return true;
}
} // namespace ptm
