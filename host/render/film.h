#pragma once
// Film: splats weighted radiance samples through a box, tent or Gaussian reconstruction filter and
// develops Σ w·L / Σ w per pixel (Mitsuba 3 ImageBlock semantics, so a constant radiance gives a
// constant image whatever the filter). Tiles render into their own TileFilm (the tile plus a border
// of the filter radius) and are merged into the Film in tile order, so the result does not depend on
// which thread finished first.
#include <map>
#include <string>
#include <vector>

#include "core/math.h"
#include "render/integrator.h"
#include "scene/scene.h"

namespace rc {

class ReconstructionFilter {
 public:
  explicit ReconstructionFilter(const FilmSettings& settings);
  float radius() const { return radius_; }
  // 1-D weight at offset x (pixels) from a pixel centre; the 2-D weight is eval(dx)·eval(dy).
  float eval(float x) const;
  bool isBox() const { return box_; }

 private:
  bool box_ = true;
  bool tent_ = false;                 // max(0, 1 − |x|/radius), Mitsuba 3
  float radius_ = 0.5f;
  float alpha_ = 0.0f, bias_ = 0.0f;  // gaussian: max(0, exp(alpha x²) − bias), Mitsuba 3
};

// Accumulator for one rectangular tile [x0, x1) × [y0, y1) of the image. Splats may land up to
// `radius` pixels outside the tile; the tile keeps that border.
class TileFilm {
 public:
  TileFilm(const ReconstructionFilter& filter, int imageWidth, int imageHeight, int x0, int y0, int x1, int y1);
  // filmPos in pixels of the full image ((0,0) top-left corner). Non-finite L must be filtered by the caller.
  void splat(Vec2 filmPos, const Color& L);
  // The part of splat(filmPos, L) that falls on image rows [rowBegin, rowEnd): threads that each
  // own some rows and pass every sample in the same order add exactly what one serial pass adds.
  void splatRows(Vec2 filmPos, const Color& L, int rowBegin, int rowEnd);
  // The image rows a splat into this tile can reach (the tile's rows and their filter border).
  int splatRowBegin() const { return by0_; }
  int splatRowEnd() const { return by0_ + bh_; }
  // Per-pixel AOV value (box average over the pixel's samples, no filtering): pixel (px, py) inside the tile.
  void addAov(const std::string& name, int px, int py, const Color& value);

  int x0() const { return x0_; }
  int y0() const { return y0_; }
  int x1() const { return x1_; }
  int y1() const { return y1_; }

 private:
  friend class Film;
  const ReconstructionFilter* filter_;
  int imageW_, imageH_;
  int x0_, y0_, x1_, y1_;
  int bx0_, by0_, bw_, bh_;  // border-extended, clipped to the image
  std::vector<double> sum_;  // bw_*bh_*4: Σ wL (rgb), Σ w
  struct AovAccum { std::vector<double> sum; std::vector<uint32_t> count; };
  std::map<std::string, AovAccum> aovs_;
};

class Film {
 public:
  explicit Film(const FilmSettings& settings);  // the crop window's size (the sensor's without one)
  Film(const FilmSettings& settings, int width, int height);  // override resolution (tests)

  int width() const { return width_; }
  int height() const { return height_; }
  // Where the image lies on the sensor (a crop window; 0, 0 and the image size otherwise). Pixel
  // sample streams are keyed by the sensor pixel, so a crop equals the same window of a full render.
  int cropX() const { return cropX_; }
  int cropY() const { return cropY_; }
  int sensorWidth() const { return sensorWidth_; }
  const ReconstructionFilter& filter() const { return filter_; }

  TileFilm makeTile(int x0, int y0, int x1, int y1) const;
  // Adds a tile's sums. Call in a fixed order (e.g. tile index) for bit-identical results.
  void merge(const TileFilm& tile);
  // Adds another film's sums (same size): e.g. the adaptive rounds, kept apart until they are final.
  void add(const Film& other);
  // Convenience for single-threaded use (tests): splat straight into the film.
  void splat(Vec2 filmPos, const Color& L);

  Image develop() const;

 private:
  ReconstructionFilter filter_;
  int width_, height_;
  int cropX_ = 0, cropY_ = 0, sensorWidth_ = 0;
  std::vector<double> sum_;  // width*height*4
  struct AovAccum { std::vector<double> sum; std::vector<uint32_t> count; };
  std::map<std::string, AovAccum> aovs_;
};

}  // namespace rc
