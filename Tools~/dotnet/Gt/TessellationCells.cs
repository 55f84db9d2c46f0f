using System;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// Where the tessellator puts the vertices of one edge (or one inside direction) for a factor,
    /// as the error measure models it. <c>fractional_odd</c>: the segment count is the smallest odd
    /// integer n >= F (1 for F &lt;= 1; F is clamped to 63, the largest odd count); n - 2 segments are "full", 1/F of the edge long, and the two
    /// left over share the rest, placed symmetrically (at the ends for n = 3, beside the centre
    /// segment otherwise). The hardware's exact placement differs (it is implementation-defined in
    /// detail), but the longest segment is 1/F in both, and that is what bounds the error.
    /// <c>integer</c>: n = ceil(F) equal segments (the vertex cache's partitioning, GT_VERTEX_CACHE:
    /// the tessellator's vertices sit exactly at i/n; the fallback grid).
    /// </summary>
    static class TessellationCells
    {
        /// <summary>Parameters of the n + 1 vertices in [0, 1], increasing, first 0, last 1.</summary>
        public static double[] FractionalOdd(double factor)
        {
            if (double.IsNaN(factor) || factor < 0 || factor > 64)
                throw new ArgumentException($"factor ({factor}) must lie in [0, 64]", nameof(factor));
            if (factor <= 1.0) return new[] { 0.0, 1.0 };
            factor = Math.Min(factor, 63.0);   // fractional_odd's range is [1, 63]
            int n = (int)Math.Ceiling(factor);
            if (n % 2 == 0) n++;
            double full = 1.0 / factor;
            double shortLen = 0.5 * (1.0 - (n - 2) * full);
            var len = new double[n];
            for (int i = 0; i < n; i++) len[i] = full;
            int centre = n / 2;
            if (n == 3) { len[0] = len[2] = shortLen; }
            else { len[centre - 1] = len[centre + 1] = shortLen; }
            var x = new double[n + 1];
            for (int i = 0; i < n; i++) x[i + 1] = x[i] + len[i];
            x[n] = 1.0;
            return x;
        }

        /// <summary>
        /// n = ceil(F) equal segments (integer partitioning: the vertex cache, the fallback grid);
        /// 1 for F &lt;= 1. A factor a hair above an integer (1e-9) counts as that integer.
        /// </summary>
        public static double[] Integer(double factor)
        {
            if (double.IsNaN(factor) || factor < 0 || factor > 64)
                throw new ArgumentException($"factor ({factor}) must lie in [0, 64]", nameof(factor));
            int n = Math.Max(1, (int)Math.Ceiling(factor - 1e-9));
            var x = new double[n + 1];
            for (int i = 0; i <= n; i++) x[i] = (double)i / n;
            return x;
        }

        /// <summary>
        /// The triangles the tessellator makes of one quad patch with integer partitioning and these
        /// (already integer) factors: Core's <see cref="TerrainTriangleEstimate.PatchTriangles"/>.
        /// </summary>
        public static long IntegerTriangles(PatchFactors f)
        {
            if (f.culled) return 0;
            var set = new TileFactorSet(new Float4((float)f.e0, (float)f.e1, (float)f.e2, (float)f.e3), new Float2((float)f.i0, (float)f.i1));
            return TerrainTriangleEstimate.PatchTriangles(set, TessellationPartitioning.Integer);
        }
    }
}
