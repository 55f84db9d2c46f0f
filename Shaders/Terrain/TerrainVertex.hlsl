// The one evaluation path from (draw patch, tess coordinate) to a shaded terrain vertex. The domain
// stage (tessellated tiles) and vert_fallback (the instanced UV grid) both call TerrainVertex, so the
// two draw paths cannot drift apart.
//
//   tess coordinate --RangeToTerrainPoint--> global point q (hi/lo, bit-identical on shared edges)
//     --FindPatch--> Gregory patch --PatchLocalUV--> (u, v) --GregoryEvaluate--> S, dS/du, dS/dv
//     [GT_NOISE]        + OctaveNoise(q) on the height, its gradient in the normal
//     [GT_HEIGHT_COLOR] height and ColorNoise(q) for eq. 14-15 in the fragment stage
//     [GT_SNOW]         + SnowMapSample(q) on the height, the depth to the fragment stage
//     -> object space (x, z, y), Unity is Y-up -> clip space through the adapter.
#ifndef GT_TERRAIN_VERTEX_INCLUDED
#define GT_TERRAIN_VERTEX_INCLUDED

#include "TerrainInputs.hlsl"
#include "../Library/RangeMapping.hlsl"
#include "TileLattice.hlsl"
#include "../Grid/PatchGrid.hlsl"
#include "../Library/GregoryEval.hlsl"
#include "../Library/RelativeSurface.hlsl"
#if defined(GT_NOISE)
    #include "../Library/OctaveNoise.hlsl"
#endif
#if defined(GT_NOISE) || defined(GT_LOD)
    #include "TessellationFactors.hlsl"   // PixelsPerUnit: the continuous octave rule, the levels' plain path
#endif
#if defined(GT_HEIGHT_COLOR)
    #include "../Library/HeightColor.hlsl"
#endif
#include "../Library/NormalEncoding.hlsl"
#if defined(GT_SNOW)
    #include "../Snow/SnowMap.hlsl"
#endif

// Domain/fallback output, fragment input.
struct TerrainVaryings
{
    float4 positionCS : SV_Position;
    // xy: the world normal, Lambert-encoded (NormalEncoding.hlsl); z: the height colour's weight s
    // of eq. 14 (GT_HEIGHT_COLOR, else 0), computed per vertex. Read them with VaryingsNormalWS and
    // VaryingsHeightWeight. One interpolant of three numbers, for speed (internals.md, "Varyings").
    float3 normalAndHeightWeight : TEXCOORD0;
#if defined(GT_VARYINGS_POSITION_WS)
    float3 positionWS : TEXCOORD6;   // per-pixel shadow lookup and fog (adapter: GT_VARYINGS_POSITION_WS)
#endif
#if defined(GT_DEBUG_PATCH_ID)
    nointerpolation uint patch : TEXCOORD2;   // Gregory patch index
#endif
#if defined(GT_DEBUG_TESS_FACTOR)
    float tessFactor : TEXCOORD3;
#endif
#if defined(GT_SNOW)
    float snowDepth : TEXCOORD4;              // snow depth on this vertex (SnowMapCoverage)
#endif
};

// A point of the Gregory surface (no noise yet), in terrain space (x, y, z).
struct TerrainSurfacePoint
{
    TerrainPoint q;      // global point, hi/lo
    uint patch;          // Gregory patch that was evaluated
    float4 region;       // its (a, b, e, f), the hi parts of its grid lines
    float4 regionLo;     // their lo parts (PatchRegionLo)
    float2 uv;           // patch-local coordinate that was evaluated
    float3 position;
    float3 dPdu;
    float3 dPdv;
};

// Terrain space (x, y, z = height) to Unity object space (x, z, y). The swap is orthogonal, so it
// maps normals too.
float3 TerrainToObject(float3 v) { return v.xzy; }

// The tile path after the global point q is formed (Core's TerrainVertex.EvaluateSurfaceAt):
// FindPatchAt on the hi/lo lines while a range origin is set, so at deep zoom a vertex beside a line
// takes its own patch's normal.
TerrainSurfacePoint EvaluateSurfaceAt(TerrainPoint q)
{
    TerrainSurfacePoint s;
    s.q = q;
    s.patch = FindPatchAt(q);
    s.region = PatchRegion(s.patch);
    s.regionLo = PatchRegionLo(s.patch);
    s.uv = PatchLocalUV(q, s.region, s.regionLo);
    float3 cp[20];
    LoadGregoryPatch(s.patch, cp);
    float3 relative;
    GregoryEvaluate(cp, s.uv, relative, s.dPdu, s.dPdv);
    s.position = PatchReference(s.patch) + relative;
    return s;
}

