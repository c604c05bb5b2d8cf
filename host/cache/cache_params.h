#pragma once
// The rcache integrator's parameters, typed (the table with defaults and reasons is in
// cache/rcache_integrator.h). Read once, through ParamReader, in cache_params.cpp: the default and
// the range of each are written there only.
#include "scene/param_reader.h"

namespace rc {

struct RcacheParams {
  float a = 0.4f;
  int rays = 512;
  int order = 0;
  float weber = 0.025f;
  bool adaptive = false;
  float minAScale = 0.125f;
  bool gradients = true;
  float rMinPx = 1.5f, rMaxPx = 10.0f;
  float secondaryAScale = 2.0f;
  int secondaryRays = 256;
  int secondaryOrder = 8;
  int cacheDepth = 2;
  bool worldFrame = true;
  bool autoFrame = true;
  bool tlMode = false;
  int batch = 256;
  bool sharePixel = true;
  int lightSamples = 1;
  bool envCache = true;
  float envVariance = 1.0f / 3.0f;
  bool areaCache = false;
  bool fallback = true;
  float fallbackShare = 0.25f;
  // Which of the values above are the defaults for the base budget, to be set for the render's
  // spp (cache/budget_params.h); one given on the command line or in the file is used as given.
  struct FollowBudget {
    bool rays = true, secondaryRays = true, a = true, rMin = true, rMax = true;
  } follow;
  // Lobe split of layered materials (Technique::LobeSplit): Auto lets the cost pilot choose.
  enum class LobeSplitMode { Auto, On, Off } lobeSplit = LobeSplitMode::Auto;
  // Off by default: its choice follows timings, so the same command could render a different
  // (equally unbiased) image on another run or machine, and tiles or walk frames could choose apart.
  bool costPilot = false;
  float costPilotShare = 0.05f;  // the cost pilot's budget, a share of the path-traced render
  // Whether the fill's predicted payoff (cache/fill_payoff.h) may path trace an image the share
  // pilot would cache, where the cost pilot did not decide. Off by default: its variance shares,
  // from four samples at up to 1024 points, miss rare bright paths, and it path traced a corpus
  // Cornell box that the cache renders far better (bench/RESULTS.md "The loose end of the error
  // ladder").
  bool fillPayoff = false;
};

// Throws rc::Error("parameter 'x' = '...': ...") for a malformed or out-of-range value.
RcacheParams readRcacheParams(ParamReader& in);

// M×N with N = 4M and M·N ≥ rays (M ≥ 2).
void hemisphereCells(int rays, int& M, int& N);

}  // namespace rc
