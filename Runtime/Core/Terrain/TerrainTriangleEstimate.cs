using System;

namespace GregoryTerrain
{
    /// <summary>How the tessellator spaces a factor's segments (the hull stage's <c>partitioning</c>).</summary>
    internal enum TessellationPartitioning
    {
        /// <summary><c>fractional_odd</c> (the domain-stage draw): the next odd count, 1 to 63.</summary>
        FractionalOdd,
        /// <summary><c>integer</c> (the vertex cache): ceil(F) equal segments, 1 to 64.</summary>
        Integer,
    }

    /// <summary>What <see cref="TerrainTriangleEstimate.InView"/> found.</summary>
    public struct TriangleEstimate
    {
        /// <summary>Triangles the draw makes (scaled up from the sampled tiles when not all were evaluated).</summary>
        public double triangles;
        /// <summary>Tiles whose factors were computed, and how many of them are drawn (not culled).</summary>
        public int tilesSampled, tilesSampledDrawn;
        /// <summary>Tiles drawn: M^2, (M + 1)^2 anchored, or the levels' (<see cref="LodLevels.DrawnTileCount"/>).</summary>
        public int tileCount;
        /// <summary>Of the sampled tiles drawn, those held at the max factor (the target may not hold there); 0 with a uniform factor.</summary>
        public int tilesSampledAtMaxFactor;

        /// <inheritdoc/>
        public override string ToString() => FormattableString.Invariant(
            $"{triangles:N0} triangles ({tilesSampledDrawn} of {tilesSampled} sampled tiles drawn, {tilesSampledAtMaxFactor} at the max factor, {tileCount} tiles)");
    }

    /// <summary>
    /// The triangles a camera's draw makes: each tile's factors from Core's mirror of the hull stage,
    /// counted as the tessellator triangulates a quad. The rig checks it against the GPU's clipping
    /// invocations (VertexCacheGpuTests, LodEstimateGpuTests, <c>gt bench</c>).
    /// </summary>
    internal static class TerrainTriangleEstimate
    {
        /// <summary>Segments of one factor F: integer ceil(F) (at most 64), fractional_odd the odd count >= F (at most 63); 1 for F &lt;= 1.</summary>
        public static int Segments(float factor, TessellationPartitioning partitioning)
        {
            if (!(factor >= 0f) || float.IsInfinity(factor))
                throw new ArgumentException(FormattableString.Invariant($"factor ({factor:R}) must be finite and >= 0"), nameof(factor));
            if (factor <= 1f) return 1;
            if (partitioning == TessellationPartitioning.Integer) return (int)Math.Ceiling(Math.Min(factor, VertexCache.MaxFactor));
            int n = (int)Math.Ceiling(Math.Min(factor, 63f));
            return n % 2 == 0 ? n + 1 : n;
        }

        /// <summary>
        /// Triangles of one quad patch, transition rings included: 0 culled, 2 when every count is 1;
        /// else an inside count of 1 raised to 2 (integer) or 3 (fractional_odd), an inner grid of
        /// (i0 - 2) x (i1 - 2) quads and per side e + i - 2 triangles. A uniform count n gives 2 n^2.
        /// </summary>
        public static long PatchTriangles(TileFactorSet f, TessellationPartitioning partitioning)
        {
            if (f.edge.x <= 0f || f.edge.y <= 0f || f.edge.z <= 0f || f.edge.w <= 0f) return 0;
            int e0 = Segments(f.edge.x, partitioning), e1 = Segments(f.edge.y, partitioning);
            int e2 = Segments(f.edge.z, partitioning), e3 = Segments(f.edge.w, partitioning);
            int i0 = Segments(f.inside.x, partitioning), i1 = Segments(f.inside.y, partitioning);
            if (e0 == 1 && e1 == 1 && e2 == 1 && e3 == 1 && i0 == 1 && i1 == 1) return 2;
            int raised = partitioning == TessellationPartitioning.Integer ? 2 : 3;
            if (i0 == 1) i0 = raised;
            if (i1 == 1) i1 = raised;
            // Edges e1 (v = 0) and e3 (v = 1) run along u, beside the inner rectangle's i0 - 2 segments.
            return 2L * (i0 - 2) * (i1 - 2) + e1 + e3 + 2L * (i0 - 2) + e0 + e2 + 2L * (i1 - 2);
        }

        /// <summary>Whether a drawn tile's largest factor makes as many segments as the max factor.</summary>
        public static bool ReachesMaxFactor(TileFactorSet f, float maxFactor, TessellationPartitioning partitioning)
        {
            float largest = MathF.Max(MathF.Max(MathF.Max(f.edge.x, f.edge.y), MathF.Max(f.edge.z, f.edge.w)), MathF.Max(f.inside.x, f.inside.y));
            return Segments(largest, partitioning) >= Segments(maxFactor, partitioning);
        }

