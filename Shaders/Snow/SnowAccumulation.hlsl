#ifndef GT_SNOW_ACCUMULATION_INCLUDED
#define GT_SNOW_ACCUMULATION_INCLUDED

// The snow paper's eq. 1, D(x) = s L (N . Gn) max(1 - E, 0), and the depth update.
// Mirrors Runtime/Core/Snow/SnowAccumulation.cs (read its summary for why each term is what it is).
//   catchParams = _SnowCatch = (Gn.xyz, s), Gn = -normalize(gravity) (up)
//   edge = _SnowEdge = (edgeStrength, edgeWidth, exposureSoftness, 0)

// saturate(dot(N, Gn)): N the upward detail normal. Overhangs get 0, not a negative rate.
float SnowAccumulationCatch(float3 normal, float3 up)
{
    return saturate(dot(normal, up));
}

// Crest sharpness: drop in slope across the cell, > 0 on ridges and wall tops.
float SnowAccumulationCrest(float h, float hLeft, float hRight, float hDown, float hUp, float resolution)
{
    return (4.0 * h - hLeft - hRight - hDown - hUp) * resolution;
}

// E = strength * smoothstep(0, width, crest).
float SnowAccumulationEdgeTerm(float crest, float strength, float width)
{
    return strength * smoothstep(0.0, width, crest);
}

// D = s L catch max(1 - E, 0), depth per second.
float SnowAccumulationRate(float scale, float exposure, float catchTerm, float edge)
{
    return scale * exposure * catchTerm * max(1.0 - edge, 0.0);
}

// New depth after dt seconds, clamped to [0, cap].
float SnowAccumulationStep(float depth, float rate, float dt, float cap, float melt)
{
    return clamp(depth + (rate - melt) * dt, 0.0, cap);
}

// D at cell (i, j) given its exposure (grid = _SnowGrid = (R, 1/R, rayLength, raySteps)).
float SnowAccumulationRateAt(StructuredBuffer<float4> field, uint2 cell, float exposure, float4 grid, float4 catchParams, float4 edge)
{
    int r = (int)grid.x;
    int2 c = (int2)cell;
    float4 here = field[c.y * r + c.x];
    float hl = field[c.y * r + max(c.x - 1, 0)].w;
    float hr = field[c.y * r + min(c.x + 1, r - 1)].w;
    float hd = field[max(c.y - 1, 0) * r + c.x].w;
    float hu = field[min(c.y + 1, r - 1) * r + c.x].w;
    float e = SnowAccumulationEdgeTerm(SnowAccumulationCrest(here.w, hl, hr, hd, hu, grid.x), edge.x, edge.y);
    return SnowAccumulationRate(catchParams.w, exposure, SnowAccumulationCatch(here.xyz, catchParams.xyz), e);
}

#endif // GT_SNOW_ACCUMULATION_INCLUDED
