using System;
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
        /// <summary>The fitted C1 spline surface the grid was built from (what a neighbouring tile continues).</summary>
        public SplineSurface Surface { get; }
        /// <summary>Samples per row and rows of the fitted heightmap.</summary>
        public int SampleWidth { get; }
        public int SampleHeight { get; }

        public HeightmapFit(PatchGrid grid, double maxError, double rmsError, FitErrorMap errorMap, SplineSurface surface, int sampleWidth, int sampleHeight)
        {
            Grid = grid ?? throw new ArgumentNullException(nameof(grid));
            MaxError = maxError;
            RmsError = rmsError;
            ErrorMap = errorMap;
            Surface = surface;
            SampleWidth = sampleWidth;
            SampleHeight = sampleHeight;
        }
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
    /// sample:
    /// <list type="number">
    /// <item>the surface is a C1 bicubic spline on the grid's lines (tensor product of two
    /// <see cref="C1SplineBasis"/>: a height and a slope per grid vertex and axis, 4 (n+1)(m+1)
    /// unknowns), so the fitted patches are Bezier patches joined C1, which is G1;</item>
    /// <item>least squares over all W H samples. Gridded samples and a tensor-product basis make the
    /// normal equations separable, <c>G_y C G_x = S_y^T Z S_x</c>: one pass over the samples builds
    /// the right-hand side (4 multiply-adds a sample), then two band solves (bandwidth 3) per axis.
    /// Time O(W H + n m), memory O(n m) beyond the samples;</item>
    /// <item>the Bezier net of that spline is the grid's control net, interior pairs coincident;
    /// <see cref="G1Builder.MakeG1"/> then re-derives every shared edge's interior points (it finds
    /// k = -1, h = 0 and keeps them), so the grid is G1 by the same construction as any other;</item>
    /// <item>a second pass measures the error at every sample and bins it into
    /// <see cref="FitErrorMap"/>.</item>
    /// </list>
    /// Why this and not free Gregory interiors: the C1 spline space is linear, so the least-squares
    /// fit is one exact solve with no iteration and no G1 repair that moves points away from the
    /// optimum. A Gregory grid has more freedom (independent cross-boundary slopes per edge), but a
    /// least-squares fit over it is neither separable nor linear once k, h vary.
    /// </summary>
    internal static class HeightmapFitter
    {
        /// <summary>
        /// Fits the grid; reports progress in [0, 1] and honours cancellation (throws
        /// OperationCanceledException and returns nothing half-built). The one entry point that
        /// checks its inputs first (<see cref="CheckInputs"/>).
        /// </summary>
        public static HeightmapFit Fit(double[] heights, int width, int height, int columns, int rows,
            IProgress<float> progress = null, CancellationToken cancellationToken = default)
        {
            CheckInputs(heights, width, height, columns, rows);
            return FitChecked(heights, width, height, columns, rows, null, progress, cancellationToken);
        }

        /// <summary>
        /// Fits a heightmap that continues <paramref name="west"/> eastwards: its first column of
        /// samples is the west fit's last one, rows are the same rows, and samples are as far apart.
        /// The east grid's first grid line takes the west grid's last heights and slopes exactly, so
        /// the two grids joined side by side (<see cref="PatchGridJoin.WestEast"/>) are G1 across
        /// the seam. Its rows must equal west's.
        /// </summary>
        public static HeightmapFit FitEastOf(HeightmapFit west, double[] heights, int width, int height, int columns,
            IProgress<float> progress = null, CancellationToken cancellationToken = default)
        {
            if (west == null) throw new ArgumentNullException(nameof(west));
            if (west.Surface == null) throw new ArgumentException("west has no spline surface to continue.", nameof(west));
            int rows = west.Grid.Rows;
            CheckInputs(heights, width, height, columns, rows);
            if (height != west.SampleHeight)
                throw new ArgumentException($"height = {height} rows of samples, the west fit has {west.SampleHeight}: the tiles must share their rows.", nameof(height));
            return FitChecked(heights, width, height, columns, rows, west, progress, cancellationToken);
        }

        /// <summary>
        /// Fits with the fewest patches that bring the chosen error to <paramref name="target"/> or
        /// below: columns double from 1 until the target is met (or <paramref name="maxColumns"/> is
        /// reached), then bisect; rows follow the heightmap's aspect. Returns the last fit tried that
        /// met the target, or the one at maxColumns if none did (its error then says so).
        /// </summary>
        public static HeightmapFit FitToTarget(double[] heights, int width, int height, double target, FitErrorKind kind, int maxColumns,
            IProgress<float> progress = null, CancellationToken cancellationToken = default)
        {
            if (!(target > 0) || double.IsInfinity(target))
                throw new ArgumentException(string.Format(CultureInfo.InvariantCulture, "target = {0}, need a positive finite error.", target), nameof(target));
            CheckInputs(heights, width, height, maxColumns, RowsFor(maxColumns, width, height));
            Func<int, HeightmapFit> fit = n => FitChecked(heights, width, height, n, RowsFor(n, width, height), null, null, cancellationToken);
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

        /// <summary>
        /// The fitter's input checks, all before any work: a W x H array of finite samples and a
        /// grid shape the GPU buffers can hold (<see cref="GpuLayout.CheckSize"/>).
        /// </summary>
        public static void CheckInputs(double[] heights, int width, int height, int columns, int rows)
        {
            CheckHeights(heights, width, height);
            GpuLayout.CheckSize(columns, rows);   // the GPU's patch limit, before anything is allocated
        }

        static HeightmapFit FitChecked(double[] heights, int width, int height, int columns, int rows, HeightmapFit west,
            IProgress<float> progress, CancellationToken ct)
        {
            var bx = new C1SplineBasis(columns);
            var by = new C1SplineBasis(rows);
            int nx = bx.Count, ny = by.Count;

            // Per-column spans and weights, shared by both passes.
            var xSpan = new int[width];
            var xw = new double[4 * width];
            for (int c = 0; c < width; c++) xSpan[c] = bx.Weights(c, width, new Span<double>(xw, 4 * c, 4));

            // 1. Right-hand side V = S_y^T Z S_x (ny x nx), one row of samples at a time.
            var v = new double[ny * nx];
            var u = new double[nx];
            Span<double> wy = stackalloc double[4];
            for (int r = 0; r < height; r++)
            {
                if ((r & 63) == 0)
                {
                    ct.ThrowIfCancellationRequested();
                    progress?.Report(0.45f * r / height);
                }
                Array.Clear(u, 0, nx);
                int row = r * width;
                for (int c = 0; c < width; c++)
                {
                    double z = heights[row + c];
                    int o = 2 * xSpan[c], w = 4 * c;
                    u[o] += xw[w] * z;
                    u[o + 1] += xw[w + 1] * z;
                    u[o + 2] += xw[w + 2] * z;
                    u[o + 3] += xw[w + 3] * z;
                }
                int sy = by.Weights(r, height, wy);
                for (int p = 0; p < 4; p++)
                {
                    double f = wy[p];
                    int dst = (2 * sy + p) * nx;
                    for (int k = 0; k < nx; k++) v[dst + k] += f * u[k];
                }
            }
            ct.ThrowIfCancellationRequested();

            // 2. C = G_y^-1 V G_x^-1: the y solve on whole rows, then the x solve row by row.
            by.NormalMatrix(height).SolveRows(v, nx);
            BandedCholesky gx = bx.NormalMatrix(width);
            if (west == null)
            {
                for (int ky = 0; ky < ny; ky++) gx.Solve(new Span<double>(v, ky * nx, nx));
            }
            else
            {
                SolveWithFixedStart(gx, v, ny, nx, WestEdge(west, width, columns));
            }
            var surface = new SplineSurface(bx, by, v);
            progress?.Report(0.5f);

            // 3. The grid: the spline's Bezier patches, C1 and so G1 by construction (see the class
            // comment for why G1Builder.MakeG1 is not run here).
            ct.ThrowIfCancellationRequested();
            PatchGrid grid = surface.ToPatchGrid();
            progress?.Report(0.55f);

            // 4. Error at every sample, from the spline (the grid's patches are its Bezier patches).
            var map = new FitErrorMap(width, height);
            var q = new double[nx];
            double max = 0, sum2 = 0;
            for (int r = 0; r < height; r++)
            {
                if ((r & 63) == 0)
                {
                    ct.ThrowIfCancellationRequested();
                    progress?.Report(0.55f + 0.45f * r / height);
                }
                int sy = by.Weights(r, height, wy);
                for (int k = 0; k < nx; k++)
                    q[k] = wy[0] * v[(2 * sy) * nx + k] + wy[1] * v[(2 * sy + 1) * nx + k]
                         + wy[2] * v[(2 * sy + 2) * nx + k] + wy[3] * v[(2 * sy + 3) * nx + k];
                double rowSum = 0;
                int row = r * width;
                for (int c = 0; c < width; c++)
                {
                    int o = 2 * xSpan[c], w = 4 * c;
                    double f = xw[w] * q[o] + xw[w + 1] * q[o + 1] + xw[w + 2] * q[o + 2] + xw[w + 3] * q[o + 3];
                    double e = Math.Abs(f - heights[row + c]);
                    if (e > max) max = e;
                    rowSum += e * e;
                    map.Add(map.CellOf(c, r), e);
                }
                sum2 += rowSum;
            }
            progress?.Report(1f);
            return new HeightmapFit(grid, max, Math.Sqrt(sum2 / ((double)width * height)), map, surface, width, height);
        }

        /// <summary>
        /// The west fit's last knot column (z, d per y coefficient), d rescaled to this fit's span:
        /// d = (span / 3) slope, and spans differ when the tiles' samples per patch differ.
        /// </summary>
        static double[] WestEdge(HeightmapFit west, int width, int columns)
        {
            SplineSurface s = west.Surface;
            int wnx = s.X.Count, ny = s.Y.Count;
            double ratio = ((double)(width - 1) / columns) / ((double)(west.SampleWidth - 1) / s.X.Spans);
            var edge = new double[2 * ny];
            for (int ky = 0; ky < ny; ky++)
            {
                edge[2 * ky] = s.Coefficients[ky * wnx + wnx - 2];
                edge[2 * ky + 1] = s.Coefficients[ky * wnx + wnx - 1] * ratio;
            }
            return edge;
        }

        /// <summary>
        /// Row by row, solves <c>G_x c = rhs</c> with c[0], c[1] held at the given values: the free
        /// part solves <c>G_x[2.., 2..] c_free = rhs[2..] - G_x[2.., 0..1] c_fixed</c>, which is the
        /// least-squares optimum over the free coefficients (the y solve before it is unchanged).
        /// </summary>
        static void SolveWithFixedStart(BandedCholesky gx, double[] v, int ny, int nx, double[] fixedStart)
        {
            int n = nx - 2;
            var reduced = new BandedCholesky(n, C1SplineBasis.Bandwidth);
            for (int i = 0; i < n; i++)
                for (int k = 0; k <= C1SplineBasis.Bandwidth && i + k < n; k++)
                    reduced.Add(i, i + k, gx.Get(i + 2, i + k + 2));
            var coupling = new double[2 * 2];   // G_x(2 + i, f) for i = 0, 1 (rows 4.. are outside the band)
            for (int i = 0; i < 2; i++)
                for (int f = 0; f < 2; f++) coupling[2 * i + f] = gx.Get(2 + i, f);
            var rhs = new double[n];
            for (int ky = 0; ky < ny; ky++)
            {
                double z0 = fixedStart[2 * ky], d0 = fixedStart[2 * ky + 1];
                for (int i = 0; i < n; i++) rhs[i] = v[ky * nx + 2 + i];
                for (int i = 0; i < 2 && i < n; i++) rhs[i] -= coupling[2 * i] * z0 + coupling[2 * i + 1] * d0;
                reduced.Solve(rhs);
                v[ky * nx] = z0;
                v[ky * nx + 1] = d0;
                for (int i = 0; i < n; i++) v[ky * nx + 2 + i] = rhs[i];
            }
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
