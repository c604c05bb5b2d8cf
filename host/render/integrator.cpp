// Integrator::render (render/integrator.h): a render is one pass of the integrator's passes.
#include "render/integrator.h"

#include "render/film.h"

namespace rc {

Image Integrator::render(const RenderContext& ctx, RenderStats& stats) {
  const std::unique_ptr<PassRender> passes = beginPasses(ctx, stats);
  Film film(ctx.scene.film);
  const bool complete = passes->addPass(film, 0);
  return passes->finish(film, 1, !complete, stats);
}

}  // namespace rc
