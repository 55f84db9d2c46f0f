using System;
using System.Collections.Generic;

namespace GregoryTerrain
{
    /// <summary>A tile's six tessellation factors. HLSL <c>TileFactorSet</c> (TileFactors.hlsl).</summary>
    internal struct TileFactorSet : IEquatable<TileFactorSet>
    {
        /// <summary>Quad domain: x is the edge u = 0, y v = 0, z u = 1, w v = 1.</summary>
        public Float4 edge;
        /// <summary>x subdivides along u, y along v.</summary>
        public Float2 inside;

        public TileFactorSet(Float4 edge, Float2 inside) { this.edge = edge; this.inside = inside; }

        /// <summary>All zero: the tile is culled (a zero edge factor drops the patch).</summary>
        public bool IsCulled => edge.x == 0f;

        public bool Equals(TileFactorSet o) => edge.Equals(o.edge) && inside.Equals(o.inside);
        public override bool Equals(object obj) => obj is TileFactorSet o && Equals(o);
        public override int GetHashCode() => HashCode.Combine(edge, inside);
        public override string ToString() => FormattableString.Invariant($"edges {edge}, inside {inside}");
    }

    /// <summary>
    /// The vertex cache's layout (GT_VERTEX_CACHE; internals.md, "Vertex cache"), name for name as
    /// <c>Shaders/Cache/VertexCache.hlsl</c>: a compute pass evaluates every vertex the tessellator will
    /// make at a tile's integer factors into a fixed slot; the domain stage reads it back by index.
    /// </summary>
    internal static class VertexCache
    {
        /// <summary>The hardware's largest tessellation factor.</summary>
        public const float MaxFactor = TessellationSettings.HardwareMaxFactor;

        /// <summary>uint4 per record (R): (positionOS bits, <see cref="PackCachedVaryings"/>), and with snow (snowDepth bits, 0, 0, 0).</summary>
        public static int Uint4sPerRecord(bool snow) => snow ? 2 : 1;

        /// <summary>
        /// L from the <c>_Tess</c> float4 (<see cref="TessellationSettings.ToFloat4"/>): the uniform factor
        /// when set, else the maximum factor, rounded up, in [1, 64]. Throws ArgumentException naming the
        /// component when it is not finite (or w is negative).
        /// </summary>
        public static int FactorLimit(Float4 tess)
        {
            if (!GMath.isfinite(tess.w) || tess.w < 0f)
                throw new ArgumentException(FormattableString.Invariant($"_Tess.w (uniformFactor, {tess.w:R}) must be finite and >= 0"), nameof(tess));
            float f = tess.w > 0f ? tess.w : tess.y;
            if (!GMath.isfinite(f))
                throw new ArgumentException(FormattableString.Invariant($"_Tess.y (maxFactor, {tess.y:R}) must be finite"), nameof(tess));
            // The kernel rounds every factor up and clamps to [1, 64]; ceil and the clamp commute.
            return (int)GMath.clamp(MathF.Ceiling(f), 1f, MaxFactor);
        }

        /// <summary>L of validated settings (the same number the shaders derive from <c>_Tess</c>).</summary>
        public static int FactorLimit(TessellationSettings tessellation)
        {
            tessellation.Validate();
            return FactorLimit(tessellation.ToFloat4());
        }

        /// <summary>S(L) = (L+1)^2 slots of the inside grid, then 4 edges of L + 1. Throws ArgumentException unless L lies in [1, 64].</summary>
        public static int SlotsPerTile(int limit)
        {
            if (limit < 1 || limit > (int)MaxFactor)
                throw new ArgumentException(FormattableString.Invariant($"factorLimit ({limit}) must lie in [1, {(int)MaxFactor}]"), nameof(limit));
            return (limit + 1) * (limit + 1) + 4 * (limit + 1);
        }

        /// <summary>Lanes of a CacheTileFactors group (HLSL <c>GT_VERTEX_CACHE_GROUP</c>): a lane a factor sample.</summary>
        public const int FactorThreadsPerGroup = 64;

        /// <summary>Lanes of a CacheTileVertices group (HLSL <c>GT_VERTEX_CACHE_VERTEX_GROUP</c>).</summary>
        public const int VertexThreadsPerGroup = 128;