#if defined(GT_EXTEND_DRAW_PATCHES)
// Extension point: the entry file's draw patches are not tiles (internals.md, "Extension points").
// It defines these three after including the stages; EvaluateSurface and EvaluateCellSurface
// return ExtensionSurface's point, and its positions are output absolute (no range origin).
TerrainSurfacePoint ExtensionSurface(uint drawPatch, float2 tess);
TerrainPoint ExtensionNoisePoint(TerrainSurfacePoint s);   // where the noise is read
float2 ExtensionSnowPoint(TerrainSurfacePoint s);          // where the snow map is read
#endif

// drawPatch: the index of the patch being drawn: a tile, tile = tj * M + ti. tess: the coordinate
// inside it, in [0, 1]^2.
TerrainSurfacePoint EvaluateSurface(TileLayout l, uint drawPatch, float2 tess)
{
#if defined(GT_EXTEND_DRAW_PATCHES)
    return ExtensionSurface(drawPatch, tess);
#else
    // Integer tile index first: RangeCoordinate (LatticePoint) forms ti + s before dividing, so the
    // vertices of a shared tile edge get bit-identical q (watertight).
    return EvaluateSurfaceAt(TileToTerrainPoint(l, drawPatch, tess));
#endif
}

// The surface at tess in the whole cell slot `slot` holds (CellToTerrainPoint): where the adaptive
// factors sample it (TileFactors.hlsl). Draw patches that are not tiles have no cells: their own point.
TerrainSurfacePoint EvaluateCellSurface(TileLayout l, uint slot, float2 tess)
{
#if defined(GT_EXTEND_DRAW_PATCHES)
    return EvaluateSurface(l, slot, tess);
#else
    return EvaluateSurfaceAt(CellToTerrainPoint(l, slot, tess));
#endif
}

// The surface position a vertex outputs (before noise): S(q) itself, or, while a range origin is
// set (deep zoom), S(q) - S(O) from precise differences (RelativeSurface.hlsl, precision.md); the
// renderer then adds S(O) in the object-to-world transform.
float3 OutputSurfacePosition(TileLayout l, TerrainSurfacePoint s)
{
#if !defined(GT_EXTEND_DRAW_PATCHES) && defined(GT_RANGE_ORIGIN_CODE)
    [branch] if (RelativeSurfaceIsActive(l.origin))
        return RelativeSurfaceFromOrigin(s.q, l.origin);
#endif
    return s.position;
}

// A terrain vertex before the camera: what the domain stage computes per vertex, and what the
// vertex cache (VertexCache.hlsl) stores. Object space is Unity's Y-up (x, z, y).
struct TerrainVertexAttributes
{
    float3 positionOS;       // noise and snow included; relative to S(O) + p(O) at deep zoom
    float3 normalOS;         // unit
    float absoluteHeight;    // S'z of eq. 14: Gregory + noise, absolute even at deep zoom, no snow
    float colorNoise;        // l of eq. 14 (GT_HEIGHT_COLOR), else 0
    float snowDepth;         // GT_SNOW, else 0
    uint patch;              // the Gregory patch that was evaluated
};

#if !defined(GT_EXTEND_DRAW_PATCHES) && defined(GT_RANGE_ORIGIN_CODE) && (defined(GT_NOISE) || defined(GT_LOD))
// Pixels per object unit where a vertex outputs surfaceOutput (terrain space).
float SurfacePixelScale(float3 surfaceOutput)
{
    float3 p = TerrainToObject(surfaceOutput);
    return PixelsPerUnit(GT_TessObjectToClip(p), GT_TessObjectToClip(p + float3(1.0, 0.0, 0.0)),
                         GT_TessObjectToClip(p + float3(0.0, 1.0, 0.0)), GT_TessObjectToClip(p + float3(0.0, 0.0, 1.0)),
                         GT_TessScreenSize());
}
#endif

