#include "stratum/render/compare.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <utility>

#include "image_codecs.hpp"
#include "image_plugin.hpp"
#include "stratum/analysis/image_spectrum.hpp"
#include "stratum/distributed.hpp"
#include "stratum/io/json.hpp"
#include "stratum/io/output_file.hpp"
#include "stratum/registry/spec.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/hash.hpp"
#include "stratum/util/interrupt.hpp"

namespace stratum::render {

namespace {

RenderSettings base(const std::string& integrator, std::uint32_t spp, unsigned threads, std::uint64_t seed) {
  RenderSettings s;
  s.integrator = integrator;
  s.sampler.spp = spp;
  s.sampler.seed = seed;
  s.sampler.sampler = "random";
  s.threads = threads;
  return s;
}

CompareConfig with(std::string label, RenderSettings s, const std::function<void(RenderSettings&)>& change) {
  change(s);
  return {std::move(label), std::move(s)};
}

}  // namespace

const std::vector<std::pair<std::string, std::string>>& builtin_comparisons() {
  static const std::vector<std::pair<std::string, std::string>> list = {
      {"shadow-rays", "direct lighting, 1 vs 16 shadow rays per eye ray (LECTURE.md §2)"},
      {"light-strategy", "4 eye rays x 100 shadow rays, area vs solid-angle light sampling (§3)"},
      {"hemisphere", "irradiance, uniform vs cosine-weighted hemisphere sampling (§3)"},
      {"time-pattern", "motion blur: random vs Cook vs magic-square time assignment, 16 spp (§8)"},
      {"path", "path tracing at equal ray budget: complete (4 eye x 16 shadow) vs incomplete (64 x 1) (§9)"},
      {"pixel-samplers", "direct lighting, 16 spp: random vs jittered vs Owen-scrambled Sobol' vs PMJ02 (§4)"},
  };
  return list;
}

std::vector<CompareConfig> builtin_comparison(const std::string& name, unsigned threads, std::uint64_t seed) {
  if (name == "shadow-rays") {
    RenderSettings s = base("direct", 4, threads, seed);
    s.pixel_centers = true;
    return {with("1 shadow ray", s, [](auto& c) { c.light_samples = 1; }),
            with("16 shadow rays", s, [](auto& c) { c.light_samples = 16; })};
  }
  if (name == "light-strategy") {
    RenderSettings s = base("direct", 4, threads, seed);
    s.pixel_centers = true;
    s.light_samples = 100;
    return {with("area", s, [](auto& c) { c.light_strategy = "area"; }),
            with("solid angle", s, [](auto& c) { c.light_strategy = "solid-angle"; })};
  }
  if (name == "hemisphere") {
    RenderSettings s = base("irradiance", 4, threads, seed);
    s.pixel_centers = true;
    s.light_samples = 16;
    return {with("uniform", s, [](auto& c) { c.hemisphere = "uniform"; }),
            with("cosine", s, [](auto& c) { c.hemisphere = "cosine"; })};
  }
  if (name == "time-pattern") {
    const RenderSettings s = base("direct", 16, threads, seed);
    return {with("random time", s, [](auto& c) { c.sampler.time_pattern = "random"; }),
            with("cook", s, [](auto& c) { c.sampler.time_pattern = "cook"; }),
            with("magic square", s, [](auto& c) { c.sampler.time_pattern = "magic-square"; })};
  }
  if (name == "path") {
    const RenderSettings s = base("path", 4, threads, seed);
    return {with("complete 4x16", s, [](auto& c) { c.light_samples = 16; }),
            with("incomplete 64x1", s, [](auto& c) { c.sampler.spp = 64, c.light_samples = 1; })};
  }
  if (name == "pixel-samplers") {
    const RenderSettings s = base("direct", 16, threads, seed);
    return {with("random", s, [](auto& c) { c.sampler.sampler = "random"; }),
            with("jittered", s, [](auto& c) { c.sampler.sampler = "jittered"; }),
            with("sobol owen-hash", s, [](auto& c) { c.sampler.sampler = "sobol"; }),
            with("pmj02", s, [](auto& c) { c.sampler.sampler = "pmj02"; })};
  }
  std::string names;
  for (const auto& [n, d] : builtin_comparisons()) names += (names.empty() ? "" : ", ") + n;
  throw invalid_argument("comparison", name, "built-in comparisons are " + names);
}

std::vector<CompareConfig> parse_configs(const nlohmann::json& configs, unsigned threads, std::uint64_t seed) {
  std::vector<CompareConfig> result = read_configs(configs, base("direct", 16, threads, seed));
  for (std::size_t i = 0; i < result.size(); ++i) {
    RenderSettings& s = result[i].settings;
    // "sampler" is a spec (docs/samplers.md); "randomize" its :RANDOMIZER part, given once.
    set_pixel_sampler(s.sampler, s.sampler.sampler, {}, s.sampler.randomize);
    validate_settings(s);
  }
  return result;
}

void set_pixel_sampler(PixelSamplerSettings& settings, const std::string& spec, const std::vector<std::string>& params,
                       const std::string& randomize) {
  const SamplerSpec parsed = combine_sampler_options(spec, params, randomize);
  settings.sampler = parsed.name;
  settings.params = parsed.params;
  settings.randomize = parsed.randomize;
}

double mean_squared_error(const Image& image, const Image& reference) {
  require(image.rgb.size() == reference.rgb.size(), "reference", "(another resolution)", "must match the image's size");
  double sum = 0;
  for (std::size_t i = 0; i < image.rgb.size(); ++i)
    sum += (image.rgb[i] - reference.rgb[i]) * (image.rgb[i] - reference.rgb[i]);
  return sum / double(image.rgb.size());
}

double relative_mean_squared_error(const Image& image, const Image& reference) {
  require(image.rgb.size() == reference.rgb.size(), "reference", "(another resolution)", "must match the image's size");
  double sum = 0;
  for (std::size_t i = 0; i < image.rgb.size(); ++i) {
    const double e = image.rgb[i] - reference.rgb[i];
    sum += e * e / (reference.rgb[i] * reference.rgb[i] + 0.01);
  }
  return sum / double(image.rgb.size());
}

Image read_image(const std::string& path) {
  std::optional<image_plugin::Pixels> direct = image_codecs::read(path);  // PNG and EXR as stratum writes them
  const image_plugin::Pixels pixels = direct ? std::move(*direct) : image_plugin::read(path, "image");
  Image image;
  image.width = pixels.width;
  image.height = pixels.height;
  image.rgb.resize(std::size_t(pixels.width) * pixels.height * 3);
  for (std::size_t p = 0; p < std::size_t(pixels.width) * pixels.height; ++p)
    for (int c = 0; c < 3; ++c) image.rgb[3 * p + c] = pixels.values[p * pixels.channels + c];
  return image;
}

namespace {

RenderSettings reference_settings(const RenderSettings& settings, std::uint32_t spp) {
  RenderSettings reference = settings;
  reference.sampler = PixelSamplerSettings{"sobol", "owen-hash", 0x7265665ULL, spp, ""};
  reference.light_strategy = "solid-angle";
  reference.light_samples = 4;
  reference.hemisphere = "cosine";
  reference.time_limit = 0;
  return reference;
}

std::string variance_sibling(const std::string& path) { return path.substr(0, path.size() - 4) + ".variance.exr"; }

/// "3-16 shadow rays" -> "3-16-shadow-rays": a file name for a row.
std::string file_name_for(std::size_t index, const std::string& label) {
  std::string name = std::to_string(index) + "-";
  for (const char c : label) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '-';
  return name + ".exr";
}

}  // namespace

std::string reference_cache_path(const Scene& scene, const std::string& scene_key, const RenderSettings& settings,
                                 std::uint32_t spp, const std::string& cache_dir) {
  const std::uint64_t key = hash64(std::hash<std::string>{}(scene_key), std::hash<std::string>{}(settings.integrator),
                                   settings.max_depth, spp, std::uint64_t(scene.camera.width),
                                   std::uint64_t(scene.camera.height), std::uint64_t(settings.pixel_centers), 2);
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(key));
  return (std::filesystem::path(cache_dir) / (scene.name + "-" + settings.integrator + "-" + hex + ".exr")).string();
}

