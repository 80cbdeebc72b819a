/// Registry entries of the space-time patterns (LECTURE.md section 8).
#include "families.hpp"
#include "support.hpp"

namespace stratum::registry_families {

std::vector<SamplerInfo> spacetime() { return {}; }

}  // namespace stratum::registry_families
