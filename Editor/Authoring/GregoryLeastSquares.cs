using System;
using System.Collections.Generic;
using System.Numerics;
using System.Runtime.InteropServices;
using System.Threading;

namespace GregoryTerrain
{
    /// <summary>
    /// Least squares over every sample of a W x H heightmap (sample (c, r) at
    /// <c>(c/(W-1), r/(H-1))</c>) in the space of <see cref="GregoryNet"/>: minimises
    /// <c>sum_s w_s (S x - z)_s^2 + mu |x - x0|^2</c> by conjugate gradients on the normal equations
    /// (all weights w_s 1 unless <see cref="Reweight"/> raised some).
    /// The matrix is never stored (one 20 x 20 Gram matrix per class of patches with the same sample
    /// offsets; a reweighted patch gets its own), the passes are separable, block-Jacobi preconditioned
    /// CG runs from x0, the C1 spline fit, and every sum runs in a fixed order whatever the SIMD width
    /// (<c>Vector&lt;double&gt;</c> lane by lane, never across lanes), so the fit is the same to the
    /// bit on any SIMD width: Tools~/docs/design-notes.md, "Fitting: how the solve runs" and "Fitting: the ridge and G1".
    /// </summary>
    internal sealed class GregoryLeastSquares
    {
        /// <summary>mu as a fraction of the mean diagonal of the data's normal matrix.</summary>
        public const double RidgeWeight = 1e-6;
        /// <summary>
        /// CG stops when the residual's norm is this fraction of the first solve's initial one (or at
        /// <see cref="MaxIterations"/>). Looser moves the weakly determined directions of the net first.
        /// </summary>
        public const double Tolerance = 1e-4;
        /// <summary>The most CG iterations: bounds the time where the data barely determine the net.</summary>
        public const int MaxIterations = 200;
        /// <summary>Rational-weight tables are cached up to this many doubles (32 MiB); beyond, recomputed per patch.</summary>
        const long TableCacheDoubles = 4L << 20;

        const int L = GregoryNet.LocalCount;
        // Gram rows are Stride doubles (20 rounded up to the SIMD width).
        static readonly int Lanes = Vector<double>.Count;
        static readonly int Stride = (L + Lanes - 1) / Lanes * Lanes;
        // The pairs' slots: first point (grid slot 4 a + b) and second point (16 + ...), pair p = 0..3.
        static readonly int[] FirstSlot = { 5, 6, 9, 10 };
        static readonly int[] SecondSlot = { 16, 17, 18, 19 };

        readonly GregoryNet net;
        readonly int width, height;
        readonly Axis xAxis, yAxis;
        readonly double[][] rational, grams;
        readonly bool cacheTables;
        double[] scratch;
        // Reweighted patches: ownOf[patch] indexes ownGrams and extra (-1: the class's Gram).
        int[] ownOf;
        readonly List<double[]> ownGrams = new List<double[]>();
        readonly List<List<(int sample, double weight)>> extra = new List<List<(int, double)>>();
        readonly List<int> ownPatch = new List<int>();

        public GregoryNet Net => net;
        /// <summary>Iterations the last <see cref="Solve"/> took.</summary>
        public int Iterations { get; private set; }
        /// <summary>Samples whose weight <see cref="Reweight"/> has raised above 1.</summary>
        public int ReweightedSamples { get; private set; }

        /// <summary>
        /// Where one axis's samples fall: per patch its first sample and class; per class the offsets
        /// and Bernstein weights. Classes with the same first offset form a group sharing the longest
        /// class's rational-weight table.
        /// </summary>
        sealed class Axis
        {
            public int[] First, Count, Class;
            public List<double[]> Offsets = new List<double[]>();
            /// <summary>Per class, B_0..B_3 at each offset: [4 a + k].</summary>
            public List<double[]> Bernstein = new List<double[]>();
            /// <summary>Per class its group; per group the class with the most samples.</summary>
            public List<int> Group = new List<int>(), Longest = new List<int>();

