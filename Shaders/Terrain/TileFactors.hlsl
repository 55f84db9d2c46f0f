// Per-tile tessellation factors: frustum culling and the adaptive factors, for hull_const and the
// vertex cache's CacheTileFactors kernel alike. Mirrors Runtime/Core/Terrain/TileFactors.cs name for
// name (the arithmetic: TessellationPolicy.cs; the rule: internals.md, "Shader stages and compiled files"). Needs the adapter's
// GT_ObjectToClip (the culling: the pass's view), GT_TessObjectToClip / GT_TessScreenSize (the pixel
// scales: the camera's, also in a shadow pass) and TerrainVertex.hlsl's EvaluateCellSurface.
//
// Every sample below is of the tile's cell (TileLattice.hlsl): the tile itself unless anchored and
// clipped to the range. A clipped tile draws its cell's factors scaled to the part it keeps
// (TileFactorsOfCell; the vertex cache's draw: ClippedCell.hlsl), so a pan, which only moves the
// clipped tiles, changes no sample.
#ifndef GT_TILE_FACTORS_INCLUDED
#define GT_TILE_FACTORS_INCLUDED

#include "TerrainVertex.hlsl"
#include "TessellationFactors.hlsl"

// A tile's six factors. Quad domain: edge.x is u = 0, .y v = 0, .z u = 1, .w v = 1; inside.x
// subdivides along u, inside.y along v. All zero = culled.
struct TileFactorSet
{
    float4 edge;
    float2 inside;
};

// Corner c sits at tess coordinate (c & 1, c >> 1).
float2 CornerTessCoordinate(uint corner) { return float2(corner & 1u, corner >> 1u); }

// Object position of corner c of the tile's cell (no noise): the input of the culling and the edge
// factors. Corners are lattice points, so a corner shared by neighbouring cells is evaluated from
// identical inputs: identical positions, identical edge factors.
float3 CellCornerObjectPosition(TileLayout l, uint drawPatch, uint corner)
{
    return TerrainToObject(OutputSurfacePosition(l, EvaluateCellSurface(l, drawPatch, CornerTessCoordinate(corner))));
}

// The height the noise may move the tile's surface from its corners' (no noise) frame: while a range
// origin O is set the vertices output p(q) - p(O) (TerrainVertex.hlsl), bounded through the corners'
// largest distance from O (NoiseDifferenceBound: metres near the feet, where the whole relief's
// bound kept tiles behind a ground-level camera); else p(q) itself, within NoiseHeightBound. A cell
// is a rectangle in q, so its farthest point from O is a corner. 0 without GT_NOISE. Mirrors Core
// TileFactors.TileNoiseMargin.
float TileNoiseMargin(TileLayout l, uint slot)
{
#if defined(GT_NOISE)
    #if !defined(GT_EXTEND_DRAW_PATCHES) && defined(GT_RANGE_ORIGIN_CODE)
    [branch] if (RelativeSurfaceIsActive(l.origin))
    {
        TerrainPoint origin = MakeTerrainPoint(l.origin.xy, l.origin.zw);
        float d = 0.0;
        [unroll] for (uint c = 0u; c < 4u; c++)
            d = max(d, length(TerrainPointDifference(CellToTerrainPoint(l, slot, CornerTessCoordinate(c)), origin)));
        return NoiseDifferenceBound(NoiseSettings(), MaxNoiseOctaves(), d);
    }
    #endif
    return NoiseHeightBound();
#else
    return 0.0;
#endif
}

// True when the cell's box (corners' bounds grown in height by the noise margin plus their own
// height spread) lies outside the view. Corners as an array: not every HLSL compiler accepts an
// InputPatch as a helper argument.
bool TileCulled(float3 cornerOS[4], float noiseMargin)
{
    float3 lo = cornerOS[0], hi = lo;
    [unroll] for (uint c = 1; c < 4; c++)
    {
        lo = min(lo, cornerOS[c]);
        hi = max(hi, cornerOS[c]);
    }
    float margin = hi.y - lo.y;
    margin += noiseMargin;
    lo.y -= margin;
    hi.y += margin;
#if defined(GT_SNOW)
    hi.y += SnowDepthCap();   // snow only raises the surface, by at most the cap
#endif
    float4 boxCS[8];
    [unroll] for (uint k = 0; k < 8; k++)
    {
        float3 p = float3((k & 1u) ? hi.x : lo.x, (k & 2u) ? hi.y : lo.y, (k & 4u) ? hi.z : lo.z);
        boxCS[k] = GT_ObjectToClip(p);
    }
    // The height margin is already in the box (object units), so no clip-space margin on top.
    return BoxOutsideFrustum(boxCS, 0.0);
}

