#include "scene/curve_loader.h"

#include <cmath>
#include <cstdlib>
#include <limits>

#include "core/error.h"
#include "core/regular_file.h"

namespace rc {

namespace {

size_t minimumPoints(CurveBasis basis) { return basis == CurveBasis::Linear ? 2 : 4; }

// Appends the segments of the curve made of points [first, end).
void finishCurve(CurveData& data, size_t first, CurveBasis basis, const std::string& path, int line) {
  const size_t count = data.points.size() - first, need = minimumPoints(basis);
  if (count == 0) return;
  if (count < need)
    throw Error(atLocation(path, line,
                           std::string(basis == CurveBasis::Linear ? "a linear" : "a B-spline") + " curve needs at least " +
                               std::to_string(need) + " control points, this one has " + std::to_string(count)));
  for (size_t i = first; i + need <= data.points.size(); ++i) data.segments.push_back(static_cast<uint32_t>(i));
}

bool blank(const std::string& s) { return s.find_first_not_of(" \t\r") == std::string::npos; }

}  // namespace

CurveData parseCurves(const std::string& text, const std::string& path, CurveBasis basis) {
  CurveData data;
  size_t curveFirst = 0;
  int curveLine = 0;  // where the open curve starts, for its message
  int lineNo = 0;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    if (lineNo == std::numeric_limits<int>::max()) throw Error(path + ": too many lines");
    ++lineNo;
    if (end - pos > kMaxCurveLineLength)
      throw Error(atLocation(path, lineNo, "line longer than " + std::to_string(kMaxCurveLineLength) + " characters"));
    const std::string line = text.substr(pos, end - pos);
    pos = end + 1;
    if (blank(line)) {
      finishCurve(data, curveFirst, basis, path, curveLine);
      curveFirst = data.points.size();
      continue;
    }
    if (data.points.size() == curveFirst) curveLine = lineNo;
    // Segment indices are 32-bit (Embree's index buffer).
    if (data.points.size() >= 0xFFFFFFF0u) throw Error(atLocation(path, lineNo, "too many control points"));
    float v[4];
    const char* cur = line.c_str();
    for (float& x : v) {
      char* next = nullptr;
      x = std::strtof(cur, &next);
      if (next == cur) throw Error(atLocation(path, lineNo, "expected four numbers 'x y z radius', got '" + line + "'"));
      cur = next;
    }
    if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
      throw Error(atLocation(path, lineNo, "control point position is not finite: '" + line + "'"));
    if (!std::isfinite(v[3]) || v[3] < 0.0f)
      throw Error(atLocation(path, lineNo, "control point radius must be finite and non-negative: '" + line + "'"));
    data.points.emplace_back(v[0], v[1], v[2], v[3]);
  }
  finishCurve(data, curveFirst, basis, path, curveLine);
  if (data.points.empty()) throw Error(path + ": no control points in the curve file");
  return data;
}

CurveData loadCurves(const std::string& path, CurveBasis basis) {
  return parseCurves(readRegularFile(path, "curve file"), path, basis);
}

}  // namespace rc