            public Axis(int samples, int spans)
            {
                First = new int[spans];
                Count = new int[spans];
                Class = new int[spans];
                long n = samples - 1;
                var key = new Dictionary<long, int>();
                var group = new Dictionary<long, int>();
                Span<double> b = stackalloc double[4], d = stackalloc double[4];
                for (int i = 0; i < spans; i++)
                {
                    // First sample c with c P >= i (W - 1); integer arithmetic so knots land exactly.
                    long c0 = (i * n + spans - 1) / spans;
                    long c1 = i == spans - 1 ? samples : ((i + 1) * n + spans - 1) / spans;
                    First[i] = (int)c0;
                    Count[i] = (int)(c1 - c0);
                    long num0 = c0 * spans - i * n;
                    long k = num0 * (samples + 1L) + Count[i];
                    if (!key.TryGetValue(k, out int cls))
                    {
                        cls = Offsets.Count;
                        key.Add(k, cls);
                        var t = new double[Count[i]];
                        var bt = new double[4 * Count[i]];
                        for (int a = 0; a < t.Length; a++)
                        {
                            t[a] = (double)(num0 + (long)a * spans) / n;
                            GregoryBasis.Bernstein(GMath.saturate(t[a]), b, d);
                            for (int q = 0; q < 4; q++) bt[4 * a + q] = b[q];
                        }
                        Offsets.Add(t);
                        Bernstein.Add(bt);
                        if (!group.TryGetValue(num0, out int g))
                        {
                            g = Longest.Count;
                            group.Add(num0, g);
                            Longest.Add(cls);
                        }
                        Group.Add(g);
                        if (Count[i] > Offsets[Longest[g]].Length) Longest[g] = cls;
                    }
                    Class[i] = cls;
                }
            }
        }

        public GregoryLeastSquares(GregoryNet net, int width, int height)
        {
            this.net = net;
            this.width = width;
            this.height = height;
            xAxis = new Axis(width, net.Columns);
            yAxis = new Axis(height, net.Rows);
            grams = new double[xAxis.Offsets.Count * yAxis.Offsets.Count][];
            rational = new double[xAxis.Longest.Count * yAxis.Longest.Count][];
            long tableDoubles = 0;
            foreach (int cu in xAxis.Longest)
                foreach (int cv in yAxis.Longest) tableDoubles += 4L * xAxis.Offsets[cu].Length * yAxis.Offsets[cv].Length;
            cacheTables = tableDoubles <= TableCacheDoubles;
        }

        int Pair(int i, int j) => yAxis.Class[j] * xAxis.Offsets.Count + xAxis.Class[i];

        /// <summary>Patch (i, j)'s Gram matrix: its own when reweighted, else its class's.</summary>
        double[] GramOf(int i, int j)
        {
            if (ownOf != null)
            {
                int o = ownOf[j * net.Columns + i];
                if (o >= 0) return ownGrams[o];
            }
            return grams[Pair(i, j)] ?? throw new InvalidOperationException("RightHandSide builds the Gram matrices first.");
        }

        /// <summary>
        /// The rational weights of the 4 pairs' first points at every sample of patch (i, j),
        /// [4 (b stride + a) + p] (the group's table, <see cref="Axis"/>); builds the class's Gram
        /// matrix the first time it is seen.
        /// </summary>
        double[] Rational(int i, int j, out int stride)
        {
            int pair = Pair(i, j), cx = xAxis.Class[i], cy = yAxis.Class[j];
            if (grams[pair] == null) grams[pair] = BuildGram(xAxis.Offsets[cx], yAxis.Offsets[cy]);
            int gx = xAxis.Group[cx], gy = yAxis.Group[cy], table = gy * xAxis.Longest.Count + gx;
            double[] us = xAxis.Offsets[xAxis.Longest[gx]], vs = yAxis.Offsets[yAxis.Longest[gy]];
            stride = us.Length;
            if (rational[table] != null) return rational[table];
            int n = 4 * us.Length * vs.Length;
            double[] t;
            if (cacheTables) t = new double[n];
            else
            {
                if (scratch == null || scratch.Length < n) scratch = new double[n];
                t = scratch;
            }
            Span<double> w = stackalloc double[GregoryBasis.WeightCount];
            Span<double> wu = stackalloc double[GregoryBasis.WeightCount];
            Span<double> wv = stackalloc double[GregoryBasis.WeightCount];
            for (int b = 0; b < vs.Length; b++)
                for (int a = 0; a < us.Length; a++)
                {
                    GregoryBasis.Weights(us[a], vs[b], w, wu, wv);
                    int s = 4 * (b * us.Length + a);
                    for (int p = 0; p < 4; p++) t[s + p] = w[FirstSlot[p]];
                }
            if (cacheTables) rational[table] = t;
            return t;
        }

