#ifndef GT_TESSELLATION_FACTORS_INCLUDED
#define GT_TESSELLATION_FACTORS_INCLUDED

// Hull constant function helpers. Mirrors Runtime/Core/TessellationPolicy.cs.
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

float TessInsideFactor(float e0, float e1, float e2, float e3)
{
    return max(max(e0, e1), max(e2, e3));
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
