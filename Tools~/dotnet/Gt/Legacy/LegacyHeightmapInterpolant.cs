// The interpolant of the pre-issue-27 fitter (git show 5bbbfe0:Runtime/Core/Grid/HeightmapInterpolant.cs), for gt fit-bench only.
using System;

namespace GregoryTerrain.Rig.Legacy
{
    /// <summary>
    /// A C1 bicubic interpolant of a height array: Catmull-Rom (cubic convolution) in x and in y.
    /// Sample (c, r) of a W x H array (row-major, <c>heights[r * W + c]</c>) sits at
    /// <c>(c / (W-1), r / (H-1))</c> of the terrain's unit square. Outside the array the samples are
    /// extended linearly (<c>s[-1] = 2 s[0] - s[1]</c>), so the slope at the border is the one-sided
    /// difference instead of being forced to 0. Inputs are checked by <see cref="HeightmapFitter"/>.
    /// </summary>
    public sealed class LegacyHeightmapInterpolant
    {
        readonly double[] heights;
        readonly int width, height;

        public LegacyHeightmapInterpolant(double[] heights, int width, int height)
        {
            LegacyHeightmapFitter.CheckHeights(heights, width, height);
            this.heights = heights;
            this.width = width;
            this.height = height;
        }

        /// <summary>Height z and its gradient (dz/dx, dz/dy) in terrain units at (x, y) of the unit square.</summary>
        public void Sample(double x, double y, out double z, out double dzdx, out double dzdy)
        {
            Span<double> wx = stackalloc double[4], dx = stackalloc double[4];
            Span<double> wy = stackalloc double[4], dy = stackalloc double[4];
            int c = Cell(x, width, wx, dx);
            int r = Cell(y, height, wy, dy);
            z = dzdx = dzdy = 0;
            for (int b = 0; b < 4; b++)
                for (int a = 0; a < 4; a++)
                {
                    double s = At(c - 1 + a, r - 1 + b);
                    z += wx[a] * wy[b] * s;
                    dzdx += dx[a] * wy[b] * s;
                    dzdy += wx[a] * dy[b] * s;
                }
            dzdx *= width - 1;  // d/dx = (W - 1) d/d(sample index)
            dzdy *= height - 1;
        }

        /// <summary>Cell index (the sample left of x) and the Catmull-Rom weights and their derivatives.</summary>
        static int Cell(double x, int count, Span<double> w, Span<double> d)
        {
            double X = x * (count - 1);
            int c = (int)Math.Floor(X);
            if (c < 0) c = 0;
            if (c > count - 2) c = count - 2;
            double f = X - c, f2 = f * f, f3 = f2 * f;
            w[0] = 0.5 * (-f3 + 2 * f2 - f);
            w[1] = 0.5 * (3 * f3 - 5 * f2 + 2);
            w[2] = 0.5 * (-3 * f3 + 4 * f2 + f);
            w[3] = 0.5 * (f3 - f2);
            d[0] = 0.5 * (-3 * f2 + 4 * f - 1);
            d[1] = 0.5 * (9 * f2 - 10 * f);
            d[2] = 0.5 * (-9 * f2 + 8 * f + 1);
            d[3] = 0.5 * (3 * f2 - 2 * f);
            return c;
        }

        /// <summary>Sample (c, r), linearly extended one step beyond each border.</summary>
        double At(int c, int r)
        {
            if (c < 0) return 2 * At(0, r) - At(1, r);
            if (c >= width) return 2 * At(width - 1, r) - At(width - 2, r);
            if (r < 0) return 2 * At(c, 0) - At(c, 1);
            if (r >= height) return 2 * At(c, height - 1) - At(c, height - 2);
            return heights[r * width + c];
        }
    }
}