        /// <summary>One class's Gram matrix, row k at k Stride, summed in sample order lane by lane.</summary>
        static double[] BuildGram(double[] us, double[] vs)
        {
            var g = new double[L * Stride];
            var w = new double[Stride];
            for (int b = 0; b < vs.Length; b++)
                for (int a = 0; a < us.Length; a++)
                {
                    GregoryNet.LocalWeights(us[a], vs[b], new Span<double>(w, 0, L));
                    for (int k = 0; k < L; k++)
                    {
                        var f = new Vector<double>(w[k]);
                        int c = k * Stride;
                        for (int v = 0; v < Stride; v += Lanes) (new Vector<double>(g, c + v) + f * new Vector<double>(w, v)).CopyTo(g, c + v);
                    }
                }
            return g;
        }

        /// <summary>
        /// <c>S^T z</c> in one pass over the samples, building the Gram matrices on the way. Progress
        /// runs from <paramref name="p0"/> to <paramref name="p1"/>.
        /// </summary>
        public double[] RightHandSide(double[] heights, IProgress<float> progress, float p0, float p1, CancellationToken ct)
        {
            var rhs = new double[net.Count];
            Span<int> index = stackalloc int[L];
            Span<double> m = stackalloc double[16];
            Span<double> slot = stackalloc double[GregoryPatch.SlotCount];
            Span<double> local = stackalloc double[L];
            for (int j = 0; j < net.Rows; j++)
            {
                ct.ThrowIfCancellationRequested();
                progress?.Report(p0 + (p1 - p0) * j / net.Rows);
                int r0 = yAxis.First[j], rn = yAxis.Count[j];
                double[] bv = yAxis.Bernstein[yAxis.Class[j]];
                for (int i = 0; i < net.Columns; i++)
                {
                    double[] t = Rational(i, j, out int stride);
                    double[] bu = xAxis.Bernstein[xAxis.Class[i]];
                    int c0 = xAxis.First[i], cn = xAxis.Count[i];
                    m.Clear();
                    double n0 = 0, n1 = 0, n2 = 0, n3 = 0;
                    for (int b = 0; b < rn; b++)
                    {
                        long row = (long)(r0 + b) * width + c0;
                        int ts = 4 * b * stride;
                        double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
                        for (int a = 0; a < cn; a++)
                        {
                            double z = heights[row + a];
                            int o = 4 * a, q = ts + o;
                            s0 += bu[o] * z; s1 += bu[o + 1] * z; s2 += bu[o + 2] * z; s3 += bu[o + 3] * z;
                            n0 += t[q] * z; n1 += t[q + 1] * z; n2 += t[q + 2] * z; n3 += t[q + 3] * z;
                        }
                        // Moment of grid slot (ka, kb) at 4 ka + kb: sum of B_ka(u) B_kb(v) z.
                        int vb = 4 * b;
                        for (int kb = 0; kb < 4; kb++)
                        {
                            double f = bv[vb + kb];
                            m[kb] += s0 * f; m[4 + kb] += s1 * f; m[8 + kb] += s2 * f; m[12 + kb] += s3 * f;
                        }
                    }
                    for (int k = 0; k < 16; k++) slot[k] = m[k];
                    // A pair's first point takes B B t, its second B B (1 - t) = B B - B B t.
                    ReadOnlySpan<double> nf = stackalloc double[] { n0, n1, n2, n3 };
                    for (int p = 0; p < 4; p++)
                    {
                        slot[FirstSlot[p]] = nf[p];
                        slot[SecondSlot[p]] = m[FirstSlot[p]] - nf[p];
                    }
                    local.Clear();
                    GregoryNet.SlotsToLocal(slot, local);
                    net.LocalUnknowns(i, j, index);
                    for (int k = 0; k < L; k++) rhs[index[k]] += local[k];
                }
            }
            return rhs;
        }

