#include <softchain/chain/mujoco_model_file.h>
#include <softchain/data/input_error.h>

namespace softchain::chain
{
  mjModel *load_mujoco_model(const std::string &path)
  {
    char     error[1000] = "";
    mjModel *model       = mj_loadXML(path.c_str(), nullptr, error, sizeof(error));
    if (!model)
      throw data::InputError("MuJoCo cannot load '" + path + "': " + error);
    return model;
  }
} // namespace softchain::chain
