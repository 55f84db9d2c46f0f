// The terrain's GPU inputs: three buffers sent once and the TerrainParams constants
// (Documentation~/internals.md, "GPU layout"; Tools~/rig/README.md, "Descriptor bindings"; GpuLayout in Core packs them).
//
// The pipeline adapter, included before this file, defines:
//   GT_CBUFFER_START(name) / GT_CBUFFER_END  how a block of material constants is declared
//                                            (Unity: UnityPerMaterial, for the SRP Batcher; the
//                                            rig: cbuffer name : register(b0));
//   GT_REGISTER(r)                           ": register(r)" where the registers are fixed (the rig),
//                                            nothing where Unity binds by name.
// Every stage reads its inputs through the accessors below, never through the raw float4s, so the
// packing lives in one place.
#ifndef GT_TERRAIN_INPUTS_INCLUDED
#define GT_TERRAIN_INPUTS_INCLUDED

#if !defined(GT_CBUFFER_START) || !defined(GT_CBUFFER_END) || !defined(GT_REGISTER)
#error "Include a pipeline adapter (Shaders/Pipelines/*Adapter.hlsl) before TerrainInputs.hlsl"
#endif

// The range origin's code (deep zoom: relative output, precise lookup and noise differences) is
// compiled only where an origin can be set: the renderer's GT_RANGE_ORIGIN, set exactly while it
// sends one (RelativeSurface.NeedsRangeOriginKeyword); the levels (GT_LOD), whose origin follows the
// feet; the vertex cache's kernels and the passes without a tessellator (GT_FALLBACK), which keep
// one variant and a run-time branch. Elsewhere the layout's origin is the constant 0
// (FrameTileLayout), so not even an untaken branch is left: the driver kept registers for it.
#if defined(GT_RANGE_ORIGIN) || defined(GT_LOD) || defined(GT_VERTEX_CACHE) || defined(GT_FALLBACK)
    #define GT_RANGE_ORIGIN_CODE 1
#endif

#include "TileLattice.hlsl"
#if defined(GT_LOD)
    #include "LodTiles.hlsl"
    // The renderer never turns GT_LOD on with GT_VERTEX_CACHE (the cache path then wins: one range)
    // and the harness not with GT_SNOW, but Unity compiles every multi_compile combination.
    #if defined(GT_EXTEND_DRAW_PATCHES)
        #error "GT_LOD (levels of detail) draws tiles, not an extension's own draw patches"
    #endif
#endif

// One record per patch, 320 bytes: Core's GregoryPatchRecord is its one declaration (gt generate
// writes the struct; ShaderContractTests compares the compiled offsets and stride).
#include "GregoryPatchRecord.cs.hlsl"
StructuredBuffer<GregoryPatchRecord> _ControlPoints GT_REGISTER(t0);
// (a, b, e, f) per patch: the patch covers [a, e] x [b, f] of the unit square.
StructuredBuffer<float4> _Regions GT_REGISTER(t1);
// xLines[0..n] then yLines[0..m], each strictly increasing from 0 to 1.
StructuredBuffer<float> _GridLines GT_REGISTER(t2);

// Core's TerrainParams (11 float4, 176 bytes) is the one declaration of these constants: its fields,
// in order, are the generated members below (gt generate; ShaderContractTests compares the compiled
// offsets). Named float4s, not one struct member: Unity sets them by name (internals.md, "One
// contract to the GPU"). The variants' own constants follow, always last.
GT_CBUFFER_START(TerrainParams)
#include "TerrainParams.cs.hlsl"
#if defined(GT_SNOW)
    float4 _SnowMapSize;   // (R, 1/R, depthCap, 0): snow variant only, always last   on change
#endif
#if defined(GT_LOD)
    // Levels of detail only (internals.md, "Levels of detail"), always last: the level count, then
    // one range per level relative to the origin, finest first (LodLevels.Layout).
    float4 _LodLevels;                       // (levels L, kernel factors 0/1, cache records C, 0)  on change
    float4 _Ranges[GT_MAX_LOD_LEVELS];       // level k's (c, d, g, h)                per frame
