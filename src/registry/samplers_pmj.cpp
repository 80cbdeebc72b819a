/// Registry entries: (0,2)-sequence and progressive multi-jittered (0,2) points.
#include "families.hpp"
#include "support.hpp"

namespace stratum::registry_families {

std::vector<SamplerInfo> pmj() { return {}; }

}  // namespace stratum::registry_families
