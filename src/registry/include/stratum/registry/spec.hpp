#pragma once
/// The sampler spec, one grammar for every face (docs/samplers.md):
///
///     NAME[(KEY=VALUE,...)][:RANDOMIZER]
///
/// e.g. `sobol:owen`, `poisson-disk(periodic=1)`, `jittered(strata=4x8)`,
/// `lattice(generator=1,55,133):cp`. Inside the parentheses a comma followed
/// by text without '=' continues the previous value (vector values); a list
/// of specs splits on the commas outside parentheses. The CLI, Python,
/// analysis studies and the report all parse through these functions, so a
/// spec means the same thing and is refused with the same message everywhere.
///
/// Also here: the numbers every face reads the same way (seeds, threads).
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace stratum {

struct SamplerSpec {
  std::string name;
  std::map<std::string, std::string> params;  ///< KEY=VALUE, values as text ("1,55,133")
  std::string randomize;                      ///< empty: the sampler's default
  bool operator==(const SamplerSpec&) const = default;
};

/// Parses a spec's syntax only (no registry look-up). Throws
/// stratum::invalid_argument("sampler", spec, ...) naming the position (1-based)
/// and what is allowed: unbalanced parentheses, empty name, key or value,
/// duplicate key, an empty randomizer, text after ')'.
SamplerSpec parse_sampler_spec_syntax(std::string_view text);

/// Parses a spec and checks it against the registry: the sampler exists
/// (else: the nearest names), every key is one of its parameters (else: its
/// keys), the randomizer is one it accepts (else: the accepted ones). Values
/// are checked when the points are generated (each sampler's own rules).
SamplerSpec parse_sampler_spec(std::string_view text);

/// The canonical text of a spec: NAME, then (KEY=VALUE,...) in key order when
/// there are parameters, then :RANDOMIZER when one is set.
/// parse_sampler_spec_syntax(format_sampler_spec(s)) == s.
std::string format_sampler_spec(const SamplerSpec& spec);

/// Splits a list of specs on the commas outside parentheses ("sobol:owen,
/// poisson-disk(periodic=1)"); blanks around items are dropped. Throws naming
/// the list for an empty item; unbalanced parentheses are left in an item (an
/// unclosed '(' takes the rest) for parse_sampler_spec to report.
std::vector<std::string> split_sampler_list(std::string_view text);

/// split_sampler_list, then parse_sampler_spec on each item.
std::vector<SamplerSpec> parse_sampler_list(std::string_view text);

/// One KEY=VALUE item as given to an option such as -p (`option` names it in
/// errors): a non-empty key, '=', a non-empty value.
std::pair<std::string, std::string> parse_key_value(std::string_view option, std::string_view item);

/// Every item of a repeatable KEY=VALUE option (--integrand-param,
/// --warp-param, --measure-param); a key given twice is an error.
std::map<std::string, std::string> parse_key_values(std::string_view option, const std::vector<std::string>& items);

/// The sampler a face was given in parts: the spec text (`-s`), KEY=VALUE
/// items (`-p`, repeatable) and a randomizer (`--randomize`). Parses the spec,
/// adds the items and the randomizer, and throws naming both forms when the
/// same key, or the randomizer, is given twice ("-s sobol:owen" and
/// "--randomize xor"); then checks the result against the registry.
SamplerSpec combine_sampler_options(std::string_view spec, const std::vector<std::string>& params,
                                    std::string_view randomize);

/// Exactly the decimal integers in [0, 2^64) ("-1", "1e3", "0x10",
/// "18446744073709551616" are refused naming `argument` and the value).
std::uint64_t parse_uint64(std::string_view argument, std::string_view text);

/// The one default seed of every randomized operation, on every face.
inline constexpr std::uint64_t default_seed = 0;

/// A seed: parse_uint64("seed", text).
std::uint64_t parse_seed(std::string_view text);

/// Largest thread count a face may ask for.
inline constexpr std::int64_t max_threads = 1024;

/// The one thread rule: 0 means every core this process may use, at most
/// max_threads: the CPUs of its affinity mask where the launcher bound it
/// to some of the machine's (mpirun, srun, taskset), else the machine's
/// cores divided among the job's processes on it (local_processes());
/// 1..max_threads as given; anything else is refused. 0 is every CLI
/// subcommand's default.
unsigned resolve_threads(std::int64_t threads);

/// The processes of this job on this machine: Open MPI's
/// OMPI_COMM_WORLD_LOCAL_SIZE, MPICH's MPI_LOCALNRANKS, or Slurm's tasks of
/// this step on this node (srun: SLURM_STEP_TASKS_PER_NODE at SLURM_NODEID);
/// 1 outside a job or where none of them reads as a count.
unsigned local_processes();

/// Slurm's per-node task list ("2(x3),1": 2 tasks on each of nodes 0-2,
/// 1 on node 3) read at `node`; 0 where the text is not such a list or
/// `node` is past its end.
unsigned slurm_tasks_on_node(std::string_view list, unsigned node);

}  // namespace stratum