namespace {

/// The metadata beside a cached reference: "X.exr" -> "X.json".
std::string metadata_sibling(const std::string& path) { return path.substr(0, path.size() - 4) + ".json"; }

/// FNV-1a (64 bits) of a file's bytes and its size; false when it cannot be read.
bool file_fingerprint(const std::string& path, std::uint64_t& size, std::string& hex) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return false;
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  size = 0;
  unsigned char buffer[1 << 16];
  for (std::size_t got; (got = std::fread(buffer, 1, sizeof buffer, file)) > 0;) {
    for (std::size_t i = 0; i < got; ++i) hash = (hash ^ buffer[i]) * 0x100000001b3ULL;
    size += got;
  }
  const bool ok = !std::ferror(file);
  std::fclose(file);
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  hex = text;
  return ok;
}

nlohmann::json fingerprint_entry(const std::string& staged) {
  std::uint64_t size = 0;
  std::string hex;
  if (!file_fingerprint(staged, size, hex)) throw std::runtime_error("cache: cannot read back " + staged);
  return {{"bytes", size}, {"fnv1a64", hex}};
}

/// Loads a cached reference after checking it against its metadata; empty `why` when it is sound.
Image load_cached_reference(const std::string& path, std::uint32_t spp, std::string& why) {
  const std::string meta_path = metadata_sibling(path), variance_path = variance_sibling(path);
  Image image;
  try {
    if (!std::filesystem::exists(meta_path)) {
      why = "it has no metadata " + meta_path + " (written by an older stratum, or cut short)";
      return image;
    }
    const nlohmann::json meta = io::parse_json(io::read_regular_file("cache", meta_path, 1 << 20), "cache", meta_path);
    if (!meta.is_object() || meta.value("format", "") != "stratum-reference-1") {
      why = meta_path + " is not stratum's reference metadata";
      return image;
    }
    for (const auto& [file, key] : {std::pair{path, "image"}, std::pair{variance_path, "variance"}}) {
      std::uint64_t size = 0;
      std::string hex;
      if (!file_fingerprint(file, size, hex)) {
        why = file + " cannot be read";
        return image;
      }
      const nlohmann::json& expected = meta.at(key);
      if (expected.at("bytes").get<std::uint64_t>() != size || expected.at("fnv1a64").get<std::string>() != hex) {
        why = file + " is not the file its metadata describes (" + std::to_string(size) + " bytes, fingerprint " + hex +
              ")";
        return image;
      }
    }
    image = read_image(path);
    image.variance = read_image(variance_path).rgb;
    if (image.width != meta.at("width").get<int>() || image.height != meta.at("height").get<int>() ||
        image.variance.size() != image.rgb.size()) {
      why = "its images do not have the size in its metadata";
      return Image{};
    }
    image.samples = spp;
    why.clear();
  } catch (const std::exception& e) {
    why = e.what();
    image = Image{};
  }
  return image;
}

}  // namespace

