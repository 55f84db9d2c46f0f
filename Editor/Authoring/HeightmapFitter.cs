using System;
using System.Collections.Generic;
using System.Globalization;
using System.Threading;

namespace GregoryTerrain
{
    /// <summary>What <see cref="HeightmapFitter.Fit"/> returns: the G1 grid and how well it reproduces the samples.</summary>
    internal sealed class HeightmapFit
    {
        public PatchGrid Grid { get; }
        /// <summary>Largest |surface height - sample| over all samples, in the samples' height units.</summary>
        public double MaxError { get; }
        /// <summary>Root mean square of (surface height - sample) over all samples.</summary>
        public double RmsError { get; }
        /// <summary>Where the error is: the largest |error| per cell of a coarse picture of the heightmap.</summary>
        public FitErrorMap ErrorMap { get; }
        /// <summary>The least-squares C1 spline the fit started from (and fell back to where the samples say nothing).</summary>
        public SplineSurface Surface { get; }
        /// <summary>The fitted G1 net's layout and unknowns (what a neighbouring tile continues).</summary>
        public GregoryNet Net { get; }
        /// <summary>The fitted net's unknowns, in <see cref="Net"/>'s layout.</summary>
        public double[] Unknowns { get; }
        /// <summary>Conjugate-gradient iterations the solve took.</summary>
        public int Iterations { get; }
        /// <summary>Samples per row and rows of the fitted heightmap.</summary>
        public int SampleWidth { get; }
        public int SampleHeight { get; }
        /// <summary>Max and RMS error of the bilinear baseline (<see cref="BilinearBaseline"/>); NaN when not measured or none exists.</summary>
        public double BaselineMax { get; internal set; } = double.NaN;
        public double BaselineRms { get; internal set; } = double.NaN;
        /// <summary>Reweighting rounds that lowered the max (0: the plain least-squares fit).</summary>
        public int ReweightRounds { get; internal set; }
        /// <summary>Max and RMS error of the plain least-squares fit, before reweighting.</summary>
        public double LeastSquaresMax { get; internal set; }
        public double LeastSquaresRms { get; internal set; }

        public HeightmapFit(PatchGrid grid, double maxError, double rmsError, FitErrorMap errorMap, SplineSurface surface,
            GregoryNet net, double[] unknowns, int iterations, int sampleWidth, int sampleHeight)
        {
            Net = net;
            Unknowns = unknowns;
            Iterations = iterations;
            Grid = grid ?? throw new ArgumentNullException(nameof(grid));
            MaxError = maxError;
            RmsError = rmsError;
            ErrorMap = errorMap;
            Surface = surface;
            SampleWidth = sampleWidth;
            SampleHeight = sampleHeight;
        }
    }

    /// <summary>What <see cref="HeightmapFitter.Fit"/> minimises.</summary>
    internal enum FitObjective
    {
        /// <summary>
        /// Least squares, then reweighted rounds that lower the max toward the bilinear baseline's
        /// (<see cref="BilinearBaseline"/>) while the RMS stays at or below the baseline's.
        /// </summary>
        BoundedMax,
        /// <summary>The least-squares optimum alone.</summary>
        LeastSquares,
    }

    /// <summary>Which error <see cref="HeightmapFitter.FitToTarget"/> holds below its target.</summary>
    internal enum FitErrorKind
    {
        /// <summary>The largest |error| over all samples.</summary>
        Max,
        /// <summary>The root mean square error.</summary>
        Rms,
    }

    /// <summary>
    /// Fits an n x m G1 grid of Gregory patches to a height array (W x H doubles, row-major, sample
    /// (c, r) at <c>(c/(W-1), r/(H-1))</c> of the unit square) by linear least squares over every
    /// sample, in the space of G1 Gregory nets (<see cref="GregoryNet"/>): the C1 spline
    /// (<see cref="SplineSurface.Fit"/>) starts CG (<see cref="GregoryLeastSquares"/>), and the net's
    /// 20 points a patch are the grid, G1 by construction. The pairs free each edge's cross slope from
    /// the twists, so the fit is never worse than the spline (fitting.md, "What the fit is").
    /// </summary>
    internal static class HeightmapFitter
    {
        /// <summary>
        /// Fits the grid; reports progress in [0, 1] and honours cancellation (throws
        /// OperationCanceledException, nothing half-built). Checks its inputs first (<see cref="CheckInputs"/>).
        /// </summary>
        public static HeightmapFit Fit(double[] heights, int width, int height, int columns, int rows,
            IProgress<float> progress = null, CancellationToken cancellationToken = default, FitObjective objective = FitObjective.BoundedMax)
        {
            CheckInputs(heights, width, height, columns, rows);
            return FitChecked(heights, width, height, columns, rows, null, null, progress, cancellationToken, objective);
        }

