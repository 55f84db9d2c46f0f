// What both vertex caches' kernels write (VertexCacheKernels.hlsl, the single range;
// LevelVertexCacheKernels.hlsl, the levels): the records buffer, a record, and a tile's points in
// the order the kernels visit them. Include after VertexCache.hlsl. Core's twin of the points:
// VertexCache.TilePoints.
#ifndef GT_VERTEX_CACHE_WRITES_INCLUDED
#define GT_VERTEX_CACHE_WRITES_INCLUDED

// The same buffer as the graphics stages' _VertexCache (t6): binding 8 in the rig either way.
RWStructuredBuffer<uint4> _VertexCacheRW GT_REGISTER(u3);

void WriteVertexCacheRecord(uint slot, TerrainVertexAttributes a)
{
    [unroll] for (uint part = 0u; part < GT_VERTEX_CACHE_RECORD_UINT4S; part++)
        _VertexCacheRW[GT_VERTEX_CACHE_RECORD_UINT4S * slot + part] = VertexCacheRecordPart(a, part);
}

// The inside points a tile's slots hold per axis: the (Iu - 1) x (Iv - 1) interior of the grid
// (its border is the edges'), or with wholeGrid (the single range anchored) the whole
// (Iu + 1) x (Iv + 1) grid (ClippedCell.hlsl blends a clipped tile's edge from the border too).
uint2 VertexCacheGridPoints(float2 inside, bool wholeGrid) { return wholeGrid ? (uint2)inside + 1u : (uint2)inside - 1u; }

// The points a tile at integer factors (edge, inside) has: its inside points and 4 edges of F + 1.
uint VertexCacheTilePointCount(float4 edge, float2 inside, bool wholeGrid)
{
    uint2 n = VertexCacheGridPoints(inside, wholeGrid);
    return n.x * n.y + (uint)(edge.x + edge.y + edge.z + edge.w) + 4u;
}

// Point k of the tile's list "inside points, then edge 0, 1, 2, 3": its tess coordinate and slot.
void VertexCachePoint(uint k, float4 edge, float2 inside, uint limit, bool wholeGrid, out float2 tess, out uint slot)
{
    uint2 n = VertexCacheGridPoints(inside, wholeGrid);
    uint interior = n.x * n.y;
    if (k < interior)
    {
        uint first = wholeGrid ? 0u : 1u;
        uint2 ij = uint2(first + k % n.x, first + k / n.x);
        tess = (float2)ij / inside;
        slot = VertexCacheInteriorSlot(ij, (uint)inside.x);
        return;
    }
    k -= interior;
    uint e = 0u;
    [unroll] for (uint i = 0u; i < 3u; i++)
    {
        uint count = (uint)edge[e] + 1u;
        if (k >= count) { k -= count; e++; }
    }
    tess = VertexCacheEdgeTess(e, k, edge[e]);
    slot = VertexCacheEdgeSlot(e, k, limit);
}

#endif // GT_VERTEX_CACHE_WRITES_INCLUDED
