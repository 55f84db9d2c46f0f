using System;

namespace GregoryTerrain
{
    /// <summary>
    /// 2D gradient (Perlin) noise on the integer lattice (eq. 11-13's K), mirrored by
    /// Shaders/Library/GradientNoise.hlsl (<c>GradientNoise.Evaluate</c> is HLSL <c>GradientNoise</c>).
    /// <list type="bullet">
    /// <item>No permutation table: the gradient of a lattice point comes from a 32-bit integer hash of
    /// its two coordinates (<see cref="Hash(int, int)"/>), in unsigned arithmetic that wraps modulo
    /// 2^32 in C# (unchecked) and in HLSL alike, so both pick the same gradient bit for bit.</item>
    /// <item>8 unit gradients (axes and diagonals), quintic fade <c>6t^5 - 15t^4 + 10t^3</c> (C2, so
    /// normals from the analytic gradient are continuous).</item>
    /// <item>Value scaled by sqrt(2) so it spans [-1, 1]: unscaled 2D Perlin noise with unit gradients
    /// peaks at sqrt(2)/2, at a cell centre whose four gradients point at it.</item>
    /// <item>Exactly 0 on lattice points (fraction 0: every term is 0 or multiplied by fade(0) = 0).</item>
    /// </list>
    /// </summary>
    internal static class GradientNoise
    {
        /// <summary>sqrt(2) as float: maps the natural range [-sqrt(2)/2, sqrt(2)/2] onto [-1, 1].</summary>
        public const float Scale = 1.41421356f;

        /// <summary>1/sqrt(2) as float: the diagonal gradients' components.</summary>
        const float D = 0.707106781f;

        static readonly float[] GradX = { 1f, D, 0f, -D, -1f, -D, 0f, D };
        static readonly float[] GradY = { 0f, D, 1f, D, 0f, -D, -1f, -D };

        // ------------------------------------------------------------ hash

        /// <summary>
        /// A 32-bit integer mix with good avalanche (a PCG output permutation: one LCG step, a
        /// data-dependent xorshift, a multiply, a final xorshift). Every step wraps modulo 2^32.
        /// </summary>
        public static uint Hash(uint v)
        {
            unchecked
            {
                uint state = v * 747796405u + 2891336453u;
                uint word = ((state >> (int)((state >> 28) + 4u)) ^ state) * 277803737u;
                return (word >> 22) ^ word;
            }
        }

        /// <summary>Hash of a lattice point: nests the 1D hash, <c>Hash(x + Hash(y))</c>, negative ints as their bits.</summary>
        public static uint Hash(int x, int y) => unchecked(Hash((uint)x + Hash((uint)y)));

        /// <summary>The unit gradient that hash <paramref name="h"/> picks (one of 8 directions, low 3 bits).</summary>
        public static Float2 Gradient(uint h) => new Float2(GradX[h & 7u], GradY[h & 7u]);

        /// <summary>
        /// A fixed offset for noise stream <paramref name="stream"/> (octave k uses stream k): an integer
        /// part in [0, 256) and a 16-bit fraction, so the offset is exact in float (24 bits) and the
        /// octaves' lattices neither coincide nor share their zeros.
        /// </summary>
        public static Float2 StreamOffset(uint stream)
        {
            uint hx = Hash(stream ^ 0x9E3779B9u);
            uint hy = Hash(hx);
            return new Float2((hx & 255u) + ((hx >> 8) & 0xFFFFu) / 65536f,
                              (hy & 255u) + ((hy >> 8) & 0xFFFFu) / 65536f);
        }

        // ------------------------------------------------------------ fade

        /// <summary>Quintic fade <c>t^3 (t (6t - 15) + 10)</c>: 0 at 0, 1 at 1, first and second derivative 0 at both.</summary>
        public static float Fade(float t) => t * t * t * (t * (t * 6f - 15f) + 10f);
        public static double Fade(double t) => t * t * t * (t * (t * 6.0 - 15.0) + 10.0);

        /// <summary>d Fade / dt = <c>30 t^2 (t - 1)^2</c>.</summary>
        public static float FadeDerivative(float t) { float k = t * (t - 1f); return 30f * k * k; }
        public static double FadeDerivative(double t) { double k = t * (t - 1.0); return 30.0 * k * k; }

        // ------------------------------------------------------------ evaluation

