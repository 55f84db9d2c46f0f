using System;

namespace GregoryTerrain
{
    /// <summary>Which vertex arithmetic <see cref="ZoomJitter"/> measures.</summary>
    internal enum VertexPath
    {
        /// <summary>The paper's: origin 0, float <c>q = c + o (g - c)</c>, absolute float S(q) as the object position.</summary>
        Plain,
        /// <summary>The hi/lo range origin (precise q and u, v) but still the absolute float S(q) as the output.</summary>
        OriginOnly,
        /// <summary>What the shaders do: <see cref="RangeOrigin.For"/>, and with an origin the relative output <see cref="RelativeSurface"/>.</summary>
        Shipped,
    }

    /// <summary>
    /// Vertex jitter at deep zoom (precision.md). The zoom view maps the range's width w onto
    /// <c>pixels</c> pixels, uniformly in x, y and height, so a terrain-space error e is
    /// <c>e * pixels / w</c> pixels on screen. A vertex (tile, s, t) of a frame has the error
    /// <c>E = (P - S_true(q_true)) * pixels / w</c>, P the position the path computes (relative outputs
    /// plus their double reference point), q_true the exact double point of that vertex. When the range pans by a
    /// sub-pixel amount, the vertex should move exactly as the true surface does; the part that does
    /// not is <c>E(frame) - E(frame 0)</c>. Jitter = the largest length of that, over every vertex of
    /// the tiling and every panned frame. The origin is the one <see cref="RangeOrigin.For"/> picks
    /// for frame 0 and is kept for all frames (a renderer re-snaps only when the view has moved far).
    /// </summary>
    internal static class ZoomJitter
    {
        /// <summary>Frames measured after frame 0; frame k pans by (k, k/2) * panPixels.</summary>
        public const int Frames = 8;

