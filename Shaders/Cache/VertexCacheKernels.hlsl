// The vertex cache's two compute kernels (GT_VERTEX_CACHE; Documentation~/internals.md, "Vertex
// cache"). Include a pipeline adapter first (with GT_ObjectToClipMatrix) (the rig: StandaloneAdapter through Tools~/rig/TerrainRig.hlsl;
// Unity: TerrainCache.compute with LodCameraComputeAdapter.hlsl): the factors need GT_ObjectToClip
// and GT_ScreenSize of the camera that decides the tessellation.
//
//   CacheTileFactors    a group per tile: culling and adaptive (or uniform) factors, rounded to
//                       the integer factors the draw will use (VertexCacheIntegerFactors); a
//                       cell's factors are kept while nothing they depend on moved
//   CacheTileVertices   a few groups per tile: every vertex the tessellator makes at those factors,
//                       evaluated by EvaluateTerrainVertex (the domain stage's own path) into its slot,
//                       for the tiles whose factors or range changed since their last evaluation
//
// A frame dispatches both, in that order, then draws; the hull stage reads the factors and the
// domain stage reads the records (VertexSource.Cache.hlsl). Why: the per-vertex work runs on every
// compute unit instead of the few that run the graphics stages, and once per vertex, not once per
// triangle fan the tessellator emits.
#ifndef GT_VERTEX_CACHE_KERNELS_INCLUDED
#define GT_VERTEX_CACHE_KERNELS_INCLUDED

#include "VertexCache.hlsl"
#include "VertexCacheWrites.hlsl"
#include "TileCellRecord.cs.hlsl"
#include "TileFactorGroup.hlsl"

// The same binding as the graphics stages' _TileFactors (t5): binding 7 in the rig either way
// (TerrainInputs.hlsl); _VertexCacheRW: VertexCacheWrites.hlsl; _TileCellsRW: binding 10.
RWStructuredBuffer<TileFactorRecord> _TileFactorsRW GT_REGISTER(u2);
RWStructuredBuffer<TileCellRecord> _TileCellsRW GT_REGISTER(u5);

// What a tile's slots and its factor samples depend on (besides factors and camera): the range, or
// anchored, only its cell (the slots hold the whole cell and the draw clips it, ClippedCell.hlsl; a
// pan that keeps the cell changes nothing in them). Two records keep it: the slots' (written when
// the slots are, WriteTileFactors) and the samples' (written with the cell's factors, which a
// uniform-factor pass leaves alone).
float4 CellRecordKey(uint tile) { return TilesAnchored() ? CellSpan(FrameTileLayout(), tile) : _Range; }

// Whether a key moved since the tile's last pass: a zero record was never written (the renderer
// zeroes the keys to force a pass), so it always reads as moved, even for a key that happens to be
// 0. Every lane reads both; only lane 0 acts on the slots' key, and the cell's key is written
// after the group's barriers.
bool KeyMoved(float4 kept, float4 key) { return all(kept == 0.0) || any(kept != key); }

bool TileRangeMoved(uint tile) { return KeyMoved(_TileFactorsRW[tile].slotsKey, CellRecordKey(tile)); }
bool TileCellMoved(uint tile) { return KeyMoved(_TileFactorsRW[tile].cellKey, CellRecordKey(tile)); }

// The inputs of a cell's factors that the keys do not cover: the camera (its object-to-clip matrix,
// the object transform included; its pixel size) and the knob (max factor, target). The rest (grid,
// origin, noise, snow) the renderer guards by zeroing the keys. Compared whole, so factors are
// never kept across a camera change, however small: neighbours decided in different passes agree.
float4 FactorInput(uint k)
{
    float4x4 m = GT_ObjectToClipMatrix();
    return k < 4u ? m[k] : float4(GT_ScreenSize(), MaxTessFactor(), TargetPixelError());
}

bool FactorInputsHeld(uint tile)
{
    bool held = true;
    [unroll] for (uint k = 0u; k < GT_FACTOR_INPUTS; k++)
        held = held && all(_TileCellsRW[tile].inputs[k] == FactorInput(k));
    return held;
}