        /// <summary>
        /// Fits a heightmap that continues <paramref name="west"/> eastwards (its first sample column is
        /// west's last, same rows and spacing). The first grid line is held at west's last, so the grids
        /// joined by <see cref="PatchGridJoin.WestEast"/> are G1 across the seam.
        /// </summary>
        public static HeightmapFit FitEastOf(HeightmapFit west, double[] heights, int width, int height, int columns,
            IProgress<float> progress = null, CancellationToken cancellationToken = default, FitObjective objective = FitObjective.BoundedMax)
        {
            CheckNeighbour(west, nameof(west));
            int rows = west.Grid.Rows;
            CheckInputs(heights, width, height, columns, rows);
            CheckSharedSamples(height, west.SampleHeight, nameof(height), "west", "rows");
            return FitChecked(heights, width, height, columns, rows, west, null, progress, cancellationToken, objective);
        }

        /// <summary>
        /// Fits a heightmap that continues <paramref name="south"/> northwards: <see cref="FitEastOf"/>
        /// mirrored across the diagonal, joined by <see cref="PatchGridJoin.SouthNorth"/>.
        /// </summary>
        public static HeightmapFit FitNorthOf(HeightmapFit south, double[] heights, int width, int height, int rows,
            IProgress<float> progress = null, CancellationToken cancellationToken = default, FitObjective objective = FitObjective.BoundedMax)
        {
            CheckNeighbour(south, nameof(south));
            int columns = south.Grid.Columns;
            CheckInputs(heights, width, height, columns, rows);
            CheckSharedSamples(width, south.SampleWidth, nameof(width), "south", "columns");
            return FitChecked(heights, width, height, columns, rows, null, south, progress, cancellationToken, objective);
        }

        /// <summary>
        /// Fits the north-east tile of a 2 x 2 block: its first column held at <paramref name="west"/>'s
        /// last and its first row at <paramref name="south"/>'s last, after <see cref="FitEastOf"/> and
        /// <see cref="FitNorthOf"/>, so the four grids (<see cref="PatchGridJoin.WestEast"/>,
        /// <see cref="PatchGridJoin.SouthNorth"/>) are G1 at every seam and the corner. Both neighbours
        /// hold the corner vertex; a pair that disagrees on it is refused.
        /// </summary>
        public static HeightmapFit FitNorthEastOf(HeightmapFit west, HeightmapFit south, double[] heights, int width, int height,
            IProgress<float> progress = null, CancellationToken cancellationToken = default, FitObjective objective = FitObjective.BoundedMax)
        {
            CheckNeighbour(west, nameof(west));
            CheckNeighbour(south, nameof(south));
            int columns = south.Grid.Columns, rows = west.Grid.Rows;
            CheckInputs(heights, width, height, columns, rows);
            CheckSharedSamples(height, west.SampleHeight, nameof(height), "west", "rows");
            CheckSharedSamples(width, south.SampleWidth, nameof(width), "south", "columns");
            CheckCorner(west, south, width, height, columns, rows);
            return FitChecked(heights, width, height, columns, rows, west, south, progress, cancellationToken, objective);
        }

        /// <summary>A neighbour fit must carry its net, consistent with its grid.</summary>
        static void CheckNeighbour(HeightmapFit fit, string name)
        {
            if (fit == null) throw new ArgumentNullException(name);
            if (fit.Unknowns == null) throw new ArgumentException($"{name} has no net to continue ({name}.Unknowns = null).", name);
            if (fit.Net.Columns != fit.Grid.Columns || fit.Net.Rows != fit.Grid.Rows)
                throw new ArgumentException($"{name}.Net is {fit.Net.Columns} x {fit.Net.Rows} patches, {name}.Grid is {fit.Grid.Columns} x {fit.Grid.Rows}: not one fit.", name);
            if (fit.Unknowns.Length != fit.Net.Count)
                throw new ArgumentException($"{name}.Unknowns.Length = {fit.Unknowns.Length}, its {fit.Net.Columns} x {fit.Net.Rows} net has {fit.Net.Count}: not one fit.", name);
        }

        static void CheckSharedSamples(int value, int neighbours, string field, string neighbour, string what)
        {
            if (value != neighbours)
                throw new ArgumentException($"{field} = {value} samples, the {neighbour} fit has {neighbours}: the tiles must share their {what}.", field);
        }

        /// <summary>Relative tolerance on the corner vertex's slopes both neighbours of a north-east tile hold.</summary>
        const double CornerTolerance = 1e-9;

