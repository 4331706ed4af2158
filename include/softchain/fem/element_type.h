#pragma once
// ElementType: the Lagrange element of `Mesh/Element type` -- Q1/Q2 on
// hexahedra, P1/P2 on tetrahedra -- with its cell shape and degree. The .prm
// and the database name it by the letters below.
#include <string>

namespace softchain::fem
{
  enum class ElementType
  {
    Q1,
    Q2,
    P1,
    P2
  };

  // "Q1", "Q2", "P1" or "P2".
  std::string name(ElementType type);
  // Tetrahedral (P) rather than hexahedral (Q) cells.
  bool is_simplex(ElementType type);
  // Polynomial degree, 1 or 2.
  unsigned int degree(ElementType type);
} // namespace softchain::fem