Image reference_image(const Scene& scene, const std::string& scene_key, const RenderSettings& settings,
                      std::uint32_t spp, const std::string& cache_dir, bool* cached, std::string* warning,
                      const std::function<void(std::uint32_t, std::uint32_t, double)>& progress) {
  const std::string path = reference_cache_path(scene, scene_key, settings, spp, cache_dir);
  const bool there = std::filesystem::exists(path) || std::filesystem::exists(metadata_sibling(path));
  std::string why = "not cached";
  Image loaded = there ? load_cached_reference(path, spp, why) : Image{};
  // Used only if every process of a distributed job has a sound entry (their
  // caches need not be shared): otherwise they render it together.
  if (!distributed::any(!why.empty())) {
    if (cached) *cached = true;
    return loaded;
  }
  if (there && !why.empty()) {
    const std::string message = "the cached reference " + path + " is not sound (" + why + "): rendering it again";
    if (warning) *warning = message;
    else std::fprintf(stderr, "stratum: warning: %s\n", message.c_str());
  }
  if (cached) *cached = false;
  std::error_code error;
  std::filesystem::create_directories(cache_dir, error);
  if (error) throw invalid_argument("cache", cache_dir, "must be a folder stratum can create: " + error.message());
  // Staged before the render; the metadata goes in place last, so an entry
  // is trusted only once its images are complete and match it.
  io::OutputGroup entry;
  io::OutputFile* variance = entry.add("cache", variance_sibling(path));
  io::OutputFile* picture = entry.add("cache", path);
  io::OutputFile* meta = entry.add("cache", metadata_sibling(path));
  entry.prepare();
  Image image = render(scene, reference_settings(settings, spp), progress, &interrupt_flag());
  if (image.stopped) throw interrupted();  // nothing cached
  // Rounded to what the cache stores (32-bit floats), so a measurement
  // against a fresh reference equals one against its cached copy.
  for (double& v : image.rgb) v = static_cast<float>(v);
  for (double& v : image.variance) v = static_cast<float>(v);
  write_variance_image(image, *variance);
  write_image(image, *picture);
  if (!meta->active()) return image;  // written by rank 0 of a distributed job
  const nlohmann::json metadata = {{"format", "stratum-reference-1"},
                                   {"width", image.width},
                                   {"height", image.height},
                                   {"spp", spp},
                                   {"image", fingerprint_entry(picture->staging())},
                                   {"variance", fingerprint_entry(variance->staging())}};
  meta->write([&](std::ostream& out) { out << metadata.dump(1) << "\n"; });
  entry.commit();
  return image;
}