        /// <summary>The corner vertex as each neighbour holds it (z, dx, dy) must agree, else no net is G1 with both.</summary>
        static void CheckCorner(HeightmapFit west, HeightmapFit south, int width, int height, int columns, int rows)
        {
            int wv = west.Net.Vertex(west.Net.Columns, 0), sv = south.Net.Vertex(0, south.Net.Rows);
            double rx = Ratio(width, columns, west.SampleWidth, west.Net.Columns);
            double ry = Ratio(height, rows, south.SampleHeight, south.Net.Rows);
            double[] w = west.Unknowns, s = south.Unknowns;
            double[] fromWest = { w[wv], w[wv + 1] * rx, w[wv + 2] };
            double[] fromSouth = { s[sv], s[sv + 1], s[sv + 2] * ry };
            double scale = 1;
            for (int k = 0; k < 3; k++) scale = Math.Max(scale, Math.Max(Math.Abs(fromWest[k]), Math.Abs(fromSouth[k])));
            string[] names = { "height", "x offset", "y offset" };
            // The height exactly: the joined grids' seams must be bit-identical (PatchGrid.Validate).
            for (int k = 0; k < 3; k++)
                if (!(Math.Abs(fromWest[k] - fromSouth[k]) <= (k == 0 ? 0 : CornerTolerance * scale)))
                    throw new ArgumentException(string.Format(CultureInfo.InvariantCulture,
                        "south's corner vertex {0} = {1:R}, west's = {2:R}: the neighbours disagree where the four tiles meet (fit both against the same south-west tile: FitEastOf, FitNorthOf).",
                        names[k], fromSouth[k], fromWest[k]), "south");
        }

        /// <summary>This tile's patch size over the neighbour's, in samples: an offset is (size / 3) times a slope.</summary>
        static double Ratio(int samples, int patches, int neighbourSamples, int neighbourPatches) =>
            ((double)(samples - 1) / patches) / ((double)(neighbourSamples - 1) / neighbourPatches);

        /// <summary>
        /// Fits with the fewest patches that bring the chosen error to <paramref name="target"/> or
        /// below: columns double, then bisect, up to <paramref name="maxColumns"/>; rows follow the
        /// aspect. Returns the last fit that met the target, else the one at maxColumns.
        /// </summary>
        public static HeightmapFit FitToTarget(double[] heights, int width, int height, double target, FitErrorKind kind, int maxColumns,
            IProgress<float> progress = null, CancellationToken cancellationToken = default)
        {
            if (!(target > 0) || double.IsInfinity(target))
                throw new ArgumentException(string.Format(CultureInfo.InvariantCulture, "target = {0}, need a positive finite error.", target), nameof(target));
            CheckInputs(heights, width, height, maxColumns, RowsFor(maxColumns, width, height));
            Func<int, HeightmapFit> fit = n => FitChecked(heights, width, height, n, RowsFor(n, width, height), null, null, null, cancellationToken, FitObjective.BoundedMax);
            Func<HeightmapFit, bool> meets = f => (kind == FitErrorKind.Max ? f.MaxError : f.RmsError) <= target;
            int lo = 0, hi = 1;   // lo fails (0: none tried), hi is the next to try
            HeightmapFit best = null;
            int step = 0, steps = 2 * (int)Math.Ceiling(Math.Log(maxColumns + 1, 2)) + 2;
            while (true)
            {
                HeightmapFit f = fit(hi);
                progress?.Report(Math.Min(1f, (float)++step / steps));
                if (meets(f)) { best = f; break; }
                if (hi == maxColumns) return f;
                lo = hi;
                hi = Math.Min(2 * hi, maxColumns);
            }
            while (hi - lo > 1)
            {
                int mid = lo + (hi - lo) / 2;
                HeightmapFit f = fit(mid);
                progress?.Report(Math.Min(1f, (float)++step / steps));
                if (meets(f)) { best = f; hi = mid; } else lo = mid;
            }
            progress?.Report(1f);
            return best;
        }

        /// <summary>Rows for n columns that keep patches about square in samples.</summary>
        public static int RowsFor(int columns, int width, int height) =>
            Math.Max(1, (int)Math.Round(columns * (double)(height - 1) / (width - 1)));

        /// <summary>Input checks before any work: W x H finite samples, a grid the GPU can hold (<see cref="GpuLayout.CheckSize"/>).</summary>
        public static void CheckInputs(double[] heights, int width, int height, int columns, int rows)
        {
            CheckHeights(heights, width, height);
            GpuLayout.CheckSize(columns, rows);   // the GPU's patch limit, before anything is allocated
        }