// Object point -> pixels per object unit there (TessellationFactors.hlsl, PixelsPerUnit), camera's view.
float ObjectPixelsPerUnit(float3 p)
{
    return PixelsPerUnit(GT_TessObjectToClip(p), GT_TessObjectToClip(p + float3(1.0, 0.0, 0.0)),
                         GT_TessObjectToClip(p + float3(0.0, 1.0, 0.0)), GT_TessObjectToClip(p + float3(0.0, 0.0, 1.0)),
                         GT_TessScreenSize());
}

// Object position of the Gregory surface (no noise) at a tess coordinate of the tile's cell, in the
// frame the vertices output (OutputSurfacePosition: relative to S(O) while a range origin is set),
// as the corners: a line's sagitta and pixel scales compare its inner points with its corners.
float3 CellSurfaceObjectPosition(TileLayout l, uint drawPatch, float2 tess)
{
    return TerrainToObject(OutputSurfacePosition(l, EvaluateCellSurface(l, drawPatch, tess)));
}

// Uniform factors (_Tess.w > 0; tests and benchmarks): every tile, every edge _Tess.w, nothing
// culled, so the vertex count is known in advance, and no corner is needed. True with f set.
bool UniformTileFactors(out TileFactorSet f)
{
    f.edge = UniformTessFactor();
    f.inside = UniformTessFactor();
    return UsesUniformTessFactor();
}

// A culled tile: a zero edge factor drops the patch.
TileFactorSet CulledTileFactors()
{
    TileFactorSet f;
    f.edge = 0.0;
    f.inside = 0.0;
    return f;
}

// A zero edge factor drops the patch (Core's TileFactorSet.IsCulled).
bool TileFactorsCulled(TileFactorSet f) { return f.edge.x == 0.0; }

// Otherwise, unless the tile is culled (TileCulled), the adaptive factors come in seven pieces, each from its own samples of the surface, so that the
// vertex cache's kernel can give each its own lane (CacheTileFactors); the hull stage computes the
// seven in turn (ComputeTileFactors). Pieces 0-3: the edges u = 0, v = 0, u = 1, v = 1 (the
// tessellator's edge order). 4, 5: the midlines along u and along v. 6: the centre's deviation from
// the diagonals.
#define GT_TILE_FACTOR_PIECES 7u

// Piece 0-5 is a line of the tile from tess coordinate a to b (a the lower one); its end points are
// corners for the edges, surface points for the midlines; its length in terrain units.
void TileFactorLine(uint piece, out float2 a, out float2 b, out uint2 corners, out uint axis)
{
    // u = 0, v = 0, u = 1, v = 1, midline along u (v = 1/2), midline along v (u = 1/2)
    static const float4 lines[6] = { float4(0, 0, 0, 1), float4(0, 0, 1, 0), float4(1, 0, 1, 1),
                                     float4(0, 1, 1, 1), float4(0, 0.5, 1, 0.5), float4(0.5, 0, 0.5, 1) };
    static const uint2 ends[4] = { uint2(0, 2), uint2(0, 1), uint2(1, 3), uint2(2, 3) };
    a = lines[piece].xy;
    b = lines[piece].zw;
    corners = ends[min(piece, 3u)];
    axis = (piece == 1u || piece == 3u || piece == 4u) ? 0u : 1u;   // 0: along u (x), 1: along v (y)
}

// The surface samples the adaptive factors read, numbered so that the vertex cache's kernel can
// give each its own lane (CacheTileFactors): 0-3 the corners, then the GT_EDGE_SEGMENTS - 1 inner
// points of line 0, 1, .. 5 in turn, then the midlines' end points (line 4's a and b, line 5's a
// and b), then the centre. A sample is (object position, pixels per object unit), the latter only
// where a factor reads it (inner points, centre), else 0.
#define GT_TILE_INNER_POINTS (GT_EDGE_SEGMENTS - 1u)
#define GT_TILE_MIDLINE_END_SAMPLE (4u + 6u * GT_TILE_INNER_POINTS)
#define GT_TILE_CENTRE_SAMPLE (GT_TILE_MIDLINE_END_SAMPLE + 4u)
#define GT_TILE_FACTOR_SAMPLES (GT_TILE_CENTRE_SAMPLE + 1u)

