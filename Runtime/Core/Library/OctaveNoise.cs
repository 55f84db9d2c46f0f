using System;

namespace GregoryTerrain
{
    /// <summary>
    /// Height detail <c>p = amplitude * sum_k beta^-k * K(f_k q + offset_k)</c> over octaves
    /// k = 0 .. count-1 (eq. 12-13 with N octaves), K = <see cref="GradientNoise"/>, the last octave
    /// weighted by the fractional part of the count. Mirrored by Shaders/Library/OctaveNoise.hlsl
    /// (<c>OctaveNoise.Evaluate</c> is HLSL <c>OctaveNoise</c>).
    /// Octave frequencies are defined as the float sequence <c>f_0 = frequency, f_{k+1} = f_k * alpha</c>
    /// (the same on CPU and GPU); the double reference uses exactly those values, because at
    /// q ~ 0.7 and f ~ 1e4 a relative frequency difference of 1e-7 already moves the lattice by 1e-3 cells.
    /// </summary>
    internal static class OctaveNoise
    {
        /// <summary>
        /// Float evaluation at a <see cref="TerrainPoint"/> (deep-zoom safe, see <see cref="GradientNoise.AtPoint"/>).
        /// <paramref name="gradient"/> is d p / d q (terrain units), for the normal.
        /// <paramref name="octaveCount"/> is clamped to [0, settings.octaves].
        /// <see cref="TerrainKeywords.NoiseTable"/> in <paramref name="keywords"/>: every octave is the tiled noise (<see cref="GradientNoiseTable"/>).
        /// </summary>
        public static float Evaluate(TerrainPoint p, NoiseSettings settings, float octaveCount, out Float2 gradient, TerrainKeywords keywords = TerrainKeywords.None)
        {
            float count = ClampedCount(settings, octaveCount);
            var sum = new OctaveSum(settings);
            // Without a hi part (no range origin) the lattice split skips TwoProduct, as the HLSL
            // does (its branch): the same values bit for bit.
            bool local = p.originHi.x == 0f && p.originHi.y == 0f;
            for (int k = 0; k < settings.octaves; k++)
            {
                float fade = GMath.saturate(count - k);   // 1 for whole octaves, the fraction for the last
                if (fade <= 0f) break;
                Float2 offset = GradientNoise.StreamOffset((uint)k);
                float nk = local ? GradientNoise.AtLocal(p.local, sum.frequency, offset, out Float2 gk, keywords)
                                 : GradientNoise.AtPoint(p, sum.frequency, offset, out gk, keywords);
                sum.Add(fade, nk, gk, settings.alpha);
            }
            return sum.Result(settings.amplitude, out gradient);
        }

        /// <summary>
        /// The running sum over octaves of the float paths (HLSL <c>OctaveSum</c>): octave k weighted
        /// by <c>beta^-k</c> times its fade, its lattice gradient scaled by its frequency (chain rule:
        /// d/dq = f d/d(lattice)), frequencies the float sequence <c>f_{k+1} = f_k alpha</c>.
        /// </summary>
        struct OctaveSum
        {
            public float frequency;
            float _weight, _invBeta, _height;
            Float2 _gradient;

            public OctaveSum(NoiseSettings settings)
            {
                frequency = settings.frequency;
                _weight = 1f;
                _invBeta = 1f / settings.beta;
                _height = 0f;
                _gradient = new Float2(0f, 0f);
            }

            /// <summary>Adds octave value <paramref name="nk"/> (gradient <paramref name="gk"/>, lattice units) at the current frequency, then steps to the next octave.</summary>
            public void Add(float fade, float nk, Float2 gk, float alpha)
            {
                float wk = _weight * fade;
                _height += wk * nk;
                _gradient += gk * (wk * frequency);
                frequency *= alpha;
                _weight *= _invBeta;
            }

            public float Result(float amplitude, out Float2 gradient)
            {
                gradient = _gradient * amplitude;
                return amplitude * _height;
            }
        }

        /// <summary>The octave count clamped to [0, settings.octaves], after checking the inputs.</summary>
        static float ClampedCount(NoiseSettings settings, float octaveCount)
        {
            settings.Validate(nameof(settings));
            if (float.IsNaN(octaveCount)) throw new ArgumentException("octaveCount (NaN) must be a number", nameof(octaveCount));
            return GMath.clamp(octaveCount, 0f, settings.octaves);
        }