// How the last pass decided the cell's factors (TileCellRecord.inside.z; the rig's tests read it).
#define GT_CELL_FACTORS_SAMPLED 0.0       // from the surface: the cell moved (or its key was zeroed)
#define GT_CELL_FACTORS_RESCALED 1.0      // from the kept samples: the camera or the knob moved
#define GT_CELL_FACTORS_HELD 2.0          // as they were

// The cell factors of the tile's last adaptive pass, marked as held by this one; keeping new ones
// with what they hold for (KeepCellFactors).
TileFactorSet HeldCellFactors(uint tile)
{
    TileFactorSet f;
    f.edge = _TileCellsRW[tile].edge;
    f.inside = _TileCellsRW[tile].inside.xy;
    _TileCellsRW[tile].inside = float4(f.inside, GT_CELL_FACTORS_HELD, 0.0);
    return f;
}

void KeepCellFactors(uint tile, TileFactorSet cell, bool cellMoved)
{
    _TileCellsRW[tile].edge = cell.edge;
    _TileCellsRW[tile].inside = float4(cell.inside, cellMoved ? GT_CELL_FACTORS_SAMPLED : GT_CELL_FACTORS_RESCALED, 0.0);
    [unroll] for (uint k = 0u; k < GT_FACTOR_INPUTS; k++)
        _TileCellsRW[tile].inputs[k] = FactorInput(k);
    _TileFactorsRW[tile].cellKey = CellRecordKey(tile);
}

// True when the tile's slots do not hold its vertices at factors f: the range moved, or last pass
// it was culled or drawn at other factors. Everything else the records depend on (origin, grid,
// noise, colour, snow, object transform) the renderer guards: it zeroes the keys when one of those
// changes, and a zero key always reads as moved (KeyMoved).
bool TileSlotsOutdated(uint tile, TileFactorSet f, bool rangeMoved)
{
    float4 edge = _TileFactorsRW[tile].edge;
    float4 inside = _TileFactorsRW[tile].inside;
    return rangeMoved || inside.z != 0.0 || any(edge != f.edge) || any(inside.xy != f.inside);
}

void WriteTileFactors(uint tile, TileFactorSet f, bool rangeMoved)
{
    f = VertexCacheIntegerFactors(f);
    bool culled = TileFactorsCulled(f);
    bool evaluate = !culled && TileSlotsOutdated(tile, f, rangeMoved);
    _TileFactorsRW[tile].edge = f.edge;
    _TileFactorsRW[tile].inside = float4(f.inside, culled ? 1.0 : 0.0, evaluate ? 1.0 : 0.0);
    if (rangeMoved) _TileFactorsRW[tile].slotsKey = CellRecordKey(tile);
}

// Sample s of the tile's cell: its position read back while the cell holds and the sample was
// written (w = 1), else evaluated and kept; then the camera's part (TileFactorSampleAt). The
// positions depend on the cell only, so a camera move costs no surface evaluation here.
float4 CachedTileFactorSample(uint tile, uint s, bool cellMoved)
{
    float4 kept = _TileCellsRW[tile].samples[s];
    float3 p = kept.xyz;
    if (cellMoved || kept.w != 1.0)
    {
        p = TileFactorSamplePosition(FrameTileLayout(), tile, s);
        _TileCellsRW[tile].samples[s] = float4(p, 1.0);
    }
    return TileFactorSampleAt(s, p);
}