        /// <summary>Reweighting rounds at most (each a warm-started CG solve and an error pass).</summary>
        public const int MaxReweightRounds = 40;
        /// <summary>Samples above this fraction of the baseline's max get their weights raised.</summary>
        public const double ReweightThreshold = 0.9;
        /// <summary>Where the least-squares RMS is already above the baseline's, how much reweighting may raise it.</summary>
        public const double RmsAllowance = 0.02;
        /// <summary>Samples reweighted in one round at most (bounds the memory of the lists).</summary>
        const int MaxCollected = 1 << 16;
        /// <summary>Doubles one solve allocates per unknown: x, the right-hand side, CG's r, q, z, p, the block inverses.</summary>
        const long SolverBytesPerUnknown = 9 * sizeof(double);
        /// <summary>Garbage from the solve above which the fit collects it before allocating the grid (step 6).</summary>
        const long CollectAboveBytes = 4L << 20;

        static HeightmapFit FitChecked(double[] heights, int width, int height, int columns, int rows, HeightmapFit west,
            HeightmapFit south, IProgress<float> progress, CancellationToken ct, FitObjective objective)
        {
            // 1. One pass over the samples: S^T z and the patch Gram matrices.
            var net = new GregoryNet(columns, rows);
            var ls = new GregoryLeastSquares(net, width, height);
            double[] rhs = ls.RightHandSide(heights, progress, 0f, 0.3f, ct);

            // 2. The C1 spline from the same pass: the starting net and the ridge's prior.
            C1SplineBasis bx = new C1SplineBasis(columns), by = new C1SplineBasis(rows);
            BandedCholesky gy = by.NormalMatrix(height), gx = bx.NormalMatrix(width);
            SplineSurface surface = SplineSurface.Solve(bx, by, net.SplineRightHandSide(rhs), gy, gx);
            var x = new double[net.Count];
            net.FromSpline(surface.Coefficients, x);
            bool[] fixedMask = Hold(west, south, net, x, width, height);

            // 3. CG from the spline on the normal equations (x is the start and the ridge's prior).
            ls.Solve(rhs, x, x, fixedMask, progress, 0.3f, 0.5f, ct);
            int iterations = ls.Iterations;

            // 4. Error at every sample, the baseline and the samples above ReweightThreshold of it.
            double bMax = double.NaN, bRms = double.NaN;
            bool bounded = objective == FitObjective.BoundedMax && BilinearBaseline.Measure(heights, width, height, columns, rows, out bMax, out bRms);
            double tau = bounded ? ReweightThreshold * bMax : double.PositiveInfinity;
            var collected = new List<(int patch, int sample, double error)>();
            var map = new FitErrorMap(width, height);
            ls.Errors(heights, x, map, out double max, out double rms, tau, collected, progress, 0.5f, 0.7f, ct);
            double lsMax = max, lsRms = rms;
            if (collected.Count > MaxCollected) collected.RemoveRange(MaxCollected, collected.Count - MaxCollected);

            // 5. Lawson-style reweighting while the max is above the baseline's and the RMS holds
            // (or stays within RmsAllowance where least squares is already above it).
            int rounds = 0;
            double rmsCap = rms <= bRms ? bRms : rms * (1 + RmsAllowance);
            if (!(bounded && max > bMax)) ls.ReleaseWorkspace();
            else
            {
                double[] prior = new double[net.Count];
                net.FromSpline(surface.Coefficients, prior);
                Hold(west, south, net, prior, width, height);
                // One candidate net and list, swapped with the kept ones when a round lowers the max: rounds
                // allocate nothing net-sized. Rounds skip the error map; the kept net's is drawn once at the end.
                double[] weighted = new double[net.Count], next = new double[net.Count];
                var nextCollected = new List<(int patch, int sample, double error)>();
                for (int round = 1; round <= MaxReweightRounds && max > bMax && collected.Count > 0; round++)
                {
                    ct.ThrowIfCancellationRequested();
                    progress?.Report(0.7f + 0.25f * round / MaxReweightRounds);
                    ls.Reweight(heights, rhs, collected, tau, weighted);
                    Array.Copy(x, next, x.Length);
                    ls.Solve(weighted, next, prior, fixedMask, null, 0f, 0f, ct);
                    iterations += ls.Iterations;
                    nextCollected.Clear();
                    ls.Errors(heights, next, null, out double nextMax, out double nextRms, tau, nextCollected, null, 0f, 0f, ct);
                    if (nextRms > rmsCap) break;   // the RMS would pass the baseline's: keep the last net
                    if (nextCollected.Count > MaxCollected) nextCollected.RemoveRange(MaxCollected, nextCollected.Count - MaxCollected);
                    (collected, nextCollected) = (nextCollected, collected);
                    if (nextMax < max)
                    {
                        (x, next) = (next, x);
                        max = nextMax; rms = nextRms; rounds = round;
                    }
                }
                if (rounds > 0)
                {
                    // The same pass as the round's that chose x, so the same max and RMS.
                    map.Clear();
                    ls.Errors(heights, x, map, out max, out rms, double.PositiveInfinity, nextCollected, null, 0f, 0f, ct);
                }
            }

            // 6. The grid. The solves' vectors are large-object-heap garbage a gen-0 collection leaves;
            // collecting them first makes peak memory the larger of solve and grid, not their sum.
            rhs = null;
            collected = null;
            ls = null;
            ct.ThrowIfCancellationRequested();
            if ((long)net.Count * SolverBytesPerUnknown >= CollectAboveBytes) GC.Collect();
            PatchGrid grid = net.ToPatchGrid(x);
            progress?.Report(1f);
            return new HeightmapFit(grid, max, rms, map, surface, net, x, iterations, width, height)
            {
                BaselineMax = bMax, BaselineRms = bRms, ReweightRounds = rounds, LeastSquaresMax = lsMax, LeastSquaresRms = lsRms,
            };
        }

