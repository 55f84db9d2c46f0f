// Both vertex caches' kernels' writes: the records, and a tile's points in order (Core:
// VertexCache.TilePoints). Include after VertexCache.hlsl.
#ifndef GT_VERTEX_CACHE_WRITES_INCLUDED
#define GT_VERTEX_CACHE_WRITES_INCLUDED

// The same buffer as the graphics stages' _VertexCache (t6): binding 8 in the rig either way.
RWStructuredBuffer<uint4> _VertexCacheRW GT_REGISTER(u3);

void WriteVertexCacheRecord(uint slot, TerrainVertexAttributes a)
{
    [unroll] for (uint part = 0u; part < GT_VERTEX_CACHE_RECORD_UINT4S; part++)
        _VertexCacheRW[GT_VERTEX_CACHE_RECORD_UINT4S * slot + part] = VertexCacheRecordPart(a, part);
}

// Inside points a tile's slots hold per axis: the grid's interior, or with wholeGrid (the single
// range anchored) the whole grid (ClippedCell.hlsl blends a clipped tile's edge from the border).
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