        /// <summary>
        /// y = A p (the data's normal matrix only): per patch, gather 20, multiply by its Gram, scatter.
        /// The local unknowns are five runs of consecutive indices (<see cref="GregoryNet.LocalUnknowns"/>).
        /// </summary>
        void Multiply(double[] p, double[] y)
        {
            Array.Clear(y, 0, y.Length);
            Span<double> local = stackalloc double[L];
            Span<double> acc = stackalloc double[Stride];
            int columns = net.Columns, xClasses = xAxis.Offsets.Count;
            int[] xClass = xAxis.Class;
            for (int j = 0; j < net.Rows; j++)
            {
                int v0 = net.Vertex(0, j), v1 = net.Vertex(0, j + 1);
                int eb = net.HorizontalEdge(0, j), et = net.HorizontalEdge(0, j + 1), el = net.VerticalEdge(0, j);
                int pairRow = yAxis.Class[j] * xClasses;
                for (int i = 0; i < columns; i++)
                {
                    double[] g = ownOf != null && ownOf[j * columns + i] >= 0 ? ownGrams[ownOf[j * columns + i]] : grams[pairRow + xClass[i]];
                    int a = v0 + 3 * i, b = v1 + 3 * i, c = eb + 2 * i, d = et + 2 * i, e = el + 2 * i;
                    p.AsSpan(a, 6).CopyTo(local);
                    p.AsSpan(b, 6).CopyTo(local.Slice(6));
                    local[12] = p[c]; local[13] = p[c + 1];
                    local[14] = p[d]; local[15] = p[d + 1];
                    p.AsSpan(e, 4).CopyTo(local.Slice(16));
                    if (Stride == 5 * Lanes)
                    {
                        // 4 lanes: five accumulators in registers; lane q is entry q of G p, summed over k in order.
                        ReadOnlySpan<Vector<double>> gv = MemoryMarshal.Cast<double, Vector<double>>(new ReadOnlySpan<double>(g, 0, L * Stride));
                        Vector<double> a0 = Vector<double>.Zero, a1 = a0, a2 = a0, a3 = a0, a4 = a0;
                        for (int k = 0; k < L; k++)
                        {
                            var f = new Vector<double>(local[k]);
                            int o = 5 * k;
                            a0 += gv[o] * f;
                            a1 += gv[o + 1] * f;
                            a2 += gv[o + 2] * f;
                            a3 += gv[o + 3] * f;
                            a4 += gv[o + 4] * f;
                        }
                        Span<Vector<double>> av = MemoryMarshal.Cast<double, Vector<double>>(acc);
                        av[0] = a0; av[1] = a1; av[2] = a2; av[3] = a3; av[4] = a4;
                    }
                    else
                    {
                        // Any other width: the same sums, entry by entry, in the same order.
                        for (int q = 0; q < L; q++)
                        {
                            double sum = 0;
                            for (int k = 0; k < L; k++) sum += g[k * Stride + q] * local[k];
                            acc[q] = sum;
                        }
                    }
                    Span<double> ya = y.AsSpan(a, 6), yb = y.AsSpan(b, 6), ye = y.AsSpan(e, 4);
                    for (int q = 0; q < 6; q++) ya[q] += acc[q];
                    for (int q = 0; q < 6; q++) yb[q] += acc[6 + q];
                    y[c] += acc[12]; y[c + 1] += acc[13];
                    y[d] += acc[14]; y[d + 1] += acc[15];
                    for (int q = 0; q < 4; q++) ye[q] += acc[16 + q];
                }
            }
        }

        // Preconditioner blocks: local unknowns 0..11 are 4 vertices of 3, 12..19 four edges of 2
        // (GregoryNet.LocalUnknowns); plain Jacobi would need hundreds of iterations.
        static readonly int[] BlockStart = { 0, 3, 6, 9, 12, 14, 16, 18 };
        static readonly int[] BlockSize = { 3, 3, 3, 3, 2, 2, 2, 2 };

