#ifndef GT_GRADIENT_NOISE_INCLUDED
#define GT_GRADIENT_NOISE_INCLUDED

// 2D gradient (Perlin) noise on the integer lattice. Mirrors Runtime/Core/Library/GradientNoise.cs
// (C# GradientNoise.Evaluate == HLSL GradientNoise; other members GradientNoise<Name>).
// Integer hash instead of a permutation table: 32-bit uint arithmetic wraps modulo 2^32 here as in
// C# unchecked code, so both pick the same gradient bit for bit. 8 unit gradients, quintic fade,
// value scaled by sqrt(2) to span [-1, 1], exactly 0 on lattice points.

#include "RangeMapping.hlsl"

#define GT_NOISE_SCALE 1.41421356
#define GT_NOISE_DIAG 0.707106781

static const float2 kGradientNoiseDirections[8] =
{
    float2(1.0, 0.0), float2(GT_NOISE_DIAG, GT_NOISE_DIAG), float2(0.0, 1.0), float2(-GT_NOISE_DIAG, GT_NOISE_DIAG),
    float2(-1.0, 0.0), float2(-GT_NOISE_DIAG, -GT_NOISE_DIAG), float2(0.0, -1.0), float2(GT_NOISE_DIAG, -GT_NOISE_DIAG)
};

