using System;
using System.Globalization;

namespace GregoryTerrain
{
    /// <summary>
    /// A symmetric positive definite band matrix of order N with <see cref="Bandwidth"/> diagonals
    /// above the main one, factored in place as <c>L L^T</c>. Row i keeps entries (i, i..i+b) before
    /// factoring and L's column i (entries (i..i+b, i)) after, so memory is N (b + 1) doubles and a
    /// factorisation costs N b^2 flops. Used for the normal equations of 1D spline bases.
    /// </summary>
    internal sealed class BandedCholesky
    {
        readonly double[] band;   // band[i * (b + 1) + k] = A(i, i + k), then L(i + k, i)
        bool factored;

        public int Order { get; }
        public int Bandwidth { get; }

        public BandedCholesky(int order, int bandwidth)
        {
            if (order < 1) throw new ArgumentException($"order = {order}, need at least 1.", nameof(order));
            if (bandwidth < 0) throw new ArgumentException($"bandwidth = {bandwidth}, need at least 0.", nameof(bandwidth));
            Order = order;
            Bandwidth = bandwidth;
            band = new double[(long)order * (bandwidth + 1) <= int.MaxValue ? order * (bandwidth + 1) : throw new ArgumentException($"order = {order} is too large.", nameof(order))];
        }

        /// <summary>Adds v to A(i, j) (and by symmetry A(j, i)); |i - j| must be within the band.</summary>
        public void Add(int i, int j, double v)
        {
            if (factored) throw new InvalidOperationException("the matrix is already factored.");
            if (j < i) (i, j) = (j, i);
            if (j - i > Bandwidth) throw new ArgumentOutOfRangeException(nameof(j), j, $"entry ({i}, {j}) is outside the band of width {Bandwidth}.");
            band[i * (Bandwidth + 1) + (j - i)] += v;
        }

        public double Get(int i, int j)
        {
            if (j < i) (i, j) = (j, i);
            return j - i > Bandwidth ? 0 : band[i * (Bandwidth + 1) + (j - i)];
        }

        /// <summary>Factors A = L L^T. Throws if a pivot is not positive (A not positive definite).</summary>
        public void Factor()
        {
            if (factored) return;
            int b = Bandwidth, w = b + 1;
            for (int i = 0; i < Order; i++)
            {
                // Pivot: A(i,i) minus the squares already subtracted (done eagerly below).
                double d = band[i * w];
                if (!(d > 0))
                    throw new ArgumentException(string.Format(CultureInfo.InvariantCulture,
                        "pivot {0} = {1} is not positive: the matrix is not positive definite.", i, d));
                d = Math.Sqrt(d);
                band[i * w] = d;
                int last = Math.Min(b, Order - 1 - i);
                for (int k = 1; k <= last; k++) band[i * w + k] /= d;        // L(i+k, i)
                for (int k = 1; k <= last; k++)
                {
                    double lk = band[i * w + k];
                    int row = i + k;
                    for (int m = k; m <= last; m++)                           // A(i+k, i+m) -= L(i+k,i) L(i+m,i)
                        band[row * w + (m - k)] -= lk * band[i * w + m];
                }
            }
            factored = true;
        }

        /// <summary>Solves A x = rhs in place for one vector of length N (factors first if needed).</summary>
        public void Solve(Span<double> x)
        {
            if (x.Length != Order) throw new ArgumentException($"x.Length = {x.Length}, need {Order}.", nameof(x));
            Factor();
            int b = Bandwidth, w = b + 1;
            for (int i = 0; i < Order; i++)
            {
                double s = x[i];
                for (int k = 1; k <= b && k <= i; k++) s -= band[(i - k) * w + k] * x[i - k];
                x[i] = s / band[i * w];
            }
            for (int i = Order - 1; i >= 0; i--)
            {
                double s = x[i];
                for (int k = 1; k <= b && i + k < Order; k++) s -= band[i * w + k] * x[i + k];
                x[i] = s / band[i * w];
            }
        }

        /// <summary>
        /// Solves A X = R in place for an N x M row-major matrix (M right-hand sides as columns):
        /// row operations over whole rows, so the inner loop runs along memory.
        /// </summary>
        public void SolveRows(double[] x, int columns)
        {
            if (x == null) throw new ArgumentNullException(nameof(x));
            if ((long)Order * columns != x.Length) throw new ArgumentException($"x.Length = {x.Length}, need {Order} x {columns}.", nameof(x));
            Factor();
            int b = Bandwidth, w = b + 1, M = columns;
            for (int i = 0; i < Order; i++)
            {
                for (int k = 1; k <= b && k <= i; k++)
                {
                    double l = band[(i - k) * w + k];
                    int src = (i - k) * M, dst = i * M;
                    for (int c = 0; c < M; c++) x[dst + c] -= l * x[src + c];
                }
                double inv = 1.0 / band[i * w];
                for (int c = 0; c < M; c++) x[i * M + c] *= inv;
            }
            for (int i = Order - 1; i >= 0; i--)
            {
                for (int k = 1; k <= b && i + k < Order; k++)
                {
                    double l = band[i * w + k];
                    int src = (i + k) * M, dst = i * M;
                    for (int c = 0; c < M; c++) x[dst + c] -= l * x[src + c];
                }
                double inv = 1.0 / band[i * w];
                for (int c = 0; c < M; c++) x[i * M + c] *= inv;
            }
        }
    }
}
