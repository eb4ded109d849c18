#pragma once
// A MuJoCo model from MJCF text (through a virtual file), for the benchmarks against MuJoCo.
#include <fmt/format.h>
#include <mujoco/mujoco.h>

#include <array>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>

namespace tumble {

// The caller owns the model (mj_deleteModel). Throws std::runtime_error with MuJoCo's message.
inline mjModel* load_mujoco_xml(const std::string& xml, const char* name) {
  const auto vfs = std::make_unique<mjVFS>();  // about 2 MB: not on the stack
  mj_defaultVFS(vfs.get());
  if (mj_makeEmptyFileVFS(vfs.get(), name, static_cast<int>(xml.size())) != 0) {
    throw std::runtime_error("MuJoCo: cannot make the virtual file");
  }
  std::memcpy(vfs->filedata[vfs->nfile - 1], xml.data(), xml.size());
  std::array<char, 1000> error{};
  mjModel* model = mj_loadXML(name, vfs.get(), error.data(), static_cast<int>(error.size()));
  mj_deleteVFS(vfs.get());
  if (model == nullptr) throw std::runtime_error(fmt::format("MuJoCo: {}", error.data()));
  return model;
}

}  // namespace tumble
