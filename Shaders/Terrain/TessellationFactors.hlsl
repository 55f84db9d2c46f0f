#ifndef GT_TESSELLATION_FACTORS_INCLUDED
#define GT_TESSELLATION_FACTORS_INCLUDED

// Hull constant function helpers. Mirrors Runtime/Core/Terrain/TessellationPolicy.cs.
// An edge factor depends only on the edge's two endpoints, so the two tiles sharing an edge agree
// (no cracks), and it is symmetric bit for bit in them (the neighbour walks the edge the other way).

// Clip position -> pixels from the screen centre (valid for w > 0).
float2 ClipToPixels(float4 clip, float2 screenSize)
{
    // precise: each endpoint is projected by the same instructions, never fused with the other's.
    precise float2 p = clip.xy / clip.w * (0.5 * screenSize);
    return p;
}

// Screen-space length of an edge; +inf when an endpoint is at or behind the eye plane.
float EdgeLengthPixels(float4 clip0, float4 clip1, float2 screenSize)
{
    if (!(clip0.w > 0.0) || !(clip1.w > 0.0)) return asfloat(0x7F800000u);
    float2 p0 = ClipToPixels(clip0, screenSize);
    float2 p1 = ClipToPixels(clip1, screenSize);
    precise float2 d = p1 - p0;            // == -(p0 - p1) exactly
    precise float l2 = d.x * d.x + d.y * d.y;
    return sqrt(l2);
}

// clamp(length / targetPixels, 1, maxFactor); a non-finite length gives maxFactor.
float EdgeTessFactor(float4 clip0, float4 clip1, float2 screenSize, float targetPixels, float maxFactor)
{
    float len = EdgeLengthPixels(clip0, clip1, screenSize);
    if (isinf(len) || isnan(len)) return maxFactor;
    return clamp(len / targetPixels, 1.0, maxFactor);
}

// --- Adaptive: target screen-space error (TessellationPolicy.PixelsPerUnit ... ErrorTessFactor) ---

// Mirrors TessellationPolicy.PixelsPerUnit; clipX/Y/Z: the point moved one object unit along x, y, z.
float PixelsPerUnit(float4 clip, float4 clipX, float4 clipY, float4 clipZ, float2 screenSize)
{
    if (!(clip.w > 0.0)) return asfloat(0x7F800000u);
    float invW = 1.0 / clip.w;
    float2 s = clip.xy * invW;
    float4 ax = clipX - clip, ay = clipY - clip, az = clipZ - clip;
    float2 h = 0.5 * screenSize * invW;
    float3 r0 = float3(ax.x - s.x * ax.w, ay.x - s.x * ay.w, az.x - s.x * az.w) * h.x;
    float3 r1 = float3(ax.y - s.y * ax.w, ay.y - s.y * ay.w, az.y - s.y * az.w) * h.y;
    // sqrt of the larger eigenvalue of J J^T = [[a, b], [b, c]]
    float a = dot(r0, r0), b = dot(r0, r1), c = dot(r1, r1);
    float hd = 0.5 * (a - c);
    return sqrt(0.5 * (a + c) + sqrt(hd * hd + b * b));
}

// Chord error (pixels) of an edge drawn as one segment, from its points at 0, 1/4, 1/2, 3/4, 1.
// Mirrors TessellationPolicy.EdgeSagittaPixels.
float EdgeSagittaPixels(float3 p0, float3 pQuarter, float3 pMid, float3 pThreeQuarter, float3 p1,
                        float kQuarter, float kMid, float kThreeQuarter)
{
    precise float whole = length(pMid - 0.5 * (p0 + p1)) * kMid;
    precise float first = 4.0 * length(pQuarter - 0.5 * (p0 + pMid)) * kQuarter;
    precise float second = 4.0 * length(pThreeQuarter - 0.5 * (pMid + p1)) * kThreeQuarter;
    return max(whole, max(first, second));
}

// Segments per tile edge the estimate samples (TessellationPolicy.EdgeSegments): the surface is
// evaluated at the GT_EDGE_SEGMENTS - 1 inner points (the corners are known). A power of two.
#define GT_EDGE_SEGMENTS 8

// EdgeSagittaPixels over GT_EDGE_SEGMENTS + 1 points p[i] at i / n with pixel scales k[i].
// Mirrors TessellationPolicy.EdgeSagittaPixels(points, scales).
float SampledEdgeSagittaPixels(float3 p[GT_EDGE_SEGMENTS + 1], float k[GT_EDGE_SEGMENTS + 1])
{
    float s = 0.0;
    [unroll] for (uint d = GT_EDGE_SEGMENTS / 2u; d >= 1u; d /= 2u)
    {
        float weight = (float)((GT_EDGE_SEGMENTS / (2u * d)) * (GT_EDGE_SEGMENTS / (2u * d)));
        [unroll] for (uint i = d; i < GT_EDGE_SEGMENTS; i += 2u * d)
        {
            precise float e = weight * length(p[i] - 0.5 * (p[i - d] + p[i + d])) * k[i];
            s = max(s, e);
        }
    }
    return s;
}

// Bound on |d^2 GradientNoise / dx^2| per unit lattice (TessellationPolicy.GradientNoiseCurvature).
#define GT_GRADIENT_NOISE_CURVATURE 12.0

