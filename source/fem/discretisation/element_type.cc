#include <softchain/fem/element_type.h>

namespace softchain::fem
{
  std::string name(const ElementType type)
  {
    switch (type)
      {
        case ElementType::Q1:
          return "Q1";
        case ElementType::Q2:
          return "Q2";
        case ElementType::P1:
          return "P1";
        case ElementType::P2:
          return "P2";
      }
    return "";
  }

  bool is_simplex(const ElementType type)
  {
    return type == ElementType::P1 || type == ElementType::P2;
  }

  unsigned int degree(const ElementType type)
  {
    return (type == ElementType::Q1 || type == ElementType::P1) ? 1 : 2;
  }
} // namespace softchain::fem
