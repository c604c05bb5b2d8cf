#pragma once
// Salts of the cache's RNG streams: every stream is hashMix(seed, item, salt) or Rng(seed, stream),
// and distinct salts keep the streams of different purposes independent. Changing one changes
// the images (not their expectation).
#include <cstdint>

namespace rc {

// Shade-point seeds of the fill passes' lookups: pixel centres, and the four quadrant centres of
// edge pixels (salt + quadrant).
constexpr uint64_t kSaltFillCentre = 0xF111;
constexpr uint64_t kSaltFillQuadrant = 0xF112;
// Shade-point seed of final-pass sample s of a pixel: salt + s.
constexpr uint64_t kSaltFinalSample = 0xF1A1000000ULL;
// Shade-point seed of the hit of a record's ray: hashMix(record seed, ray, salt).
constexpr uint64_t kSaltRecordRayHit = 0x5EED;
// Scramble seed of the padded Sobol sequence shared by a record's ray hits.
constexpr uint64_t kSaltRecordLightSequence = 0x1D5EED;
// Order in which uncovered points are considered as record candidates (a deterministic shuffle).
constexpr uint64_t kSaltCandidateOrder = 0xA11CE;
// The pilot that decides whether the cache can pay (path_fallback.h): per pilot pixel.
constexpr uint64_t kSaltPilot = 0x9117;
// The direction of a pilot point's neighbour in the coherence test (record_coherence.h).
constexpr uint64_t kSaltPilotNeighbour = 0x9118;
// The path samples at which the fill's payoff is measured (fill_payoff.h): per point.
constexpr uint64_t kSaltFillPayoff = 0x9119;
// The α node of a point of a material tabulated over α (MaterialPlan::tableAt).
constexpr uint64_t kSaltAlphaNode = 0xA1FA;
// Rng stream ids: the direct light a fill point's Weber threshold is relative to, the stratified
// pattern of a record batch's rays, and a record's azimuth rotation φ0.
constexpr uint64_t kStreamFillDirectLight = 1;
constexpr uint64_t kStreamRecordPattern = 3;
constexpr uint64_t kStreamRecordAzimuth = 4;

}  // namespace rc
