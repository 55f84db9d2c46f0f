// The R x R cell grid of the snow maps (the depth map, SnowMap.hlsl, and the exposure pass's height
// field, SnowExposure.hlsl): cell (i, j) at j * R + i, centred on ((i + 0.5) / R, (j + 0.5) / R).
// Mirrors Runtime/Core/Snow/SnowCells.cs.
#ifndef GT_SNOW_CELLS_INCLUDED
#define GT_SNOW_CELLS_INCLUDED

// A bilinear read at q between cell centres, edge cells repeated: the four cells' indices and the
// fractions along u and v.
struct SnowCellBlend
{
    int c00, c10, c01, c11;
    float2 t;
};

SnowCellBlend SnowCellsBilinear(float r, float2 q)
{
    int n = (int)r;
    float2 uv = q * r - 0.5;
    float2 f = floor(uv);
    int2 c0 = clamp((int2)f, 0, n - 1);
    int2 c1 = clamp((int2)f + 1, 0, n - 1);
    SnowCellBlend b;
    b.c00 = c0.y * n + c0.x;
    b.c10 = c0.y * n + c1.x;
    b.c01 = c1.y * n + c0.x;
    b.c11 = c1.y * n + c1.x;
    b.t = uv - f;
    return b;
}

// The four cells' values blended, along u first.
float SnowCellsBlend(SnowCellBlend b, float v00, float v10, float v01, float v11)
{
    return lerp(lerp(v00, v10, b.t.x), lerp(v01, v11, b.t.x), b.t.y);
}

#endif // GT_SNOW_CELLS_INCLUDED
