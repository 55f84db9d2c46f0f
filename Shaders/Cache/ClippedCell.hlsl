// Anchored tiles drawn from whole cells (Documentation~/internals.md, "Vertex cache"). Mirrors
// Runtime/Core/Cache/ClippedCell.cs, same names, step for step.
//
// The vertex cache holds each lattice cell whole. A tile the range clips keeps [s0, s1] of its
// cell per axis (TileKeptCellSpan) and draws the segments of its cell's lines that meet it: its
// points on the cell's lines are the cell's own records, and only the points on the range's edge
// are blended from the two records either side. So a pan that keeps the cells changes nothing the
// kernels read (the renderer dispatches nothing), and no vertex but those on the range's edge moves.
#ifndef GT_CLIPPED_CELL_INCLUDED
#define GT_CLIPPED_CELL_INCLUDED

#include "VertexCache.hlsl"

// Exactly (0, 1, 0, 1): the tile is its whole cell.
bool CellKeptWhole(float4 kept) { return all(kept == float4(0.0, 1.0, 0.0, 1.0)); }

// The segments of a line of n that meet [s0, s1] (cell parameters); n for the whole line.
float KeptSegments(float n, float s0, float s1) { return ceil(s1 * n) - floor(s0 * n); }

// The integer factors of a tile that keeps `kept` = (s0.x, s1.x, s0.y, s1.y) of a cell drawn at
// `cell` (VertexCacheIntegerFactors'): a line on a cell line keeps its KeptSegments, an edge on the
// range's edge takes the tile's kept inside count across it. No segment is longer than the cell's
// (its error bound holds); tiles sharing an edge share its cell line and part (one factor). Then
// raised as the tessellator draws it. Whole: the cell's, bit for bit; no area: culled.
TileFactorSet ClippedTileFactors(TileFactorSet cell, float4 kept)
{
    if (TileFactorsCulled(cell) || CellKeptWhole(kept)) return cell;
    if (kept.x == kept.y || kept.z == kept.w) return CulledTileFactors();
    float2 inside = float2(KeptSegments(cell.inside.x, kept.x, kept.y), KeptSegments(cell.inside.y, kept.z, kept.w));
    TileFactorSet f;
    f.edge = float4(kept.x > 0.0 ? inside.y : KeptSegments(cell.edge.x, kept.z, kept.w),
                    kept.z > 0.0 ? inside.x : KeptSegments(cell.edge.y, kept.x, kept.y),
                    kept.y < 1.0 ? inside.y : KeptSegments(cell.edge.z, kept.z, kept.w),
                    kept.w < 1.0 ? inside.x : KeptSegments(cell.edge.w, kept.x, kept.y));
    f.inside = inside;
    return VertexCacheDrawnFactors(f);
}

// Where point k of the d a tile draws over [s0, s1] of a line of n segments sits, in that line's
// units: the ends at s0 n and s1 n, the others on the line's own points from floor(s0 n) + 1 on; an
// inside count of 1 drawn as 2 puts its middle point halfway.
float KeptLinePosition(float n, float s0, float s1, float d, float k)
{
    if (k == 0.0) return s0 * n;
    if (k == d) return s1 * n;
    if (KeptSegments(n, s0, s1) < d) return 0.5 * (s0 + s1) * n;
    return floor(s0 * n) + k;
}

// A vertex as cell records: slots a, b blended at t.x, then c, d likewise, the two at t.y.
struct CellPointBlend
{
    uint4 slots;   // a, b, c, d
    float2 t;
};

CellPointBlend CellSlotBlend(uint slot)
{
    CellPointBlend p;
    p.slots = uint4(slot, slot, slot, slot);
    p.t = float2(0.0, 0.0);
    return p;
}