        /// <summary>
        /// Noise at <c>(x, y)</c>, with its gradient d noise / d(x, y). The lattice cell is
        /// <c>floor</c> of each coordinate (so negative coordinates work). Coordinates must be below
        /// 2^31 in magnitude (the cell is an int). Float precision: at |x| ~ 1e6 a float's step is
        /// 1/16, so the fraction has 4 bits and the noise is blocky but finite; a far coordinate
        /// should come through <see cref="AtPoint"/>, which keeps the fraction separate.
        /// </summary>
        public static float Evaluate(float x, float y, out Float2 gradient, TerrainKeywords keywords = TerrainKeywords.None)
        {
            float fx = GMath.floor(x), fy = GMath.floor(y);
            return Cell((int)fx, (int)fy, x - fx, y - fy, out gradient, keywords);
        }

        /// <summary>
        /// Noise in cell <c>(ix, iy)</c> at fraction <c>(fx, fy)</c> (normally in [0, 1]); the core every
        /// float path shares. Its gradient is with respect to the lattice coordinate.
        /// <see cref="TerrainKeywords.NoiseTable"/> in <paramref name="keywords"/>: the tiled noise (<see cref="GradientNoiseTable"/>).
        /// </summary>
        public static float Cell(int ix, int iy, float fx, float fy, out Float2 gradient, TerrainKeywords keywords = TerrainKeywords.None)
        {
            if ((keywords & TerrainKeywords.NoiseTable) != 0) return GradientNoiseTable.EvaluateCell(ix, iy, fx, fy, out gradient);
            CornerGradients(ix, iy, keywords, out Float2 g00, out Float2 g10, out Float2 g01, out Float2 g11);
            return EvaluateCorners(g00, g10, g01, g11, fx, fy, out gradient);
        }

        /// <summary><see cref="Cell"/> once the cell's four corner gradients are known.</summary>
        static float EvaluateCorners(Float2 g00, Float2 g10, Float2 g01, Float2 g11, float fx, float fy, out Float2 gradient)
        {
            CornerRamps(g00, g10, g01, g11, new Float2(fx, fy), out float n00, out float n10, out float n01, out float n11);
            float u = Fade(fx), v = Fade(fy);
            float du = FadeDerivative(fx), dv = FadeDerivative(fy);
            // Bilinear blend written as n00 + u k1 + v k2 + u v k3 so the gradient is its plain derivative.
            float k1 = n10 - n00, k2 = n01 - n00, k3 = (n00 - n10) - (n01 - n11);
            float n = n00 + u * k1 + v * k2 + u * v * k3;
            float dx = g00.x + u * (g10.x - g00.x) + v * (g01.x - g00.x) + u * v * ((g00.x - g10.x) - (g01.x - g11.x))
                     + du * (k1 + v * k3);
            float dy = g00.y + u * (g10.y - g00.y) + v * (g01.y - g00.y) + u * v * ((g00.y - g10.y) - (g01.y - g11.y))
                     + dv * (k2 + u * k3);
            gradient = new Float2(Scale * dx, Scale * dy);
            return Scale * n;
        }

        /// <summary>Each corner's linear ramp <c>g . (f - corner)</c> at the fraction f of the cell.</summary>
        static void CornerRamps(Float2 g00, Float2 g10, Float2 g01, Float2 g11, Float2 f, out float n00, out float n10, out float n01, out float n11)
        {
            float gx = f.x - 1f, gy = f.y - 1f;
            n00 = g00.x * f.x + g00.y * f.y;
            n10 = g10.x * gx + g10.y * f.y;
            n01 = g01.x * f.x + g01.y * gy;
            n11 = g11.x * gx + g11.y * gy;
        }

        /// <summary>
        /// <c>Fade(t + s) - Fade(t)</c> as its exact Taylor polynomial in the step s (Fade is a quintic):
        /// <c>s (F1 + s (F2/2 + s (F3/6 + s (F4/24 + 6 s))))</c>, Fn the n-th derivative at t. Every
        /// term carries a factor s, so a tiny step keeps float's relative precision instead of the
        /// ~6e-8 absolute error of the difference of two rounded fades.
        /// </summary>
        public static float FadeStep(float t, float s)
        {
            float f1 = FadeDerivative(t);                        // 30 t^2 (t - 1)^2
            float f2 = 30f * t * ((2f * t - 1f) * (t - 1f));     // F2/2 = 60 t^3 - 90 t^2 + 30 t
            float f3 = (60f * t - 60f) * t + 10f;                // F3/6
            float f4 = 30f * t - 15f;                            // F4/24
            return s * (f1 + s * (f2 + s * (f3 + s * (f4 + s * 6f))));
        }

