#pragma once
// The message of the invalid_argument that generate_points throws for a
// request (empty when it throws none): the bad-input tests assert on it.
#include <string>

#include "stratum/registry.hpp"
#include "stratum/util/error.hpp"

namespace stratum::testing {

inline std::string error_of(const std::string& name, const SamplerRequest& request) {
  try {
    generate_points(name, request);
  } catch (const invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace stratum::testing