        /// <summary>
        /// The deep-zoom noise height <c>p(q) - p(O)</c> (precision.md), O the range origin, from the
        /// precise difference <paramref name="qMinusOrigin"/> = q - O (<c>RelativeSurface.Difference</c>),
        /// never as the difference of two absolute floats. Per octave: q in O's cell, one
        /// <see cref="GradientNoise.CellDifference"/>; in a neighbouring cell, through r1 = O clamped into
        /// q's cell; farther, the two absolute values (Tools~/docs/design-notes.md, "Precision: the noise
        /// difference, term by term"). Depends on q and per-frame constants only (shared tile edges stay bit-identical).
        /// <paramref name="gradient"/> is d p / d q at q, as from <see cref="Evaluate(TerrainPoint, NoiseSettings, float, out Float2, TerrainKeywords)"/>.
        /// Mirrors HLSL <c>OctaveNoiseRelative</c>; the renderer adds p(O) (double) back.
        /// </summary>
        public static float Relative(TerrainPoint q, TerrainPoint origin, Float2 qMinusOrigin, NoiseSettings settings, float octaveCount, out Float2 gradient,
                                     TerrainKeywords keywords = TerrainKeywords.None)
        {
            float count = ClampedCount(settings, octaveCount);
            var sum = new OctaveSum(settings);
            for (int k = 0; k < settings.octaves; k++)
            {
                float fade = GMath.saturate(count - k);
                if (fade <= 0f) break;
                float nk = OctaveNoiseDifference(q, origin, qMinusOrigin, sum.frequency, GradientNoise.StreamOffset((uint)k), out Float2 gk, keywords);
                sum.Add(fade, nk, gk, settings.alpha);
            }
            return sum.Result(settings.amplitude, out gradient);
        }

        /// <summary>One octave of <see cref="Relative"/>: <c>K(f q + offset) - K(f O + offset)</c>, gradient at q (lattice units).</summary>
        public static float OctaveNoiseDifference(TerrainPoint q, TerrainPoint origin, Float2 qMinusOrigin, float frequency, Float2 offset, out Float2 gradient,
                                             TerrainKeywords keywords = TerrainKeywords.None)
        {
            GradientNoise.SplitLattice(origin.originHi.x, origin.local.x, frequency, offset.x, out int cx, out float fx);
            GradientNoise.SplitLattice(origin.originHi.y, origin.local.y, frequency, offset.y, out int cy, out float fy);
            float sx = qMinusOrigin.x * frequency, sy = qMinusOrigin.y * frequency;   // the lattice step
            int mx = (int)GMath.floor(fx + sx), my = (int)GMath.floor(fy + sy);      // q's cell relative to O's
            if (mx == 0 && my == 0)
                return GradientNoise.CellDifference(cx, cy, fx, fy, sx, sy, out gradient, out _, keywords);
            if (Math.Abs(mx) <= 1 && Math.Abs(my) <= 1)
            {
                // r1 = O clamped into q's cell, in O's cell frame: f0, or the line at 1 or 0.
                float rx = mx == 0 ? fx : (mx > 0 ? 1f : 0f), ry = my == 0 ? fy : (my > 0 ? 1f : 0f);
                float tx = rx - fx, ty = ry - fy;                                    // O -> r1
                float toR1 = GradientNoise.CellDifference(cx, cy, fx, fy, tx, ty, out _, out _, keywords);
                float fromR1 = GradientNoise.CellDifference(cx + mx, cy + my, rx - mx, ry - my, sx - tx, sy - ty, out gradient, out _, keywords);
                return fromR1 + toR1;
            }
            float atQ = GradientNoise.AtPoint(q, frequency, offset, out gradient, keywords);
            return atQ - GradientNoise.Cell(cx, cy, fx, fy, out _, keywords);
        }

