#pragma once
/// The lecture's comparison of patterns (LECTURE.md §12, after Mitchell 1992,
/// "Ray tracing and irregularities of distribution"): random-edge
/// discrepancy of Zaremba, jittered, Poisson-disk, N-rooks and random
/// patterns at 16, 256 and 1600 points, averaged over K realizations with
/// standard errors, beside each pattern's radially averaged power spectrum.
///
/// Every pattern comes from the sampler registry. A requested count a
/// sampler cannot take is replaced by the nearest count it can (jittered
/// needs a perfect square: 16, 256 and 1600 all are); the table reports the
/// count used. Realization r of every pattern uses the pattern seed
/// hash64(seed, r) and the same L random lines, random_isotropic_line(
/// hash64(seed, r, 1), ·) (common random numbers, so the comparison between
/// patterns is sharper). Zaremba's set is deterministic: its standard error
/// is that of the random lines alone. Every (pattern, count, realization) is
/// one oneTBB task; the results are identical for any thread count.
///
/// Further registry patterns (options.extra_patterns, e.g. `stratum report
/// --sampler sobol:owen`) run after Mitchell's five through exactly the same
/// code: same counts, seeds, lines and spectra.
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace stratum::analysis {

/// One pattern: the registry sampler behind it.
struct MitchellPattern {
  std::string label;                          ///< as in Mitchell's table: "Zaremba", "jittered", ...
  std::string sampler;                        ///< registry name
  std::map<std::string, std::string> params;  ///< sampler parameters
  std::string randomize;                      ///< registry randomizer; empty: the sampler's default
};

/// How cells and spectra name a pattern: the sampler name, or
/// "sampler:randomizer" when a randomizer is given.
std::string mitchell_pattern_id(const MitchellPattern& pattern);
/// Zaremba, jittered, Poisson disk, N-rooks, random.
const std::vector<MitchellPattern>& mitchell_patterns();

struct MitchellStudyOptions {
  std::vector<std::size_t> counts{16, 256, 1600};
  std::size_t realizations = 20;  ///< K
  std::size_t lines = 10000;      ///< L random lines per realization
  std::uint64_t seed = 0;
  unsigned threads = 1;  ///< 0: all cores
  /// Spectra are computed at this count (0: the largest requested count ≤
  /// 1024, else the smallest), up to frequency ⌈3√n⌉, averaged over the K realizations.
  std::size_t spectrum_count = 0;
  /// Patterns compared after mitchell_patterns(); each must make 2D points
  /// and have an id (mitchell_pattern_id) not already in the study.
  std::vector<MitchellPattern> extra_patterns;
};

/// Mean and standard error (s/√K; 0 for K = 1) over the realizations.
struct MeanAndError {
  double mean = 0;
  double error = 0;
};

struct MitchellCell {
  std::string pattern;  ///< mitchell_pattern_id (the sampler name for Mitchell's five)
  std::size_t requested = 0;
  std::size_t n = 0;               ///< points actually used
  MeanAndError rms, mean, max;     ///< of the random-edge RMS, mean and max per realization
  std::vector<double> rms_values;  ///< per realization
};

struct MitchellSpectrum {
  std::string pattern;  ///< mitchell_pattern_id
  std::size_t n = 0;
  std::vector<double> frequency;  ///< normalized by √n
  std::vector<double> power;
  std::vector<double> example;  ///< realization 0's points, row-major (x, y), for a figure
};

struct MitchellStudy {
  MitchellStudyOptions options;
  std::vector<MitchellPattern> patterns;  ///< mitchell_patterns(), then the extras, in this order
  std::vector<MitchellCell> cells;        ///< pattern-major (order of `patterns`), then counts in the given order
  std::vector<MitchellSpectrum> spectra;  ///< one per pattern, order of `patterns`
  std::vector<std::string> notes;         ///< substitutions made (count changes)
  const MitchellCell& cell(const std::string& pattern, std::size_t requested) const;
};

/// Runs the study; throws stratum::invalid_argument for counts < 2 or > 10^6,
/// realizations < 1 or > 10^5, lines < 1 or > 10^8, or no counts, and for an
/// extra pattern that is unknown, cannot make 2D points, takes no such
/// randomizer, or repeats a pattern id.
MitchellStudy run_mitchell_study(const MitchellStudyOptions& options);

/// The table as text: one row per pattern, one column per count
/// ("RMS +- SE"), then the notes.
std::string mitchell_table(const MitchellStudy& study);

}  // namespace stratum::analysis
