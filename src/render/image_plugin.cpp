#include "image_plugin.hpp"

#include <dlfcn.h>
#include <link.h>

#include <cstddef>
#include <cstdint>
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

/// Whether `address` lies in the main program (glibc's dl_iterate_phdr visits
/// it first) rather than in a shared library such as the Python module.
bool in_main_program(const void* address) {
  struct Query {
    std::uintptr_t address;
    bool inside;
  } query{reinterpret_cast<std::uintptr_t>(address), false};
  dl_iterate_phdr(
      [](dl_phdr_info* object, std::size_t, void* data) {
        auto& q = *static_cast<Query*>(data);
        for (int i = 0; i < object->dlpi_phnum; ++i) {
          const ElfW(Phdr)& segment = object->dlpi_phdr[i];
          const std::uintptr_t begin = object->dlpi_addr + segment.p_vaddr;
          if (segment.p_type == PT_LOAD && q.address >= begin && q.address < begin + segment.p_memsz) q.inside = true;
        }
        return 1;  // stop after the first object, the main program
      },
      &query);
  return query.inside;
}

/// The file of the program or shared library that holds this code, with
/// symlinks resolved; empty if unknown. For the main program dladdr gives
/// argv[0] as typed (a bare name when run through PATH), so that one is
/// read from /proc/self/exe instead.
std::filesystem::path own_file() {
  Dl_info info{};
  if (!dladdr(reinterpret_cast<void*>(&own_file), &info) || !info.dli_fname) return {};
  std::error_code error;
  const std::filesystem::path file =
      in_main_program(reinterpret_cast<void*>(&own_file)) ? std::filesystem::path("/proc/self/exe") : info.dli_fname;
  std::filesystem::path resolved = std::filesystem::canonical(file, error);
  return error ? std::filesystem::path() : resolved;
}

/// Candidates in order: the environment's; the one in the tree of the
/// program (or library) that holds this code, where `cmake --install` puts
/// it and where the build tree mirrors that layout (so a moved install tree
/// works); the build tree's (for the Python module, outside bin/); the one at
/// the configured install prefix.
std::vector<std::string> candidates() {
  std::vector<std::string> paths;
  if (const char* given = std::getenv("STRATUM_OIIO_PLUGIN"); given && *given) paths.emplace_back(given);
  if (const std::filesystem::path self = own_file(); !self.empty())
    paths.push_back((self.parent_path() / STRATUM_OIIO_PLUGIN_FROM_BINDIR).lexically_normal().string());
  paths.emplace_back(STRATUM_OIIO_PLUGIN_BUILD_PATH);
  paths.emplace_back(STRATUM_OIIO_PLUGIN_INSTALLED_PATH);
  return paths;
}

Module load(const std::vector<std::string>& paths) {
  std::string tried;
  for (const std::string& path : paths) {
    std::error_code error;
    if (!std::filesystem::exists(path, error)) {  // an unreadable folder counts as absent too
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
  const Module* loaded = nullptr;
  try {
    loaded = &module();
  } catch (const std::runtime_error& e) {
    throw invalid_argument(argument, path, std::string("cannot be read: ") + e.what());
  }
  Pixels pixels;
  const Allocate allocate = [](void* context, int width, int height, int channels) -> float* {
    auto& p = *static_cast<Pixels*>(context);
    if (width <= 0 || height <= 0 || channels < 3) return nullptr;
    p.width = width, p.height = height, p.channels = channels;
    p.values.resize(std::size_t(width) * std::size_t(height) * std::size_t(channels));
    return p.values.data();
  };
  char error[1024] = "";
  switch (loaded->read(path.c_str(), &pixels, allocate, error, sizeof error)) {
    case 0:
      return pixels;
    case 1:
      throw invalid_argument(argument, path, std::string("must be a readable image: ") + error);
    case 2:
      throw invalid_argument(argument, path, std::string("must be a 2D image with 3 or more channels: ") + error);
    default:
      throw invalid_argument(argument, path, std::string("could not be read: ") + error);
  }
}

std::string module_path() { return module().path; }

std::vector<std::string> candidate_paths() { return candidates(); }

std::string load_first(const std::vector<std::string>& paths) { return load(paths).path; }

}  // namespace stratum::render::image_plugin
