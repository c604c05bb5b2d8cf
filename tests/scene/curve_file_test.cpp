// Mitsuba 3's curve files (linearcurve, bsplinecurve): curves split at blank lines, segments per
// basis, errors located at file:line, hostile input bounded, and the shapes' to_world (positions
// move, radii do not).
#include "scene/curve_loader.h"
#include "scene_test_util.h"

namespace rc::test {
namespace {

TEST(CurveFile, BlankLinesSeparateCurvesIntoSegments) {
  // Two linear curves (3 and 2 points) after a leading blank line, CRLF and tabs, a fifth column.
  const std::string text = "\n-1 0 0 0.5\r\n0\t1 0 0.25 trailing\n1 0 0 0.5\n \t\n2 2 2 1\n3 3 3 2";
  const CurveData lin = parseCurves(text, "c.txt", CurveBasis::Linear);
  ASSERT_EQ(lin.points.size(), 5u);
  EXPECT_EQ(lin.points[1], Vec4(0, 1, 0, 0.25f));
  EXPECT_EQ(lin.points[4], Vec4(3, 3, 3, 2));
  EXPECT_EQ(lin.segments, (std::vector<uint32_t>{0, 1, 3}));
  // A B-spline of 6 points has 3 segments, one of 4 has one.
  std::string six, four;
  for (int i = 0; i < 6; ++i) six += std::to_string(i) + " 0 0 0.1\n";
  for (int i = 0; i < 4; ++i) four += std::to_string(i) + " 1 0 0.1\n";
  const CurveData bs = parseCurves(six + "\n\n" + four, "c.txt", CurveBasis::BSpline);
  EXPECT_EQ(bs.segments, (std::vector<uint32_t>{0, 1, 2, 6}));
}

TEST(CurveFile, BadInputIsReportedAtItsLine) {
  auto parse = [](const std::string& text, CurveBasis basis = CurveBasis::Linear) {
    return [=] { parseCurves(text, "c.txt", basis); };
  };
  expectError(parse("0 0 0 1\n0 0 x 1\n"), {"c.txt:2:", "four numbers"});
  expectError(parse("0 0 0 1\n0 0 0\n"), {"c.txt:2:", "four numbers"});
  expectError(parse("0 0 0 1\nnan 0 0 1\n"), {"c.txt:2:", "position is not finite"});
  expectError(parse("0 0 0 1\n0 0 0 1e99\n"), {"c.txt:2:", "radius"});
  expectError(parse("0 0 0 1\n0 0 0 -0.5\n"), {"c.txt:2:", "non-negative"});
  // Too few control points: reported where the curve starts.
  expectError(parse("0 0 0 1\n1 0 0 1\n\n5 0 0 1\n"), {"c.txt:4:", "at least 2", "has 1"});
  expectError(parse("0 0 0 1\n1 0 0 1\n2 0 0 1\n", CurveBasis::BSpline), {"c.txt:1:", "at least 4", "has 3"});
  expectError(parse(""), {"c.txt", "no control points"});
  expectError(parse("\n  \n\n"), {"c.txt", "no control points"});
}

TEST(CurveFile, HostileInputIsBounded) {
  // An over-long line is refused at its line, before it is parsed (a megabyte of digits).
  const std::string longLine = "0 0 0 1\n" + std::string(1 << 20, '1') + " 0 0 1\n";
  const std::string msg = expectError([&] { parseCurves(longLine, "c.txt", CurveBasis::Linear); },
                                      {"c.txt:2:", "longer than 1024"});
  EXPECT_LT(msg.size(), 200u);
  // Binary junk: a located parse error, not a crash.
  std::string junk(4096, '\0');
  for (size_t i = 0; i < junk.size(); ++i) junk[i] = static_cast<char>((i * 7919u) & 0xff);
  expectError([&] { parseCurves(junk, "c.txt", CurveBasis::BSpline); }, {"c.txt:"});
  // Not a regular file.
  TempDir dir;
  expectError([&] { loadCurves(dir.path(""), CurveBasis::Linear); }, {"curve file"});
  expectError([&] { loadCurves(dir.path("missing.txt"), CurveBasis::Linear); }, {"missing.txt"});
}

TEST(CurveFile, ShapesMovePositionsButNotRadii) {
  TempDir dir;
  dir.write("c.txt", "0 0 0 0.1\n1 0 0 0.2\n2 0 0 0.3\n3 0 0 0.4\n");
  const Scene s = loadText(dir, sceneXml(
      "<shape type=\"linearcurve\"><string name=\"filename\" value=\"c.txt\"/>"
      "<transform name=\"to_world\"><scale x=\"2\" y=\"3\" z=\"4\"/><translate y=\"1\"/></transform></shape>"
      "<shape type=\"bsplinecurve\" id=\"b\"><string name=\"filename\" value=\"c.txt\"/><bsdf type=\"conductor\"/></shape>"));
  ASSERT_EQ(s.curves.size(), 2u);
  ASSERT_TRUE(s.meshes.empty());
  const Curve& lin = s.curves[0];
  EXPECT_EQ(lin.basis, CurveBasis::Linear);
  EXPECT_EQ(lin.points[1], Vec4(2, 1, 0, 0.2f));
  EXPECT_EQ(lin.points[3], Vec4(6, 1, 0, 0.4f));
  EXPECT_EQ(lin.segments.size(), 3u);
  EXPECT_EQ(s.curves[1].basis, CurveBasis::BSpline);
  EXPECT_EQ(s.curves[1].segments, (std::vector<uint32_t>{0}));
  EXPECT_NE(s.curves[1].bsdf, lin.bsdf);
  // A projective to_world: points are divided by w, as Mitsuba's Transform does for a point.
  const Scene p = loadText(dir, sceneXml("<shape type=\"linearcurve\"><string name=\"filename\" value=\"c.txt\"/>"
                                         "<transform name=\"to_world\"><matrix value=\"1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 2\"/>"
                                         "</transform></shape>"));
  EXPECT_EQ(p.curves.at(0).points[1], Vec4(0.5f, 0, 0, 0.2f));
}

TEST(CurveFile, ShapeErrorsNameTheSceneLine) {
  TempDir dir;
  dir.write("c.txt", "0 0 0 0.1\n1 0 0 0.2\n");
  dir.write("bad.txt", "0 0 0 0.1\n1 0 zz 0.2\n");
  const auto load = [&](const std::string& body) { return [&dir, body] { loadText(dir, sceneXml(body)); }; };
  expectError(load("<shape type=\"linearcurve\"><string name=\"filename\" value=\"bad.txt\"/></shape>"),
              {"bad.txt:2:", "four numbers"});
  expectError(load("<shape type=\"linearcurve\"/>"), {"scene.xml:3:", "filename"});
  // Four points are needed for a B-spline; this file has a linear curve's two.
  expectError(load("<shape type=\"bsplinecurve\"><string name=\"filename\" value=\"c.txt\"/></shape>"),
              {"c.txt:1:", "at least 4"});
  expectError(load("<shape type=\"linearcurve\"><string name=\"filename\" value=\"c.txt\"/>"
                   "<boolean name=\"flip_normals\" value=\"true\"/></shape>"),
              {"scene.xml:3:", "normals cannot be flipped"});
  // Mitsuba cannot sample positions on curves, so it cannot make one an area light either.
  expectError(load("<shape type=\"linearcurve\"><string name=\"filename\" value=\"c.txt\"/>"
                   "<emitter type=\"area\"/></shape>"),
              {"scene.xml:3:", "area emitter on a linearcurve"});
}

}  // namespace
}  // namespace rc::test
