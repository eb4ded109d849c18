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

// A MuJoCo model and its data, owned together: deleted with it. Not copyable, so neither is a
// benchmark's class that holds one.
class MuJoCoModel {
 public:
  MuJoCoModel() = default;
  MuJoCoModel(const MuJoCoModel&) = delete;
  MuJoCoModel& operator=(const MuJoCoModel&) = delete;
  ~MuJoCoModel() {
    if (data_ != nullptr) mj_deleteData(data_);
    if (model_ != nullptr) mj_deleteModel(model_);
  }
  // From MJCF text (load_mujoco_xml), with fresh data.
  void load(const std::string& xml, const char* name) {
    model_ = load_mujoco_xml(xml, name);
    data_ = mj_makeData(model_);
  }
  mjModel* model() const { return model_; }
  mjData* data() const { return data_; }

 private:
  mjModel* model_ = nullptr;
  mjData* data_ = nullptr;
};

}  // namespace tumble