#if defined(GT_NOISE)
// The octaves a vertex draws, from its surface position before noise. Mirrors Core
// TerrainVertex.VertexOctaveCount (the two rules). Paper mode keeps the single-range rule.
// NoiseSegmentPixels() is sent only with the levels (GT_LOD), so the continuous rule is compiled with
// the origin's code only: elsewhere its untaken branch kept registers.
float VertexOctaveCountAt(TileLayout l, float3 surfaceOutput)
{
#if !defined(GT_EXTEND_DRAW_PATCHES) && defined(GT_RANGE_ORIGIN_CODE)
    [branch] if (NoiseSegmentPixels() > 0.0)
        return OctaveCountAtPixelScale(SurfacePixelScale(surfaceOutput), NoiseSegmentPixels(), NoiseSettings(), MaxNoiseOctaves());
#endif
    return OctaveCount(LayoutWidth(l), NoiseVerticesAcross(), NoiseSettings(), MaxNoiseOctaves());
}

float VertexOctaveCount(TileLayout l, TerrainSurfacePoint s)
{
    return VertexOctaveCountAt(l, OutputSurfacePosition(l, s));
}
#endif

#if defined(GT_LOD)
// The levels' plain path (internals.md): where k e <= 1/4 px, k the pixel scale at the plain
// S(q) - S(O), e the bound PlainPathError. Mirrors Core TerrainVertex.UsesPlainPath.
#define GT_PLAIN_PATH_PIXELS 0.25
bool UsesPlainPath(float pixelScale)
{
    float e = PlainPathError();
    return e > 0.0 && NoiseSegmentPixels() > 0.0 && pixelScale * e <= GT_PLAIN_PATH_PIXELS;
}
#endif

