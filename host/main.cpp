// rcache's entry point: the CLI (host/app/cli.cpp).
#include <malloc.h>

#include "app/cli.h"

int main(int argc, char** argv) {
  // The cache engine allocates and frees buffers of tens of MB per batch (record rays, their
  // hits and shade points). glibc serves those with mmap and returns them on free, so every
  // batch paid page faults on fresh pages again: keep them in the heap instead. Memory peaks are
  // unchanged, only not returned early.
  mallopt(M_MMAP_THRESHOLD, 256 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  return rc::runCli(argc, argv);
}
