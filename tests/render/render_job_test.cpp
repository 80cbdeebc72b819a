// RenderJob: the one check of what a face asks of the renderer
// (stratum/render/render_job.hpp), and that a job renders what render() does.
#include <gtest/gtest.h>

#include "stratum/render/render_job.hpp"
#include "stratum/util/error.hpp"

namespace stratum::render {
namespace {

/// What `check(job)` refuses the job with ("" when it accepts it).
template <class Job, class Check>
std::string refusal_of(Job job, const Check& check) {
  try {
    check(job);
  } catch (const invalid_argument& e) {
    return e.what();
  }
  return "";
}

std::string refusal(const RenderJob& job) {
  return refusal_of(job, [](RenderJob& j) { prepare_render_job(j); });
}

TEST(RenderJob, RefusesEachBadFieldNamingItsValue) {
  RenderJob job;
  job.width = job.height = 4;
  const auto with = [&](auto change) {
    RenderJob changed = job;
    change(changed);
    return refusal(changed);
  };
  EXPECT_EQ(refusal(job), "");
  EXPECT_EQ(with([](RenderJob& j) { j.spp = 0; }), "invalid spp = 0: must be in [1, 2^24]");
  EXPECT_EQ(with([](RenderJob& j) { j.width = 16385; }), "invalid width = 16385: must be an integer in [1, 16384]");
  EXPECT_EQ(with([](RenderJob& j) { j.height = 0; }), "invalid height = 0: must be an integer in [1, 16384]");
  EXPECT_EQ(with([](RenderJob& j) { j.frame = -1; }).rfind("invalid frame = -1: ", 0), 0u);
  EXPECT_EQ(with([](RenderJob& j) { j.reference_spp = 0; }), "invalid reference-spp = 0: must be in [1, 2^24]");
  EXPECT_EQ(with([](RenderJob& j) { j.sampler = "no-such"; }).rfind("invalid sampler", 0), 0u);
  EXPECT_EQ(with([](RenderJob& j) { j.sampler = "sobol", j.randomize = "permute"; }).rfind("invalid randomize", 0), 0u);
  EXPECT_EQ(
      with([](RenderJob& j) { j.spp = 1, j.variance = "v.exr"; }).rfind("invalid variance = v.exr: needs spp 2", 0),
      0u);
  EXPECT_EQ(with([](RenderJob& j) { j.spp = 1, j.variance = "v.exr", j.reference = true; }),
            "");  // a reference has its own
  EXPECT_EQ(with([](RenderJob& j) { j.settings.integrator = "bdpt"; }).rfind("invalid integrator = bdpt", 0), 0u);
}

TEST(RenderJob, FillsThePixelSamplerFromTheSpecAndRendersAsRender) {
  RenderJob job;
  job.width = 8, job.height = 6, job.spp = 4, job.seed = 7, job.frame = 2;
  job.sampler = "halton:owen";
  job.settings.passes = 1;
  prepare_render_job(job);
  EXPECT_EQ(job.settings.sampler.sampler, "halton");
  EXPECT_EQ(job.settings.sampler.randomize, "owen");
  EXPECT_EQ(job.settings.sampler.spp, 4u);
  EXPECT_EQ(job.settings.sampler.seed, 7u);
  EXPECT_EQ(job.settings.sampler.frame, 2u);
  const Scene scene = job_scene(job);
  EXPECT_EQ(scene.camera.width, 8);
  EXPECT_EQ(scene.camera.height, 6);
  const RenderJobResult result = run_render_job(job, scene);
  const Image direct = render(scene, job.settings);
  EXPECT_EQ(result.image.rgb, direct.rgb);
  EXPECT_FALSE(result.cached);
}

}  // namespace
}  // namespace stratum::render

namespace stratum::render {
namespace {

std::string compare_refusal(const CompareJob& job) {
  return refusal_of(job, [](const CompareJob& j) { run_compare_job(j); });
}

TEST(CompareJob, RefusesEachBadFieldBeforeRendering) {
  CompareJob job;
  job.width = job.height = 4, job.reference_spp = 4;
  const auto with = [&](auto change) {
    CompareJob changed = job;
    change(changed);
    return compare_refusal(changed);
  };
  EXPECT_EQ(with([](CompareJob& j) { j.width = 0; }), "invalid width = 0: must be an integer in [1, 16384]");
  EXPECT_EQ(with([](CompareJob& j) { j.reference_spp = 0; }), "invalid reference-spp = 0: must be in [1, 2^24]");
  EXPECT_EQ(with([](CompareJob& j) { j.repeats = 1001; }), "invalid repeats = 1001: must be in [1, 1000]");
  EXPECT_EQ(
      with([](CompareJob& j) { j.confidence = 0.9; }).rfind("invalid confidence = 0.9: applies with repeats 2", 0), 0u);
  EXPECT_EQ(with([](CompareJob& j) { j.repeats = 2, j.confidence = 1.5; }),
            "invalid confidence = 1.5: must be in (0, 1)");
  EXPECT_EQ(
      with([](CompareJob& j) {
        j.builtin = "path", j.configs = "[]";
      }).rfind("invalid configs = (the configs given): give a built-in comparison or configurations, not both", 0),
      0u);
  // Configurations given as empty text are read (and refused), not taken for "none given".
  EXPECT_EQ(with([](CompareJob& j) { j.configs = ""; }).rfind("invalid configs = (the configs given): is empty", 0),
            0u);
  EXPECT_EQ(with([](CompareJob& j) { j.builtin = "nope"; }).rfind("invalid comparison = nope", 0), 0u);
}

TEST(CompareJob, RunsTheConfigurationsItIsGiven) {
  CompareJob job;
  job.width = job.height = 4, job.reference_spp = 8, job.seed = 3;
  job.options.cache_dir = testing::TempDir() + "/compare-job-cache";
  job.configs = R"([{"label": "a", "spp": 2, "sampler": "random"}, {"label": "b", "spp": 2, "sampler": "sobol"}])";
  const CompareJobResult result = run_compare_job(job);
  ASSERT_EQ(result.repeated.summary.size(), 2u);
  EXPECT_EQ(result.repeated.summary[0].label, "a");
  EXPECT_EQ(result.repeated.summary[1].label, "b");
  EXPECT_EQ(result.confidence, 0.95);
}

}  // namespace
}  // namespace stratum::render
