#pragma once
// PNG (libpng) and OpenEXR (the OpenEXR library) read and written directly:
// the two formats stratum writes by default (`render -o`, `--exr`, the
// reference cache, the report's renders). They load in milliseconds, where
// OpenImageIO's module maps ~260 shared libraries and costs every process that
// writes an image ~0.4 s (image_plugin.hpp: every other format goes there).
#include <optional>
#include <string>

#include "image_plugin.hpp"

namespace stratum::render::image_codecs {

/// Whether files with this lower-case extension (".png", ".exr") are
/// written here rather than by OpenImageIO.
bool writes(const std::string& extension);
/// Writes width × height RGB pixels: 8-bit codes to a PNG, floats to a
/// ZIP-compressed OpenEXR with channels R, G, B in 32-bit float. Throws
/// std::runtime_error with the library's message when it fails.
void write_png(const std::string& path, int width, int height, const unsigned char* rgb);
void write_exr(const std::string& path, int width, int height, const float* rgb);
/// Reads what the writers above write, as OpenImageIO would read it (8-bit
/// codes / 255, floats as stored): an 8-bit RGB PNG, or a single-part
/// OpenEXR with channels R, G, B (and maybe A) whose data window is its
/// display window from (0, 0). Any other file — another layout, another
/// format, a damaged or absent file — gives nullopt: OpenImageIO reads it or
/// says why it cannot.
std::optional<image_plugin::Pixels> read(const std::string& path);

}  // namespace stratum::render::image_codecs
