/// §8, in time: a pixel's error across the frames of an animation.
#pragma once

#include "sections.hpp"

namespace stratum::report {

/// Renders F frames at 1 spp of the penumbra scene with random, Owen–Sobol',
/// ZSobol and the ranked blue-noise samplers (frame K continues each pixel's
/// sequence, stratum render --frame) and adds to `section`: the temporal
/// spectrum of each pixel's error (analysis::temporal_spectrum), the
/// consecutive-frame correlation, frames 0–3 averaged against one frame at
/// 4 spp and against 4 independent frames, a space-time slice of the error
/// and the text relating it to Cook's and the magic square's assignments.
void frames_error(SectionContext& context, Section& section);

}  // namespace stratum::report
