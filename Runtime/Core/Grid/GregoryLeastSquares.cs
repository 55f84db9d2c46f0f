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
    /// <c>|S x - z|^2 + mu |x - x0|^2</c> by conjugate gradients on the normal equations.
    /// <para><b>Normal matrix without storing it.</b> A patch's heights depend on its 20 local
    /// unknowns, so <c>A = sum over patches of E_p^T G_p E_p</c> with a 20 x 20 patch Gram matrix
    /// G_p. G_p depends only on where the samples fall inside the patch, and on a uniform grid that
    /// repeats: a column of patches is identified by its first sample's offset and its sample count,
    /// and when P divides W - 1 (8193 into 256) every patch has the same offsets. So the fitter keeps
    /// one Gram matrix and one weight table per distinct (column class, row class), at most
    /// <c>(P / gcd(P, W-1)) (Q / gcd(Q, H-1))</c> of them, and A p costs 400 multiply-adds a patch.
    /// (Worst case, every patch its own class: 3.2 KB a patch of Gram matrices.)</para>
    /// <para><b>The ridge.</b> mu (<see cref="RidgeWeight"/> of the mean diagonal) pulls toward x0,
    /// the C1 spline fit, only where the samples leave unknowns open (patches with fewer samples than
    /// unknowns, interior offsets whose weight is 0 at every sample): there the fit keeps the spline's
    /// values, which its own smoothing term chose. Elsewhere it moves the optimum by about mu.</para>
    /// <para><b>Preconditioner and stop.</b> Block Jacobi: the inverse of each vertex's 3 x 3 and each
    /// edge's 2 x 2 diagonal block (a height and the offsets next to it are strongly coupled). From x0
    /// (already the best C1 net) CG reaches a residual of <see cref="Tolerance"/> of the initial one
    /// in 40 to 70 iterations on the tests' data and the bench, 16 to 256 patches a side, where
    /// the reported max and RMS no longer change in their fourth digit (they are the same from 1e-3).
    /// With very few samples a patch (2 to 4 a side) the data barely tell some unknowns apart and CG
    /// would need hundreds of iterations; it stops at <see cref="MaxIterations"/>, and since every CG
    /// step lowers the objective the result still fits at least as well as the spline it started from.</para>
    /// </summary>
    internal sealed class GregoryLeastSquares
    {
        /// <summary>mu as a fraction of the mean diagonal of the data's normal matrix.</summary>
        public const double RidgeWeight = 1e-6;
        /// <summary>CG stops when the residual's norm is this fraction of the initial one (or at <see cref="MaxIterations"/>).</summary>
        public const double Tolerance = 1e-5;
        /// <summary>The most CG iterations: bounds the time where the data barely determine the net (see the class comment).</summary>
        public const int MaxIterations = 200;
        /// <summary>Weight tables are cached up to this many doubles (64 MiB); beyond, recomputed per patch.</summary>
        const long TableCacheDoubles = 8L << 20;

        // The hot loops run on Vector<double> (4 doubles at a time on AVX2): Gram rows are Stride
        // doubles (20 rounded up to the SIMD width), table rows a patch's samples rounded up likewise.
        static readonly int Lanes = Vector<double>.Count;
        static readonly int Stride = (GregoryNet.LocalCount + Lanes - 1) / Lanes * Lanes;

        readonly GregoryNet net;
        readonly int width, height;
        readonly Axis xAxis, yAxis;
        readonly double[][] tables, grams;
        readonly bool cacheTables;
        readonly int[] unknownsOf;   // patch (i, j)'s 20 global unknowns at (j P + i) 20
        double[] scratch;

        public GregoryNet Net => net;
        /// <summary>Iterations the last <see cref="Solve"/> took.</summary>
        public int Iterations { get; private set; }

        /// <summary>Where one axis's samples fall: per patch its first sample and class; per class the offsets.</summary>
        sealed class Axis
        {
            public int[] First, Count, Class;
            public List<double[]> Offsets = new List<double[]>();

            public Axis(int samples, int spans)
            {
                First = new int[spans];
                Count = new int[spans];
                Class = new int[spans];
                long n = samples - 1;
                var key = new Dictionary<long, int>();
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
                        for (int a = 0; a < t.Length; a++) t[a] = (double)(num0 + (long)a * spans) / n;
                        Offsets.Add(t);
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
            int pairs = xAxis.Offsets.Count * yAxis.Offsets.Count;
            tables = new double[pairs][];
            grams = new double[pairs][];
            long tableDoubles = 0;
            foreach (double[] u in xAxis.Offsets)
                foreach (double[] v in yAxis.Offsets) tableDoubles += ((long)u.Length * v.Length + Lanes) * GregoryNet.LocalCount;
            cacheTables = tableDoubles <= TableCacheDoubles;
            unknownsOf = new int[net.Columns * net.Rows * GregoryNet.LocalCount];
            for (int j = 0; j < net.Rows; j++)
                for (int i = 0; i < net.Columns; i++)
                    net.LocalUnknowns(i, j, new Span<int>(unknownsOf, (j * net.Columns + i) * GregoryNet.LocalCount, GregoryNet.LocalCount));
        }

        int Pair(int i, int j) => yAxis.Class[j] * xAxis.Offsets.Count + xAxis.Class[i];

        /// <summary>Samples of patch (i, j) rounded up to a multiple of the SIMD width (the tables' row length).</summary>
        int PaddedSamples(int i, int j) => (xAxis.Count[i] * yAxis.Count[j] + Lanes - 1) / Lanes * Lanes;

        /// <summary>
        /// The local weights of every sample of patch (i, j), one row per local unknown: weight k of
        /// sample (a, b) at <c>k S + b count_u + a</c> (S = <see cref="PaddedSamples"/>, padding 0), so
        /// the passes over the samples run along memory 4 samples at a time.
        /// </summary>
        double[] Table(int i, int j)
        {
            const int L = GregoryNet.LocalCount;
            int pair = Pair(i, j);
            if (tables[pair] != null) return tables[pair];
            double[] us = xAxis.Offsets[xAxis.Class[i]], vs = yAxis.Offsets[yAxis.Class[j]];
            int S = PaddedSamples(i, j), n = L * S;
            double[] t;
            if (cacheTables) t = new double[n];
            else
            {
                if (scratch == null || scratch.Length < n) scratch = new double[n];
                t = scratch;
                Array.Clear(t, 0, n);
            }
            Span<double> w = stackalloc double[L];
            for (int b = 0; b < vs.Length; b++)
                for (int a = 0; a < us.Length; a++)
                {
                    GregoryNet.LocalWeights(us[a], vs[b], w);
                    int smp = b * us.Length + a;
                    for (int k = 0; k < L; k++) t[k * S + smp] = w[k];
                }
            if (grams[pair] == null)
            {
                // Row k of the (symmetric) Gram matrix at k Stride.
                var g = new double[L * Stride];
                for (int k = 0; k < L; k++)
                    for (int q = k; q < L; q++)
                    {
                        Vector<double> d = Vector<double>.Zero;
                        for (int v = 0; v < S; v += Lanes) d += new Vector<double>(t, k * S + v) * new Vector<double>(t, q * S + v);
                        g[k * Stride + q] = g[q * Stride + k] = Vector.Dot(d, Vector<double>.One);
                    }
                grams[pair] = g;
            }
            if (cacheTables) tables[pair] = t;
            return t;
        }

        /// <summary>The most padded samples any patch has (the gather buffers' length).</summary>
        int MostSamples()
        {
            int cu = 0, cv = 0;
            foreach (int c in xAxis.Count) cu = Math.Max(cu, c);
            foreach (int c in yAxis.Count) cv = Math.Max(cv, c);
            return (cu * cv + Lanes - 1) / Lanes * Lanes;
        }

        /// <summary>Copies patch (i, j)'s samples into z, row after row, the padding 0.</summary>
        void Gather(double[] heights, int i, int j, double[] z)
        {
            int c0 = xAxis.First[i], cn = xAxis.Count[i], r0 = yAxis.First[j], rn = yAxis.Count[j];
            for (int b = 0; b < rn; b++) Array.Copy(heights, (long)(r0 + b) * width + c0, z, b * cn, cn);
            Array.Clear(z, rn * cn, PaddedSamples(i, j) - rn * cn);
        }

        /// <summary>
        /// <c>S^T z</c> (one pass over the samples, 20 multiply-adds each), building the Gram matrices
        /// on the way. Progress runs from <paramref name="p0"/> to <paramref name="p1"/>.
        /// </summary>
        public double[] RightHandSide(double[] heights, IProgress<float> progress, float p0, float p1, CancellationToken ct)
        {
            const int L = GregoryNet.LocalCount;
            var rhs = new double[net.Count];
            var z = new double[MostSamples()];
            for (int j = 0; j < net.Rows; j++)
            {
                ct.ThrowIfCancellationRequested();
                progress?.Report(p0 + (p1 - p0) * j / net.Rows);
                for (int i = 0; i < net.Columns; i++)
                {
                    double[] t = Table(i, j);
                    Gather(heights, i, j, z);
                    int S = PaddedSamples(i, j), u = (j * net.Columns + i) * L;
                    for (int k = 0; k < L; k++)
                    {
                        Vector<double> acc = Vector<double>.Zero;
                        for (int v = 0; v < S; v += Lanes) acc += new Vector<double>(t, k * S + v) * new Vector<double>(z, v);
                        rhs[unknownsOf[u + k]] += Vector.Dot(acc, Vector<double>.One);
                    }
                }
            }
            return rhs;
        }

        /// <summary>y = A p (the data's normal matrix only): per patch, gather 20, multiply by its Gram, scatter.</summary>
        void Multiply(double[] p, double[] y)
        {
            const int L = GregoryNet.LocalCount;
            Array.Clear(y, 0, y.Length);
            Span<double> acc = stackalloc double[Stride];
            Span<Vector<double>> accV = MemoryMarshal.Cast<double, Vector<double>>(acc);
            int nu = xAxis.Offsets.Count;
            for (int j = 0; j < net.Rows; j++)
            {
                int rowPair = yAxis.Class[j] * nu;
                for (int i = 0; i < net.Columns; i++)
                {
                    double[] g = grams[rowPair + xAxis.Class[i]];
                    int o = (j * net.Columns + i) * L;
                    if (Stride == 5 * Lanes)
                    {
                        // The common case (4 or 2 lanes): five accumulators the JIT keeps in registers.
                        Vector<double> a0 = Vector<double>.Zero, a1 = a0, a2 = a0, a3 = a0, a4 = a0;
                        for (int k = 0; k < L; k++)
                        {
                            var f = new Vector<double>(p[unknownsOf[o + k]]);
                            int c = k * Stride;
                            a0 += new Vector<double>(g, c) * f;
                            a1 += new Vector<double>(g, c + Lanes) * f;
                            a2 += new Vector<double>(g, c + 2 * Lanes) * f;
                            a3 += new Vector<double>(g, c + 3 * Lanes) * f;
                            a4 += new Vector<double>(g, c + 4 * Lanes) * f;
                        }
                        accV[0] = a0; accV[1] = a1; accV[2] = a2; accV[3] = a3; accV[4] = a4;
                    }
                    else
                    {
                        acc.Clear();
                        for (int k = 0; k < L; k++)
                        {
                            var f = new Vector<double>(p[unknownsOf[o + k]]);
                            int c = k * Stride;
                            for (int v = 0; v < accV.Length; v++) accV[v] += new Vector<double>(g, c + v * Lanes) * f;
                        }
                    }
                    for (int q = 0; q < L; q++) y[unknownsOf[o + q]] += acc[q];
                }
            }
        }

        // The preconditioner's blocks: a vertex's 3 unknowns and an edge's 2 are strongly coupled (a
        // height and the offsets next to it), so the diagonal alone (Jacobi) needs hundreds of CG
        // iterations; the inverses of these small diagonal blocks of A + mu I bring it to tens.
        // Local unknowns 0..11 are 4 vertices of 3, 12..19 four edges of 2 (GregoryNet.LocalUnknowns).
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
            const int L = GregoryNet.LocalCount;
            int vb = net.VerticalBase;
            var blocks = new double[3 * vb + 2 * (net.Count - vb)];
            for (int j = 0; j < net.Rows; j++)
                for (int i = 0; i < net.Columns; i++)
                {
                    double[] g = grams[Pair(i, j)] ?? throw new InvalidOperationException("RightHandSide builds the Gram matrices first.");
                    int o = (j * net.Columns + i) * L;
                    for (int bl = 0; bl < BlockStart.Length; bl++)
                    {
                        int l0 = BlockStart[bl], m = BlockSize[bl];
                        int at = BlockOf(unknownsOf[o + l0], out _, out _);
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

        /// <summary>z = B^-1 r block by block; 0 on fixed unknowns.</summary>
        /// <remarks>
        /// A second level through the C1 splines (z += T (G_y kron G_x)^-1 T^T r, separable and exact
        /// in the spline subspace) was tried: it saved 5 to 15% of the iterations and cost as much as
        /// a product with A each, so it is not used. What CG spends its iterations on is local.
        /// </remarks>
        void Precondition(double[] blocks, double[] r, double[] z, bool[] fixedMask)
        {
            PreconditionBlocks(blocks, r, z);
            if (fixedMask != null)
                for (int k = 0; k < z.Length; k++) if (fixedMask[k]) z[k] = 0;
        }

        void PreconditionBlocks(double[] blocks, double[] r, double[] z)
        {
            int vb = net.VerticalBase;
            for (int k = 0; k < vb; k += 3)
            {
                int at = 3 * k;
                double r0 = r[k], r1 = r[k + 1], r2 = r[k + 2];
                z[k] = blocks[at] * r0 + blocks[at + 1] * r1 + blocks[at + 2] * r2;
                z[k + 1] = blocks[at + 3] * r0 + blocks[at + 4] * r1 + blocks[at + 5] * r2;
                z[k + 2] = blocks[at + 6] * r0 + blocks[at + 7] * r1 + blocks[at + 8] * r2;
            }
            for (int k = vb; k < net.Count; k += 2)
            {
                int at = 3 * vb + 2 * (k - vb);
                double r0 = r[k], r1 = r[k + 1];
                z[k] = blocks[at] * r0 + blocks[at + 1] * r1;
                z[k + 1] = blocks[at + 2] * r0 + blocks[at + 3] * r1;
            }
        }

        /// <summary>
        /// Solves <c>(A + mu I) x = rhs + mu x0</c> by Jacobi-preconditioned CG from x0. Unknowns with
        /// <paramref name="fixedMask"/> set keep their x0 values (a neighbour's seam). Returns x.
        /// </summary>
        public double[] Solve(double[] rhs, double[] x0, bool[] fixedMask, IProgress<float> progress, float p0, float p1, CancellationToken ct)
        {
            const int L = GregoryNet.LocalCount;
            int n = net.Count;
            // Mean diagonal of A (every global unknown appears at most once in a patch's local list) sets mu.
            double trace = 0;
            for (int j = 0; j < net.Rows; j++)
                for (int i = 0; i < net.Columns; i++)
                {
                    double[] g = grams[Pair(i, j)] ?? throw new InvalidOperationException("RightHandSide builds the Gram matrices first.");
                    for (int k = 0; k < L; k++) trace += g[k * Stride + k];
                }
            double mean = trace / n;
            double mu = RidgeWeight * (mean > 0 ? mean : 1);
            double[] blocks = BlockInverses(mu);

            var x = (double[])x0.Clone();
            var r = new double[n];
            var q = new double[n];
            Multiply(x, q);
            // r = rhs + mu x0 - (A + mu) x = rhs - A x0 at the start.
            for (int k = 0; k < n; k++) r[k] = fixedMask != null && fixedMask[k] ? 0 : rhs[k] - q[k];
            var z = new double[n];
            var p = new double[n];
            double rz = 0, r0 = 0;
            Precondition(blocks, r, z, fixedMask);
            for (int k = 0; k < n; k++)
            {
                p[k] = z[k];
                rz += r[k] * z[k];
                r0 += r[k] * r[k];
            }
            r0 = Math.Sqrt(r0);
            int it = 0;
            double rn = r0, done = 0;
            while (rn > Tolerance * r0 && it < MaxIterations)
            {
                if ((it & 7) == 0)
                {
                    ct.ThrowIfCancellationRequested();
                    // CG's residual is not monotone: report the best fraction of the way so far.
                    done = Math.Max(done, Math.Min(1.0, Math.Log(r0 / rn) / Math.Log(1 / Tolerance)));
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
                double alpha = rz / pq, rzNew = 0, rr = 0;
                for (int k = 0; k < n; k++)
                {
                    x[k] += alpha * p[k];
                    r[k] -= alpha * q[k];
                    rr += r[k] * r[k];
                }
                Precondition(blocks, r, z, fixedMask);
                for (int k = 0; k < n; k++) rzNew += r[k] * z[k];
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

        /// <summary>The error of the net x at every sample: max, RMS, and the binned picture.</summary>
        public void Errors(double[] heights, double[] x, FitErrorMap map, out double max, out double rms,
            IProgress<float> progress, float p0, float p1, CancellationToken ct)
        {
            const int L = GregoryNet.LocalCount;
            Span<Vector<double>> local = stackalloc Vector<double>[L];
            // The map's cell of (c, r) is rowCell[r] + colCell[c]: no divisions per sample.
            var colCell = new int[width];
            var rowCell = new int[height];
            for (int c = 0; c < width; c++) colCell[c] = map.CellOf(c, 0);
            for (int r = 0; r < height; r++) rowCell[r] = map.CellOf(0, r);
            int most = MostSamples();
            var z = new double[most];
            var e = new double[most];
            Vector<double> vmax = Vector<double>.Zero, vsum = Vector<double>.Zero;
            for (int j = 0; j < net.Rows; j++)
            {
                ct.ThrowIfCancellationRequested();
                progress?.Report(p0 + (p1 - p0) * j / net.Rows);
                int r0 = yAxis.First[j], rn = yAxis.Count[j];
                for (int i = 0; i < net.Columns; i++)
                {
                    double[] t = Table(i, j);
                    Gather(heights, i, j, z);
                    int S = PaddedSamples(i, j), u = (j * net.Columns + i) * L;
                    for (int k = 0; k < L; k++) local[k] = new Vector<double>(x[unknownsOf[u + k]]);
                    // Padding: weights 0 and samples 0 give error 0, which changes neither max nor sum.
                    for (int v = 0; v < S; v += Lanes)
                    {
                        Vector<double> f = Vector<double>.Zero;
                        for (int k = 0; k < L; k++) f += local[k] * new Vector<double>(t, k * S + v);
                        Vector<double> d = Vector.Abs(f - new Vector<double>(z, v));
                        vmax = Vector.Max(vmax, d);
                        vsum += d * d;
                        d.CopyTo(e, v);
                    }
                    int c0 = xAxis.First[i], cn = xAxis.Count[i];
                    for (int b = 0; b < rn; b++)
                    {
                        int cellRow = rowCell[r0 + b], o = b * cn;
                        for (int a = 0; a < cn; a++) map.Add(cellRow + colCell[c0 + a], e[o + a]);
                    }
                }
            }
            max = 0;
            double sum2 = 0;
            for (int k = 0; k < Lanes; k++)
            {
                max = Math.Max(max, vmax[k]);
                sum2 += vsum[k];
            }
            rms = Math.Sqrt(sum2 / ((double)width * height));
            progress?.Report(p1);
        }
    }
}
