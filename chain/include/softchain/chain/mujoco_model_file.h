#pragma once
// load_mujoco_model: an MJCF file compiled by MuJoCo (mj_loadXML), or
// data::InputError naming the file with MuJoCo's message. The caller owns
// the model (mj_deleteModel).
#include <mujoco/mujoco.h>

#include <string>

namespace softchain::chain
{
  mjModel *load_mujoco_model(const std::string &path);
} // namespace softchain::chain
