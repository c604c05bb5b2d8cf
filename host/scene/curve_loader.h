#pragma once
// Mitsuba 3's curve files (shapes `linearcurve`, `bsplinecurve`): one control point per line,
// "x y z radius" (what follows the fourth number is ignored, as Mitsuba's reader does); a blank
// line ends a curve. A linear curve needs 2 control points and has one segment per pair, a cubic
// B-spline needs 4 and has one segment per 4 consecutive points (count − 3).
#include <cstdint>
#include <string>
#include <vector>

#include "core/math.h"

namespace rc {

enum class CurveBasis { Linear, BSpline };

struct CurveData {
  std::vector<Vec4> points;        // x, y, z (object space) and the radius
  std::vector<uint32_t> segments;  // each segment's first control point, curve after curve
};

// Longest line accepted (Mitsuba's reader refuses longer ones too); bounds the per-line work.
constexpr size_t kMaxCurveLineLength = 1024;

// Parses `text` (the contents of `path`, used in messages). Throws rc::Error("path:LINE: what")
// for a line that is not four numbers, a non-finite value, a negative radius, an over-long line
// or a curve with too few control points; "path: ..." for a file without control points.
CurveData parseCurves(const std::string& text, const std::string& path, CurveBasis basis);
// Reads the regular file `path` whole and parses it.
CurveData loadCurves(const std::string& path, CurveBasis basis);

}  // namespace rc
