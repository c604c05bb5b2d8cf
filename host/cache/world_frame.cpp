#include "cache/world_frame.h"

#include <algorithm>

#include "cl/sh_backend.h"

namespace rc {

WorldCopies rotateToWorld(ShBackend& backend, int order, const std::vector<RecordInfo>& infos,
                          const std::vector<float>& lambda, const std::vector<float>& gradT,
                          const std::vector<float>& gradB) {
  const size_t coeffs = 3 * static_cast<size_t>(order) * order, records = infos.size();
  RotateBatch batch;
  batch.order = order;
  batch.count = static_cast<int>(3 * records);
  batch.rotations.resize(9 * 3 * records);
  batch.coeffs.resize(coeffs * 3 * records);
  for (size_t part = 0; part < 3; ++part)
    for (size_t r = 0; r < records; ++r) {
      const Frame& f = infos[r].frame;
      const Vec3 cols[3] = {f.t, f.b, f.n};
      float* rotation = &batch.rotations[9 * (part * records + r)];
      for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) rotation[3 * row + col] = cols[col][row];
      const std::vector<float>& src = part == 0 ? lambda : part == 1 ? gradT : gradB;
      std::copy(src.begin() + coeffs * r, src.begin() + coeffs * (r + 1),
                batch.coeffs.begin() + coeffs * (part * records + r));
    }
  std::vector<float> rotated;
  backend.rotate(batch, rotated);
  WorldCopies out;
  out.lambda.assign(rotated.begin(), rotated.begin() + coeffs * records);
  out.gradT.assign(rotated.begin() + coeffs * records, rotated.begin() + 2 * coeffs * records);
  out.gradB.assign(rotated.begin() + 2 * coeffs * records, rotated.end());
  return out;
}

}  // namespace rc
