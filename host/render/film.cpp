#include "render/film.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"

namespace rc {

ReconstructionFilter::ReconstructionFilter(const FilmSettings& s) {
  if (s.filter == "box") {
    box_ = true;
    radius_ = 0.5f;
  } else if (s.filter == "tent") {
    if (!(s.tentRadius > 0.0f && s.tentRadius <= 64.0f)) throw Error("rfilter tent: radius must be in (0, 64] pixels");
    box_ = false;
    tent_ = true;
    radius_ = s.tentRadius;
  } else if (s.filter == "gaussian") {
    if (!(s.gaussianStddev > 0.0f) || !std::isfinite(s.gaussianStddev))
      throw Error("rfilter gaussian: stddev must be positive");
    if (s.gaussianStddev > 16.0f) throw Error("rfilter gaussian: stddev above 16 pixels is not supported");
    box_ = false;
    radius_ = 4.0f * s.gaussianStddev;  // Mitsuba 3
    alpha_ = -1.0f / (2.0f * s.gaussianStddev * s.gaussianStddev);
    bias_ = std::exp(alpha_ * radius_ * radius_);
  } else {
    throw Error("rfilter: unknown type '" + s.filter + "' (box, tent, gaussian)");
  }
}

float ReconstructionFilter::eval(float x) const {
  if (box_) return (x >= -0.5f && x < 0.5f) ? 1.0f : 0.0f;
  if (tent_) return std::max(0.0f, 1.0f - std::fabs(x) / radius_);
  return std::max(0.0f, std::exp(alpha_ * x * x) - bias_);
}

namespace {

// The tent's and Gaussian's footprint (forEachFootprint's general case). Kept out of line: its
// weight table and loops would otherwise give the box case (one pixel, weight 1) their stack
// frame and register saves on every sample.
template <typename Add>
[[gnu::noinline]] void forEachFilteredFootprint(const ReconstructionFilter& f, Vec2 pos, int w, int h, Add&& add,
                                                int rowBegin, int rowEnd) {
  const float r = f.radius();
  const int xa = std::max(0, static_cast<int>(std::ceil(pos.x - 0.5f - r)));
  const int xb = std::min(w - 1, static_cast<int>(std::floor(pos.x - 0.5f + r)));
  const int ya = std::max(std::max(0, rowBegin), static_cast<int>(std::ceil(pos.y - 0.5f - r)));
  const int yb = std::min(std::min(h, rowEnd) - 1, static_cast<int>(std::floor(pos.y - 0.5f + r)));
  if (ya > yb) return;
  float wx[160];  // radius ≤ 64 (stddev ≤ 16) → at most 129 pixels
  const int nx = std::min(160, xb - xa + 1);
  for (int i = 0; i < nx; ++i) wx[i] = f.eval(static_cast<float>(xa + i) + 0.5f - pos.x);
  for (int iy = ya; iy <= yb; ++iy) {
    const float wy = f.eval(static_cast<float>(iy) + 0.5f - pos.y);
    if (wy <= 0.0f) continue;
    for (int i = 0; i < nx; ++i)
      if (wx[i] > 0.0f) add(xa + i, iy, wx[i] * wy);
  }
}

// Calls add(ix, iy, weight) for every image pixel the sample at filmPos reaches (only those in
// rows [rowBegin, rowEnd) where given).
template <typename Add>
void forEachFootprint(const ReconstructionFilter& f, Vec2 pos, int w, int h, Add&& add, int rowBegin = 0,
                      int rowEnd = std::numeric_limits<int>::max()) {
  if (!f.isBox()) return forEachFilteredFootprint(f, pos, w, h, add, rowBegin, rowEnd);
  const int ix = floorToInt(pos.x), iy = floorToInt(pos.y);
  if (ix >= 0 && iy >= std::max(0, rowBegin) && ix < w && iy < std::min(h, rowEnd)) add(ix, iy, 1.0f);
}

}  // namespace

TileFilm::TileFilm(const ReconstructionFilter& filter, int imageWidth, int imageHeight, int x0, int y0, int x1, int y1)
    : filter_(&filter), imageW_(imageWidth), imageH_(imageHeight), x0_(x0), y0_(y0), x1_(x1), y1_(y1) {
  const int border = filter.isBox() ? 0 : static_cast<int>(std::ceil(filter.radius())) + 1;
  bx0_ = std::max(0, x0 - border);
  by0_ = std::max(0, y0 - border);
  bw_ = std::min(imageWidth, x1 + border) - bx0_;
  bh_ = std::min(imageHeight, y1 + border) - by0_;
  sum_.assign(static_cast<size_t>(bw_) * bh_ * 4, 0.0);
}

void TileFilm::splat(Vec2 pos, const Color& L) { splatRows(pos, L, by0_, by0_ + bh_); }

void TileFilm::splatRows(Vec2 pos, const Color& L, int rowBegin, int rowEnd) {
  forEachFootprint(*filter_, pos, imageW_, imageH_, [&](int ix, int iy, float w) {
    const int lx = ix - bx0_, ly = iy - by0_;
    if (lx < 0 || ly < 0 || lx >= bw_ || ly >= bh_) return;  // only for samples outside the tile
    double* s = &sum_[(static_cast<size_t>(ly) * bw_ + lx) * 4];
    s[0] += static_cast<double>(w) * L.r;
    s[1] += static_cast<double>(w) * L.g;
    s[2] += static_cast<double>(w) * L.b;
    s[3] += w;
  }, rowBegin, rowEnd);
}

void TileFilm::addAov(const std::string& name, int px, int py, const Color& value) {
  if (px < x0_ || py < y0_ || px >= x1_ || py >= y1_) return;
  AovAccum& a = aovs_[name];
  const size_t n = static_cast<size_t>(x1_ - x0_) * (y1_ - y0_);
  if (a.sum.empty()) {
    a.sum.assign(n * 3, 0.0);
    a.count.assign(n, 0);
  }
  const size_t i = static_cast<size_t>(py - y0_) * (x1_ - x0_) + (px - x0_);
  a.sum[3 * i] += value.r;
  a.sum[3 * i + 1] += value.g;
  a.sum[3 * i + 2] += value.b;
  a.count[i] += 1;
}

Film::Film(const FilmSettings& settings) : Film(settings, settings.imageWidth(), settings.imageHeight()) {
  cropX_ = settings.cropX;
  cropY_ = settings.cropY;
  sensorWidth_ = settings.width;
}

Film::Film(const FilmSettings& settings, int width, int height)
    : filter_(settings), width_(width), height_(height), sensorWidth_(width) {
  if (width <= 0 || height <= 0) throw Error("film: width and height must be positive");
  sum_.assign(static_cast<size_t>(width) * height * 4, 0.0);
}

TileFilm Film::makeTile(int x0, int y0, int x1, int y1) const {
  return TileFilm(filter_, width_, height_, std::max(0, x0), std::max(0, y0), std::min(width_, x1),
                  std::min(height_, y1));
}

void Film::merge(const TileFilm& tile) {
  for (int ly = 0; ly < tile.bh_; ++ly)
    for (int lx = 0; lx < tile.bw_; ++lx) {
      const double* s = &tile.sum_[(static_cast<size_t>(ly) * tile.bw_ + lx) * 4];
      double* d = &sum_[(static_cast<size_t>(tile.by0_ + ly) * width_ + tile.bx0_ + lx) * 4];
      for (int c = 0; c < 4; ++c) d[c] += s[c];
    }
  for (const auto& [name, a] : tile.aovs_) {
    AovAccum& dst = aovs_[name];
    if (dst.sum.empty()) {
      dst.sum.assign(static_cast<size_t>(width_) * height_ * 3, 0.0);
      dst.count.assign(static_cast<size_t>(width_) * height_, 0);
    }
    const int tw = tile.x1_ - tile.x0_;
    for (int y = tile.y0_; y < tile.y1_; ++y)
      for (int x = tile.x0_; x < tile.x1_; ++x) {
        const size_t i = static_cast<size_t>(y - tile.y0_) * tw + (x - tile.x0_);
        const size_t j = static_cast<size_t>(y) * width_ + x;
        for (int c = 0; c < 3; ++c) dst.sum[3 * j + c] += a.sum[3 * i + c];
        dst.count[j] += a.count[i];
      }
  }
}

void Film::add(const Film& other) {
  if (other.width_ != width_ || other.height_ != height_) throw Error("Film::add: films of different sizes");
  for (size_t i = 0; i < sum_.size(); ++i) sum_[i] += other.sum_[i];
  for (const auto& [name, a] : other.aovs_) {
    AovAccum& dst = aovs_[name];
    if (dst.sum.empty()) {
      dst.sum.assign(a.sum.size(), 0.0);
      dst.count.assign(a.count.size(), 0);
    }
    for (size_t i = 0; i < a.sum.size(); ++i) dst.sum[i] += a.sum[i];
    for (size_t i = 0; i < a.count.size(); ++i) dst.count[i] += a.count[i];
  }
}

void Film::splat(Vec2 pos, const Color& L) {
  forEachFootprint(filter_, pos, width_, height_, [&](int ix, int iy, float w) {
    double* s = &sum_[(static_cast<size_t>(iy) * width_ + ix) * 4];
    s[0] += static_cast<double>(w) * L.r;
    s[1] += static_cast<double>(w) * L.g;
    s[2] += static_cast<double>(w) * L.b;
    s[3] += w;
  });
}

Image Film::develop() const {
  Image img;
  img.width = width_;
  img.height = height_;
  const size_t n = static_cast<size_t>(width_) * height_;
  img.pixels.assign(n, Color(0.0f));
  for (size_t i = 0; i < n; ++i) {
    const double* s = &sum_[4 * i];
    if (s[3] > 0.0) img.pixels[i] = Color(s[0] / s[3], s[1] / s[3], s[2] / s[3]);
  }
  for (const auto& [name, a] : aovs_) {
    std::vector<Color> layer(n, Color(0.0f));
    for (size_t i = 0; i < n; ++i)
      if (a.count[i] > 0)
        layer[i] = Color(a.sum[3 * i] / a.count[i], a.sum[3 * i + 1] / a.count[i], a.sum[3 * i + 2] / a.count[i]);
    img.aovs[name] = std::move(layer);
  }
  return img;
}

}  // namespace rc