        /// <summary>
        /// The jitter in pixels of <paramref name="path"/> on <paramref name="grid"/> for a square range of
        /// width <paramref name="width"/> centred at <paramref name="center"/>, drawn as tiles x tiles
        /// tiles at integer factor <paramref name="factor"/>, panned by <paramref name="panPixels"/>
        /// per frame. <paramref name="largestError"/>: the largest |E| itself (accuracy, not jitter).
        /// With <paramref name="noise"/> the height includes the octave noise (GT_NOISE) at the
        /// frame-0 octave count for <c>tiles * factor</c> vertices across, kept for all frames; the
        /// shipped path then adds p(O) (double) to the relative noise as the renderer does.
        /// </summary>
        public static double Measure(PatchGrid grid, VertexPath path, Double2 center, double width,
            double pixels, int tiles, int factor, double panPixels, out double largestError, NoiseSettings? noise = null)
        {
            if (grid == null) throw new ArgumentNullException(nameof(grid));
            if (!GMath.isfinite(width) || !(width > 0.0) || width > 1.0)
                throw new ArgumentException(FormattableString.Invariant($"width ({width:R}) must lie in (0, 1]"), nameof(width));
            TerrainRange.CheckSize(nameof(width), width);
            if (!GMath.isfinite(pixels) || !(pixels >= 1.0))
                throw new ArgumentException(FormattableString.Invariant($"pixels ({pixels:R}) must be at least 1"), nameof(pixels));
            if (factor < 1 || factor > 64)
                throw new ArgumentException(FormattableString.Invariant($"factor ({factor}) must lie in [1, 64]"), nameof(factor));
            if (!GMath.isfinite(panPixels) || panPixels < 0.0)
                throw new ArgumentException(FormattableString.Invariant($"panPixels ({panPixels:R}) must be finite and >= 0"), nameof(panPixels));
            var fgrid = TerrainInputs.ForGrid(grid);
            TerrainRange range0 = Square(center, width, 0.0, 0.0);
            RangeOrigin origin = path == VertexPath.Plain ? RangeOrigin.zero : RangeOrigin.For(range0);
            if (path == VertexPath.OriginOnly && origin.Equals(RangeOrigin.zero)) origin = RangeOrigin.Snap(range0.Center);
            bool relative = path == VertexPath.Shipped && RelativeSurface.IsActive(origin.ToFloat4());
            Double3 reference = relative ? RelativeSurface.ReferencePoint(grid, origin) : default;
            float octaves = 0f;
            if (noise.HasValue)
            {
                octaves = (float)OctaveNoise.OctaveCount(width, tiles * factor, noise.Value);
                Double2 o = origin.Value;
                if (relative) reference.z += OctaveNoise.Evaluate(o.x, o.y, noise.Value, octaves, out _);
            }
            double scale = pixels / width, pan = panPixels * width / pixels;
            int across = factor + 1, perFrame = tiles * tiles * across * across;
            var first = new Double3[perFrame];
            double jitter = 0.0;
            largestError = 0.0;
            for (int frame = 0; frame <= Frames; frame++)
            {
                TerrainRange range = Square(center, width, frame * pan, 0.5 * frame * pan);
                RangeMapping.EncodeRange(range, origin, out Float4 rangeF, out Float4 originF);
                int n = 0;
                for (int tj = 0; tj < tiles; tj++)
                    for (int ti = 0; ti < tiles; ti++)
                        for (int y = 0; y < across; y++)
                            for (int x = 0; x < across; x++, n++)
                            {
                                float s = (float)x / factor, t = (float)y / factor;
                                Double3 p = PathPosition(fgrid, relative, reference, rangeF, originF, tiles, ti, tj, s, t, noise, octaves);
                                Double2 q = RangeMapping.GlobalPoint(range, tiles, ti, tj, s, t);
                                Double3 truth = RelativeSurface.SurfaceAt(grid, q);
                                if (noise.HasValue) truth.z += OctaveNoise.Evaluate(q.x, q.y, noise.Value, octaves, out _);
                                Double3 e = (p - truth) * scale;
                                if (!e.IsFinite) return double.PositiveInfinity;
                                largestError = Math.Max(largestError, Length(e));
                                if (frame == 0) first[n] = e;
                                else jitter = Math.Max(jitter, Length(e - first[n]));
                            }
            }
            return jitter;
        }

        /// <summary>The vertex position a path computes, in double (relative output + its reference point).</summary>
        static Double3 PathPosition(TerrainInputs grid, bool relative, Double3 reference,
            Float4 rangeF, Float4 originF, int tiles, int ti, int tj, float s, float t, NoiseSettings? noise, float octaves)
        {
            TerrainPoint q = RangeMapping.ToTerrainPoint(rangeF, originF, tiles, ti, tj, s, t);
            if (relative)
            {
                Float3 d = RelativeSurface.FromOrigin(grid, q, originF);
                if (noise.HasValue)
                {
                    TerrainPoint o = RelativeSurface.OriginPoint(originF);
                    d.z += OctaveNoise.Relative(q, o, RelativeSurface.Difference(q, o), noise.Value, octaves, out _);
                }
                return reference + new Double3(d.x, d.y, d.z);
            }
            Float3 position = TerrainVertex.EvaluateSurfaceAt(grid, q).position;
            if (noise.HasValue) position.z += OctaveNoise.Evaluate(q, noise.Value, octaves, out _);
            return new Double3(position.x, position.y, position.z);
        }

        /// <summary>A square range of width w centred at c + (dx, dy), clamped inside the unit square.</summary>
        static TerrainRange Square(Double2 c, double w, double dx, double dy)
        {
            double x0 = Math.Min(Math.Max(c.x + dx - 0.5 * w, 0.0), 1.0 - w);
            double y0 = Math.Min(Math.Max(c.y + dy - 0.5 * w, 0.0), 1.0 - w);
            return new TerrainRange(x0, y0, x0 + w, y0 + w);
        }

        static double Length(Double3 v) => Math.Sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    }
}