// Everything TerrainVertex computes before the camera, from the surface point s.
TerrainVertexAttributes FinishTerrainVertex(TileLayout l, TerrainSurfacePoint s)
{
    float3 position;
    float3 dPdu = s.dPdu;
    float3 dPdv = s.dPdv;
    float noiseHeight = 0.0;   // the absolute p(q): the height of the plain path, and the height colour

#if defined(GT_NOISE)
    // Noise lives on the global point, so it is continuous across patches and tiles.
    #if defined(GT_EXTEND_DRAW_PATCHES)
    TerrainPoint noisePoint = ExtensionNoisePoint(s);
    #else
    TerrainPoint noisePoint = s.q;
    #endif
    float2 gradient;   // d(noise)/dq
#endif
    bool plainColor = false;   // the levels' plain path: the colour noise from the float point
#if defined(GT_LOD)
    [branch] if (RelativeSurfaceIsActive(l.origin))
    {
        float4 o = LevelsOriginSurface();
        float3 plainSurface = s.position - o.xyz;
        float k = SurfacePixelScale(plainSurface);
        [branch] if (UsesPlainPath(k))
        {
            position = plainSurface;
            plainColor = true;
    #if defined(GT_NOISE)
            float octaves = OctaveCountAtPixelScale(k, NoiseSegmentPixels(), NoiseSettings(), MaxNoiseOctaves());
            noiseHeight = OctaveNoise(MakeTerrainPoint(float2(0.0, 0.0), TerrainPointApprox(s.q)), NoiseSettings(), octaves, gradient);
            position.z += noiseHeight - o.w;
    #endif
        }
        else
        {
            position = RelativeSurfaceFromOrigin(s.q, l.origin);
    #if defined(GT_NOISE)
            float octaves = VertexOctaveCountAt(l, position);
            TerrainPoint origin = MakeTerrainPoint(l.origin.xy, l.origin.zw);
            float relative = OctaveNoiseRelative(s.q, origin, TerrainPointDifference(s.q, origin), NoiseSettings(), octaves, gradient);
            position.z += relative;
            noiseHeight = relative + o.w;   // for the colour: no precision needed
    #endif
        }
    }
    else
    {
        position = s.position;
    #if defined(GT_NOISE)
        noiseHeight = OctaveNoise(noisePoint, NoiseSettings(), VertexOctaveCount(l, s), gradient);
        position.z += noiseHeight;
    #endif
    }
#else
    #if defined(GT_NOISE)
    float octaves = VertexOctaveCount(l, s);
    #endif
#endif
#if !defined(GT_LOD) && !defined(GT_EXTEND_DRAW_PATCHES) && defined(GT_RANGE_ORIGIN_CODE)
    // Deep zoom (a range origin set): S(q) - S(O) and p(q) - p(O) from precise differences, which
    // the renderer adds back. Compiled only with GT_RANGE_ORIGIN_CODE, in one branch for the surface
    // and the noise: even untaken, branches slow the plain path (Tools~/bench/records.md, "Where the
    // domain stage's time goes").
    [branch] if (RelativeSurfaceIsActive(l.origin))
    {
        position = RelativeSurfaceFromOrigin(s.q, l.origin);
    #if defined(GT_NOISE)
        TerrainPoint origin = MakeTerrainPoint(l.origin.xy, l.origin.zw);
        position.z += OctaveNoiseRelative(s.q, origin, TerrainPointDifference(s.q, origin), NoiseSettings(), octaves, gradient);
        #if defined(GT_HEIGHT_COLOR)
        float2 colourGradient;
        noiseHeight = OctaveNoise(noisePoint, NoiseSettings(), octaves, colourGradient);
        #endif
    #endif
    }
    else
#endif
#if !defined(GT_LOD)
    {
        position = s.position;   // absolute: no origin, or the extension's draw patches
    #if defined(GT_NOISE)
        noiseHeight = OctaveNoise(noisePoint, NoiseSettings(), octaves, gradient);
        position.z += noiseHeight;
    #endif
    }
#endif
#if defined(GT_NOISE)
    // q = (a + u (e - a), b + v (f - b)), so the chain rule scales the gradient by the region size.
    float2 regionSize = RegionSize(s.region, s.regionLo);
    dPdu.z += gradient.x * regionSize.x;
    dPdv.z += gradient.y * regionSize.y;
#endif

    TerrainVertexAttributes a;
    a.snowDepth = 0.0;
#if defined(GT_SNOW)
    // After the noise: snow lies on the detailed surface. The normal stays the terrain's: the map's
    // bilinear slope (up to cap / cell size) is no surface normal.
    #if defined(GT_EXTEND_DRAW_PATCHES)
    float2 snowPoint = ExtensionSnowPoint(s);
    #else
    float2 snowPoint = TerrainPointApprox(s.q);
    #endif
    a.snowDepth = SnowMapSample(_SnowDepth, SnowMapSize(), snowPoint);
    position.z += a.snowDepth;
#endif

    // The derivatives already carry the noise term, so the normal is taken from them directly.
    a.positionOS = TerrainToObject(position);
    a.normalOS = TerrainToObject(GregoryNormalFromDerivatives(dPdu, dPdv));
    // The absolute height S'z (position.z is relative to S(O) at deep zoom).
    a.absoluteHeight = s.position.z + noiseHeight;
    a.colorNoise = 0.0;
#if defined(GT_HEIGHT_COLOR)
    #if defined(GT_RANGE_ORIGIN_CODE) || defined(GT_EXTEND_DRAW_PATCHES)
    // A branch, not ?:, which evaluates both noises in HLSL 2018 (FXC).
    [branch] if (plainColor)
        a.colorNoise = HeightColorNoiseAtLocal(TerrainPointApprox(s.q), HeightColorSettings());
    else
        a.colorNoise = HeightColorNoise(s.q, HeightColorSettings());
    #else
    // Without the origin's code q's hi part is the constant 0: the same value without TwoProduct.
    a.colorNoise = HeightColorNoiseAtLocal(s.q.local, HeightColorSettings());
    #endif
#endif
    a.patch = s.patch;
    return a;
}

#if defined(GT_EXTEND_VERTEX)
// Extension point (internals.md, "Extension points"): the entry file sees every vertex
// EvaluateTerrainVertex computes; it defines this after including the stages.
void ExtensionVertex(uint drawPatch, float2 tess, TerrainSurfacePoint s, TerrainVertexAttributes a);
#endif

// Everything TerrainVertex computes before the camera.
TerrainVertexAttributes EvaluateTerrainVertex(TileLayout l, uint drawPatch, float2 tess)
{
    TerrainSurfacePoint s = EvaluateSurface(l, drawPatch, tess);
    TerrainVertexAttributes a = FinishTerrainVertex(l, s);
#if defined(GT_EXTEND_VERTEX)
    ExtensionVertex(drawPatch, tess, s, a);
#endif
    return a;
}

// The same at tess of the whole cell slot `slot` holds (CellToTerrainPoint): what the vertex cache
// stores (ClippedCell.hlsl). The tile's own vertex wherever the tile is the whole cell, bit for bit.
TerrainVertexAttributes EvaluateCellTerrainVertex(TileLayout l, uint slot, float2 tess)
{
    return FinishTerrainVertex(l, EvaluateCellSurface(l, slot, tess));
}

