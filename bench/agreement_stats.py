"""How far an rcache image is from a Mitsuba reference, in units of its noise (bench/real_scenes.py).

The noise of a 16-px block mean is estimated from K rcache seed images, pooled over the block's
4×4-px sub-blocks (so the reconstruction filter's pixel correlation stays inside one estimate) and
per channel (a coloured light or material makes one channel far noisier than the others). The pooled
estimate is only as good as its degrees of freedom: where a few sub-blocks hold all the noise (an
emitter's edge, a firefly), 16 sub-blocks × (K−1) give far fewer than 16·(K−1) effective degrees of
freedom, and the ratio difference/estimated-σ then follows Student's t with that many, not a normal
law — its tails beyond 4 are orders of magnitude heavier. So each block's ratio is turned into the
normal deviate of the same two-sided tail probability under t(ν_eff), with the Welch–Satterthwaite
ν_eff of the pooled sum. The threshold (4) keeps its meaning: a 4σ event of a normal variable.
"""
import math
from statistics import NormalDist

import numpy as np


def block_means(img, b):
    h, w, c = img.shape
    h2, w2 = h // b * b, w // b * b
    return img[:h2, :w2].reshape(h2 // b, b, w2 // b, b, c).mean(axis=(1, 3))


def _betacf(a, b, x):
    """Continued fraction of the regularised incomplete beta function (modified Lentz)."""
    tiny = 1e-300
    c, d = 1.0, 1.0 - (a + b) * x / (a + 1.0)
    d = 1.0 / (d if abs(d) > tiny else tiny)
    h = d
    for m in range(1, 400):
        m2 = 2 * m
        for num in (m * (b - m) * x / ((a + m2 - 1) * (a + m2)), -(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1))):
            d = 1.0 + num * d
            d = 1.0 / (d if abs(d) > tiny else tiny)
            c = 1.0 + num / c
            c = c if abs(c) > tiny else tiny
            h *= d * c
        if abs(d * c - 1.0) < 1e-15:
            break
    return h


def betainc(a, b, x):
    """Regularised incomplete beta function I_x(a, b)."""
    if x <= 0.0:
        return 0.0
    if x >= 1.0:
        return 1.0
    lfront = math.lgamma(a + b) - math.lgamma(a) - math.lgamma(b) + a * math.log(x) + b * math.log1p(-x)
    if x < (a + 1.0) / (a + b + 2.0):
        return math.exp(lfront) * _betacf(a, b, x) / a
    return 1.0 - math.exp(lfront) * _betacf(b, a, 1.0 - x) / b


def t_two_sided_tail(t, nu):
    """P(|T| > t) for Student's t with nu degrees of freedom."""
    return betainc(0.5 * nu, 0.5, nu / (nu + t * t))


def normal_equivalent(t, nu):
    """The normal deviate with the same two-sided tail probability as |t| under t(nu)."""
    p = max(t_two_sided_tail(abs(t), nu), 1e-300)
    return -NormalDist().inv_cdf(0.5 * p)


def _sub_terms(images, scale):
    """Per 4-px sub-block and channel: the variance of the images' mean (their scatter, ddof 1, over
    their count, times scale) and its degrees of freedom."""
    imgs = np.stack(images)
    return np.stack([block_means(i, 4) for i in imgs]).var(axis=0, ddof=1) / imgs.shape[0] * scale, imgs.shape[0] - 1


def _noise_terms(seeds, mseeds, spp, spp_mitsuba):
    """The sub-block variance terms of the difference of the two means, each with its degrees of
    freedom: rcache's and Mitsuba's scatter, or with one Mitsuba image rcache's scatter standing for
    both (one term: the same data must not count its degrees of freedom twice)."""
    if len(mseeds) >= 2:
        return [_sub_terms(seeds, 1.0), _sub_terms(mseeds, 1.0)]
    return [_sub_terms(seeds, 1.0 + len(seeds) * spp / spp_mitsuba)]


def block_z(seeds, mseeds, spp, spp_mitsuba):
    """Per 16-px block and channel: |mean of the rcache seeds − mean of the Mitsuba seeds| in units of
    its noise, as the normal deviate of the same tail probability (module docstring). seeds: K ≥ 2
    rcache images of spp samples each; mseeds: Mitsuba's images, spp_mitsuba samples in all. With
    two or more Mitsuba seeds their own scatter is their noise (a firefly in the reference counts);
    with one, Mitsuba's noise is taken as rcache's per-sample variance at Mitsuba's sample count."""
    terms = _noise_terms(seeds, mseeds, spp, spp_mitsuba)
    a16, m16 = block_means(np.mean(seeds, axis=0), 16), block_means(np.mean(mseeds, axis=0), 16)
    H, W = a16.shape[:2]
    blk = [(v[:H * 4, :W * 4].reshape(H, 4, W, 4, -1), dof) for v, dof in terms]
    var = sum(v.sum(axis=(1, 3)) for v, _ in blk) / 256.0                 # a block mean averages 16 sub-blocks
    # Welch–Satterthwaite: ν = (Σ vᵢ)² / Σ vᵢ²/νᵢ over every sub-block term of both renderers.
    spread = sum((v ** 2).sum(axis=(1, 3)) / dof for v, dof in blk) / 256.0 ** 2
    nu = np.where(var > 0, var ** 2 / np.maximum(spread, 1e-300), 1.0)
    diff = np.abs(a16 - m16)
    t = diff / np.sqrt(np.maximum(var, 1e-20))
    z = np.vectorize(normal_equivalent)(t, np.maximum(nu, 1e-3))
    # Blocks that are exactly equal and noiseless (black background) carry no information.
    z[diff < 1e-7] = 0.0
    return z


def compare(seeds, mseeds, spp, spp_mitsuba):
    """Per-channel mean ratio (rcache / Mitsuba, each the mean of its seeds), the largest block z
    (block_z) and the per-channel z of the whole image's mean."""
    a, m = np.mean(seeds, axis=0), np.mean(mseeds, axis=0)
    mean_ratio = (a.mean(axis=(0, 1)) / np.maximum(m.mean(axis=(0, 1)), 1e-12)).tolist()
    if a.shape[0] < 16 or a.shape[1] < 16:
        return mean_ratio, None, None
    # The whole image's mean in units of its noise, per channel (the same sub-block variances; with
    # hundreds of sub-blocks a normal deviate): tells a mean ratio beyond 1 % that is noise from a bias.
    v = sum(v for v, _ in _noise_terms(seeds, mseeds, spp, spp_mitsuba))
    var_mean = v.sum(axis=(0, 1)) / (v.shape[0] * v.shape[1]) ** 2
    mean_z = (np.abs(a.mean(axis=(0, 1)) - m.mean(axis=(0, 1))) / np.sqrt(np.maximum(var_mean, 1e-30))).tolist()
    return mean_ratio, float(block_z(seeds, mseeds, spp, spp_mitsuba).max()), mean_z
