// Film: filter weights, normalisation and deterministic tile merging.
#include <gtest/gtest.h>

#include "core/error.h"
#include "core/rng.h"
#include "render/film.h"

namespace rc {
namespace {

FilmSettings settings(const std::string& filter, int w, int h) {
  FilmSettings s;
  s.filter = filter;
  s.width = w;
  s.height = h;
  return s;
}

TEST(Film, GaussianMatchesMitsuba) {
  const ReconstructionFilter f(settings("gaussian", 4, 4));
  EXPECT_FLOAT_EQ(f.radius(), 2.0f);  // 4 σ, σ = 0.5
  const float bias = std::exp(-2.0f * 4.0f);
  EXPECT_NEAR(f.eval(0.0f), 1.0f - bias, 1e-7f);
  EXPECT_NEAR(f.eval(0.5f), std::exp(-0.5f) - bias, 1e-7f);
  EXPECT_EQ(f.eval(2.0f), 0.0f);
  EXPECT_EQ(f.eval(-2.5f), 0.0f);
}

// A constant radiance must give a constant image with any filter, borders included: the film
// divides by the sum of weights, so filters need no normalisation constant.
TEST(Film, ConstantStaysConstant) {
  for (const char* filter : {"box", "gaussian"}) {
    Film film(settings(filter, 13, 7));
    Rng rng(3);
    for (int y = 0; y < 7; ++y)
      for (int x = 0; x < 13; ++x)
        for (int s = 0; s < 4; ++s) film.splat(Vec2(x + rng.nextFloat(), y + rng.nextFloat()), Color(0.25f, 2.0f, 7.0f));
    const Image img = film.develop();
    for (const Color& c : img.pixels) {
      EXPECT_NEAR(c.r, 0.25f, 1e-6f) << filter;
      EXPECT_NEAR(c.g, 2.0f, 1e-6f) << filter;
      EXPECT_NEAR(c.b, 7.0f, 1e-6f) << filter;
    }
  }
}

TEST(Film, BoxKeepsSamplesInTheirPixel) {
  Film film(settings("box", 4, 4));
  film.splat(Vec2(1.0f, 2.0f), Color(1.0f));   // corner of pixel (1,2): belongs to it
  film.splat(Vec2(2.999f, 0.5f), Color(3.0f)); // pixel (2,0)
  const Image img = film.develop();
  EXPECT_EQ(img.pixels[2 * 4 + 1], Color(1.0f));
  EXPECT_EQ(img.pixels[0 * 4 + 2], Color(3.0f));
  EXPECT_EQ(img.pixels[2 * 4 + 0], Color(0.0f));
  EXPECT_EQ(img.pixels[1 * 4 + 1], Color(0.0f));
}

TEST(Film, GaussianSpreadsAcrossTilesLikeOneFilm) {
  // Splatting through tiles (with their border) and merging equals splatting into one film.
  const FilmSettings s = settings("gaussian", 20, 12);
  Film whole(s), tiled(s);
  Rng rng(9);
  struct Sample { Vec2 p; Color c; };
  std::vector<Sample> samples;
  for (int i = 0; i < 2000; ++i)
    samples.push_back({Vec2(rng.nextFloat() * 20, rng.nextFloat() * 12), Color(rng.nextFloat(), rng.nextFloat(), 1)});
  for (const auto& smp : samples) whole.splat(smp.p, smp.c);
  for (int ty = 0; ty < 12; ty += 8)
    for (int tx = 0; tx < 20; tx += 8) {
      TileFilm tile = tiled.makeTile(tx, ty, tx + 8, ty + 8);
      for (const auto& smp : samples)
        if (smp.p.x >= tile.x0() && smp.p.x < tile.x1() && smp.p.y >= tile.y0() && smp.p.y < tile.y1())
          tile.splat(smp.p, smp.c);
      tiled.merge(tile);
    }
  const Image a = whole.develop(), b = tiled.develop();
  for (size_t i = 0; i < a.pixels.size(); ++i) EXPECT_NEAR(glm::length(a.pixels[i] - b.pixels[i]), 0.0f, 1e-6f);
}

TEST(Film, SplatsByRowStripesEqualOneSplatBitForBit) {
  // The final pass splats a tile by stripes of rows (each stripe passing all samples in order):
  // every pixel must sum the same terms in the same order as one splat per sample.
  for (const char* filter : {"gaussian", "box"}) {
    const FilmSettings s = settings(filter, 16, 16);
    Film once(s), striped(s);
    TileFilm a = once.makeTile(0, 4, 16, 12), b = striped.makeTile(0, 4, 16, 12);
    Rng rng(5);
    std::vector<std::pair<Vec2, Color>> samples;
    for (int i = 0; i < 1500; ++i)
      samples.push_back({Vec2(rng.nextFloat() * 16, 4 + rng.nextFloat() * 8), Color(rng.nextFloat(), 0.5f, 2.0f)});
    for (const auto& smp : samples) a.splat(smp.first, smp.second);
    for (int y = b.splatRowBegin(); y < b.splatRowEnd(); y += 3)
      for (const auto& smp : samples) b.splatRows(smp.first, smp.second, y, std::min(y + 3, b.splatRowEnd()));
    once.merge(a);
    striped.merge(b);
    const Image ia = once.develop(), ib = striped.develop();
    for (size_t i = 0; i < ia.pixels.size(); ++i) EXPECT_EQ(ia.pixels[i], ib.pixels[i]) << filter << " pixel " << i;
  }
}

TEST(Film, AovsAreBoxAveraged) {
  Film film(settings("gaussian", 4, 4));
  TileFilm tile = film.makeTile(0, 0, 4, 4);
  tile.addAov("records", 1, 1, Color(2.0f));
  tile.addAov("records", 1, 1, Color(4.0f));
  film.merge(tile);
  const Image img = film.develop();
  ASSERT_EQ(img.aovs.count("records"), 1u);
  EXPECT_EQ(img.aovs.at("records")[1 * 4 + 1], Color(3.0f));
  EXPECT_EQ(img.aovs.at("records")[0], Color(0.0f));
}

TEST(Film, RejectsUnknownFilter) { EXPECT_THROW(Film(settings("mitchell", 4, 4)), Error); }

}  // namespace
}  // namespace rc