        /// <summary>Where unknown k's block starts in the block store (vertices 9 doubles, edges 4), and its first unknown and size.</summary>
        int BlockOf(int k, out int first, out int size)
        {
            int vb = net.VerticalBase;
            if (k < vb) { first = k - k % 3; size = 3; return 3 * first; }
            first = k - (k - vb) % 2; size = 2;
            return 3 * vb + 2 * (first - vb);
        }

        double[] BlockInverses(double mu)
        {
            int vb = net.VerticalBase;
            if (blockStore == null) blockStore = new double[3 * vb + 2 * (net.Count - vb)];
            else Array.Clear(blockStore, 0, blockStore.Length);
            double[] blocks = blockStore;
            Span<int> index = stackalloc int[L];
            for (int j = 0; j < net.Rows; j++)
                for (int i = 0; i < net.Columns; i++)
                {
                    double[] g = GramOf(i, j);
                    net.LocalUnknowns(i, j, index);
                    for (int bl = 0; bl < BlockStart.Length; bl++)
                    {
                        int l0 = BlockStart[bl], m = BlockSize[bl];
                        int at = BlockOf(index[l0], out _, out _);
                        for (int a = 0; a < m; a++)
                            for (int b = 0; b < m; b++) blocks[at + a * m + b] += g[(l0 + a) * Stride + l0 + b];
                    }
                }
            Span<double> m3 = stackalloc double[9];
            for (int k = 0; k < net.Count;)
            {
                int at = BlockOf(k, out _, out int m);
                for (int a = 0; a < m; a++) blocks[at + a * m + a] += mu;
                Invert(new Span<double>(blocks, at, m * m), m, m3);
                k += m;
            }
            return blocks;
        }

        /// <summary>Inverts a symmetric positive definite 2x2 or 3x3 block in place (cofactors).</summary>
        static void Invert(Span<double> a, int m, Span<double> t)
        {
            if (m == 2)
            {
                double det = a[0] * a[3] - a[1] * a[2];
                double a0 = a[0];
                a[0] = a[3] / det; a[3] = a0 / det;
                a[1] = -a[1] / det; a[2] = -a[2] / det;
                return;
            }
            t[0] = a[4] * a[8] - a[5] * a[7];
            t[1] = a[2] * a[7] - a[1] * a[8];
            t[2] = a[1] * a[5] - a[2] * a[4];
            t[3] = a[5] * a[6] - a[3] * a[8];
            t[4] = a[0] * a[8] - a[2] * a[6];
            t[5] = a[2] * a[3] - a[0] * a[5];
            t[6] = a[3] * a[7] - a[4] * a[6];
            t[7] = a[1] * a[6] - a[0] * a[7];
            t[8] = a[0] * a[4] - a[1] * a[3];
            double d = a[0] * t[0] + a[1] * t[3] + a[2] * t[6];
            for (int k = 0; k < 9; k++) a[k] = t[k] / d;
        }

        double mu = -1;
        // The first solve's initial residual norm: what every solve's stop is relative to.
        double firstResidual = -1;
        // CG's vectors and the blocks: allocated by the first solve, reused by reweighting rounds.
        double[] cgR, cgQ, cgZ, cgP, blockStore;

        /// <summary>Drops CG's vectors and blocks, so the grid that follows can reuse the memory.</summary>
        public void ReleaseWorkspace() => cgR = cgQ = cgZ = cgP = blockStore = null;

