// merl_generate: writes MERL-format BRDF files (bsdf/merl_data.h) for tests and benchmarks.
//   merl_generate SCENE.xml BSDF_ID OUT.binary   tabulate the isotropic BSDF with that id of a scene
//                                                (its twin: <bsdf type="merl"> on OUT renders alike)
//   merl_generate --retro OUT.binary             the hand-made retro-reflective lobe
//                                                (bsdf/merl_tabulate.h, RetroReflectiveLobe)
// Full database resolution (90×90×180, 35 MB): write into a build or bench output folder.
#include <cstdio>
#include <string>

#include "bsdf/merl_tabulate.h"
#include "core/error.h"
#include "scene/scene_loader.h"

int main(int argc, char** argv) {
  try {
    if (argc == 3 && std::string(argv[1]) == "--retro") {
      rc::writeMerlFile(argv[2], rc::tabulateMerl(rc::RetroReflectiveLobe()));
      return 0;
    }
    if (argc != 4) {
      std::fprintf(stderr, "usage: merl_generate SCENE.xml BSDF_ID OUT.binary | merl_generate --retro OUT.binary\n");
      return 2;
    }
    const rc::Scene scene = rc::loadScene(argv[1]);
    for (const rc::BsdfPtr& b : scene.bsdfs)
      if (b->id == argv[2]) {
        rc::writeMerlFile(argv[3], rc::tabulateMerl(rc::brdfOf(*b)));
        return 0;
      }
    throw rc::Error(std::string(argv[1]) + ": no BSDF with id '" + argv[2] + "' on a shape");
  } catch (const rc::Error& e) {
    std::fprintf(stderr, "merl_generate: %s\n", e.what());
    return 1;
  }
}