        /// <summary>
        /// The surface samples of a tile's adaptive factors (HLSL <c>GT_TILE_FACTOR_SAMPLES</c>).
        /// CacheTileFactors runs one group a tile and one sample a lane, so they must fit a group.
        /// </summary>
        public const int FactorSamplesPerTile = 4 + 6 * 7 + 4 + 1;

        /// <summary>The most passes a CacheTileVertices group makes over its tile's points (HLSL <c>GT_VERTEX_CACHE_PASSES</c>).</summary>
        public const int PassesPerGroup = 4;

        /// <summary>
        /// The most points a tile at factors up to L has: anchored, its cell's whole (L + 1)^2 grid
        /// (<see cref="ClippedCell"/> blends a clipped tile's edge from it) and 4 edges of L + 1.
        /// </summary>
        public static int MaxTilePoints(int limit)
        {
            SlotsPerTile(limit);   // validates L
            return (limit + 1) * (limit + 1) + 4 * (limit + 1);
        }

        /// <summary>
        /// G, the CacheTileVertices groups sharing one tile (dispatch (T, T, G)), so that no group makes
        /// more than <see cref="PassesPerGroup"/> passes. HLSL <c>VertexCacheGroupsPerTile</c>.
        /// </summary>
        public static int GroupsPerTile(int limit)
        {
            const int perGroup = VertexThreadsPerGroup * PassesPerGroup;
            return (MaxTilePoints(limit) + perGroup - 1) / perGroup;
        }

        /// <summary>How the last pass decided a tile's cell factors (HLSL <c>GT_CELL_FACTORS_*</c>).</summary>
        public const float CellFactorsSampled = 0f, CellFactorsRescaled = 1f, CellFactorsHeld = 2f;

        /// <summary>Inside grid point (i, j) of a tile whose inside factor along u is <paramref name="insideU"/>.</summary>
        public static int InteriorSlot(int i, int j, int insideU) => i + j * (insideU + 1);

        /// <summary>Point k (from the edge's lower tess coordinate) of edge e (0: u = 0, 1: v = 0, 2: u = 1, 3: v = 1).</summary>
        public static int EdgeSlot(int edge, int k, int limit) => (limit + 1) * (limit + 1) + edge * (limit + 1) + k;

        /// <summary>Tess coordinate of point k of edge e at factor f.</summary>
        public static Float2 EdgeTess(int edge, int k, float f)
        {
            float s = k / f;
            return edge switch
            {
                0 => new Float2(0f, s),
                1 => new Float2(s, 0f),
                2 => new Float2(1f, s),
                _ => new Float2(s, 1f),
            };
        }

        /// <summary>HLSL <c>VertexCacheSlot</c>: the slot (within its tile) of the vertex at <paramref name="tess"/>.</summary>
        public static int Slot(Float2 tess, TileFactorSet f, int limit)
        {
            if (tess.x == 0f) return EdgeSlot(0, (int)RoundToPoint(tess.y * f.edge.x), limit);
            if (tess.y == 0f) return EdgeSlot(1, (int)RoundToPoint(tess.x * f.edge.y), limit);
            if (tess.x == 1f) return EdgeSlot(2, (int)RoundToPoint(tess.y * f.edge.z), limit);
            if (tess.y == 1f) return EdgeSlot(3, (int)RoundToPoint(tess.x * f.edge.w), limit);
            return InteriorSlot((int)RoundToPoint(tess.x * f.inside.x), (int)RoundToPoint(tess.y * f.inside.y), (int)f.inside.x);
        }

        /// <summary>
        /// HLSL <c>VertexCacheIntegerFactors</c>: each factor rounded up to an integer in [1, 64] (keeps
        /// the fractional factor's error bound), as drawn (<see cref="DrawnFactors"/>). Culled stays zero.
        /// </summary>
        public static TileFactorSet IntegerFactors(TileFactorSet f)
        {
            if (f.IsCulled) return f;
            float R(float x) => MathF.Ceiling(GMath.clamp(x, 1f, MaxFactor));
            return DrawnFactors(new TileFactorSet(new Float4(R(f.edge.x), R(f.edge.y), R(f.edge.z), R(f.edge.w)),
                                                  new Float2(R(f.inside.x), R(f.inside.y))));
        }

