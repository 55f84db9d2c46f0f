using System;

namespace GregoryTerrain
{
    /// <summary>
    /// The reference a fit's error is held against: a (3P + 1) x (3Q + 1) lattice, as dense as a
    /// P x Q grid's control net, each node the mean of the samples nearest it (a box of one lattice
    /// spacing), interpolated bilinearly at every sample. <see cref="HeightmapFitter"/> keeps its max
    /// error at or below this surface's (<see cref="HeightmapFitter.Fit"/>). Two passes over the
    /// samples, a handful of operations each; per-axis tables, so no division per sample.
    /// </summary>
    internal static class BilinearBaseline
    {
        /// <summary>
        /// Max and RMS |bilinear - sample| over all samples; false (max, rms NaN) when some lattice
        /// node has no sample nearest it (the lattice is denser than the samples: no baseline).
        /// </summary>
        public static bool Measure(double[] z, int w, int h, int columns, int rows, out double max, out double rms)
        {
            int lx = 3 * columns + 1, ly = 3 * rows + 1;
            max = rms = double.NaN;
            if (lx > w || ly > h) return false;
            int[] nodeX = Nearest(w, lx, out int[] countX), nodeY = Nearest(h, ly, out int[] countY);
            foreach (int c in countX) if (c == 0) return false;
            foreach (int c in countY) if (c == 0) return false;
            var mean = new double[(long)lx * ly];
            for (int r = 0; r < h; r++)
            {
                long row = (long)r * w, node = (long)nodeY[r] * lx;
                for (int c = 0; c < w; c++) mean[node + nodeX[c]] += z[row + c];
            }
            for (int b = 0; b < ly; b++)
                for (int a = 0; a < lx; a++) mean[(long)b * lx + a] /= (double)countX[a] * countY[b];
            // Cell and fraction of every column and row.
            var cellX = new int[w];
            var fracX = new double[w];
            for (int c = 0; c < w; c++) Cell(c, w, lx, out cellX[c], out fracX[c]);
            max = 0;
            double s2 = 0;
            for (int r = 0; r < h; r++)
            {
                Cell(r, h, ly, out int b, out double ty);
                long m0 = (long)b * lx, m1 = m0 + lx, row = (long)r * w;
                for (int c = 0; c < w; c++)
                {
                    int a = cellX[c];
                    double tx = fracX[c];
                    double f = (1 - ty) * ((1 - tx) * mean[m0 + a] + tx * mean[m0 + a + 1]) + ty * ((1 - tx) * mean[m1 + a] + tx * mean[m1 + a + 1]);
                    double e = Math.Abs(f - z[row + c]);
                    if (e > max) max = e;
                    s2 += e * e;
                }
            }
            rms = Math.Sqrt(s2 / ((double)w * h));
            return true;
        }

        /// <summary>Per sample the nearest lattice node (round half to even, as Math.Round), and per node its samples.</summary>
        static int[] Nearest(int samples, int nodes, out int[] count)
        {
            var node = new int[samples];
            count = new int[nodes];
            for (int c = 0; c < samples; c++)
            {
                node[c] = (int)Math.Round((double)c * (nodes - 1) / (samples - 1));
                count[node[c]]++;
            }
            return node;
        }

        static void Cell(int c, int samples, int nodes, out int cell, out double frac)
        {
            double X = (double)c * (nodes - 1) / (samples - 1);
            cell = Math.Min((int)X, nodes - 2);
            frac = X - cell;
        }
    }
}
