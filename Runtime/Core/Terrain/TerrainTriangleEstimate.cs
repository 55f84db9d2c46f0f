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
        /// <summary>Tiles drawn: M^2, or (M + 1)^2 anchored.</summary>
        public int tileCount;
        /// <summary>
        /// Of the sampled tiles drawn, those with an adaptive factor held at the max factor: the
        /// target pixel error may not hold there, and more tiles (or a larger max factor) would
        /// restore it. 0 with a uniform factor.
        /// </summary>
        public int tilesSampledAtMaxFactor;

        /// <inheritdoc/>
        public override string ToString() => FormattableString.Invariant(
            $"{triangles:N0} triangles ({tilesSampledDrawn} of {tilesSampled} sampled tiles drawn, {tilesSampledAtMaxFactor} at the max factor, {tileCount} tiles)");
    }

    /// <summary>
    /// How many triangles the terrain's draw makes for a camera: each tile's factors from Core's
    /// mirror of the hull stage (<see cref="TileFactors.ComputeTileFactors"/>), counted as the
    /// tessellator triangulates a quad (<see cref="PatchTriangles"/>). The renderer's inspector shows
    /// it, so that the target pixel error's cost is visible before anything is drawn. The rig checks
    /// it against the GPU's clipping invocations (Tools~/RigTests/VertexCacheGpuTests.cs,
    /// <c>TriangleEstimateIsWhatTheGpuDraws</c>; and every adaptive job of <c>gt bench</c>).
    /// </summary>
    internal static class TerrainTriangleEstimate
    {
        /// <summary>
        /// The segments the tessellator makes of one factor: for <see cref="TessellationPartitioning.Integer"/>
        /// ceil(F) (at most 64), for <see cref="TessellationPartitioning.FractionalOdd"/> the smallest
        /// odd count >= F (at most 63); 1 for F &lt;= 1.
        /// </summary>
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
        /// Triangles of one quad patch at these factors, transition rings included: 0 when culled (an
        /// edge factor 0), 2 when every count is 1; otherwise an inside count of 1 is raised to 2
        /// (integer) or 3 (fractional_odd), as the tessellator does, and the patch makes an inner grid
        /// of (i0 - 2) x (i1 - 2) quads plus, per side, e + i - 2 triangles joining the side's e
        /// segments to the inner rectangle's i - 2. A uniform count n gives 2 n^2.
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

        /// <summary>
        /// Whether any of a drawn tile's factors makes as many segments as the max factor allows
        /// (segments grow with the factor, so the largest factor decides).
        /// </summary>
        public static bool ReachesMaxFactor(TileFactorSet f, float maxFactor, TessellationPartitioning partitioning)
        {
            float largest = MathF.Max(MathF.Max(MathF.Max(f.edge.x, f.edge.y), MathF.Max(f.edge.z, f.edge.w)), MathF.Max(f.inside.x, f.inside.y));
            return Segments(largest, partitioning) >= Segments(maxFactor, partitioning);
        }

        /// <summary>
        /// The draw's triangles for a camera (<paramref name="objectToClip"/>, <paramref name="screenSize"/>
        /// pixels) at the inputs' settings and range. At most <paramref name="maxTiles"/> tiles are
        /// evaluated (51 surface points each): with more, the k x k tiles nearest the centres of a
        /// k x k split of the tiles (k = floor(sqrt(maxTiles))), their count scaled to all of them (M^2, or (M + 1)^2 anchored). The
        /// vertex cache's factors are the integers it rounds them to (<see cref="VertexCache.IntegerFactors"/>).
        /// </summary>
        public static TriangleEstimate InView(TerrainInputs inputs, Float4x4 objectToClip, Float2 screenSize, TerrainKeywords keywords,
                                              TessellationPartitioning partitioning, int maxTiles = 256)
        {
            if (inputs == null) throw new ArgumentNullException(nameof(inputs));
            if (!objectToClip.IsFinite) throw new ArgumentException($"objectToClip {objectToClip} must be finite", nameof(objectToClip));
            if (!screenSize.IsFinite || !(screenSize.x > 0f) || !(screenSize.y > 0f))
                throw new ArgumentException($"screenSize {screenSize} must be finite and positive", nameof(screenSize));
            if (maxTiles < 1) throw new ArgumentException(FormattableString.Invariant($"maxTiles ({maxTiles}) must be >= 1"), nameof(maxTiles));
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
    }
}