        /// <summary>
        /// Holds the neighbours' edges in x0 and returns the mask of held unknowns (null: none held).
        /// Along the line values are copied; slopes across it are rescaled to this tile's patch size.
        /// </summary>
        static bool[] Hold(HeightmapFit west, HeightmapFit south, GregoryNet net, double[] x0, int width, int height)
        {
            if (west == null && south == null) return null;
            var mask = new bool[net.Count];
            if (west != null)
            {
                GregoryNet w = west.Net;
                double[] wx = west.Unknowns;
                double ratio = Ratio(width, net.Columns, west.SampleWidth, w.Columns);
                for (int j = 0; j <= net.Rows; j++)
                {
                    int src = w.Vertex(w.Columns, j), dst = net.Vertex(0, j);
                    x0[dst] = wx[src];
                    x0[dst + 1] = wx[src + 1] * ratio;
                    x0[dst + 2] = wx[src + 2];
                    mask[dst] = mask[dst + 1] = mask[dst + 2] = true;
                }
                for (int j = 0; j < net.Rows; j++)
                {
                    int src = w.VerticalEdge(w.Columns, j), dst = net.VerticalEdge(0, j);
                    for (int k = 0; k < 2; k++)
                    {
                        x0[dst + k] = wx[src + k] * ratio;
                        mask[dst + k] = true;
                    }
                }
            }
            if (south != null)
            {
                GregoryNet s = south.Net;
                double[] sx = south.Unknowns;
                double ratio = Ratio(height, net.Rows, south.SampleHeight, s.Rows);
                for (int i = 0; i <= net.Columns; i++)
                {
                    int src = s.Vertex(i, s.Rows), dst = net.Vertex(i, 0);
                    x0[dst] = sx[src];
                    x0[dst + 1] = sx[src + 1];
                    x0[dst + 2] = sx[src + 2] * ratio;
                    mask[dst] = mask[dst + 1] = mask[dst + 2] = true;
                }
                for (int i = 0; i < net.Columns; i++)
                {
                    int src = s.HorizontalEdge(i, s.Rows), dst = net.HorizontalEdge(i, 0);
                    for (int k = 0; k < 2; k++)
                    {
                        x0[dst + k] = sx[src + k] * ratio;
                        mask[dst + k] = true;
                    }
                }
            }
            return mask;
        }

        /// <summary>Throws unless heights is W x H (W, H >= 2) and every sample is finite.</summary>
        public static void CheckHeights(double[] heights, int width, int height)
        {
            if (heights == null) throw new ArgumentNullException(nameof(heights));
            if (width < 2) throw new ArgumentException($"width = {width}, need at least 2 samples.", nameof(width));
            if (height < 2) throw new ArgumentException($"height = {height}, need at least 2 samples.", nameof(height));
            if ((long)width * height != heights.Length)
                throw new ArgumentException($"heights.Length = {heights.Length}, need width * height = {(long)width * height}.", nameof(heights));
            for (int k = 0; k < heights.Length; k++)
                if (!GMath.isfinite(heights[k]))
                    throw new ArgumentException(string.Format(CultureInfo.InvariantCulture,
                        "heights[{0}] (column {1}, row {2}) = {3} is not finite (a void? fill voids first: HeightmapVoids.Fill).", k, k % width, k / width, heights[k]), nameof(heights));
        }
    }
}