namespace {

/// Whether equal-time passes may continue one progressive set and stop
/// after any pass: the sampler is progressive and each of its points is
/// uniform on its own under the randomizer (the registry's typed flags,
/// SamplerFlags::prefix_unbiased; Owen 1997, "Scrambled net variance for
/// integrals of smooth functions"), so any prefix of a pixel's set is an
/// unbiased estimate. A time pattern draws whole space-time sets.
bool prefix_unbiased(const PixelSamplerSettings& s) {
  const SamplerInfo& sampler = find_sampler(s.sampler);
  return s.time_pattern.empty() && sampler.flags.progressive && stratum::prefix_unbiased(sampler, s.randomize);
}

/// Samples per pixel of one progressive set in equal-time rendering.
constexpr std::uint32_t progressive_set = 4096;

}  // namespace

Image render_equal_time(const Accelerator& accelerator, const RenderSettings& settings, double seconds,
                        std::uint32_t* passes) {
  require(std::isfinite(seconds) && seconds > 0 && seconds <= 1e6, "equal-time", seconds,
          "must be in (0, 1e6] seconds");
  validate_settings(settings);
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  const std::uint32_t spp = settings.sampler.spp;
  const bool progressive = prefix_unbiased(settings.sampler);
  const std::uint32_t set_passes = progressive ? std::max<std::uint32_t>(1, progressive_set / spp) : 1;
  Image total;
  std::uint64_t samples = 0;
  for (std::uint32_t set = 0; samples == 0 || elapsed() < seconds; ++set) {
    // One render per set: a progressive one stops after the pass (spp
    // samples) that reaches the remaining time.
    RenderSettings pass = settings;
    pass.sampler.spp = spp * set_passes;
    pass.passes = set_passes;
    pass.time_limit = progressive ? std::max(seconds - elapsed(), 1e-9) : 0;
    if (set > 0) pass.sampler.seed = hash64(settings.sampler.seed, set);
    const Image image = render(accelerator, pass, {}, &interrupt_flag());
    if (image.stopped) throw interrupted();
    const double n = image.samples;
    if (set == 0) {
      total = image;
      for (double& v : total.rgb) v *= n;
      for (double& v : total.variance) v *= n * n;
    } else {
      for (std::size_t i = 0; i < total.rgb.size(); ++i) {
        total.rgb[i] += n * image.rgb[i];
        total.variance[i] += n * n * image.variance[i];
      }
    }
    samples += image.samples;
    if (samples + std::uint64_t(spp) * set_passes > std::numeric_limits<std::uint32_t>::max()) break;
  }
  // The mean of all samples; the variance of that mean from the sets'.
  const double n = double(samples);
  for (double& v : total.rgb) v /= n;
  for (double& v : total.variance) v /= n * n;
  total.samples = std::uint32_t(samples);
  total.seconds = elapsed();
  if (passes) *passes = std::uint32_t(samples / spp);
  return total;
}

namespace {
constexpr double luminance_weights[3] = {0.2126, 0.7152, 0.0722};  // Rec. 709 / sRGB primaries
}  // namespace

std::vector<double> luminance_error(const Image& image, const Image& reference) {
  require(image.width == reference.width && image.height == reference.height, "reference",
          std::to_string(reference.width) + "x" + std::to_string(reference.height),
          "must have the image's size " + std::to_string(image.width) + "x" + std::to_string(image.height));
  std::vector<double> error(std::size_t(image.width) * std::size_t(image.height));
  for (std::size_t p = 0; p < error.size(); ++p) {
    double e = 0;
    for (int c = 0; c < 3; ++c) e += luminance_weights[c] * (image.rgb[3 * p + c] - reference.rgb[3 * p + c]);
    error[p] = e;
  }
  return error;
}

std::vector<CompareRow> compare(const Scene& scene, const std::string& scene_key,
                                const std::vector<CompareConfig>& configs, std::uint32_t reference_spp,
                                const std::string& cache_dir) {
  CompareOptions options;
  options.reference_spp = reference_spp;
  options.cache_dir = cache_dir;
  return compare(scene, scene_key, configs, options);
}