        /// <summary>
        /// Integer factors as the tessellator draws them: an inside factor of 1 is 2 unless all six
        /// are 1, so the slot grid is the one it draws. HLSL <c>VertexCacheDrawnFactors</c>.
        /// </summary>
        public static TileFactorSet DrawnFactors(TileFactorSet f)
        {
            Float4 e = f.edge;
            bool allOnes = e.x == 1f && e.y == 1f && e.z == 1f && e.w == 1f && f.inside.x == 1f && f.inside.y == 1f;
            return allOnes ? f : new TileFactorSet(e, new Float2(MathF.Max(f.inside.x, 2f), MathF.Max(f.inside.y, 2f)));
        }

        /// <summary>Round half away from zero: the integer a tessellator's coordinate times a factor stands for (HLSL <c>round</c>).</summary>
        internal static float RoundToPoint(float x) => MathF.Round(x, MidpointRounding.AwayFromZero);

        /// <summary>
        /// The points CacheTileVertices writes for one tile, in its order (HLSL <c>VertexCachePoint</c>):
        /// tess coordinate and slot; inside points are the grid's interior, or with <paramref name="anchored"/>
        /// the whole grid (HLSL <c>VertexCacheGridPoints</c>).
        /// </summary>
        public static IEnumerable<(Float2 tess, int slot)> TilePoints(TileFactorSet f, int limit, bool anchored = false)
        {
            if (f.IsCulled) yield break;
            int first = anchored ? 0 : 1;
            int nu = (int)f.inside.x + (anchored ? 1 : -1), nv = (int)f.inside.y + (anchored ? 1 : -1);
            for (int k = 0; k < nu * nv; k++)
            {
                int i = first + k % nu, j = first + k / nu;
                yield return (new Float2(i / f.inside.x, j / f.inside.y), InteriorSlot(i, j, (int)f.inside.x));
            }
            float[] edges = { f.edge.x, f.edge.y, f.edge.z, f.edge.w };
            for (int e = 0; e < 4; e++)
            {
                float fe = edges[e];
                for (int k = 0; k <= (int)fe; k++)
                    yield return (EdgeTess(e, k, fe), EdgeSlot(e, k, limit));
            }
        }

        /// <summary>
        /// HLSL <c>PackCachedVaryings</c>: the Lambert-encoded world normal e (|e| &lt;= 2) and height weight
        /// s in [0, 1] in one uint: e.x, e.y in 11 bits (0 exact), s in the top 10. Out-of-range values
        /// clamp. Rounds half to even; HLSL's round may not on ties: compare packed words to one step.
        /// </summary>
        public static uint PackCachedVaryings(Float3 normalAndHeightWeight)
        {
            float ex = MathF.Round(GMath.clamp(normalAndHeightWeight.x, -2f, 2f) * 511.5f) + 1023f;   // 0 .. 2046
            float ey = MathF.Round(GMath.clamp(normalAndHeightWeight.y, -2f, 2f) * 511.5f) + 1023f;
            float s = MathF.Round(GMath.saturate(normalAndHeightWeight.z) * 1023f);                   // 0 .. 1023
            return (uint)ex | ((uint)ey << 11) | ((uint)s << 22);
        }

        /// <summary>HLSL <c>UnpackCachedVaryings</c>: the three numbers of a packed word.</summary>
        public static Float3 UnpackCachedVaryings(uint bits)
        {
            float ex = (bits & 2047u) - 1023f, ey = ((bits >> 11) & 2047u) - 1023f;
            return new Float3(ex * (2f / 1023f), ey * (2f / 1023f), (bits >> 22) * (1f / 1023f));
        }

        /// <summary>
        /// The record of a vertex (HLSL <c>VertexCacheRecordPart</c>) as 4 R words, for an identity
        /// object-to-world. <paramref name="heightWeight"/>: <see cref="TerrainVertex.HeightWeight"/>.
        /// </summary>
        public static uint[] Record(TerrainVertexOutput v, float heightWeight, bool snow)
        {
            Float3 p = v.PositionOS;
            var r = new uint[4 * Uint4sPerRecord(snow)];
            r[0] = (uint)BitConverter.SingleToInt32Bits(p.x);
            r[1] = (uint)BitConverter.SingleToInt32Bits(p.y);
            r[2] = (uint)BitConverter.SingleToInt32Bits(p.z);
            Float2 e = NormalEncoding.LambertEncodeNormal(v.NormalOS);
            r[3] = PackCachedVaryings(new Float3(e.x, e.y, heightWeight));
            if (snow) r[4] = (uint)BitConverter.SingleToInt32Bits(v.snowDepth);
            return r;
        }
    }
}