#endif
GT_CBUFFER_END

#if defined(GT_LOD)
// The levels' tile factors the factor kernels wrote this frame (LevelFactorKernels.hlsl), read
// while _LodLevels.y is 1 (LodKernelTileFactors): a LodFactorRecord per draw patch.
#include "../Cache/LodFactorRecord.cs.hlsl"
StructuredBuffer<LodFactorRecord> _LodFactors GT_REGISTER(t5);
#endif

#if defined(GT_SNOW)
// The snow depth map (internals.md, "Snow"): R x R floats over the unit square, written by the snow
// simulation. Declared only in the snow variant, so without GT_SNOW nothing needs binding. t4, not
// t3: the rig's texture shift (+2) would put t3 on binding 5, the readback's.
StructuredBuffer<float> _SnowDepth GT_REGISTER(t4);

float4 SnowMapSize() { return _SnowMapSize; }
// Largest snow depth: the tile bounds grow by it.
float SnowDepthCap() { return _SnowMapSize.z; }
#endif

#if defined(GT_VERTEX_CACHE)
// The vertex cache (internals.md, "Vertex cache"), written this frame by the compute pass
// (VertexCacheKernels.hlsl: _TileFactorsRW, _VertexCacheRW, the same buffers): a TileFactorRecord
// per tile (VertexCache.hlsl), and GT_VERTEX_CACHE_RECORD_UINT4S uint4 per slot.
#include "../Cache/TileFactorRecord.cs.hlsl"
StructuredBuffer<TileFactorRecord> _TileFactors GT_REGISTER(t5);
#endif
#if defined(GT_VERTEX_CACHE) || defined(GT_LOD)
// GT_LOD: the levels' records (LevelVertexCacheKernels.hlsl), read while _LodLevels.z is nonzero.
StructuredBuffer<uint4> _VertexCache GT_REGISTER(t6);
#endif

#if defined(GT_NOISE_TABLE)
// The tiled noise's table (internals.md, "Tiled noise"): 256 x 256 lattice cells, two float4 rows
// each (C# GradientNoiseTable.Floats), sent once. Declared only in the tiled variants. The rig's
// texture shift (+2) puts t7 on binding 9.
StructuredBuffer<float4> _NoiseCells GT_REGISTER(t7);

// GradientNoise.hlsl's hook: cell rows firstRow and firstRow + 1.
void GradientNoiseTableRows(uint firstRow, out float4 r0, out float4 r1)
{
    r0 = _NoiseCells[firstRow];
    r1 = _NoiseCells[firstRow + 1u];
}
#endif

// --- Patch grid -----------------------------------------------------------------------------------

uint GridColumns() { return (uint)_GridSize.x; }
uint GridRows() { return (uint)_GridSize.y; }
uint PatchCount() { return GridColumns() * GridRows(); }

// --- Range ----------------------------------------------------------------------------------------

// Width g - c of the drawn range in terrain units (the origin cancels out of a difference).
float RangeWidth() { return _Range.z - _Range.x; }

// --- Tessellation ---------------------------------------------------------------------------------

