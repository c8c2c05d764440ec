#ifndef PTM_PROPERTY_CHECKS_H
#define PTM_PROPERTY_CHECKS_H
// Collects the property values a filter refuses, one clause per bad property
// ("MinimumAngle must lie in [1, 34] degrees, not 50"), so the error names
// exactly what is wrong and the allowed range. Property values are the same on
// every rank, so every rank refuses together without communicating.
#include <sstream>
#include <string>

namespace ptm
{
class PropertyChecks
{
public:
  explicit PropertyChecks(std::string filterName)
    : FilterName(std::move(filterName))
  {
  }

  // Records "<name> must <rule>, not <value>" unless `ok`.
  template <typename T>
  void Require(bool ok, const char* name, const char* rule, T value)
  {
    if (ok)
    {
      return;
    }
    std::ostringstream clause;
    clause << name << " must " << rule << ", not " << value;
    this->Problems += (this->Problems.empty() ? "" : "; ") + clause.str();
  }

  bool Ok() const { return this->Problems.empty(); }

  // "<filter>: <clause>; <clause>"
  std::string Message() const { return this->FilterName + ": " + this->Problems; }

private:
  std::string FilterName;
  std::string Problems;
};
} // namespace ptm
#endif
