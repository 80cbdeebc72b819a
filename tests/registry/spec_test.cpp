// The sampler spec grammar NAME[(KEY=VALUE,...)][:RANDOMIZER]: parsing, the
// canonical text, list splitting, every error message, the combination with
// -p/--randomize, and the seed and thread rules (registry/spec.hpp).
#include "stratum/registry/spec.hpp"

#include <gtest/gtest.h>
#include <sched.h>

#include <algorithm>
#include <cstdlib>
#include <thread>

#include "error_of.hpp"
#include "stratum/registry.hpp"

namespace stratum {
namespace {

using testing::error_of;

/// The message parse_sampler_spec throws for `text` (empty: none).
std::string spec_error(const std::string& text) {
  return error_of([&] { parse_sampler_spec(text); });
}

/// EXPECT that `message` contains every one of `parts`.
void expect_contains(const std::string& message, std::initializer_list<std::string> parts) {
  for (const auto& part : parts)
    EXPECT_NE(message.find(part), std::string::npos) << "'" << message << "' lacks '" << part << "'";
}

TEST(SamplerSpec, ParsesTheFourForms) {
  EXPECT_EQ(parse_sampler_spec("halton"), (SamplerSpec{"halton", {}, ""}));
  EXPECT_EQ(parse_sampler_spec("sobol:owen"), (SamplerSpec{"sobol", {}, "owen"}));
  EXPECT_EQ(parse_sampler_spec("poisson-disk(periodic=1)"), (SamplerSpec{"poisson-disk", {{"periodic", "1"}}, ""}));
  EXPECT_EQ(parse_sampler_spec("jittered(strata=4x8)"), (SamplerSpec{"jittered", {{"strata", "4x8"}}, ""}));
  EXPECT_EQ(parse_sampler_spec("lattice(generator=1,55,133):cp"),
            (SamplerSpec{"lattice", {{"generator", "1,55,133"}}, "cp"}));
  // A vector value followed by another key: a comma starts a new item only when the text after it has '='.
  EXPECT_EQ(parse_sampler_spec("lattice(generator=1,55,133,gamma=0.5)"),
            (SamplerSpec{"lattice", {{"generator", "1,55,133"}, {"gamma", "0.5"}}, ""}));
  EXPECT_EQ(parse_sampler_spec("poisson-disk(candidates=10,periodic=1)"),
            (SamplerSpec{"poisson-disk", {{"candidates", "10"}, {"periodic", "1"}}, ""}));
}

TEST(SamplerSpec, FormatIsCanonicalAndRoundTrips) {
  EXPECT_EQ(format_sampler_spec({"sobol", {}, ""}), "sobol");
  EXPECT_EQ(format_sampler_spec({"sobol", {}, "owen"}), "sobol:owen");
  // Keys in key order, whatever order they were written in.
  EXPECT_EQ(format_sampler_spec(parse_sampler_spec("poisson-disk(periodic=1,candidates=10)")),
            "poisson-disk(candidates=10,periodic=1)");
  for (const char* text : {"sobol", "sobol:owen", "halton:permute", "poisson-disk(periodic=1)", "jittered(strata=4x8)",
                           "lattice(generator=1,55,133):cp", "lattice(a=76,gamma=0.5)",
                           "poisson-disk(candidates=10,periodic=1)", "kronecker(alpha=0.25,0.5):cp"}) {
    const SamplerSpec spec = parse_sampler_spec(text);
    EXPECT_EQ(format_sampler_spec(spec), text);  // these are written canonically
    EXPECT_EQ(parse_sampler_spec(format_sampler_spec(spec)), spec) << text;
  }
}

TEST(SamplerSpec, EverySamplerAndAcceptedRandomizerRoundTrips) {
  for (const auto& sampler : samplers())
    for (const auto& randomizer : sampler.randomizers) {
      const std::string text = sampler.name + ":" + randomizer;
      EXPECT_EQ(format_sampler_spec(parse_sampler_spec(text)), text);
    }
}

TEST(SamplerSpec, SyntaxErrorsNameTheSpecThePositionAndTheGrammar) {
  expect_contains(spec_error(""), {"invalid sampler = '': ", "empty sampler name at position 1"});
  expect_contains(spec_error(":owen"), {"invalid sampler = :owen: ", "empty sampler name at position 1"});
  expect_contains(spec_error("sobol:"), {"invalid sampler = sobol:: ", "empty randomizer after ':' at position 6",
                                         "NAME[(KEY=VALUE,...)][:RANDOMIZER]"});
  expect_contains(
      spec_error("lattice(generator=1,55"),
      {"invalid sampler = lattice(generator=1,55: ", "unbalanced parentheses", "'(' at position 8 is never closed"});
  expect_contains(spec_error("sobol)"), {"unbalanced parentheses", "')' at position 6 has no '('"});
  expect_contains(spec_error("sobol:owen)"), {"unbalanced parentheses", "')' at position 11 has no '('"});
  expect_contains(spec_error("jittered(=4x8)"), {"invalid sampler = jittered(=4x8): ", "empty key at position 10"});
  expect_contains(spec_error("jittered(strata=)"), {"empty value for key 'strata' at position 17", "write KEY=VALUE"});
  expect_contains(spec_error("lattice(generator=1,,2)"), {"empty value at position 21", "key 'generator'"});
  expect_contains(spec_error("poisson-disk(periodic=1,periodic=0)"),
                  {"duplicate key 'periodic' at position 25 (first at position 14)", "give each key once"});
  expect_contains(spec_error("jittered(4x8)"), {"'4x8' at position 10 is not KEY=VALUE"});
  expect_contains(spec_error("sobol()"), {"empty parameter list at position 6"});
  expect_contains(spec_error("jittered(strata=4x8)x"),
                  {"unexpected 'x' at position 21 after the parameters", "only :RANDOMIZER may follow ')'"});
  expect_contains(spec_error("sobol:owen(x=1)"),
                  {"unexpected '(' at position 11 in the randomizer", "parameters come before ':'"});
  expect_contains(spec_error("sob ol"), {"unexpected ' ' at position 4 in the sampler name"});
  expect_contains(spec_error("sobol:ow=en"), {"unexpected '=' at position 9 in the randomizer"});
  expect_contains(spec_error("jittered(str ata=4)"), {"unexpected ' ' at position 13 in the key"});
}

TEST(SamplerSpec, RegistryErrorsListWhatIsAllowed) {
  // Unknown sampler: the near names.
  expect_contains(spec_error("sobl:owen"),
                  {"invalid sampler = sobl:owen: ", "unknown sampler 'sobl' at position 1", "did you mean sobol"});
  expect_contains(spec_error("poisson"), {"unknown sampler 'poisson'", "poisson-disk"});
  // Nothing near: every name.
  expect_contains(spec_error("nosuch"), {"invalid sampler = nosuch: ", "unknown sampler 'nosuch'",
                                         "valid samplers are ", "halton", "sobol", "poisson-disk"});
  // Unknown key: the sampler's keys.
  expect_contains(spec_error("poisson-disk(periodc=1)"),
                  {"unknown key 'periodc' at position 14", "poisson-disk takes candidates, periodic"});
  expect_contains(spec_error("sobol(x=1)"), {"unknown key 'x' at position 7", "sobol takes"});
  expect_contains(spec_error("random(x=1)"), {"random takes no parameters"});
  // Randomizer: the accepted ones.
  expect_contains(spec_error("halton:owen-hash"),
                  {"invalid sampler = halton:owen-hash: ", "randomizer 'owen-hash' at position 8",
                   "is not one halton accepts", "halton accepts "});
  expect_contains(spec_error("random:bogus"), {"randomizer 'bogus' at position 8", "random accepts none"});
  // The syntax alone does not consult the registry.
  EXPECT_EQ(parse_sampler_spec_syntax("nosuch(k=v):r"), (SamplerSpec{"nosuch", {{"k", "v"}}, "r"}));
}

TEST(SamplerSpec, ListsSplitOnCommasOutsideParentheses) {
  EXPECT_EQ(split_sampler_list("sobol:owen,poisson-disk(periodic=1)"),
            (std::vector<std::string>{"sobol:owen", "poisson-disk(periodic=1)"}));
  EXPECT_EQ(split_sampler_list("lattice(generator=1,55,133):cp,random, jittered(strata=4x8)"),
            (std::vector<std::string>{"lattice(generator=1,55,133):cp", "random", "jittered(strata=4x8)"}));
  EXPECT_EQ(split_sampler_list("halton"), (std::vector<std::string>{"halton"}));
  const auto specs = parse_sampler_list("sobol:owen,lattice(generator=1,55,133,gamma=0.5)");
  ASSERT_EQ(specs.size(), 2u);
  EXPECT_EQ(specs[1], (SamplerSpec{"lattice", {{"generator", "1,55,133"}, {"gamma", "0.5"}}, ""}));
  expect_contains(error_of([] { split_sampler_list("sobol,,random"); }),
                  {"invalid samplers = sobol,,random: ", "empty item at position 7"});
  expect_contains(error_of([] { split_sampler_list(""); }), {"invalid samplers = '': ", "empty item at position 1"});
  expect_contains(error_of([] { split_sampler_list("sobol,"); }), {"empty item at position 7"});
  // Unbalanced parentheses are the spec parser's to report, in the words it uses for one spec.
  EXPECT_EQ(split_sampler_list("sobol,lattice(generator=1,2,random"),
            (std::vector<std::string>{"sobol", "lattice(generator=1,2,random"}));
  EXPECT_EQ(split_sampler_list("sobol),random"), (std::vector<std::string>{"sobol)", "random"}));
  expect_contains(
      error_of([] { parse_sampler_list("sobol,lattice(generator=1,2,random"); }),
      {"invalid sampler = lattice(generator=1,2,random: unbalanced parentheses", "'(' at position 8 is never closed"});
  expect_contains(error_of([] { parse_sampler_list("sobol),random"); }),
                  {"invalid sampler = sobol): unbalanced parentheses: ')' at position 6 has no '('"});
  expect_contains(error_of([] { parse_sampler_list("sobol,nosuch"); }), {"invalid sampler = nosuch: "});
}

TEST(SamplerSpec, CombinesParamsAndRandomizerAndRefusesConflicts) {
  EXPECT_EQ(combine_sampler_options("sobol", {}, "owen"), (SamplerSpec{"sobol", {}, "owen"}));
  EXPECT_EQ(combine_sampler_options("poisson-disk", {"periodic=1"}, ""),
            (SamplerSpec{"poisson-disk", {{"periodic", "1"}}, ""}));
  EXPECT_EQ(combine_sampler_options("poisson-disk(candidates=5)", {"periodic=1"}, ""),
            (SamplerSpec{"poisson-disk", {{"candidates", "5"}, {"periodic", "1"}}, ""}));
  expect_contains(error_of([] { combine_sampler_options("sobol:owen", {}, "xor"); }),
                  {"invalid randomize = xor: ", "conflicts with the randomizer of the sampler spec sobol:owen"});
  expect_contains(
      error_of([] { combine_sampler_options("poisson-disk(periodic=1)", {"periodic=0"}, ""); }),
      {"invalid param = periodic=0: ", "conflicts with periodic=1 in the sampler spec poisson-disk(periodic=1)"});
  expect_contains(error_of([] {
                    combine_sampler_options("poisson-disk", {"periodic=0", "periodic=1"}, "");
                  }),
                  {"invalid param = periodic=1: ", "conflicts with -p periodic=0"});
  expect_contains(error_of([] { combine_sampler_options("poisson-disk", {"periodc=1"}, ""); }),
                  {"invalid param = periodc=1: ", "poisson-disk takes candidates, periodic"});
  expect_contains(error_of([] { combine_sampler_options("random", {}, "owen"); }),
                  {"invalid randomize = owen: ", "random accepts none"});
  expect_contains(error_of([] { combine_sampler_options("poisson-disk", {"periodic"}, ""); }),
                  {"invalid param = periodic: must be written KEY=VALUE"});
  expect_contains(error_of([] { combine_sampler_options("sobl", {}, ""); }), {"unknown sampler 'sobl'"});
}

TEST(SamplerSpec, KeyValueItems) {
  EXPECT_EQ(parse_key_value("param", "a=1,2"), (std::pair<std::string, std::string>{"a", "1,2"}));
  EXPECT_EQ(parse_key_value("param", "a=b=c"), (std::pair<std::string, std::string>{"a", "b=c"}));
  for (const char* bad : {"a", "=1", "a=", ""})
    EXPECT_NE(error_of([&] { parse_key_value("measure-param", bad); }).find("invalid measure-param = "),
              std::string::npos)
        << bad;
}

TEST(SamplerSpec, SeedsAreExactlyTheIntegersBelowTwoToThe64) {
  EXPECT_EQ(parse_seed("0"), 0u);
  EXPECT_EQ(parse_seed("42"), 42u);
  EXPECT_EQ(parse_seed("18446744073709551615"), ~std::uint64_t{0});
  for (const char* bad :
       {"-1", "18446744073709551616", "99999999999999999999999", "1e3", "abc", "", "+5", " 5", "5 ", "0x10", "1.0"}) {
    const std::string message = error_of([&] { parse_seed(bad); });
    expect_contains(message, {"invalid seed = ", "must be an integer in [0, 2^64)"});
    if (*bad) {
      EXPECT_NE(message.find(std::string("invalid seed = ") + bad + ":"), std::string::npos) << message;
    }
  }
}

TEST(SamplerSpec, Uint64NamesItsArgument) {
  EXPECT_EQ(parse_uint64("start", "7"), 7u);
  expect_contains(error_of([] { parse_uint64("start", "-1"); }),
                  {"invalid start = -1: must be an integer in [0, 2^64)"});
}

TEST(SamplerSpec, ThreadRuleZeroIsEveryCore) {
  EXPECT_EQ(resolve_threads(1), 1u);
  EXPECT_EQ(resolve_threads(1024), 1024u);
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  EXPECT_EQ(resolve_threads(0), std::min(cores, 1024u));
  expect_contains(error_of([] { resolve_threads(-1); }),
                  {"invalid threads = -1: must be an integer in [0, 1024] (0: every core)"});
  expect_contains(error_of([] { resolve_threads(1025); }), {"invalid threads = 1025: "});
}

/// The CPUs of this process's affinity mask.
unsigned allowed_cpus() {
  cpu_set_t mask;
  CPU_ZERO(&mask);
  EXPECT_EQ(::sched_getaffinity(0, sizeof mask, &mask), 0);
  return static_cast<unsigned>(CPU_COUNT(&mask));
}

TEST(SamplerSpec, ThreadRuleSharesTheCoresOfAnMpiJob) {
  const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  // Bound by the launcher (a cpuset smaller than the machine), the mask is the share and the counts are not read.
  const bool bound = allowed_cpus() < hardware;
  const auto expected = [&](unsigned processes) {
    return std::clamp(bound ? allowed_cpus() : hardware / processes, 1u, 1024u);
  };
  for (const char* name : {"OMPI_COMM_WORLD_LOCAL_SIZE", "MPI_LOCALNRANKS"}) {
    ::setenv(name, "1", 1);
    EXPECT_EQ(resolve_threads(0), expected(1)) << name;
    ::setenv(name, "2", 1);
    EXPECT_EQ(local_processes(), 2u) << name;
    EXPECT_EQ(resolve_threads(0), expected(2)) << name;
    ::setenv(name, "100000", 1);  // more processes than cores: one thread each
    EXPECT_EQ(resolve_threads(0), bound ? expected(1) : 1u) << name;
    ::setenv(name, "2x", 1);  // not a count: ignored
    EXPECT_EQ(local_processes(), 1u) << name;
    EXPECT_EQ(resolve_threads(0), expected(1)) << name;
    EXPECT_EQ(resolve_threads(3), 3u) << name;  // an explicit count is kept
    ::unsetenv(name);
  }
}

TEST(SamplerSpec, ThreadRuleReadsSlurmsTasksOnThisNode) {
  // srun's SLURM_STEP_TASKS_PER_NODE: "T(xR)" is T tasks on each of R nodes.
  EXPECT_EQ(slurm_tasks_on_node("2(x3),1", 0), 2u);
  EXPECT_EQ(slurm_tasks_on_node("2(x3),1", 2), 2u);
  EXPECT_EQ(slurm_tasks_on_node("2(x3),1", 3), 1u);
  EXPECT_EQ(slurm_tasks_on_node("2(x3),1", 4), 0u);  // past the list
  EXPECT_EQ(slurm_tasks_on_node("4", 0), 4u);
  EXPECT_EQ(slurm_tasks_on_node("1,3(x2)", 2), 3u);
  for (const char* bad : {"", "x", "2(x", "2(x3", "2(x0)", "0", "-1", "2(y3)", "2,,1"})
    EXPECT_EQ(slurm_tasks_on_node(bad, 1), 0u) << bad;
  ::setenv("SLURM_STEP_TASKS_PER_NODE", "3(x2),1", 1);
  ::setenv("SLURM_NODEID", "1", 1);
  EXPECT_EQ(local_processes(), 1u);  // an allocation without a step (no SLURM_STEP_ID): not a job's process
  ::setenv("SLURM_STEP_ID", "0", 1);
  EXPECT_EQ(local_processes(), 3u);
  ::setenv("SLURM_NODEID", "2", 1);
  EXPECT_EQ(local_processes(), 1u);
  ::setenv("SLURM_NODEID", "9", 1);  // a node the list does not reach: read as one process
  EXPECT_EQ(local_processes(), 1u);
  ::setenv("OMPI_COMM_WORLD_LOCAL_SIZE", "5", 1);  // the MPI library's own count comes first
  EXPECT_EQ(local_processes(), 5u);
  for (const char* name : {"OMPI_COMM_WORLD_LOCAL_SIZE", "SLURM_STEP_TASKS_PER_NODE", "SLURM_NODEID", "SLURM_STEP_ID"})
    ::unsetenv(name);
}

TEST(SamplerSpec, ThreadRuleKeepsToTheCpusALauncherBoundItTo) {
  cpu_set_t saved;
  CPU_ZERO(&saved);
  ASSERT_EQ(::sched_getaffinity(0, sizeof saved, &saved), 0);
  int first = 0;
  while (!CPU_ISSET(first, &saved)) ++first;
  cpu_set_t one;
  CPU_ZERO(&one);
  CPU_SET(first, &one);
  ASSERT_EQ(::sched_setaffinity(0, sizeof one, &one), 0);  // as mpirun --bind-to core or taskset -c would
  const unsigned bound = resolve_threads(0);
  ::setenv("OMPI_COMM_WORLD_LOCAL_SIZE", "1", 1);
  const unsigned bound_in_job = resolve_threads(0);
  ::unsetenv("OMPI_COMM_WORLD_LOCAL_SIZE");
  ASSERT_EQ(::sched_setaffinity(0, sizeof saved, &saved), 0);
  EXPECT_EQ(bound, 1u);  // one CPU allowed: one thread, not the machine's cores
  EXPECT_EQ(bound_in_job, 1u);
  EXPECT_EQ(resolve_threads(0), std::clamp(allowed_cpus() < std::max(1u, std::thread::hardware_concurrency())
                                               ? allowed_cpus()
                                               : std::max(1u, std::thread::hardware_concurrency()),
                                           1u, 1024u));
}

}  // namespace
}  // namespace stratum