        /// <summary>The four corner gradients of cell (ix, iy): hashed, or wrapped modulo 256 with <see cref="TerrainKeywords.NoiseTable"/>.</summary>
        static void CornerGradients(int ix, int iy, TerrainKeywords keywords, out Float2 g00, out Float2 g10, out Float2 g01, out Float2 g11)
        {
            if ((keywords & TerrainKeywords.NoiseTable) != 0) { GradientNoiseTable.CornerGradients(ix, iy, out g00, out g10, out g01, out g11); return; }
            g00 = Gradient(Hash(ix, iy));
            g10 = Gradient(Hash(unchecked(ix + 1), iy));
            g01 = Gradient(Hash(ix, unchecked(iy + 1)));
            g11 = Gradient(Hash(unchecked(ix + 1), unchecked(iy + 1)));
        }

        /// <summary>
        /// <c>K(cell, f + step) - K(cell, f)</c> within one lattice cell's polynomial, from the precise
        /// step (lattice units, per axis; f + step may leave [0, 1] slightly: the polynomial goes on
        /// smoothly). The corner ramps are linear, so their differences are <c>g . step</c> exactly;
        /// products use <c>A1 B1 - A0 B0 = dA B1 + A0 dB</c>; fades use <see cref="FadeStep"/>.
        /// <paramref name="gradient"/>: d K / d(lattice) at <c>f + step</c>; <paramref name="baseValue"/>:
        /// K at f (plain float, for uses that do not need the precision). The tiled noise takes the
        /// wrapped corners' gradients here (not its table: the steps need the gradients themselves).
        /// </summary>
        public static float CellDifference(int ix, int iy, float fx, float fy, float sx, float sy, out Float2 gradient, out float baseValue,
                                           TerrainKeywords keywords = TerrainKeywords.None)
        {
            CornerGradients(ix, iy, keywords, out Float2 g00, out Float2 g10, out Float2 g01, out Float2 g11);
            CornerRamps(g00, g10, g01, g11, new Float2(fx, fy), out float n00, out float n10, out float n01, out float n11);
            float d00 = g00.x * sx + g00.y * sy, d10 = g10.x * sx + g10.y * sy;
            float d01 = g01.x * sx + g01.y * sy, d11 = g11.x * sx + g11.y * sy;
            float k1 = n10 - n00, k2 = n01 - n00, k3 = (n00 - n10) - (n01 - n11);
            float e1 = d10 - d00, e2 = d01 - d00, e3 = (d00 - d10) - (d01 - d11);   // steps of k1, k2, k3
            float u0 = Fade(fx), v0 = Fade(fy);
            float du = FadeStep(fx, sx), dv = FadeStep(fy, sy);
            float v1 = v0 + dv, k31 = k3 + e3;
            // n = n00 + u k1 + v k2 + u v k3, term by term.
            float dn = d00 + (du * (k1 + e1) + u0 * e1) + (dv * (k2 + e2) + v0 * e2)
                     + (du * v1 * k31 + u0 * (dv * k31 + v0 * e3));
            baseValue = Scale * (n00 + u0 * k1 + v0 * k2 + u0 * v0 * k3);
            EvaluateCorners(g00, g10, g01, g11, fx + sx, fy + sy, out gradient);
            return Scale * dn;
        }

        /// <summary>
        /// The double reference: same hash, same gradients (the float constants, widened), same
        /// formula, double arithmetic. Coordinates must be below 2^31 in magnitude. <see cref="TerrainKeywords.NoiseTable"/>:
        /// the tiled noise's reference, the corners wrapped modulo 256 (its table's values unrounded).
        /// </summary>
        public static double Evaluate(double x, double y, out Double2 gradient, TerrainKeywords keywords = TerrainKeywords.None)
        {
            double flx = Math.Floor(x), fly = Math.Floor(y);
            if (!(Math.Abs(flx) < 2147483647.0 && Math.Abs(fly) < 2147483647.0))
                throw new ArgumentException(FormattableString.Invariant($"noise coordinate ({x:R}, {y:R}) must be finite and below 2^31"), nameof(x));
            int ix = (int)flx, iy = (int)fly;
            double fx = x - flx, fy = y - fly;
            CornerGradients(ix, iy, keywords, out Float2 f00, out Float2 f10, out Float2 f01, out Float2 f11);
            Double2 g00 = f00, g10 = f10, g01 = f01, g11 = f11;
            double gx = fx - 1.0, gy = fy - 1.0;
            double n00 = g00.x * fx + g00.y * fy;
            double n10 = g10.x * gx + g10.y * fy;
            double n01 = g01.x * fx + g01.y * gy;
            double n11 = g11.x * gx + g11.y * gy;
            double u = Fade(fx), v = Fade(fy), du = FadeDerivative(fx), dv = FadeDerivative(fy);
            double k1 = n10 - n00, k2 = n01 - n00, k3 = (n00 - n10) - (n01 - n11);
            double n = n00 + u * k1 + v * k2 + u * v * k3;
            double dx = g00.x + u * (g10.x - g00.x) + v * (g01.x - g00.x) + u * v * ((g00.x - g10.x) - (g01.x - g11.x))
                      + du * (k1 + v * k3);
            double dy = g00.y + u * (g10.y - g00.y) + v * (g01.y - g00.y) + u * v * ((g00.y - g10.y) - (g01.y - g11.y))
                      + dv * (k2 + u * k3);
            gradient = new Double2(Scale * dx, Scale * dy);
            return Scale * n;
        }

