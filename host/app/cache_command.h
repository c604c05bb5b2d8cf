#pragma once
// `rcache cache merge A.rcc B.rcc ... -o C.rcc` (cache/cache_merge.h).
#include <ostream>
#include <string>
#include <vector>

namespace rc {

int runCacheCommand(const std::vector<std::string>& args, std::ostream& out);

}  // namespace rc