// PCG output permutation of one LCG step: a 32-bit mix with good avalanche.
uint GradientNoiseHash(uint v)
{
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// Lattice point hash Hash(x + Hash(y)); negative ints enter as their bits.
uint GradientNoiseHash2(int2 cell)
{
    return GradientNoiseHash(asuint(cell.x) + GradientNoiseHash(asuint(cell.y)));
}

float2 GradientNoiseGradient(uint h)
{
    // A table, not arithmetic: selects computing the same directions made the domain stage
    // measurably slower (Tools~/bench/records.md, "Where the domain stage's time goes").
    return kGradientNoiseDirections[h & 7u];
}

// Offset of noise stream `stream` (octave k = stream k): integer part in [0, 256) + 16-bit fraction,
// exact in float.
float2 GradientNoiseStreamOffset(uint stream)
{
    uint hx = GradientNoiseHash(stream ^ 0x9E3779B9u);
    uint hy = GradientNoiseHash(hx);
    return float2(float(hx & 255u) + float((hx >> 8u) & 0xFFFFu) / 65536.0,
                  float(hy & 255u) + float((hy >> 8u) & 0xFFFFu) / 65536.0);
}

float GradientNoiseFade(float t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }
float GradientNoiseFadeDerivative(float t) { float k = t * (t - 1.0); return 30.0 * k * k; }

// Each corner's linear ramp g . (f - corner) at the fraction f of the cell.
void GradientNoiseCornerRamps(float2 g00, float2 g10, float2 g01, float2 g11, float2 f, out float n00, out float n10, out float n01, out float n11)
{
    float2 h = f - 1.0;
    n00 = g00.x * f.x + g00.y * f.y;
    n10 = g10.x * h.x + g10.y * f.y;
    n01 = g01.x * f.x + g01.y * h.y;
    n11 = g11.x * h.x + g11.y * h.y;
}

// GradientNoiseCell once the cell's four corner gradients are known.
float GradientNoiseCorners(float2 g00, float2 g10, float2 g01, float2 g11, float2 f, out float2 gradient)
{
    float n00, n10, n01, n11;
    GradientNoiseCornerRamps(g00, g10, g01, g11, f, n00, n10, n01, n11);
    float u = GradientNoiseFade(f.x), v = GradientNoiseFade(f.y);
    float du = GradientNoiseFadeDerivative(f.x), dv = GradientNoiseFadeDerivative(f.y);
    float k1 = n10 - n00, k2 = n01 - n00, k3 = (n00 - n10) - (n01 - n11);
    float n = n00 + u * k1 + v * k2 + u * v * k3;
    float2 d = g00 + u * (g10 - g00) + v * (g01 - g00) + u * v * ((g00 - g10) - (g01 - g11))
             + float2(du * (k1 + v * k3), dv * (k2 + u * k3));
    gradient = GT_NOISE_SCALE * d;
    return GT_NOISE_SCALE * n;
}

// --- Tiled noise (GT_NOISE_TABLE; C# GradientNoiseTable) ----------------------------------------
// The lattice wrapped modulo 256: the noise repeats every 256 cells. Each cell's polynomial comes
// from two float4 rows of a table (32 bytes, one memory sector) instead of six hashes and four
// gradient reads; the includer defines GradientNoiseTableRows(uint firstRow, out float4 r0,
// out float4 r1), reading its buffer. The rows' layout: C# GradientNoiseTable.

uint GradientNoiseTableFirstRow(int2 cell)
{
    return (((uint(cell.y) & 255u) << 8u) | (uint(cell.x) & 255u)) * 2u;
}

// The cell's noise from its rows: GradientNoiseCorners' polynomial, its differences precomputed.
float GradientNoiseTablePolynomial(float4 r0, float4 r1, float2 f, out float2 gradient)
{
    float2 h = f - 1.0;
    float n00 = r0.x * f.x + r0.y * f.y;
    float k1 = (r0.z * h.x + r0.w * f.y) - r0.x;
    float k2 = (r1.x * f.x + r1.y * h.y) - r0.y;
    float k3 = (r1.z * h.x + r1.w * h.y) - (r1.x + r0.w);
    float u = GradientNoiseFade(f.x), v = GradientNoiseFade(f.y);
    float du = GradientNoiseFadeDerivative(f.x), dv = GradientNoiseFadeDerivative(f.y);
    float uv = u * v;
    gradient = r0.xy + u * r0.zw + v * r1.xy + uv * r1.zw + float2(du * (k1 + v * k3), dv * (k2 + u * k3));
    return n00 + u * k1 + v * k2 + uv * k3;
}

// The four corner gradients of lattice cell `cell` (wrapped modulo 256 for the tiled noise).
void GradientNoiseCornerGradients(int2 cell, out float2 g00, out float2 g10, out float2 g01, out float2 g11)
{
#if defined(GT_NOISE_TABLE)
    int2 c0 = cell & 255, c1 = (cell + 1) & 255;
#else
    int2 c0 = cell, c1 = cell + 1;
#endif
    g00 = GradientNoiseGradient(GradientNoiseHash2(c0));
    g10 = GradientNoiseGradient(GradientNoiseHash2(int2(c1.x, c0.y)));
    g01 = GradientNoiseGradient(GradientNoiseHash2(int2(c0.x, c1.y)));
    g11 = GradientNoiseGradient(GradientNoiseHash2(c1));
}

// Noise in lattice cell `cell` at fraction f (normally in [0, 1]); gradient w.r.t. the lattice coordinate.
float GradientNoiseCell(int2 cell, float2 f, out float2 gradient)
{
#if defined(GT_NOISE_TABLE)
    float4 r0, r1;
    GradientNoiseTableRows(GradientNoiseTableFirstRow(cell), r0, r1);
    return GradientNoiseTablePolynomial(r0, r1, f, gradient);
#else
    float2 g00, g10, g01, g11;
    GradientNoiseCornerGradients(cell, g00, g10, g01, g11);
    return GradientNoiseCorners(g00, g10, g01, g11, f, gradient);
#endif
}

// Fade(t + s) - Fade(t) as the quintic's exact Taylor polynomial in the step s: every term carries
// a factor s, so a tiny step keeps float's relative precision (see the C#).
float GradientNoiseFadeStep(float t, float s)
{
    float f1 = GradientNoiseFadeDerivative(t);        // 30 t^2 (t - 1)^2
    float f2 = 30.0 * t * ((2.0 * t - 1.0) * (t - 1.0));
    float f3 = (60.0 * t - 60.0) * t + 10.0;
    float f4 = 30.0 * t - 15.0;
    return s * (f1 + s * (f2 + s * (f3 + s * (f4 + s * 6.0))));
}

// K(cell, f + step) - K(cell, f) within one cell's polynomial from the precise step (lattice units):
// linear ramps differ by g . step, products by dA B1 + A0 dB, fades by GradientNoiseFadeStep.
// gradient: at f + step (lattice units); baseValue: K at f (plain float).
// The tiled noise takes the wrapped corners' gradients here, not its table: the steps need them.
float GradientNoiseCellDifference(int2 cell, float2 f, float2 step, out float2 gradient, out float baseValue)
{
    float2 g00, g10, g01, g11;
    GradientNoiseCornerGradients(cell, g00, g10, g01, g11);
    float n00, n10, n01, n11;
    GradientNoiseCornerRamps(g00, g10, g01, g11, f, n00, n10, n01, n11);
    float d00 = g00.x * step.x + g00.y * step.y, d10 = g10.x * step.x + g10.y * step.y;
    float d01 = g01.x * step.x + g01.y * step.y, d11 = g11.x * step.x + g11.y * step.y;
    float k1 = n10 - n00, k2 = n01 - n00, k3 = (n00 - n10) - (n01 - n11);
    float e1 = d10 - d00, e2 = d01 - d00, e3 = (d00 - d10) - (d01 - d11);
    float u0 = GradientNoiseFade(f.x), v0 = GradientNoiseFade(f.y);
    float du = GradientNoiseFadeStep(f.x, step.x), dv = GradientNoiseFadeStep(f.y, step.y);
    float v1 = v0 + dv, k31 = k3 + e3;
    float dn = d00 + (du * (k1 + e1) + u0 * e1) + (dv * (k2 + e2) + v0 * e2)
             + (du * v1 * k31 + u0 * (dv * k31 + v0 * e3));
    baseValue = GT_NOISE_SCALE * (n00 + u0 * k1 + v0 * k2 + u0 * v0 * k3);
    GradientNoiseCorners(g00, g10, g01, g11, f + step, gradient);
    return GT_NOISE_SCALE * dn;
}

// Noise at x (|x| < 2^31; at |x| ~ 1e6 a float's fraction has only 4 bits: use GradientNoiseAtPoint).
float GradientNoise(float2 x, out float2 gradient)
{
    float2 c = floor(x);
    return GradientNoiseCell(int2(c), x - c, gradient);
}

// Dekker's TwoProduct without FMA: a * b == p + err exactly (Veltkamp split into 12-bit halves).
// `precise` keeps the compiler from fusing or reassociating, which would break exactness.
float GradientNoiseTwoProduct(float a, float b, out float err)
{
    precise float p = a * b;
    precise float ca = 4097.0 * a;
    precise float ah = ca - (ca - a);
    precise float al = a - ah;
    precise float cb = 4097.0 * b;
    precise float bh = cb - (cb - b);
    precise float bl = b - bh;
    precise float e = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
    err = e;
    return p;
}

// One axis of frequency * (hi + local) + offset = cell + fraction, with hi * frequency exact (see C#).
void GradientNoiseSplitLattice(float hi, float local, float frequency, float offset, out int cell, out float fraction)
{
    float pe;
    float ph = GradientNoiseTwoProduct(hi, frequency, pe);
    float ch = floor(ph), co = floor(offset);
    precise float fr = (ph - ch) + ((pe + local * frequency) + (offset - co));
    float cf = floor(fr);
    cell = int(ch) + int(co) + int(cf);
    fraction = fr - cf;
}

// GradientNoiseSplitLattice of a point without a hi part (hi = 0, no range origin): the same cell
// and fraction bit for bit (hi * frequency = 0 and its error 0 add nothing), without TwoProduct.
void GradientNoiseSplitLocal(float local, float frequency, float offset, out int cell, out float fraction)
{
    float co = floor(offset);
    precise float fr = local * frequency + (offset - co);
    float cf = floor(fr);
    cell = int(co) + int(cf);
    fraction = fr - cf;
}
// GradientNoiseAtPoint of a point without a hi part (originHi = 0): the same value, bit for bit.
float GradientNoiseAtLocal(float2 local, float frequency, float2 offset, out float2 gradient)
{
    int2 cell;
    float2 f;
    GradientNoiseSplitLocal(local.x, frequency, offset.x, cell.x, f.x);
    GradientNoiseSplitLocal(local.y, frequency, offset.y, cell.y, f.y);
    return GradientNoiseCell(cell, f, gradient);
}
// Noise at the lattice coordinate frequency * q + offset of a TerrainPoint (deep-zoom safe);
// gradient w.r.t. the lattice coordinate (multiply by frequency for d/dq).
float GradientNoiseAtPoint(TerrainPoint p, float frequency, float2 offset, out float2 gradient)
{
    int2 cell;
    float2 f;
    GradientNoiseSplitLattice(p.originHi.x, p.local.x, frequency, offset.x, cell.x, f.x);
    GradientNoiseSplitLattice(p.originHi.y, p.local.y, frequency, offset.y, cell.y, f.y);
    return GradientNoiseCell(cell, f, gradient);
}

#endif // GT_GRADIENT_NOISE_INCLUDED