std::vector<CompareRow> compare(const Scene& scene, const std::string& scene_key,
                                const std::vector<CompareConfig>& configs, const CompareOptions& options,
                                CompareImages* images) {
  require(options.reference_spp >= 1 && options.reference_spp <= (1u << 24), "reference-spp", options.reference_spp,
          "must be in [1, 2^24]");
  require(std::isfinite(options.equal_time) && options.equal_time >= 0 && options.equal_time <= 1e6, "equal-time",
          options.equal_time, "must be in [0, 1e6] seconds (0: equal samples)");
  require(!configs.empty(), "configs", "(none)", "must name at least one configuration");
  for (const CompareConfig& config : configs) validate_settings(config.settings);
  if (!options.variance_dir.empty()) {
    std::error_code error;
    std::filesystem::create_directories(options.variance_dir, error);
    if (error)
      throw invalid_argument("variance-dir", options.variance_dir,
                             "must be a folder stratum can create: " + error.message());
  }
  // Every variance image staged before the first render; all put in place at the end.
  io::OutputGroup variance_files;
  std::vector<io::OutputFile*> variance_file(configs.size(), nullptr);
  if (!options.variance_dir.empty()) {
    for (std::size_t index = 0; index < configs.size(); ++index)
      variance_file[index] = variance_files.add(
          "variance-dir",
          (std::filesystem::path(options.variance_dir) / file_name_for(index, configs[index].label)).string());
    variance_files.prepare();
  }
  {  // the memory of a render, of an equal-time total and of one reference (an Image) per estimand
    std::set<std::string> estimands;
    for (const CompareConfig& config : configs)
      estimands.insert(config.settings.integrator + "/" + std::to_string(config.settings.max_depth) +
                       (config.settings.pixel_centers ? "/centres" : ""));
    const double image_bytes = 6 * sizeof(double);  // per pixel: mean and variance, 3 channels
    require_render_memory(scene.camera, image_bytes * double(1 + estimands.size()),
                          "comparison (a render, its total and " + std::to_string(estimands.size()) +
                              " reference image" + (estimands.size() == 1 ? ")" : "s)"));
  }
  const Accelerator accelerator(scene);     // one BVH for every configuration
  std::map<std::string, Image> references;  // one per estimand (integrator)
  std::vector<CompareRow> rows;
  for (std::size_t index = 0; index < configs.size(); ++index) {
    const CompareConfig& config = configs[index];
    const std::string estimand = config.settings.integrator + "/" + std::to_string(config.settings.max_depth) +
                                 (config.settings.pixel_centers ? "/centres" : "");
    if (!references.count(estimand)) {
      bool cached = false;
      references[estimand] =
          reference_image(scene, scene_key, config.settings, options.reference_spp, options.cache_dir, &cached);
      if (images) {
        images->reference_cached = images->reference_cached && cached;
        if (references.size() == 1) images->reference = references[estimand];
      }
    }
    CompareRow row;
    Image image = options.equal_time > 0
                      ? render_equal_time(accelerator, config.settings, options.equal_time, &row.passes)
                      : render(accelerator, config.settings, {}, &interrupt_flag());
    if (image.stopped) throw interrupted();
    row.label = config.label;
    row.samples = image.samples;
    row.mse = mean_squared_error(image, references[estimand]);
    row.relative_mse = relative_mean_squared_error(image, references[estimand]);
    row.seconds = image.seconds;
    row.efficiency = 1 / (row.mse * row.seconds);
    if (image.width >= 4 && image.height >= 4) {  // else low_frequency_power stays NaN
      const std::vector<double> error = luminance_error(image, references[estimand]);
      // A perfect render (the same error everywhere) has no spectrum.
      if (std::any_of(error.begin(), error.end(), [&](double e) { return e != error.front(); })) {
        const analysis::ImageSpectrum spectrum = analysis::image_spectrum(error, image.width, image.height);
        row.low_frequency_power = spectrum.low_frequency_power;
        row.error_radial_frequency = spectrum.radial_frequency;
        row.error_radial_power = spectrum.radial_power;
      }
    }
    if (!options.variance_dir.empty()) {
      row.variance_path = variance_file[index]->path();
      write_variance_image(image, *variance_file[index]);
    }
    rows.push_back(row);
    if (images) images->images.push_back(std::move(image));
  }
  variance_files.commit();
  for (CompareRow& row : rows) {
    row.mse_ratio = rows.front().mse / row.mse;
    row.efficiency_ratio = row.efficiency / rows.front().efficiency;
  }
  return rows;
}

}  // namespace stratum::render
