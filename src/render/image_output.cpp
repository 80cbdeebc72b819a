/// Images through OpenImageIO (loaded on first use: image_plugin.hpp):
/// linear EXR, or 8-bit sRGB for other formats.
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "image_plugin.hpp"
#include "stratum/distributed.hpp"
#include "stratum/render/compare.hpp"
#include "stratum/render/render.hpp"
#include "stratum/util/error.hpp"

namespace stratum::render {

namespace {

/// The sRGB transfer curve (IEC 61966-2-1).
double srgb(double linear) {
  const double v = std::clamp(linear, 0.0, 1.0);
  return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
}

/// The file name's extension in lower case (".EXR" -> ".exr").
std::string lowercase_extension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  return extension;
}

}  // namespace

void write_image(const Image& image, const std::string& path) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  const std::string extension = lowercase_extension(path);
  check_image_path("output", path);
  if (!distributed::is_root()) return;  // a distributed job writes once, from rank 0
  const bool linear = extension == ".exr" || extension == ".hdr";
  std::vector<float> floats;
  std::vector<unsigned char> bytes;
  if (linear) {
    floats.assign(image.rgb.begin(), image.rgb.end());
  } else {
    bytes.resize(image.rgb.size());
    for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<unsigned char>(std::lround(255 * srgb(image.rgb[i])));
  }
  // A temporary file with the same extension (OpenImageIO picks the format
  // by it), renamed onto `path` only when complete.
  const fs::path directory = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::string name = ".";  // appended, not a chain of +: GCC 12's -Wrestrict misfires on that chain
  name.append(target.stem().string()).append(".XXXXXX").append(extension);
  std::string pattern = (directory / name).string();
  const int fd = mkstemps(pattern.data(), static_cast<int>(extension.size()));
  if (fd < 0) throw invalid_argument("output", path, std::string("must be writable (") + std::strerror(errno) + ")");
  fchmod(fd, 0644);  // mkstemps makes it private (0600); an image is for everyone to read
  close(fd);
  try {
    if (linear) image_plugin::write(pattern, image.width, image.height, floats.data());
    else image_plugin::write(pattern, image.width, image.height, bytes.data());
  } catch (const std::runtime_error& e) {
    std::remove(pattern.c_str());
    throw invalid_argument("output", path, std::string("could not be written: ") + e.what());
  }
  fs::rename(pattern, target);
}

void check_image_path(const std::string& argument, const std::string& path) {
  bool known = false;
  try {
    known = image_plugin::writable(path);
  } catch (const std::runtime_error& e) {  // the module did not load
    throw invalid_argument(argument, path, std::string("cannot be written: ") + e.what());
  }
  if (!known) throw invalid_argument(argument, path, "must end in an image format OpenImageIO writes (.exr, .png, ...)");
  std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (folder.empty()) folder = ".";
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    throw invalid_argument(argument, path, std::string("must be writable (") + std::strerror(errno) + ")");
}

void check_variance_path(const std::string& argument, const std::string& path) {
  const std::string extension = lowercase_extension(path);
  require(extension == ".exr", argument, path, "must be an OpenEXR file (.exr): variances are linear, unbounded values");
}

void write_variance_image(const Image& image, const std::string& path) {
  check_variance_path("variance", path);
  require(image.variance.size() == image.rgb.size(), "variance", path,
          "needs the image's per-pixel variances (this image has none, e.g. a reference cached without them)");
  Image variance;
  variance.width = image.width;
  variance.height = image.height;
  variance.rgb = image.variance;
  write_image(variance, path);
}

}  // namespace stratum::render