// Bound on OctaveNoise's second derivative along x or y (terrain units per unit^2) for the octaves
// the frame draws: |amplitude| * C * sum_k fade_k beta^-k (frequency alpha^k)^2, noise =
// (amplitude, frequency, alpha, beta). Mirrors TessellationPolicy.NoiseCurvatureBound.
float NoiseCurvatureBound(float4 noise, float octaveCount)
{
    float f = noise.y, w = 1.0, invBeta = 1.0 / noise.w, sum = 0.0;
    [loop] for (uint k = 0u; k < 16u; ++k)   // 16 = GT_MAX_OCTAVES (OctaveNoise.hlsl)
    {
        float fade = saturate(octaveCount - float(k));
        if (fade <= 0.0) break;
        sum += fade * w * (f * f);
        f *= noise.z;
        w *= invBeta;
    }
    return abs(noise.x) * GT_GRADIENT_NOISE_CURVATURE * sum;
}

// Bound on |grad GradientNoise| per unit lattice (TessellationPolicy.GradientNoiseSlope).
#define GT_GRADIENT_NOISE_SLOPE 3.0

// Bound on |p(q) - p(O)| (terrain units) for q within `distance` (terrain units) of the range
// origin O. Mirrors TessellationPolicy.NoiseDifferenceBound.
float NoiseDifferenceBound(float4 noise, float octaves, float distance)
{
    float a = abs(noise.x), f = noise.y, invBeta = 1.0 / noise.w, sum = 0.0;
    [loop] for (uint k = 0u; k < 16u; ++k)   // 16 = GT_MAX_OCTAVES (OctaveNoise.hlsl)
    {
        float fade = saturate(octaves - float(k));
        if (fade <= 0.0) break;
        sum += fade * min(2.0 * a, a * GT_GRADIENT_NOISE_SLOPE * f * distance);
        f *= noise.z;
        a *= invBeta;
    }
    return sum;
}

// The chord error (pixels) the noise can add to an edge edgeLength long (terrain units) drawn as one
// segment: curvature L^2 / 8 at the edge's largest pixel scale. Mirrors TessellationPolicy.NoiseSagittaPixels.
float NoiseSagittaPixels(float noiseCurvature, float edgeLength, float maxPixelsPerUnit)
{
    return noiseCurvature * (edgeLength * edgeLength) * 0.125 * maxPixelsPerUnit;
}

// F = clamp(sqrt(2 sagitta / target), 1, maxFactor): half the target per direction of a cell
// (TessellationPolicy.ErrorTessFactor).
float ErrorTessFactor(float sagittaPixels, float targetPixelError, float maxFactor)
{
    if (isinf(sagittaPixels) || isnan(sagittaPixels)) return maxFactor;
    return clamp(sqrt(2.0 * max(sagittaPixels, 0.0) / targetPixelError), 1.0, maxFactor);
}

// The tile's bend its edges cannot see (a twist): the centre's deviation from the middle of each
// diagonal of the corner quad (corners in tess order (0,0), (1,0), (0,1), (1,1)), the larger one,
// in pixels (kCentre: PixelsPerUnit at the centre).
float DiagonalSagittaPixels(float3 p00, float3 p10, float3 p01, float3 p11, float3 pCentre, float kCentre)
{
    float d0 = length(pCentre - 0.5 * (p00 + p11));
    float d1 = length(pCentre - 0.5 * (p10 + p01));
    return max(d0, d1) * kCentre;
}

// A diagonal's error already holds both directions' bending: F = sqrt(s / target).
float InsideErrorTessFactor(float diagonalSagittaPixels, float targetPixelError, float maxFactor)
{
    if (isinf(diagonalSagittaPixels) || isnan(diagonalSagittaPixels)) return maxFactor;
    return clamp(sqrt(max(diagonalSagittaPixels, 0.0) / targetPixelError), 1.0, maxFactor);
}

// Inside factors of a quad from its edge factors (e0: u = 0, e1: v = 0, e2: u = 1, e3: v = 1): each
// the max of the two edges running the same way. Mirrors TessellationPolicy.InsideFactors.
float2 TessInsideFactors(float e0, float e1, float e2, float e3)
{
    return float2(max(e1, e3), max(e0, e2));
}

// Plane p of the widened clip volume -w - m <= x, y <= w + m, w >= -m
// (0 left, 1 right, 2 bottom, 3 top, 4 behind the eye; depth is not tested, see C#).
bool ClipOutsidePlane(float4 c, uint plane, float margin)
{
    if (plane == 0u) return c.x < -c.w - margin;
    if (plane == 1u) return c.x > c.w + margin;
    if (plane == 2u) return c.y < -c.w - margin;
    if (plane == 3u) return c.y > c.w + margin;
    return c.w < -margin;
}

// True when all 8 corners lie outside the same plane: the box can be culled (factor 0).
bool BoxOutsideFrustum(float4 clipCorners[8], float margin)
{
    [unroll] for (uint plane = 0u; plane < 5u; ++plane)
    {
        bool allOut = true;
        [unroll] for (uint i = 0u; i < 8u; ++i)
            allOut = allOut && ClipOutsidePlane(clipCorners[i], plane, margin);
        if (allOut) return true;
    }
    return false;
}

#endif // GT_TESSELLATION_FACTORS_INCLUDED