// s = saturate(l + z / gamma) of eq. 14 for the absolute height z and colour noise l, 0 without
// GT_HEIGHT_COLOR. Per vertex: interpolated, it differs from per fragment only where the clamp acts.
float TerrainHeightWeight(float absoluteHeight, float colorNoise)
{
#if defined(GT_HEIGHT_COLOR)
    return HeightColorWeight(colorNoise, absoluteHeight, HeightColorSettings().x);
#else
    return 0.0;
#endif
}

// TerrainVaryings.normalAndHeightWeight of a unit world normal and a height weight, and back.
float3 PackNormalAndHeightWeight(float3 normalWS, float heightWeight)
{
    return float3(LambertEncodeNormal(normalWS), heightWeight);
}

float3 VaryingsNormalWS(TerrainVaryings i) { return LambertDecodeNormal(i.normalAndHeightWeight.xy); }

float VaryingsHeightWeight(TerrainVaryings i) { return i.normalAndHeightWeight.z; }

// The camera part: object space -> the varyings, from the fragment's three numbers (the vertex
// cache stores them packed; TerrainVertex computes them). tessFactor is only carried to the
// GT_DEBUG_TESS_FACTOR view, patch to GT_DEBUG_PATCH_ID's.
TerrainVaryings TerrainVaryingsOf(float3 positionOS, float3 normalAndHeightWeight, float snowDepth, uint patch, float tessFactor)
{
    TerrainVaryings o;
#if defined(GT_SHADOW_CASTER_NORMAL_BIAS)
    // The adapter's shadow caster also offsets along the normal (the pipeline's normal bias).
    o.positionCS = GT_ObjectToShadowClip(positionOS, LambertDecodeNormal(normalAndHeightWeight.xy));
#else
    o.positionCS = GT_ObjectToClip(positionOS);
#endif
    o.normalAndHeightWeight = normalAndHeightWeight;
#if defined(GT_VARYINGS_POSITION_WS)
    o.positionWS = GT_ObjectToWorld(positionOS);
#endif
#if defined(GT_DEBUG_PATCH_ID)
    o.patch = patch;
#endif
#if defined(GT_DEBUG_TESS_FACTOR)
    o.tessFactor = tessFactor;
#endif
#if defined(GT_SNOW)
    o.snowDepth = snowDepth;
#endif
    return o;
}

// The fragment's three numbers of a vertex whose normal is already in world space.
float3 TerrainNormalAndHeightWeight(TerrainVertexAttributes a, float3 normalWS)
{
    return PackNormalAndHeightWeight(normalWS, TerrainHeightWeight(a.absoluteHeight, a.colorNoise));
}

// TerrainVertex at a global point the caller formed (the levels' seam vertices, LodTiles.hlsl):
// drawPatch and tess only place the readback.
// The vertex at terrain point q (a level's seam vertex forms q through the coarse tile): what the
// levels' domain stage draws and their vertex kernel stores (LevelVertexCacheKernels.hlsl).
TerrainVertexAttributes EvaluatePointTerrainVertex(TileLayout l, uint drawPatch, float2 tess, TerrainPoint q)
{
    TerrainSurfacePoint s = EvaluateSurfaceAt(q);
    TerrainVertexAttributes a = FinishTerrainVertex(l, s);
#if defined(GT_EXTEND_VERTEX)
    ExtensionVertex(drawPatch, tess, s, a);
#endif
    return a;
}

TerrainVaryings TerrainVertexAtPoint(TileLayout l, uint drawPatch, float2 tess, TerrainPoint q, float tessFactor)
{
    TerrainVertexAttributes a = EvaluatePointTerrainVertex(l, drawPatch, tess, q);
    float3 shading = TerrainNormalAndHeightWeight(a, GT_ObjectToWorldNormal(a.normalOS));
    return TerrainVaryingsOf(a.positionOS, shading, a.snowDepth, a.patch, tessFactor);
}

TerrainVaryings TerrainVertex(TileLayout l, uint drawPatch, float2 tess, float tessFactor)
{
    TerrainVertexAttributes a = EvaluateTerrainVertex(l, drawPatch, tess);
    float3 shading = TerrainNormalAndHeightWeight(a, GT_ObjectToWorldNormal(a.normalOS));
    return TerrainVaryingsOf(a.positionOS, shading, a.snowDepth, a.patch, tessFactor);
}

#endif // GT_TERRAIN_VERTEX_INCLUDED