        /// <summary>
        /// One CG update in one sweep, block by block: x += alpha p, r -= alpha q, z = B^-1 r (0 on
        /// fixed unknowns), the sums r.r and r.z in unknown order. One sweep, not four: memory bound.
        /// </summary>
        void Step(double[] blocks, double alpha, double[] x, double[] p, double[] q, double[] r, double[] z, bool[] fixedMask,
            out double rr, out double rz)
        {
            int vb = net.VerticalBase, n = net.Count;
            rr = 0;
            rz = 0;
            for (int k = 0; k < vb; k += 3)
            {
                x[k] += alpha * p[k]; x[k + 1] += alpha * p[k + 1]; x[k + 2] += alpha * p[k + 2];
                double r0 = r[k] - alpha * q[k], r1 = r[k + 1] - alpha * q[k + 1], r2 = r[k + 2] - alpha * q[k + 2];
                r[k] = r0; r[k + 1] = r1; r[k + 2] = r2;
                rr += r0 * r0; rr += r1 * r1; rr += r2 * r2;
                int at = 3 * k;
                double z0 = blocks[at] * r0 + blocks[at + 1] * r1 + blocks[at + 2] * r2;
                double z1 = blocks[at + 3] * r0 + blocks[at + 4] * r1 + blocks[at + 5] * r2;
                double z2 = blocks[at + 6] * r0 + blocks[at + 7] * r1 + blocks[at + 8] * r2;
                if (fixedMask != null)
                {
                    if (fixedMask[k]) z0 = 0;
                    if (fixedMask[k + 1]) z1 = 0;
                    if (fixedMask[k + 2]) z2 = 0;
                }
                z[k] = z0; z[k + 1] = z1; z[k + 2] = z2;
                rz += r0 * z0; rz += r1 * z1; rz += r2 * z2;
            }
            for (int k = vb; k < n; k += 2)
            {
                x[k] += alpha * p[k]; x[k + 1] += alpha * p[k + 1];
                double r0 = r[k] - alpha * q[k], r1 = r[k + 1] - alpha * q[k + 1];
                r[k] = r0; r[k + 1] = r1;
                rr += r0 * r0; rr += r1 * r1;
                int at = 3 * vb + 2 * (k - vb);
                double z0 = blocks[at] * r0 + blocks[at + 1] * r1;
                double z1 = blocks[at + 2] * r0 + blocks[at + 3] * r1;
                if (fixedMask != null)
                {
                    if (fixedMask[k]) z0 = 0;
                    if (fixedMask[k + 1]) z1 = 0;
                }
                z[k] = z0; z[k + 1] = z1;
                rz += r0 * z0; rz += r1 * z1;
            }
        }

        /// <summary>
        /// Solves <c>(A + mu I) x = rhs + mu prior</c> by preconditioned CG from <paramref name="x"/>
        /// (overwritten and returned). Unknowns with <paramref name="fixedMask"/> set keep their start
        /// values. prior may be x itself.
        /// </summary>
        public double[] Solve(double[] rhs, double[] x, double[] prior, bool[] fixedMask, IProgress<float> progress, float p0, float p1, CancellationToken ct)
        {
            int n = net.Count;
            if (mu < 0)
            {
                // Mean diagonal of the unweighted A sets mu, once: reweighting does not move the ridge.
                double trace = 0;
                for (int j = 0; j < net.Rows; j++)
                    for (int i = 0; i < net.Columns; i++)
                    {
                        double[] g = grams[Pair(i, j)] ?? throw new InvalidOperationException("RightHandSide builds the Gram matrices first.");
                        for (int k = 0; k < L; k++) trace += g[k * Stride + k];
                    }
                double mean = trace / n;
                mu = RidgeWeight * (mean > 0 ? mean : 1);
            }
            double[] blocks = BlockInverses(mu);

            if (cgR == null)
            {
                cgR = new double[n]; cgQ = new double[n]; cgZ = new double[n]; cgP = new double[n];
            }
            double[] r = cgR, q = cgQ, z = cgZ, p = cgP;
            Multiply(x, q);
            // r = rhs + mu prior - (A + mu) x.
            for (int k = 0; k < n; k++) r[k] = fixedMask != null && fixedMask[k] ? 0 : rhs[k] - q[k] + mu * (prior[k] - x[k]);
            // z = B^-1 r, p = z. p is cleared first: the last solve's p may hold NaN, and 0 * NaN is NaN.
            Array.Clear(p, 0, n);
            Step(blocks, 0, x, p, q, r, z, fixedMask, out double r0, out double rz);
            Array.Copy(z, p, n);
            r0 = Math.Sqrt(r0);
            // Relative to the first solve's residual: a reweighting round starts near the answer.
            if (firstResidual < 0) firstResidual = r0;
            double stop = Tolerance * Math.Max(r0, firstResidual);
            int it = 0;
            double rn = r0, done = 0;
            while (rn > stop && it < MaxIterations)
            {
                if ((it & 7) == 0)
                {
                    ct.ThrowIfCancellationRequested();
                    // CG's residual is not monotone: report the best fraction of the way so far.
                    done = Math.Max(done, Math.Min(1.0, Math.Log(r0 / rn) / Math.Log(r0 / stop)));
                    progress?.Report(p0 + (p1 - p0) * (float)done);
                }
                Multiply(p, q);
                double pq = 0;
                for (int k = 0; k < n; k++)
                {
                    if (fixedMask != null && fixedMask[k]) q[k] = 0;
                    else q[k] += mu * p[k];
                    pq += p[k] * q[k];
                }
                if (!(pq > 0)) break;   // converged to rounding: p is (numerically) zero
                double alpha = rz / pq;
                Step(blocks, alpha, x, p, q, r, z, fixedMask, out double rr, out double rzNew);
                double beta = rzNew / rz;
                rz = rzNew;
                for (int k = 0; k < n; k++) p[k] = z[k] + beta * p[k];
                rn = Math.Sqrt(rr);
                it++;
            }
            Iterations = it;
            progress?.Report(p1);
            return x;
        }