        /// <summary>
        /// Noise at the lattice coordinate <c>frequency * q + offset</c> of a <see cref="TerrainPoint"/>,
        /// gradient with respect to that lattice coordinate (multiply by frequency for d/dq).
        /// Deep-zoom precision: <c>frequency * originHi</c> can be thousands of lattice cells, where a
        /// float keeps only ~1e-4 of a cell, and its rounding would shift the whole pattern (and jump
        /// when the origin re-snaps). So the product is formed exactly as a float pair
        /// (<see cref="TwoProduct"/>), its integer part becomes the cell (exact below 2^24), and only
        /// small numbers, the product's fraction and rounding error, <c>frequency * local</c> and the
        /// offset's fraction, are added in float. The cell is then renormalised so the fraction lies in
        /// [0, 1]. With origin 0 this is <c>Evaluate(frequency * q + offset)</c> up to one rounding.
        /// </summary>
        public static float AtPoint(TerrainPoint p, float frequency, Float2 offset, out Float2 gradient, TerrainKeywords keywords = TerrainKeywords.None)
        {
            SplitLattice(p.originHi.x, p.local.x, frequency, offset.x, out int ix, out float fx);
            SplitLattice(p.originHi.y, p.local.y, frequency, offset.y, out int iy, out float fy);
            return Cell(ix, iy, fx, fy, out gradient, keywords);
        }

        /// <summary>One axis of <see cref="AtPoint"/>: <c>frequency * (hi + local) + offset = cell + fraction</c>.</summary>
        public static void SplitLattice(float hi, float local, float frequency, float offset, out int cell, out float fraction)
        {
            float ph = TwoProduct(hi, frequency, out float pe);      // hi * f = ph + pe exactly
            float ch = GMath.floor(ph), co = GMath.floor(offset);   // integer parts, exact
            // ph - ch and offset - co are exact (they only drop the integer bits); the rest is small.
            float fr = (ph - ch) + ((pe + local * frequency) + (offset - co));
            float cf = GMath.floor(fr);                               // fr lies in about [-eps, 2 + eps)
            cell = unchecked((int)ch + (int)co + (int)cf);
            fraction = fr - cf;
        }

        /// <summary>
        /// HLSL <c>GradientNoiseSplitLocal</c>: <see cref="SplitLattice"/> of a point without a hi part
        /// (hi = 0, no range origin), the same cell and fraction bit for bit (hi * frequency = 0 and its
        /// error 0 add nothing), without <see cref="TwoProduct"/>.
        /// </summary>
        public static void SplitLocal(float local, float frequency, float offset, out int cell, out float fraction)
        {
            float co = GMath.floor(offset);
            float fr = local * frequency + (offset - co);
            float cf = GMath.floor(fr);
            cell = unchecked((int)co + (int)cf);
            fraction = fr - cf;
        }

        /// <summary>HLSL <c>GradientNoiseAtLocal</c>: <see cref="AtPoint"/> of a point whose originHi is 0, bit for bit.</summary>
        public static float AtLocal(Float2 local, float frequency, Float2 offset, out Float2 gradient, TerrainKeywords keywords = TerrainKeywords.None)
        {
            SplitLocal(local.x, frequency, offset.x, out int ix, out float fx);
            SplitLocal(local.y, frequency, offset.y, out int iy, out float fy);
            return Cell(ix, iy, fx, fy, out gradient, keywords);
        }

        /// <summary>
        /// Dekker's TwoProduct without FMA: <c>a * b = p + err</c> exactly (barring under/overflow),
        /// by Veltkamp's split of each factor into 12-bit halves whose products are exact in float.
        /// Needs strict IEEE steps; the HLSL mirror marks them <c>precise</c>.
        /// </summary>
        public static float TwoProduct(float a, float b, out float err)
        {
            float p = a * b;
            Split(a, out float ah, out float al);
            Split(b, out float bh, out float bl);
            err = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
            return p;
        }

        static void Split(float a, out float hi, out float lo)
        {
            float c = 4097f * a;            // 2^12 + 1
            hi = c - (c - a);
            lo = a - hi;
        }
    }
}
