#include "bsdf/fresnel.h"

namespace rc {

FresnelDielectric fresnelDielectric(float cosThetaI, float eta) {
  const bool outside = cosThetaI >= 0.0f;
  const float rcpEta = 1.0f / eta;
  const float etaIt = outside ? eta : rcpEta, etaTi = outside ? rcpEta : eta;
  // Snell: cos²θt = 1 − (1 − cos²θi)·(ηti)²; negative means total internal reflection.
  const float cosThetaTSqr = 1.0f - (1.0f - cosThetaI * cosThetaI) * (etaTi * etaTi);
  const float cosI = std::fabs(cosThetaI);
  const float cosT = std::sqrt(fmaxInline(0.0f, cosThetaTSqr));
  const float aS = (cosI - etaIt * cosT) / (cosI + etaIt * cosT);
  const float aP = (cosT - etaIt * cosI) / (cosT + etaIt * cosI);
  float r = 0.5f * (aS * aS + aP * aP);
  // Index-matched interfaces do not reflect; grazing incidence reflects fully (avoids 0/0).
  if (eta == 1.0f) r = 0.0f;
  else if (cosI == 0.0f) r = 1.0f;
  return {r, outside ? -cosT : cosT, etaIt, etaTi};
}

float fresnelConductor(float cosThetaI, float eta, float k) {
  const float c2 = cosThetaI * cosThetaI, s2 = 1.0f - c2, s4 = s2 * s2;
  const float temp1 = eta * eta - k * k - s2;
  const float a2pb2 = std::sqrt(fmaxInline(0.0f, temp1 * temp1 + 4.0f * k * k * eta * eta));
  const float a = std::sqrt(fmaxInline(0.0f, 0.5f * (a2pb2 + temp1)));
  const float term1 = a2pb2 + c2, term2 = 2.0f * cosThetaI * a;
  const float rS = (term1 - term2) / (term1 + term2);
  const float term3 = a2pb2 * c2 + s4, term4 = term2 * s2;
  const float rP = rS * (term3 - term4) / (term3 + term4);
  return 0.5f * (rS + rP);
}

Color fresnelConductor(float cosThetaI, const Color& eta, const Color& k) {
  return Color(fresnelConductor(cosThetaI, eta.r, k.r), fresnelConductor(cosThetaI, eta.g, k.g),
               fresnelConductor(cosThetaI, eta.b, k.b));
}

float fresnelDiffuseReflectance(float eta) {
  const float invEta = 1.0f / eta;
  // Egan & Hilgeman 1973: good for eta < 1 (max rel. error 0.1–0.6 % for 1/eta in 1–2).
  const float approx1 = 0.0636f * invEta + (eta * (eta * -1.4399f + 0.7099f) + 0.6681f);
  // d'Eon & Irving 2011: accurate for eta ≥ 1 up to 10 (Horner form in 1/eta).
  const float c[6] = {0.919317f, -3.4793f, 6.75335f, -7.80989f, 4.98554f, -1.36881f};
  float approx2 = c[5];
  for (int i = 4; i >= 0; --i) approx2 = approx2 * invEta + c[i];
  return eta < 1.0f ? approx1 : approx2;
}

}  // namespace rc