// Inner point i (1 .. GT_EDGE_SEGMENTS - 1) of the tile's line from a to b, and the centre: their
// positions, and each with its pixels per object unit. Both the kernel's numbered samples and the
// hull's loop evaluate these.
float3 TileLineInnerPosition(TileLayout l, uint patch, float2 a, float2 b, uint i)
{
    return CellSurfaceObjectPosition(l, patch, lerp(a, b, (float)i / (float)GT_EDGE_SEGMENTS));
}

float3 TileCentrePosition(TileLayout l, uint patch) { return CellSurfaceObjectPosition(l, patch, float2(0.5, 0.5)); }

float4 TileLineInnerSample(TileLayout l, uint patch, float2 a, float2 b, uint i)
{
    float3 p = TileLineInnerPosition(l, patch, a, b, i);
    return float4(p, ObjectPixelsPerUnit(p));
}

float4 TileCentreSample(TileLayout l, uint patch)
{
    float3 centre = TileCentrePosition(l, patch);
    return float4(centre, ObjectPixelsPerUnit(centre));
}

// Sample s's object position: what depends on the surface and the range, not on the camera (the
// vertex cache keeps it while the range holds).
float3 TileFactorSamplePosition(TileLayout l, uint patch, uint s)
{
    if (s < 4u) return CellCornerObjectPosition(l, patch, s);
    float2 a, b;
    uint2 corners;
    uint axis;
    if (s < GT_TILE_MIDLINE_END_SAMPLE)
    {
        uint inner = s - 4u;
        TileFactorLine(inner / GT_TILE_INNER_POINTS, a, b, corners, axis);
        return TileLineInnerPosition(l, patch, a, b, inner % GT_TILE_INNER_POINTS + 1u);
    }
    if (s < GT_TILE_CENTRE_SAMPLE)
    {
        uint end = s - GT_TILE_MIDLINE_END_SAMPLE;
        TileFactorLine(4u + end / 2u, a, b, corners, axis);
        return CellSurfaceObjectPosition(l, patch, (end & 1u) ? b : a);
    }
    return TileCentrePosition(l, patch);
}

// Sample s at its position p: the camera's part, pixels per object unit, where a factor reads it
// (the lines' inner points and the centre), else 0.
float4 TileFactorSampleAt(uint s, float3 p)
{
    bool scaled = (s >= 4u && s < GT_TILE_MIDLINE_END_SAMPLE) || s == GT_TILE_CENTRE_SAMPLE;
    return float4(p, scaled ? ObjectPixelsPerUnit(p) : 0.0);
}

// The sample at point i (0 .. GT_EDGE_SEGMENTS, from a to b) of line `piece` (0-5).
uint TileLineSample(uint piece, uint i)
{
    float2 a, b;
    uint2 corners;
    uint axis;
    TileFactorLine(piece, a, b, corners, axis);
    if (i > 0u && i < GT_EDGE_SEGMENTS) return 4u + piece * GT_TILE_INNER_POINTS + i - 1u;
    if (piece < 4u) return i == 0u ? corners.x : corners.y;
    return GT_TILE_MIDLINE_END_SAMPLE + 2u * (piece - 4u) + (i == 0u ? 0u : 1u);
}

#if defined(GT_NOISE)
// The octaves the noise bound of a line counts: the frame's one count, or under the continuous rule
// (NoiseSegmentPixels() > 0, the levels of detail) the count at the line's largest pixel scale (its
// nearest sample draws the most octaves). Mirrors Core TileFactors.LineOctaveCount.
float LineOctaveCount(TileLayout l, float maxPixelsPerUnit)
{
    if (NoiseSegmentPixels() > 0.0) return OctaveCountAtPixelScale(maxPixelsPerUnit, NoiseSegmentPixels(), NoiseSettings(), MaxNoiseOctaves());
    return OctaveCount(LayoutWidth(l), NoiseVerticesAcross(), NoiseSettings(), MaxNoiseOctaves());
}
#endif

// A line's factor from its points p and pixel scales k: the surface's chord error plus the bound of
// the noise the frame draws. Both tiles sharing an edge take it lower tess coordinate first from the
// same global points and edge length, bit for bit: no cracks.
float LineErrorTessFactor(TileLayout l, uint patch, uint piece, float3 p[GT_EDGE_SEGMENTS + 1], float k[GT_EDGE_SEGMENTS + 1])
{
    float kMax = 0.0;
    [unroll] for (uint i = 1u; i < GT_EDGE_SEGMENTS; i++)
        kMax = max(kMax, k[i]);
    float2 a, b;
    uint2 corners;
    uint axis;
    TileFactorLine(piece, a, b, corners, axis);
    float2 edgeLength = CellEdgeLengths(l, patch);   // along u (x) and along v (y), terrain units
    float noiseCurvature = 0.0;
#if defined(GT_NOISE)
    // The octaves this frame draws (the count TerrainVertex uses): the knob counts the noise it shows.
    noiseCurvature = NoiseCurvatureBound(NoiseSettings(), LineOctaveCount(l, kMax));
#endif
    float sagitta = SampledEdgeSagittaPixels(p, k) + NoiseSagittaPixels(noiseCurvature, edgeLength[axis], kMax);
    return ErrorTessFactor(sagitta, TargetPixelError(), MaxTessFactor());
}