        /// <summary>
        /// The draw's triangles for a camera at the inputs' settings and range. Beyond
        /// <paramref name="maxTiles"/> tiles, the k x k nearest the centres of a k x k split
        /// (k = floor(sqrt(maxTiles))), scaled to all. The cache's factors are its integers.
        /// </summary>
        public static TriangleEstimate InView(TerrainInputs inputs, Float4x4 objectToClip, Float2 screenSize, TerrainKeywords keywords,
                                              TessellationPartitioning partitioning, int maxTiles = 256)
        {
            CheckArguments(inputs, objectToClip, screenSize, maxTiles);
            int tiles = inputs.TilesAcross(), count = tiles * tiles;
            int k = count <= maxTiles ? tiles : Math.Max(1, (int)Math.Sqrt(maxTiles));
            int sampled = k * k;
            var e = new TriangleEstimate { tileCount = count, tilesSampled = sampled };
            long sum = 0;
            for (int i = 0; i < sampled; i++)
            {
                // Stratified in both directions: the tile holding the centre of cell (i mod k, i / k) of a k x k split.
                int ti = (int)((2L * (i % k) + 1) * tiles / (2L * k)), tj = (int)((2L * (i / k) + 1) * tiles / (2L * k));
                int tile = tj * tiles + ti;
                TileFactorSet f = partitioning == TessellationPartitioning.Integer
                    ? TileFactors.ComputeCachedTileFactors(inputs, tile, objectToClip, screenSize, keywords)
                    : TileFactors.ComputeTileFactors(inputs, tile, objectToClip, screenSize, keywords);
                if (f.IsCulled) continue;
                e.tilesSampledDrawn++;
                if (!inputs.UsesUniformTessFactor() && ReachesMaxFactor(f, inputs.MaxTessFactor(), partitioning)) e.tilesSampledAtMaxFactor++;
                sum += PatchTriangles(f, partitioning);
            }
            e.triangles = (double)sum * count / sampled;
            return e;
        }

        static void CheckArguments(TerrainInputs inputs, Float4x4 objectToClip, Float2 screenSize, int maxTiles)
        {
            if (inputs == null) throw new ArgumentNullException(nameof(inputs));
            if (!objectToClip.IsFinite) throw new ArgumentException($"objectToClip {objectToClip} must be finite", nameof(objectToClip));
            if (!screenSize.IsFinite || !(screenSize.x > 0f) || !(screenSize.y > 0f))
                throw new ArgumentException($"screenSize {screenSize} must be finite and positive", nameof(screenSize));
            if (maxTiles < 1) throw new ArgumentException(FormattableString.Invariant($"maxTiles ({maxTiles}) must be >= 1"), nameof(maxTiles));
        }

        /// <summary>
        /// <see cref="InView"/> with Horizon levels: <paramref name="levels"/> from <see cref="LodLevels.Layout"/>,
        /// factors by <see cref="LodTileFactors"/>. Beyond <paramref name="maxTiles"/>, k x k tiles a level (k = floor(sqrt(maxTiles / L))).
        /// </summary>
        public static TriangleEstimate InLevels(TerrainInputs inputs, ReadOnlySpan<TerrainRange> levels, RangeOrigin origin, Float4x4 objectToClip,
                                                Float2 screenSize, TerrainKeywords keywords, int maxTiles = 256)
        {
            CheckArguments(inputs, objectToClip, screenSize, maxTiles);
            int m = inputs.TileCountInt(), n = levels.Length, perLevel = m * m;
            if (n < 1 || n > LodTiles.MaxLevels) throw new ArgumentException(FormattableString.Invariant($"levels.Length ({n}) must lie in [1, {LodTiles.MaxLevels}]"), nameof(levels));
            if (m % 2 != 0 || m < LodLevels.MinTiles) throw new ArgumentException(FormattableString.Invariant($"tiles ({m}) must be even and >= {LodLevels.MinTiles}"), nameof(inputs));
            TerrainInputs[] layouts = LevelInputs(inputs, levels, origin);
            var e = new TriangleEstimate { tileCount = LodLevels.DrawnTileCount(n, m) };
            int k = n * perLevel <= maxTiles ? m : Math.Max(1, (int)Math.Sqrt(maxTiles / n));
            for (int l = 0; l < n; l++)
            {
                long sum = 0;
                for (int i = 0; i < k * k; i++)
                {
                    int ti = (2 * (i % k) + 1) * m / (2 * k), tj = (2 * (i / k) + 1) * m / (2 * k);
                    if (InsideFiner(layouts, l, ti, tj)) continue;
                    e.tilesSampled++;
                    TileFactorSet f = LodTileFactors(layouts, l, ti, tj, objectToClip, screenSize, keywords);
                    if (f.IsCulled) continue;
                    e.tilesSampledDrawn++;
                    if (!inputs.UsesUniformTessFactor() && ReachesMaxFactor(f, inputs.MaxTessFactor(), TessellationPartitioning.Integer)) e.tilesSampledAtMaxFactor++;
                    sum += PatchTriangles(f, TessellationPartitioning.Integer);
                }
                e.triangles += (double)sum * perLevel / (k * k);
            }
            return e;
        }

