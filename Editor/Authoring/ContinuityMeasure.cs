using System;
using System.Threading;

namespace GregoryTerrain
{
    /// <summary>
    /// How smooth a patch grid is across its shared edges, measured in double: each shared edge is
    /// sampled at <c>samplesPerEdge</c> equally spaced parameters, both ends included (default 65,
    /// i.e. steps of 1/64), and each side's patch is evaluated on its own boundary (u = 1 | u = 0 for
    /// a vertical edge, v = 1 | v = 0 for a horizontal one) at the same edge parameter.
    /// </summary>
    internal static class ContinuityMeasure
    {
        public const int DefaultSamplesPerEdge = 65;

        /// <summary>Both measures in one pass, for long runs: <paramref name="progress"/> gets the fraction done (0..1) after each row of patches; <paramref name="cancellationToken"/> is checked as often and throws OperationCanceledException, leaving the grid untouched.</summary>
        public static ContinuityResult Measure(PatchGrid grid, int samplesPerEdge = DefaultSamplesPerEdge,
            Action<float> progress = null, CancellationToken cancellationToken = default)
        {
            double gap = 0, angle = 0;
            ForEachEdgeSample(grid, samplesPerEdge, (a, ua, va, b, ub, vb) =>
            {
                gap = Math.Max(gap, GMath.length(GregoryEval.Position(a, ua, va) - GregoryEval.Position(b, ub, vb)));
                angle = Math.Max(angle, NormalAngle(a, ua, va, b, ub, vb));
            }, progress, cancellationToken);
            return new ContinuityResult(gap, angle);
        }

        /// <summary>
        /// The largest angle, in degrees, between the two sides' unit normals over all samples of all
        /// shared edges (0 for a G1 grid up to rounding). Computed as <c>atan2(|n0 x n1|, n0 . n1)</c>,
        /// accurate for tiny angles. Samples where either side's normal is degenerate (zero
        /// <c>dP/du x dP/dv</c>) are skipped. 0 for a 1 x 1 grid.
        /// </summary>
        public static double MaxNormalAngleDegrees(PatchGrid grid, int samplesPerEdge = DefaultSamplesPerEdge)
        {
            double worst = 0;
            ForEachEdgeSample(grid, samplesPerEdge, (a, ua, va, b, ub, vb) => worst = Math.Max(worst, NormalAngle(a, ua, va, b, ub, vb)), null, default);
            return worst;
        }

        /// <summary>Degrees between the two sides' normals; 0 where either is degenerate.</summary>
        static double NormalAngle(Double3[] a, double ua, double va, Double3[] b, double ub, double vb)
        {
            Double3 n0 = GregoryEval.Normal(a, ua, va), n1 = GregoryEval.Normal(b, ub, vb);
            if (GMath.dot(n0, n0) == 0 || GMath.dot(n1, n1) == 0) return 0;
            return Math.Atan2(GMath.length(GMath.cross(n0, n1)), GMath.dot(n0, n1)) * (180.0 / Math.PI);
        }

        /// <summary>The largest distance between the two sides' positions over the same samples (0 when shared edges are identical).</summary>
        public static double MaxPositionGap(PatchGrid grid, int samplesPerEdge = DefaultSamplesPerEdge)
        {
            double worst = 0;
            ForEachEdgeSample(grid, samplesPerEdge, (a, ua, va, b, ub, vb) =>
                worst = Math.Max(worst, GMath.length(GregoryEval.Position(a, ua, va) - GregoryEval.Position(b, ub, vb))), null, default);
            return worst;
        }

        delegate void EdgeSample(Double3[] a, double ua, double va, Double3[] b, double ub, double vb);

        static void ForEachEdgeSample(PatchGrid grid, int samples, EdgeSample visit, Action<float> progress, CancellationToken cancellationToken)
        {
            if (grid == null) throw new ArgumentNullException(nameof(grid));
            InputLimits.CheckSamplesPerEdge(samples);
            for (int j = 0; j < grid.Rows; j++)
            {
                cancellationToken.ThrowIfCancellationRequested();
                progress?.Invoke((float)j / grid.Rows);
                for (int i = 0; i < grid.Columns; i++)
                    for (int s = 0; s < samples; s++)
                    {
                        double t = (double)s / (samples - 1);
                        if (i + 1 < grid.Columns) visit(grid.Patch(i, j).Points, 1, t, grid.Patch(i + 1, j).Points, 0, t);
                        if (j + 1 < grid.Rows) visit(grid.Patch(i, j).Points, t, 1, grid.Patch(i, j + 1).Points, t, 0);
                    }
            }
            progress?.Invoke(1f);
        }
    }

    /// <summary>What <see cref="ContinuityMeasure.Measure"/> found: the largest position gap and normal angle (degrees) over the shared edges.</summary>
    internal readonly struct ContinuityResult
    {
        public readonly double MaxPositionGap, MaxNormalAngleDegrees;
        public ContinuityResult(double maxPositionGap, double maxNormalAngleDegrees)
        {
            MaxPositionGap = maxPositionGap;
            MaxNormalAngleDegrees = maxNormalAngleDegrees;
        }
    }
}