// Piece 6: the centre's deviation from the diagonals (centre: sample GT_TILE_CENTRE_SAMPLE, with its pixel scale).
float CentreErrorTessFactor(float3 cornerOS[4], float4 centre)
{
    return InsideErrorTessFactor(DiagonalSagittaPixels(cornerOS[0], cornerOS[1], cornerOS[2], cornerOS[3], centre.xyz, centre.w),
                                 TargetPixelError(), MaxTessFactor());
}

// One piece, its samples evaluated in turn: the hull stage's path. Not through
// TileFactorSamplePosition (Tools~/bench/records.md, "Choices in the shaders, measured").
float TileFactorPiece(TileLayout l, uint patch, uint piece, float3 cornerOS[4])
{
    if (piece == 6u) return CentreErrorTessFactor(cornerOS, TileCentreSample(l, patch));
    float2 a, b;
    uint2 corners;
    uint axis;
    TileFactorLine(piece, a, b, corners, axis);
    float3 p[GT_EDGE_SEGMENTS + 1];
    float k[GT_EDGE_SEGMENTS + 1];
    p[0] = piece < 4u ? cornerOS[corners.x] : CellSurfaceObjectPosition(l, patch, a);
    p[GT_EDGE_SEGMENTS] = piece < 4u ? cornerOS[corners.y] : CellSurfaceObjectPosition(l, patch, b);
    k[0] = k[GT_EDGE_SEGMENTS] = 0.0;
    [unroll] for (uint i = 1u; i < GT_EDGE_SEGMENTS; i++)
    {
        float4 v = TileLineInnerSample(l, patch, a, b, i);
        p[i] = v.xyz;
        k[i] = v.w;
    }
    return LineErrorTessFactor(l, patch, piece, p, k);
}

// Inside factors follow the edges they run along: inside[0] subdivides along u, like the v = 0 and
// v = 1 edges. They match no neighbour, so they may look inside: the midlines (bumps between the
// edges) and the diagonal term (a twist bends the diagonals, not the edges).
TileFactorSet TileFactorsOfPieces(float piece[GT_TILE_FACTOR_PIECES])
{
    TileFactorSet f;
    f.edge = float4(piece[0], piece[1], piece[2], piece[3]);
    f.inside = max(max(TessInsideFactors(piece[0], piece[1], piece[2], piece[3]), float2(piece[4], piece[5])), piece[6]);
    return f;
}

// The factors of a tile that keeps the part `kept` (TileKeptFraction) of its cell along x and y:
// each line's factor scaled by the part kept, at least 1, so its segments are no longer than the
// cell's. Edges u = 0, 1 (edge.x, .z) run along v (y), edges v = 0, 1 along u (x); inside.x
// subdivides along u. Tiles sharing an edge share the cell line and the row or column that scale
// it: crack-free. Whole (kept = 1): the cell's factors bit for bit. Culled stays culled.
TileFactorSet TileFactorsOfCell(TileFactorSet cell, float2 kept)
{
    if (TileFactorsCulled(cell)) return cell;
    TileFactorSet f;
    f.edge = max(cell.edge * kept.yxyx, 1.0);
    f.inside = max(cell.inside * kept, 1.0);
    return f;
}

// The hull stage's path; cornerOS: the cell's corners (CellCornerObjectPosition).
TileFactorSet ComputeTileFactors(TileLayout l, uint patch, float3 cornerOS[4])
{
    TileFactorSet f;
    if (TileEmpty(l, patch)) return CulledTileFactors();
    if (UniformTileFactors(f)) return f;
    if (TileCulled(cornerOS, TileNoiseMargin(l, patch))) return CulledTileFactors();
    float piece[GT_TILE_FACTOR_PIECES];
    [unroll] for (uint i = 0u; i < GT_TILE_FACTOR_PIECES; i++)
        piece[i] = TileFactorPiece(l, patch, i, cornerOS);
    return TileFactorsOfCell(TileFactorsOfPieces(piece), TileKeptFraction(l, patch));
}

#endif // GT_TILE_FACTORS_INCLUDED
