#pragma once
/// Rendering a Scene: settings, the image, and the progressive loop
/// (oneTBB over tiles, one pass after another, each pass a slice of every
/// pixel's samples; the result after any pass is an unbiased estimate).
#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "stratum/render/accelerator.hpp"
#include "stratum/render/pixel_sampler.hpp"
#include "stratum/render/scene.hpp"

namespace stratum::io {
class OutputFile;
}

namespace stratum::render {

struct RenderSettings {
  std::string integrator = "direct";    ///< direct | irradiance | path
  std::uint32_t light_samples = 1;      ///< shadow rays per eye-ray hit (M)
  std::string light_strategy = "area";  ///< area | solid-angle | projected-solid-angle | bsdf | mis
  std::string hemisphere = "cosine";    ///< irradiance: uniform | cosine
  std::uint32_t max_depth = 5;          ///< path: longest path (and mirror chains in direct)
  PixelSamplerSettings sampler;         ///< spp = eye rays per pixel
  unsigned threads = 1;
  double time_limit = 0;     ///< seconds; 0: none (stops after the current pass)
  std::uint32_t passes = 4;  ///< progressive passes (at most spp)
  /// Shoot every eye ray through the pixel's centre: the estimand becomes
  /// the radiance at the centre, so that comparisons of light sampling are
  /// not swamped by the antialiasing error of edges and visible lights.
  bool pixel_centers = false;
};

/// Mean radiance per pixel (linear RGB), and the per-pixel sample variance
/// of the estimate's mean (for z-tests and variance images).
struct Image {
  int width = 0, height = 0;
  std::uint32_t samples = 0;  ///< samples per pixel actually taken (in every pixel)
  std::uint32_t passes = 0;   ///< passes completed
  /// A stop (Ctrl-C) ended the render before its last pass; `partial_pass`
  /// of its tiles had also finished the pass it cut short (their pixels
  /// average those samples too; tiles not rendered at all are black).
  bool stopped = false;
  double partial_pass = 0;
  std::vector<double> rgb;       ///< width·height·3, row-major, top row first
  std::vector<double> variance;  ///< width·height·3: variance of each channel's mean
  double seconds = 0;
};

/// Validates the settings (names, counts, the pixel sampler, and that it can
/// draw light_samples points per shading point); throws stratum::invalid_argument.
void validate_settings(const RenderSettings& settings);

/// Bytes a render of `camera`'s image allocates (96 per pixel: the sums of
/// L and L², then the Image's mean and variance); render() refuses
/// (stratum::memory_error, stratum/memory.hpp) when they are not available.
double render_working_bytes(const Camera& camera);
/// Refuses unless a render and `extra_per_pixel` more bytes per pixel (a
/// comparison's references) are available; `what` is for the message.
void require_render_memory(const Camera& camera, double extra_per_pixel, const std::string& what);

/// Renders. `progress(done_passes, total_passes, seconds)` is called after
/// each pass; `stop` (e.g. stratum::interrupt_flag(), set by Ctrl-C) ends
/// the render within the tile each thread is on (in a distributed job: after
/// the current pass), see Image::stopped. Same seed and settings: the same image for any thread count.
Image render(const Scene& scene, const RenderSettings& settings,
             const std::function<void(std::uint32_t, std::uint32_t, double)>& progress = {},
             const std::atomic<bool>* stop = nullptr);
/// Renders accelerator.scene() on a BVH built beforehand: renders of one
/// scene (compare's configurations) share one build, and Image::seconds is
/// then the sampling and tracing alone. The same image as render(scene, …).
Image render(const Accelerator& accelerator, const RenderSettings& settings,
             const std::function<void(std::uint32_t, std::uint32_t, double)>& progress = {},
             const std::atomic<bool>* stop = nullptr);

/// Writes `image` as a linear OpenEXR (.exr) or a tonemapped sRGB 8-bit
/// image (.png, .jpg, …: exposure 1, clamp, sRGB curve) through
/// OpenImageIO, through an io::OutputFile (never half-written; symbolic
/// links written through, permissions kept).
void write_image(const Image& image, const std::string& path);
/// Writes `image` into the staging file of `file` (prepared here if it is
/// not yet), checked by reading it back; the caller commits (an OutputGroup
/// commits a command's outputs together).
void write_image(const Image& image, io::OutputFile& file);
/// Checks, before any work, that write_image can write `path`: OpenImageIO's
/// module loads, it writes that extension, and the folder takes new files;
/// else stratum::invalid_argument naming `argument`.
void check_image_path(const std::string& argument, const std::string& path);

}  // namespace stratum::render