        /// <summary>The double reference at <c>(x, y)</c>, same octaves, frequencies and offsets.</summary>
        public static double Evaluate(double x, double y, NoiseSettings settings, double octaveCount, out Double2 gradient, TerrainKeywords keywords = TerrainKeywords.None)
        {
            settings.Validate(nameof(settings));
            if (!GMath.isfinite(x) || !GMath.isfinite(y))
                throw new ArgumentException(FormattableString.Invariant($"point ({x:R}, {y:R}) must be finite"), nameof(x));
            if (double.IsNaN(octaveCount)) throw new ArgumentException("octaveCount (NaN) must be a number", nameof(octaveCount));
            double count = GMath.clamp(octaveCount, 0.0, settings.octaves);
            float f = settings.frequency;
            double w = 1.0, invBeta = 1.0 / settings.beta;
            double n = 0.0;
            var g = new Double2(0.0, 0.0);
            for (int k = 0; k < settings.octaves; k++)
            {
                double fade = GMath.saturate(count - k);
                if (fade <= 0.0) break;
                Double2 off = GradientNoise.StreamOffset((uint)k);
                double nk = GradientNoise.Evaluate(f * x + off.x, f * y + off.y, out Double2 gk, keywords);
                double wk = w * fade;
                n += wk * nk;
                g += gk * (wk * f);
                f *= settings.alpha;
                w *= invBeta;
            }
            gradient = g * settings.amplitude;
            return settings.amplitude * n;
        }

        /// <summary>
        /// How many octaves are worth evaluating: octave k counts when its wavelength
        /// <c>1 / (frequency * alpha^k)</c> is at least two vertex spacings, <c>2 * rangeWidth / verticesAcross</c>
        /// (finer detail only aliases): <c>1 + log_alpha(verticesAcross / (2 * rangeWidth * frequency))</c>,
        /// clamped to [0, octaves]; the fraction fades octave <c>floor(count)</c> in. Per-frame values only,
        /// so every vertex of a frame uses the same count.
        /// </summary>
        public static double OctaveCount(double rangeWidth, double verticesAcross, NoiseSettings settings)
        {
            settings.Validate(nameof(settings));
            if (!GMath.isfinite(rangeWidth) || !(rangeWidth > 0.0))
                throw new ArgumentException(FormattableString.Invariant($"rangeWidth ({rangeWidth:R}) must be finite and greater than 0"), nameof(rangeWidth));
            if (!GMath.isfinite(verticesAcross) || !(verticesAcross > 0.0))
                throw new ArgumentException(FormattableString.Invariant($"verticesAcross ({verticesAcross:R}) must be finite and greater than 0"), nameof(verticesAcross));
            double k = 1.0 + Math.Log(verticesAcross / (2.0 * rangeWidth * settings.frequency)) / Math.Log(settings.alpha);
            return GMath.clamp(k, 0.0, settings.octaves);
        }

        /// <summary>
        /// The continuous octave rule of the levels of detail (internals.md, "The continuous octave
        /// rule"): <see cref="OctaveCount"/> of the vertex spacing <c>segmentPixels / pixelsPerUnit</c>
        /// and one vertex, <paramref name="pixelsPerUnit"/> being TessellationPolicy.PixelsPerUnit at the
        /// surface point (no noise). An infinite scale (at or behind the eye plane) gives all octaves, zero none.
        /// </summary>
        public static double OctaveCountAtPixelScale(double pixelsPerUnit, double segmentPixels, NoiseSettings settings)
        {
            settings.Validate(nameof(settings));
            if (double.IsNaN(pixelsPerUnit) || pixelsPerUnit < 0.0)
                throw new ArgumentException(FormattableString.Invariant($"pixelsPerUnit ({pixelsPerUnit:R}) must be >= 0 (infinity allowed)"), nameof(pixelsPerUnit));
            if (!GMath.isfinite(segmentPixels) || !(segmentPixels > 0.0))
                throw new ArgumentException(FormattableString.Invariant($"segmentPixels ({segmentPixels:R}) must be finite and greater than 0"), nameof(segmentPixels));
            if (double.IsPositiveInfinity(pixelsPerUnit)) return settings.octaves;
            if (pixelsPerUnit == 0.0) return 0.0;
            return OctaveCount(segmentPixels / pixelsPerUnit, 1.0, settings);
        }
    }
}
