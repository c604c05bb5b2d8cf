#include "app/cache_command.h"

#include "cache/cache_merge.h"
#include "core/error.h"

namespace rc {

int runCacheCommand(const std::vector<std::string>& args, std::ostream& out) {
  if (args.empty() || args[0] != "merge") throw Error("cache: expected 'merge A.rcc B.rcc ... -o C.rcc'");
  std::vector<std::string> inputs;
  std::string output;
  bool quiet = false;
  for (size_t i = 1; i < args.size(); ++i) {
    if (args[i] == "-o") {
      if (i + 1 >= args.size()) throw Error("cache merge: -o: missing value");
      output = args[++i];
    } else if (args[i] == "--quiet" || args[i] == "-q") {
      quiet = true;
    } else if (!args[i].empty() && args[i][0] == '-') {
      throw Error("cache merge: unknown option '" + args[i] + "'");
    } else {
      inputs.push_back(args[i]);
    }
  }
  if (output.empty()) throw Error("cache merge: -o C.rcc is required");
  if (inputs.empty()) throw Error("cache merge: no input cache files");
  const MergeReport r = mergeCacheFiles(inputs, output);
  if (!quiet)
    out << "merged " << inputs.size() << " cache files: " << r.recordsIn << " records in, " << r.duplicates
        << " duplicates removed, " << r.radiiClamped << " radii clamped across parts, " << r.recordsOut
        << " records written to " << output << "\n";
  return 0;
}

}  // namespace rc