        /// <summary>
        /// The error of the net x at every sample: max, RMS, and the binned picture (none when
        /// <paramref name="map"/> is null); samples whose |error| exceeds <paramref name="collectAbove"/>
        /// go to <paramref name="collected"/> (patch, sample within the patch row-major, |error|).
        /// </summary>
        public void Errors(double[] heights, double[] x, FitErrorMap map, out double max, out double rms,
            double collectAbove, List<(int patch, int sample, double error)> collected,
            IProgress<float> progress, float p0, float p1, CancellationToken ct)
        {
            // The map's cell of (c, r) is rowCell[r] + colCell[c]: no divisions per sample.
            var colCell = new int[width];
            var rowCell = new int[height];
            if (map != null)
            {
                for (int c = 0; c < width; c++) colCell[c] = map.CellOf(c, 0);
                for (int r = 0; r < height; r++) rowCell[r] = map.CellOf(0, r);
            }
            Span<int> index = stackalloc int[L];
            Span<double> local = stackalloc double[L];
            Span<double> slot = stackalloc double[GregoryPatch.SlotCount];
            Span<double> d = stackalloc double[4];
            max = 0;
            double sum2 = 0;
            float[] cells = map?.Cells;
            for (int j = 0; j < net.Rows; j++)
            {
                ct.ThrowIfCancellationRequested();
                progress?.Report(p0 + (p1 - p0) * j / net.Rows);
                int r0 = yAxis.First[j], rn = yAxis.Count[j];
                double[] bv = yAxis.Bernstein[yAxis.Class[j]];
                for (int i = 0; i < net.Columns; i++)
                {
                    double[] t = Rational(i, j, out int stride);
                    double[] bu = xAxis.Bernstein[xAxis.Class[i]];
                    int c0 = xAxis.First[i], cn = xAxis.Count[i];
                    net.LocalUnknowns(i, j, index);
                    for (int k = 0; k < L; k++) local[k] = x[index[k]];
                    GregoryNet.SlotHeights(local, slot);
                    // The tensor product takes the second points; each pair adds B B t (first - second).
                    for (int p = 0; p < 4; p++)
                    {
                        d[p] = slot[FirstSlot[p]] - slot[SecondSlot[p]];
                        slot[FirstSlot[p]] = slot[SecondSlot[p]];
                    }
                    double d0 = d[0], d1 = d[1], d2 = d[2], d3 = d[3], patchSum = 0, patchMax = max;
                    int patch = j * net.Columns + i;
                    for (int b = 0; b < rn; b++)
                    {
                        int vb = 4 * b;
                        double q0 = slot[0] * bv[vb] + slot[1] * bv[vb + 1] + slot[2] * bv[vb + 2] + slot[3] * bv[vb + 3];
                        double q1 = slot[4] * bv[vb] + slot[5] * bv[vb + 1] + slot[6] * bv[vb + 2] + slot[7] * bv[vb + 3];
                        double q2 = slot[8] * bv[vb] + slot[9] * bv[vb + 1] + slot[10] * bv[vb + 2] + slot[11] * bv[vb + 3];
                        double q3 = slot[12] * bv[vb] + slot[13] * bv[vb + 1] + slot[14] * bv[vb + 2] + slot[15] * bv[vb + 3];
                        long row = (long)(r0 + b) * width + c0;
                        int ts = 4 * b * stride, cellRow = rowCell[r0 + b];
                        for (int a = 0; a < cn; a++)
                        {
                            int o = 4 * a, q = ts + o;
                            double f = bu[o] * q0 + bu[o + 1] * q1 + bu[o + 2] * q2 + bu[o + 3] * q3
                                     + t[q] * d0 + t[q + 1] * d1 + t[q + 2] * d2 + t[q + 3] * d3;
                            double e = Math.Abs(f - heights[row + a]);
                            if (e > patchMax) patchMax = e;
                            patchSum += e * e;
                            if (cells != null)
                            {
                                // A conditional move: on a fresh map a branch here mispredicts.
                                int cell = cellRow + colCell[c0 + a];
                                float fe = (float)e, was = cells[cell];
                                cells[cell] = fe > was ? fe : was;
                            }
                            if (e > collectAbove) collected.Add((patch, b * cn + a, e));
                        }
                    }
                    max = patchMax;
                    sum2 += patchSum;
                }
            }
            rms = Math.Sqrt(sum2 / ((double)width * height));
            progress?.Report(p1);
        }

