#pragma once
// What the rcache integrator takes besides its scene parameters: the cache files of the command
// line (--cache-save, --cache-load, --cache-reuse). They are the integrator's own options, set on
// RcacheIntegrator by the CLI (app/cli.cpp) and the walk-through driver, so the interface every
// integrator shares (render/integrator.h) knows nothing of caches.
#include <string>

namespace rc {

struct CacheFiles {
  std::string save;    // write the view-independent cache here after rendering ("" = none)
  std::string load;    // start from this cache file ("" = none)
  bool reuse = false;  // with `load`: still fill (adds records where none serve)
};

}  // namespace rc