// Dispatch (T, T, 1), T = TilesAcrossInt(): a group a tile. Three ways, the same for every lane:
//   the cell's factors held (its key and FactorInputs unchanged: an anchored pan, the camera still):
//     lane 0 writes them (rounded) as the tile's; no sample;
//   else the cell's 51 surface samples (CachedTileFactorSample) one a lane, read back while the
//     cell holds; then its seven pieces (TileFactorPiece's arithmetic on the shared samples) one a
//     lane; then lane 0 assembles, keeps the cell's factors and writes them rounded. Anchored, the
//     slots hold the whole cell and the hull clips it (ClippedCell.hlsl).
// Why so wide: the factors are a chain of surface evaluations, and the chain's length is the pass's
// (one sample a lane: a chain of 1). Why the held way: that one evaluation is still most of a pan's
// pre-pass (Tools~/bench/records.md, "Choices in the shaders, measured").
// Every lane of the group reaches both barriers: whether the cell is held is read from the records (a
// UAV), which FXC takes for non-uniform, and it refuses a barrier after a return on such a value
// (error X3663); so the held way guards the work, not the barriers.
[numthreads(64, 1, 1)]
void CacheTileFactors(uint3 group : SV_GroupID, uint lane : SV_GroupIndex)
{
    uint tiles = TilesAcrossInt();
    if (group.x >= tiles || group.y >= tiles) return;
    uint tile = group.y * tiles + group.x;
    bool rangeMoved = TileRangeMoved(tile);
    bool cellMoved = TileCellMoved(tile);
    TileFactorSet f;
    bool uniformFactors = UniformTileFactors(f);
    if (uniformFactors)
    {
        // No samples: the cell's key stays that of the samples and factors kept, which the next
        // adaptive pass then trusts only for the same cell.
        if (lane == 0u) WriteTileFactors(tile, f, rangeMoved);
        return;
    }
    // Anchored, the cell's factors and slots, even where the range keeps none of it yet: a pan
    // that keeps the cells dispatches nothing, and the hull clips (ClippedTileFactors).
    bool held = !cellMoved && FactorInputsHeld(tile);
    if (!held && lane < GT_TILE_FACTOR_SAMPLES) gtTileFactorSamples[lane] = CachedTileFactorSample(tile, lane, cellMoved);
    GroupMemoryBarrierWithGroupSync();
    float3 cornerOS[4];
    [unroll] for (uint c = 0u; c < 4u; c++)
        cornerOS[c] = gtTileFactorSamples[c].xyz;
    // The pieces of a cell sampled now and in view.
    bool pieces = false;
    if (!held) pieces = !TileCulled(cornerOS, TileNoiseMargin(FrameTileLayout(), tile));
    if (pieces) WriteGroupTileFactorPiece(FrameTileLayout(), tile, lane, cornerOS);
    GroupMemoryBarrierWithGroupSync();
    if (lane != 0u) return;
    TileFactorSet cell;
    if (held)
        cell = HeldCellFactors(tile);
    else
    {
        cell = CulledTileFactors();
        if (pieces)
        {
            float piece[GT_TILE_FACTOR_PIECES];
            [unroll] for (uint k = 0u; k < GT_TILE_FACTOR_PIECES; k++)
                piece[k] = gtTileFactorPieces[k];
            cell = TileFactorsOfPieces(piece);
        }
        KeepCellFactors(tile, cell, cellMoved);
    }
    WriteTileFactors(tile, cell, rangeMoved);
}

// Dispatch (T, T, G), G = VertexCacheGroupsPerTile(L): groups (x, y, 0 .. G - 1) share tile
// y T + x, their G x GT_VERTEX_CACHE_VERTEX_GROUP lanes striding over its points (at most
// GT_VERTEX_CACHE_PASSES each). The factors come through the read-only _TileFactors (the same
// buffer): FXC refuses a compute loop whose end depends on a UAV read without [allow_uav_condition].
[numthreads(GT_VERTEX_CACHE_VERTEX_GROUP, 1, 1)]
void CacheTileVertices(uint3 group : SV_GroupID, uint lane : SV_GroupIndex)
{
    uint tiles = TilesAcrossInt();
    if (group.x >= tiles || group.y >= tiles) return;
    uint tile = group.y * tiles + group.x;
    float4 edge = _TileFactors[tile].edge;
    float4 inside = _TileFactors[tile].inside;
    if (inside.w == 0.0) return;   // culled (the draw emits nothing), or its slots are up to date
    uint limit = VertexCacheFactorLimit();
    uint base = tile * VertexCacheSlotsPerTile(limit);
    uint count = VertexCacheTilePointCount(edge, inside.xy, TilesAnchored());
    uint stride = VertexCacheGroupsPerTile(limit) * GT_VERTEX_CACHE_VERTEX_GROUP;
    for (uint k = group.z * GT_VERTEX_CACHE_VERTEX_GROUP + lane; k < count; k += stride)
    {
        float2 tess;
        uint slot;
        VertexCachePoint(k, edge, inside.xy, limit, TilesAnchored(), tess, slot);
        WriteVertexCacheRecord(base + slot, EvaluateCellTerrainVertex(FrameTileLayout(), tile, tess));
    }
}

#endif // GT_VERTEX_CACHE_KERNELS_INCLUDED