        /// <summary>Each level's inputs (HLSL <c>LodLevelLayout</c>).</summary>
        public static TerrainInputs[] LevelInputs(TerrainInputs inputs, ReadOnlySpan<TerrainRange> levels, RangeOrigin origin)
        {
            var layouts = new TerrainInputs[levels.Length];
            for (int l = 0; l < levels.Length; l++)
            {
                TerrainParams p = inputs.Params;
                RangeMapping.EncodeRange(levels[l], origin, out p.range, out p.rangeOrigin);
                p.tileLattice = default;
                layouts[l] = inputs.WithParams(p);
            }
            return layouts;
        }

        static void Offset(TerrainInputs[] levels, int coarse, out int a, out int b) =>
            LodTiles.FinerOffsetCells(levels[coarse].Params.range, levels[coarse - 1].Params.range, levels[0].TileCountInt(), out a, out b);

        static bool InsideFiner(TerrainInputs[] levels, int level, int ti, int tj)
        {
            if (level == 0) return false;
            Offset(levels, level, out int a, out int b);
            return LodTiles.TileInsideFiner(ti, tj, a, b, levels[0].TileCountInt());
        }

        /// <summary>HLSL <c>LodTileFactors</c> (VertexSource.Levels.hlsl) of tile (ti, tj) of <paramref name="level"/>.</summary>
        public static TileFactorSet LodTileFactors(TerrainInputs[] levels, int level, int ti, int tj, Float4x4 objectToClip, Float2 screenSize, TerrainKeywords keywords)
        {
            if (InsideFiner(levels, level, ti, tj)) return TileFactors.CulledTileFactors();
            TerrainInputs l = levels[level];
            int m = l.TileCountInt(), coarseMask = 0, fineMask = 0, aUp = 0, bUp = 0;
            if (level > 0)
            {
                Offset(levels, level, out int a, out int b);
                coarseMask = LodTiles.CoarseSeamEdges(ti, tj, a, b, m);
            }
            if (level + 1 < levels.Length)
            {
                Offset(levels, level + 1, out aUp, out bUp);
                fineMask = LodTiles.FineSeamEdges(ti, tj, aUp, bUp, m);
            }
            TileFactorSet set = TileFactors.ComputeTileFactors(l, tj * m + ti, objectToClip, screenSize, keywords);
            if (set.IsCulled) return set;
            float[] edge = { set.edge.x, set.edge.y, set.edge.z, set.edge.w };
            for (int i = 0; i < 4; i++)
            {
                if ((coarseMask & 1 << i) != 0) edge[i] = 2f * LodTiles.SeamHalfFactor(edge[i], l.MaxTessFactor());
                else if ((fineMask & 1 << i) != 0)
                    edge[i] = LodTiles.SeamHalfFactor(CoarseSeamEdgeFactor(levels[level + 1], 1 << i, ti, tj, aUp, bUp, objectToClip, screenSize, keywords), l.MaxTessFactor());
            }
            return new TileFactorSet(new Float4(edge[0], edge[1], edge[2], edge[3]), set.inside);
        }

        /// <summary>HLSL <c>CoarseSeamEdgeFactor</c>.</summary>
        public static float CoarseSeamEdgeFactor(TerrainInputs coarse, int edgeBit, int ti, int tj, int aUp, int bUp, Float4x4 objectToClip, Float2 screenSize,
                                                 TerrainKeywords keywords)
        {
            if (coarse.UsesUniformTessFactor()) return coarse.UniformTessFactor();
            int m = coarse.TileCountInt();
            LodTiles.FineSeamCoarseTile(edgeBit, ti, tj, aUp, bUp, out int cti, out int ctj, out int coarseEdge, out _);
            int slot = ctj * m + cti;
            var corners = new Float3[4];
            for (int c = 0; c < 4; c++) corners[c] = TileFactors.CellCornerObjectPosition(coarse, slot, c);
            int piece = coarseEdge == LodTiles.EdgeU0 ? 0 : coarseEdge == LodTiles.EdgeV0 ? 1 : coarseEdge == LodTiles.EdgeU1 ? 2 : 3;
            return Math.Max(TileFactors.TileFactorPiece(coarse, slot, piece, corners, objectToClip, screenSize, keywords), 1f);
        }
    }
}