        /// <summary>
        /// Raises the given samples' weights by <c>(error / tau)^2</c> (Lawson's rule toward the min-max
        /// fit, squared for fewer rounds) and writes the weighted right-hand side into
        /// <paramref name="weighted"/> (<paramref name="rhs"/> plus the extra terms). Each patch with a
        /// raised weight gets its own Gram matrix: its class's plus <c>sum (w - 1) l l^T</c>.
        /// </summary>
        public void Reweight(double[] heights, double[] rhs, List<(int patch, int sample, double error)> samples, double tau, double[] weighted)
        {
            if (ownOf == null)
            {
                ownOf = new int[net.Columns * net.Rows];
                for (int k = 0; k < ownOf.Length; k++) ownOf[k] = -1;
            }
            foreach ((int patch, int sample, double error) in samples)
            {
                int o = ownOf[patch];
                if (o < 0)
                {
                    o = ownOf[patch] = ownGrams.Count;
                    ownGrams.Add(null);
                    extra.Add(new List<(int, double)>());
                    ownPatch.Add(patch);
                }
                List<(int sample, double weight)> list = extra[o];
                double g = error / tau;
                int at = list.FindIndex(e => e.sample == sample);
                if (at < 0) list.Add((sample, g * g));
                else list[at] = (sample, list[at].weight * g * g);
            }
            Array.Copy(rhs, weighted, rhs.Length);
            Span<int> index = stackalloc int[L];
            var w = new double[L];
            int count = 0;
            for (int o = 0; o < ownGrams.Count; o++)
            {
                int patch = ownPatch[o], i = patch % net.Columns, j = patch / net.Columns;
                double[] us = xAxis.Offsets[xAxis.Class[i]], vs = yAxis.Offsets[yAxis.Class[j]];
                var g = (double[])grams[Pair(i, j)].Clone();
                net.LocalUnknowns(i, j, index);
                foreach ((int sample, double weight) in extra[o])
                {
                    int a = sample % us.Length, b = sample / us.Length;
                    GregoryNet.LocalWeights(us[a], vs[b], w);
                    double z = heights[(long)(yAxis.First[j] + b) * width + xAxis.First[i] + a], e = weight - 1;
                    for (int k = 0; k < L; k++)
                    {
                        weighted[index[k]] += e * w[k] * z;
                        for (int q = 0; q < L; q++) g[k * Stride + q] += e * w[k] * w[q];
                    }
                    count++;
                }
                ownGrams[o] = g;
            }
            ReweightedSamples = count;
        }
    }
}
