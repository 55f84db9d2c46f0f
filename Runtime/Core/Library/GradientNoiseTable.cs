using System.Threading;

namespace GregoryTerrain
{
    /// <summary>
    /// The tiled noise (keyword <c>GT_NOISE_TABLE</c>), mirrored by the table functions of
    /// Shaders/Library/GradientNoise.hlsl. <see cref="GradientNoise"/> with the lattice wrapped
    /// modulo <see cref="Size"/>: cell (x, y) takes the corner gradients of cell
    /// (x mod 256, y mod 256) with its far corners wrapped too, so the noise repeats every 256 cells
    /// and stays C2 across the seam. Inside [0, 255)^2 it is <see cref="GradientNoise"/> itself.
    /// <para>
    /// The GPU reads each cell's noise polynomial from <c>_NoiseCells</c> (<see cref="Floats"/>,
    /// uploaded once) instead of hashing four corners: two float4 per cell (32 bytes, one memory
    /// sector), scaled by <see cref="GradientNoise.Scale"/>, <c>r0 = (g00, A)</c>, <c>r1 = (B, C)</c>
    /// with <c>A = g10 - g00</c>, <c>B = g01 - g00</c>, <c>C = (g00 - g10) - (g01 - g11)</c>, so that
    /// with <c>h = f - 1</c> the corner ramps' blend coefficients are <c>n00 = g00 . f</c>,
    /// <c>k1 = A . (h.x, f.y) - g00.x</c>, <c>k2 = B . (f.x, h.y) - g00.y</c>,
    /// <c>k3 = C . h - (B.x + A.y)</c>.
    /// </para>
    /// </summary>
    internal static class GradientNoiseTable
    {
        /// <summary>Lattice cells per side of the table: the noise's period.</summary>
        public const int Size = 256;
        /// <summary>float4 rows per cell.</summary>
        public const int RowsPerCell = 2;

        static float[] s_floats;

        /// <summary>
        /// The table as the GPU gets it: <c>Size * Size * RowsPerCell</c> float4, cell (x, y) from
        /// float index <c>FirstRow(x, y) * 4</c>. Built once (a few ms), shared: do not modify.
        /// </summary>
        public static float[] Floats => LazyInitializer.EnsureInitialized(ref s_floats, Build);

        /// <summary>HLSL <c>GradientNoiseTableFirstRow</c>: the first float4 row of cell (ix, iy) wrapped into the table.</summary>
        public static int FirstRow(int ix, int iy) => (((iy & (Size - 1)) << 8) | (ix & (Size - 1))) * RowsPerCell;

        /// <summary>The corner gradients of cell (ix, iy) with every corner wrapped modulo <see cref="Size"/>.</summary>
        public static void CornerGradients(int ix, int iy, out Float2 g00, out Float2 g10, out Float2 g01, out Float2 g11)
        {
            int x0 = ix & (Size - 1), x1 = (ix + 1) & (Size - 1);
            int y0 = iy & (Size - 1), y1 = (iy + 1) & (Size - 1);
            g00 = GradientNoise.Gradient(GradientNoise.Hash(x0, y0));
            g10 = GradientNoise.Gradient(GradientNoise.Hash(x1, y0));
            g01 = GradientNoise.Gradient(GradientNoise.Hash(x0, y1));
            g11 = GradientNoise.Gradient(GradientNoise.Hash(x1, y1));
        }

        static float[] Build()
        {
            const float s = GradientNoise.Scale;
            var t = new float[Size * Size * RowsPerCell * 4];
            for (int y = 0; y < Size; y++)
                for (int x = 0; x < Size; x++)
                {
                    CornerGradients(x, y, out Float2 g00, out Float2 g10, out Float2 g01, out Float2 g11);
                    Float2 a = g10 - g00, b = g01 - g00, c = (g00 - g10) - (g01 - g11);
                    int i = FirstRow(x, y) * 4;
                    t[i + 0] = s * g00.x; t[i + 1] = s * g00.y; t[i + 2] = s * a.x; t[i + 3] = s * a.y;
                    t[i + 4] = s * b.x; t[i + 5] = s * b.y; t[i + 6] = s * c.x; t[i + 7] = s * c.y;
                }
            return t;
        }

        /// <summary>
        /// HLSL <c>GradientNoiseCell</c> under <c>GT_NOISE_TABLE</c>: the noise of cell (ix, iy) at fraction
        /// (fx, fy) from the cell's table rows, gradient with respect to the lattice coordinate. The
        /// same polynomial as <see cref="GradientNoise.Cell"/> of the wrapped corners, its
        /// coefficients rounded once into the table.
        /// </summary>
        public static float EvaluateCell(int ix, int iy, float fx, float fy, out Float2 gradient)
        {
            float[] t = Floats;
            int i = FirstRow(ix, iy) * 4;
            float hx = fx - 1f, hy = fy - 1f;
            float n00 = t[i + 0] * fx + t[i + 1] * fy;
            float k1 = (t[i + 2] * hx + t[i + 3] * fy) - t[i + 0];
            float k2 = (t[i + 4] * fx + t[i + 5] * hy) - t[i + 1];
            float k3 = (t[i + 6] * hx + t[i + 7] * hy) - (t[i + 4] + t[i + 3]);
            float u = GradientNoise.Fade(fx), v = GradientNoise.Fade(fy);
            float du = GradientNoise.FadeDerivative(fx), dv = GradientNoise.FadeDerivative(fy);
            float uv = u * v;
            float dx = t[i + 0] + u * t[i + 2] + v * t[i + 4] + uv * t[i + 6] + du * (k1 + v * k3);
            float dy = t[i + 1] + u * t[i + 3] + v * t[i + 5] + uv * t[i + 7] + dv * (k2 + u * k3);
            gradient = new Float2(dx, dy);
            return n00 + u * k1 + v * k2 + uv * k3;
        }
    }
}