// Point x (line units) of edge e.
CellPointBlend CellEdgeBlend(uint edge, float x, uint limit)
{
    float a = floor(x);
    CellPointBlend p = CellSlotBlend(VertexCacheEdgeSlot(edge, (uint)a, limit));
    if (x > a) { p.slots.y = p.slots.x + 1u; p.t.x = x - a; }
    return p;
}

// The cell's inside grid (its border included) at (xu, xv), grid units: bilinear, or fewer points
// on a grid line.
CellPointBlend CellGridBlend(float xu, float xv, float insideU)
{
    float2 a = floor(float2(xu, xv));
    uint w = (uint)insideU;
    CellPointBlend p = CellSlotBlend(VertexCacheInteriorSlot((uint2)a, w));
    if (xu > a.x) { p.slots.y = p.slots.x + 1u; p.t.x = xu - a.x; }
    if (xv > a.y)
    {
        p.slots.z = p.slots.x + w + 1u;
        p.slots.w = xu > a.x ? p.slots.z + 1u : p.slots.z;
        p.t.y = xv - a.y;
    }
    return p;
}

float CellFactorOfEdge(float4 edge, uint e) { return e == 0u ? edge.x : (e == 1u ? edge.y : (e == 2u ? edge.z : edge.w)); }

// The records the vertex at tess of a tile drawn at `tile` (ClippedTileFactors) reads from its
// cell's slots (cell drawn at `cell`). Whole: VertexCacheSlot. Clipped: a corner on two cell lines is
// the cell's; a corner on one lies on it at the other axis's s0 or s1; the range's own corner blends
// the grid; an edge on a cell line reads that line; an edge on the range's edge blends the grid
// columns (or rows) either side; inside points are the grid's own.
CellPointBlend CellPoint(float2 tess, TileFactorSet tile, TileFactorSet cell, float4 kept, uint limit)
{
    if (CellKeptWhole(kept)) return CellSlotBlend(VertexCacheSlot(tess, tile.edge, tile.inside, limit));
    bool2 at0 = tess == 0.0;
    bool2 at1 = tess == 1.0;
    bool onU = at0.x || at1.x;
    bool onV = at0.y || at1.y;
    float su = at0.x ? kept.x : kept.y;   // the cell parameter of the side at tess
    float sv = at0.y ? kept.z : kept.w;
    bool clipU = at0.x ? kept.x > 0.0 : kept.y < 1.0;
    bool clipV = at0.y ? kept.z > 0.0 : kept.w < 1.0;
    if (onU && onV)
    {
        if (!clipU && !clipV) return CellSlotBlend(VertexCacheSlot(tess, cell.edge, cell.inside, limit));
        if (!clipV) { uint e = at0.y ? 1u : 3u; return CellEdgeBlend(e, su * CellFactorOfEdge(cell.edge, e), limit); }
        if (!clipU) { uint e = at0.x ? 0u : 2u; return CellEdgeBlend(e, sv * CellFactorOfEdge(cell.edge, e), limit); }
        return CellGridBlend(su * cell.inside.x, sv * cell.inside.y, cell.inside.x);
    }
    if (onU)
    {
        uint e = at0.x ? 0u : 2u;
        float d = CellFactorOfEdge(tile.edge, e);
        float k = round(tess.y * d);
        if (clipU) return CellGridBlend(su * cell.inside.x, KeptLinePosition(cell.inside.y, kept.z, kept.w, d, k), cell.inside.x);
        return CellEdgeBlend(e, KeptLinePosition(CellFactorOfEdge(cell.edge, e), kept.z, kept.w, d, k), limit);
    }
    if (onV)
    {
        uint e = at0.y ? 1u : 3u;
        float d = CellFactorOfEdge(tile.edge, e);
        float k = round(tess.x * d);
        if (clipV) return CellGridBlend(KeptLinePosition(cell.inside.x, kept.x, kept.y, d, k), sv * cell.inside.y, cell.inside.x);
        return CellEdgeBlend(e, KeptLinePosition(CellFactorOfEdge(cell.edge, e), kept.x, kept.y, d, k), limit);
    }
    float2 ij = round(tess * tile.inside);
    return CellGridBlend(KeptLinePosition(cell.inside.x, kept.x, kept.y, tile.inside.x, ij.x),
                         KeptLinePosition(cell.inside.y, kept.z, kept.w, tile.inside.y, ij.y), cell.inside.x);
}

