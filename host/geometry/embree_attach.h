#pragma once
// The last step of every Embree geometry rcache builds (meshes, spheres, cylinders, curves).
#include <embree3/rtcore.h>

namespace rc {

// Commits g, attaches it to `scene` and drops this reference (the scene keeps the geometry);
// returns its geomID.
inline unsigned commitAndAttach(RTCScene scene, RTCGeometry g) {
  rtcCommitGeometry(g);
  const unsigned id = rtcAttachGeometry(scene, g);
  rtcReleaseGeometry(g);
  return id;
}

}  // namespace rc