// M: the range is covered by M x M tiles (anchored: the lattice's width by M cells). A float,
// because RangeCoordinate divides by it.
float TileCount() { return _Tess.x; }
uint TileCountInt() { return (uint)_Tess.x; }
// The frame's tile layout (TileLattice.hlsl): _Range, _TileLattice, _RangeOrigin and M. Stage entry
// points read it and pass it down; the library functions take a layout, so a level of detail can
// pass its own.
// The origin as the stages read it: _RangeOrigin, or the constant 0 without GT_RANGE_ORIGIN_CODE.
float4 FrameRangeOrigin()
{
#if defined(GT_RANGE_ORIGIN_CODE)
    return _RangeOrigin;
#else
    return float4(0.0, 0.0, 0.0, 0.0);
#endif
}
TileLayout FrameTileLayout() { return MakeTileLayout(_Range, _TileLattice, FrameRangeOrigin(), TileCount()); }
#if defined(GT_LOD)
uint LodLevelCount() { return (uint)_LodLevels.x; }
// Level k's range relative to the origin (k clamped into the array: an out-of-range read would be
// undefined on some APIs).
float4 LodRange(uint level) { return _Ranges[min(level, (uint)GT_MAX_LOD_LEVELS - 1u)]; }
// Whether the factor kernels ran this frame and the hull reads their factors (_LodFactors).
bool LodKernelFactorsOn() { return _LodLevels.y != 0.0; }
// C: the records the levels' vertex cache holds this frame (_VertexCache; LevelVertexCacheKernels.hlsl),
// 0 when the renderer did not dispatch its kernels. A float: exact below 2^24 (the renderer's bound).
uint LodVertexCacheRecords() { return (uint)_LodLevels.z; }
bool LodVertexCacheOn() { return _LodLevels.z != 0.0; }
// Level k's tiles: M x M laid on its range (no anchoring: the range itself is snapped to the
// coarser level's cells), the frame's origin.
TileLayout LodLevelLayout(uint level) { return MakeTileLayout(LodRange(level), float4(0.0, 0.0, 0.0, 0.0), FrameRangeOrigin(), TileCount()); }
#endif
// Whether the frame's tiles are anchored to the terrain (TileLattice.hlsl): a nonzero lattice.
bool TilesAnchored() { return IsAnchored(_TileLattice); }
// Tiles (draw patches, cache tiles) per axis of the frame's layout: M, or M + 1 anchored.
uint TilesAcrossInt() { return TilesAcross(FrameTileLayout()); }
// Largest edge factor the adaptive policy may choose (at most 64, the hardware limit).
float MaxTessFactor() { return _Tess.y; }
// The adaptive knob: target screen-space error, in pixels, of the drawn triangles against the
// surface (TessellationPolicy.ErrorTessFactor).
float TargetPixelError() { return _Tess.z; }
// Factor used for every edge and inside when > 0 (tests, benchmarks, the fallback grid); 0 = adaptive.
float UniformTessFactor() { return _Tess.w; }
bool UsesUniformTessFactor() { return _Tess.w > 0; }

// --- Noise ----------------------------------------------------------------------------------------

float4 NoiseSettings() { return _Noise; }
// _NoiseOctaves.z: the on-screen length (pixels) a segment may have under the continuous octave rule
// of the levels of detail (OctaveCountAtPixelScale); 0 keeps the single-range rule bit for bit.
float NoiseSegmentPixels() { return _NoiseOctaves.z; }
// _NoiseOctaves.w: the levels' plain-path error bound (terrain units; TerrainVertex.PlainPathError),
// 0: every vertex of the levels on the precise path. _OriginSurface: S(O) and p(O) in float.
float PlainPathError() { return _NoiseOctaves.w; }
float4 LevelsOriginSurface() { return _OriginSurface; }
float NoiseAmplitude() { return _Noise.x; }
float MaxNoiseOctaves() { return _NoiseOctaves.x; }
// Vertices across the range that the octave count is budgeted for: the override when set, else the
// most the tessellator can make (M tiles of maxFactor segments). Per-frame values only, so every
// vertex of a frame uses the same octave count (watertight).
float NoiseVerticesAcross()
{
    return _NoiseOctaves.y > 0 ? _NoiseOctaves.y : TileCount() * MaxTessFactor();
}
// Bound on |OctaveNoise|: amplitude * sum_k beta^-k over the octaves (GradientNoise is in about
// [-1, 1]). Used as the height margin of the frustum test.
float NoiseHeightBound()
{
    float beta = max(_Noise.w, 1.0);
    float n = MaxNoiseOctaves();
    // Geometric series; beta == 1 degenerates to n terms of 1.
    float sum = beta > 1.0 ? (1.0 - pow(beta, -n)) / (1.0 - 1.0 / beta) : n;
    return abs(_Noise.x) * sum;
}

// --- Height colour --------------------------------------------------------------------------------

float4 HeightColorSettings() { return _HeightColor; }
float3 HeightColorLow() { return _ColorLow.rgb; }
float3 HeightColorHigh() { return _ColorHigh.rgb; }

#endif // GT_TERRAIN_INPUTS_INCLUDED
