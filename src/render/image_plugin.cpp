#include "image_plugin.hpp"

#include <dlfcn.h>

#include <cstddef>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <stdexcept>

#include "stratum/util/error.hpp"

namespace stratum::render::image_plugin {

namespace {

using Writable = int (*)(const char*);
using Write = int (*)(const char*, int, int, int, const void*, char*, std::size_t);
using Allocate = float* (*)(void*, int, int, int);
using Read = int (*)(const char*, void*, Allocate, char*, std::size_t);
using Version = int (*)();

struct Module {
  std::string path;
  Writable writable = nullptr;
  Write write = nullptr;
  Read read = nullptr;
};

/// Candidates in order: the environment's; the one beside the program (or
/// library) that contains this code, where `cmake --install` puts it and
/// where the build tree mirrors that layout (so a moved install tree works);
/// at the configured install prefix; the build tree's (for programs outside
/// bin/, such as the Python module).
std::vector<std::string> candidates() {
  std::vector<std::string> paths;
  if (const char* given = std::getenv("STRATUM_OIIO_PLUGIN"); given && *given) paths.emplace_back(given);
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&candidates), &info) && info.dli_fname) {
    const std::filesystem::path self = std::filesystem::absolute(info.dli_fname).parent_path();
    paths.push_back((self / STRATUM_OIIO_PLUGIN_FROM_BINDIR).lexically_normal().string());
  }
  paths.emplace_back(STRATUM_OIIO_PLUGIN_INSTALLED_PATH);
  paths.emplace_back(STRATUM_OIIO_PLUGIN_BUILD_PATH);
  return paths;
}

Module load(const std::vector<std::string>& paths) {
  std::string tried;
  for (const std::string& path : paths) {
    if (!std::filesystem::exists(path)) {
      tried += "\n  " + path + " (absent)";
      continue;
    }
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      tried += "\n  " + path + " (" + dlerror() + ")";
      continue;
    }
    Module module{path};
    const auto version = reinterpret_cast<Version>(dlsym(handle, "stratum_oiio_abi_version"));
    module.writable = reinterpret_cast<Writable>(dlsym(handle, "stratum_oiio_writable"));
    module.write = reinterpret_cast<Write>(dlsym(handle, "stratum_oiio_write"));
    module.read = reinterpret_cast<Read>(dlsym(handle, "stratum_oiio_read"));
    if (version && version() == 1 && module.writable && module.write && module.read) return module;  // kept loaded
    dlclose(handle);
    tried += "\n  " + path + " (not stratum's OpenImageIO module of this version)";
  }
  throw std::runtime_error("image files need stratum's OpenImageIO module (libstratum_oiio.so); tried:" + tried +
                           "\nset STRATUM_OIIO_PLUGIN to its path");
}

const Module& module() {
  static std::once_flag once;
  static Module loaded;
  std::call_once(once, [] { loaded = load(candidates()); });
  return loaded;
}

void write_pixels(const std::string& path, int width, int height, bool as_float, const void* pixels) {
  char error[1024] = "";
  if (module().write(path.c_str(), width, height, as_float ? 1 : 0, pixels, error, sizeof error) != 0)
    throw std::runtime_error(error);
}

}  // namespace

bool writable(const std::string& path) { return module().writable(path.c_str()) != 0; }

void write(const std::string& path, int width, int height, const float* pixels) {
  write_pixels(path, width, height, true, pixels);
}
void write(const std::string& path, int width, int height, const unsigned char* pixels) {
  write_pixels(path, width, height, false, pixels);
}

Pixels read(const std::string& path, const std::string& argument) {
  Pixels pixels;
  const Allocate allocate = [](void* context, int width, int height, int channels) -> float* {
    auto& p = *static_cast<Pixels*>(context);
    if (width <= 0 || height <= 0 || channels < 3) return nullptr;
    p.width = width, p.height = height, p.channels = channels;
    p.values.resize(std::size_t(width) * std::size_t(height) * std::size_t(channels));
    return p.values.data();
  };
  char error[1024] = "";
  switch (module().read(path.c_str(), &pixels, allocate, error, sizeof error)) {
    case 0: return pixels;
    case 1: throw invalid_argument(argument, path, std::string("must be a readable image: ") + error);
    case 2: throw invalid_argument(argument, path, "must have 3 channels");
    default: throw invalid_argument(argument, path, std::string("could not be read: ") + error);
  }
}

std::string module_path() { return module().path; }

std::string load_first(const std::vector<std::string>& paths) { return load(paths).path; }

}  // namespace stratum::render::image_plugin
