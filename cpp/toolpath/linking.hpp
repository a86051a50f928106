// Ordering and linking (internal): the passes of all areas ordered for the sweep and linked into moves, by
// surface-following G1 links where they are short and safe, by retracts elsewhere.
#pragma once

#include "toolpath/finishing_context.hpp"

#include <string>
#include <vector>

namespace hsm::toolpath::detail {

// The passes of all groups linked into moves; refuses a result with no pass at all (nothing to cut).
Toolpath finish(Context& context, std::vector<std::vector<std::vector<Pass>>> groups, int bottomFace,
                const std::string& why);

}  // namespace hsm::toolpath::detail
