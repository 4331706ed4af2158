#include <softchain/data/rotation_method.h>

#include <stdexcept>

namespace softchain::data
{
  const std::vector<std::pair<std::string, RotationMethod>> &rotation_methods()
  {
    static const std::vector<std::pair<std::string, RotationMethod>> methods = {
      {"M1", RotationMethod::bounding_box}, {"M2", RotationMethod::affine_fit}};
    return methods;
  }

  std::string method_name(const RotationMethod method)
  {
    for (const auto &[name, m] : rotation_methods())
      if (m == method)
        return name;
    throw std::invalid_argument("method_name: not a RotationMethod");
  }
} // namespace softchain::data