// Where the record in `slot` of a cell drawn at `cell` was evaluated, in the cell's tess
// coordinates: the point the kernel (VertexCachePoint, whole grid) gave that slot.
float2 CellSlotTess(uint slot, TileFactorSet cell, uint limit)
{
    uint grid = VertexCacheEdgeSlot(0u, 0u, limit);
    if (slot < grid)
    {
        uint w = (uint)cell.inside.x + 1u;
        return float2(slot % w, slot / w) / cell.inside;
    }
    uint e = (slot - grid) / (limit + 1u);
    return VertexCacheEdgeTess(e, slot - VertexCacheEdgeSlot(e, 0u, limit), CellFactorOfEdge(cell.edge, e));
}

// Where the vertex that blends p lies in its cell, tess coordinates: its records' points blended as
// their values are. The Patch Id view looks the patch up there (a record has no patch index).
float2 CellPointTess(CellPointBlend p, TileFactorSet cell, uint limit)
{
    float2 ab = lerp(CellSlotTess(p.slots.x, cell, limit), CellSlotTess(p.slots.y, cell, limit), p.t.x);
    float2 cd = lerp(CellSlotTess(p.slots.z, cell, limit), CellSlotTess(p.slots.w, cell, limit), p.t.x);
    return lerp(ab, cd, p.t.y);
}

#if defined(GT_VERTEX_CACHE)
// A record's position, fragment numbers and snow, unpacked for blending.
struct CachedCellRecord
{
    float3 positionOS;
    float3 shading;
    float snowDepth;
};

CachedCellRecord ReadCachedCellRecord(uint slot)
{
    uint i = GT_VERTEX_CACHE_RECORD_UINT4S * slot;
    uint4 r = _VertexCache[i];
    CachedCellRecord c;
    c.positionOS = asfloat(r.xyz);
    c.shading = UnpackCachedVaryings(r.w);
    #if defined(GT_SNOW)
    c.snowDepth = asfloat(_VertexCache[i + 1u].x);
    #else
    c.snowDepth = 0.0;
    #endif
    return c;
}

// a + t (b - a) on every part: t = 0 gives a's bits, so a shared vertex blended by two tiles from
// the same records at the same t has the same bits.
CachedCellRecord BlendCachedCellRecords(CachedCellRecord a, CachedCellRecord b, float t)
{
    CachedCellRecord c;
    c.positionOS = a.positionOS + t * (b.positionOS - a.positionOS);
    c.shading = a.shading + t * (b.shading - a.shading);
    c.snowDepth = a.snowDepth + t * (b.snowDepth - a.snowDepth);
    return c;
}

// The varyings of a blend in the tile whose slots start at `base`: only the records it weighs are read.
TerrainVaryings CachedCellPointVaryings(uint base, CellPointBlend p, float tessFactor)
{
    CachedCellRecord c = ReadCachedCellRecord(base + p.slots.x);
    if (p.t.x > 0.0) c = BlendCachedCellRecords(c, ReadCachedCellRecord(base + p.slots.y), p.t.x);
    if (p.t.y > 0.0)
    {
        CachedCellRecord d = ReadCachedCellRecord(base + p.slots.z);
        if (p.t.x > 0.0) d = BlendCachedCellRecords(d, ReadCachedCellRecord(base + p.slots.w), p.t.x);
        c = BlendCachedCellRecords(c, d, p.t.y);
    }
    return TerrainVaryingsOf(c.positionOS, c.shading, c.snowDepth, 0u, tessFactor);
}
#endif

#endif // GT_CLIPPED_CELL_INCLUDED
