#pragma once
// RotationMethod: how the reduction reads a joint's rotation from its slab of
// points (paper Sec. III-C). The tiers share it because it names their files
// and models: `M1` and `M2` in the .prm files, in the stiffness CSVs' labels
// (output_files.h) and in the chain's model names.
#include <string>
#include <utility>
#include <vector>

namespace softchain::data
{
  enum class RotationMethod
  {
    bounding_box, // M1: frame spanned by the deformed edges of the slab's box
    affine_fit    // M2: rotation of the polar decomposition of the affine fit
  };

  // "M1" or "M2".
  std::string method_name(RotationMethod method);

  // Both methods with their names, M1 first: the choices of a .prm entry
  // (PrmSection::get_enum) and the order in which the tiers list them.
  const std::vector<std::pair<std::string, RotationMethod>> &rotation_methods();
} // namespace softchain::data
