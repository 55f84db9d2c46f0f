using System;

namespace GregoryTerrain
{
    /// <summary>
    /// How smooth a patch grid is across its shared edges, measured in double: each shared edge is
    /// sampled at <c>samplesPerEdge</c> equally spaced parameters, both ends included (default 65,
    /// i.e. steps of 1/64), and each side's patch is evaluated on its own boundary (u = 1 | u = 0 for
    /// a vertical edge, v = 1 | v = 0 for a horizontal one) at the same edge parameter.
    /// </summary>
    public static class ContinuityMeasure
    {
        public const int DefaultSamplesPerEdge = 65;

        /// <summary>
        /// The largest angle, in degrees, between the two sides' unit normals over all samples of all
        /// shared edges (0 for a G1 grid up to rounding). Computed as <c>atan2(|n0 x n1|, n0 . n1)</c>,
        /// accurate for tiny angles. Samples where either side's normal is degenerate (zero
        /// <c>dP/du x dP/dv</c>) are skipped. 0 for a 1 x 1 grid.
        /// </summary>
        public static double MaxNormalAngleDegrees(PatchGrid grid, int samplesPerEdge = DefaultSamplesPerEdge)
        {
            double worst = 0;
            ForEachEdgeSample(grid, samplesPerEdge, (a, ua, va, b, ub, vb) =>
            {
                Double3 n0 = GregoryEval.Normal(a, ua, va), n1 = GregoryEval.Normal(b, ub, vb);
                if (GMath.dot(n0, n0) == 0 || GMath.dot(n1, n1) == 0) return;
                double angle = Math.Atan2(GMath.length(GMath.cross(n0, n1)), GMath.dot(n0, n1)) * (180.0 / Math.PI);
                worst = Math.Max(worst, angle);
            });
            return worst;
        }

        /// <summary>The largest distance between the two sides' positions over the same samples (0 when shared edges are identical).</summary>
        public static double MaxPositionGap(PatchGrid grid, int samplesPerEdge = DefaultSamplesPerEdge)
        {
            double worst = 0;
            ForEachEdgeSample(grid, samplesPerEdge, (a, ua, va, b, ub, vb) =>
                worst = Math.Max(worst, GMath.length(GregoryEval.Position(a, ua, va) - GregoryEval.Position(b, ub, vb))));
            return worst;
        }

        delegate void EdgeSample(Double3[] a, double ua, double va, Double3[] b, double ub, double vb);

        static void ForEachEdgeSample(PatchGrid grid, int samples, EdgeSample visit)
        {
            if (grid == null) throw new ArgumentNullException(nameof(grid));
            if (samples < 2) throw new ArgumentException($"samplesPerEdge = {samples}, need at least 2 (both ends).", nameof(samples));
            for (int j = 0; j < grid.Rows; j++)
                for (int i = 0; i < grid.Columns; i++)
                    for (int s = 0; s < samples; s++)
                    {
                        double t = (double)s / (samples - 1);
                        if (i + 1 < grid.Columns) visit(grid.Patch(i, j).Points, 1, t, grid.Patch(i + 1, j).Points, 0, t);
                        if (j + 1 < grid.Rows) visit(grid.Patch(i, j).Points, t, 1, grid.Patch(i, j + 1).Points, t, 0);
                    }
        }
    }
}
