#pragma once
// Image files through OpenImageIO, loaded on first use (see
// oiio_plugin/oiio_plugin.cpp for why): the module is looked for at
// $STRATUM_OIIO_PLUGIN, then at <program's directory>/../<libdir>/stratum/
// (installed or in the build tree), in the build tree, at the install prefix.
#include <string>
#include <vector>

namespace stratum::render::image_plugin {

/// Whether OpenImageIO writes files with this name's extension.
bool writable(const std::string& path);
/// Writes width × height RGB pixels (float or 8-bit) to `path`; throws
/// std::runtime_error with OpenImageIO's message when it fails.
void write(const std::string& path, int width, int height, const float* pixels);
void write(const std::string& path, int width, int height, const unsigned char* pixels);

/// An image read as float, all its channels interleaved.
struct Pixels {
  int width = 0, height = 0, channels = 0;
  std::vector<float> values;
};
/// Reads `path`; throws stratum::invalid_argument naming the argument `argument`.
Pixels read(const std::string& path, const std::string& argument);

/// Where the module was loaded from (loads it; for tests and messages).
std::string module_path();
/// Where the module is looked for, in order (what module_path() tries).
std::vector<std::string> candidate_paths();
/// Loads the first of `paths` that is stratum's module of this interface
/// version and returns its path; else throws std::runtime_error naming each
/// path and why it was passed over. (What module() does with its candidates.)
std::string load_first(const std::vector<std::string>& paths);

}  // namespace stratum::render::image_plugin
