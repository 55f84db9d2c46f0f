using System;

namespace GregoryTerrain
{
    /// <summary>The shader keywords that change what <see cref="TerrainVertex"/> computes.</summary>
    [Flags]
    internal enum TerrainKeywords
    {
        None = 0,
        /// <summary>GT_NOISE: octave noise on the height, its gradient in the normal.</summary>
        Noise = 1,
        /// <summary>GT_HEIGHT_COLOR: the colour noise l of eq. 14 is evaluated.</summary>
        HeightColor = 2,
        /// <summary>GT_PAPER_MODE: the draw patch is a Gregory patch tessellated over the whole range.</summary>
        PaperMode = 4,
        /// <summary>GT_SNOW: the surface is raised by the snow depth (<see cref="TerrainInputs.Snow"/>).</summary>
        Snow = 8,
        /// <summary>GT_NOISE_TABLE: the height and colour noise are the tiled noise (<see cref="GradientNoiseTable"/>).</summary>
        NoiseTable = 16,
    }

    /// <summary>A point of the Gregory surface (no noise yet), terrain space. HLSL <c>TerrainSurfacePoint</c>.</summary>
    internal struct TerrainSurfacePoint
    {
        /// <summary>The global point, hi/lo.</summary>
        public TerrainPoint q;
        /// <summary>The Gregory patch that was evaluated.</summary>
        public int patch;
        /// <summary>Its region (a, b, e, f) as the GPU holds it (the hi parts of its grid lines).</summary>
        public Float4 region;
        /// <summary>The lo parts of its grid lines (<see cref="TerrainInputs.PatchRegionLo"/>).</summary>
        public Float4 regionLo;
        /// <summary>The patch-local coordinate that was evaluated.</summary>
        public Float2 uv;
        public Float3 position, dPdu, dPdv;
    }

    /// <summary>
    /// What the vertex stage produces for one vertex: HLSL <c>TerrainVaryings</c> before the camera
    /// (object space, Unity's Y-up (x, z, y)), plus the terrain-space values and what the rig reads back.
    /// </summary>
    internal struct TerrainVertexOutput
    {
        /// <summary>The surface point it started from (q, patch, region, uv, Gregory position and derivatives).</summary>
        public TerrainSurfacePoint surface;
        /// <summary>Terrain space (x, y, z = height), noise included.</summary>
        public Float3 position;
        /// <summary>Terrain space unit normal, noise gradient included; zero on a degenerate patch.</summary>
        public Float3 normal;
        /// <summary>l of eq. 14 (0 without <see cref="TerrainKeywords.HeightColor"/>).</summary>
        public float colorNoise;
        /// <summary>
        /// S'z of eq. 14: Gregory height plus the absolute noise height, without snow, absolute even at
        /// deep zoom (where <see cref="position"/> is relative). HLSL <c>TerrainVertexAttributes.absoluteHeight</c>.
        /// </summary>
        public float absoluteHeight;
        /// <summary>Snow depth added to the height (0 without <see cref="TerrainKeywords.Snow"/>); the fragment stage's coverage input.</summary>
        public float snowDepth;

        /// <summary>Object space position (x, z, y): what the readback's first float4 holds.</summary>
        public Float3 PositionOS => TerrainVertex.TerrainToObject(position);
        /// <summary>Object space normal: the readback's second float4.</summary>
        public Float3 NormalOS => TerrainVertex.TerrainToObject(normal);
    }

    /// <summary>
    /// The one evaluation path from (draw patch, tess coordinate) to a terrain vertex, in float, step
    /// for step as <c>Shaders/Terrain/TerrainVertex.hlsl</c> does it (C# <see cref="EvaluateSurface"/> is HLSL
    /// <c>EvaluateSurface</c>, <see cref="Evaluate"/> is HLSL <c>TerrainVertex</c>):
    /// <code>
    ///   tess --RangeToTerrainPoint--> q --FindPatch (float lines)--> patch --PatchLocalUV--> (u, v)
    ///     --GregoryEval (float)--> S, dS/du, dS/dv  [+ OctaveNoise(q), its gradient by the chain rule]
    ///     --NormalFromDerivatives--> normal
    /// </code>
    /// The rig compares this with the GPU's readback; <see cref="Reference"/> is the same surface in
    /// double at the exact global point, for error measures.
    /// </summary>
    internal static class TerrainVertex
    {
        /// <summary>Terrain space (x, y, z = height) to Unity object space (x, z, y); orthogonal, so normals too.</summary>
        public static Float3 TerrainToObject(Float3 v) => new Float3(v.x, v.z, v.y);

        /// <summary>Double version of <see cref="TerrainToObject(Float3)"/>.</summary>
        public static Double3 TerrainToObject(Double3 v) => new Double3(v.x, v.z, v.y);

        /// <summary>
        /// HLSL <c>EvaluateSurface(drawPatch, tess)</c>. <paramref name="drawPatch"/>: the tile
        /// (<c>tj M + ti</c>), or with <see cref="TerrainKeywords.PaperMode"/> a Gregory patch;
        /// <paramref name="tess"/> in [0, 1]^2.
        /// </summary>
        public static TerrainSurfacePoint EvaluateSurface(TerrainInputs inputs, int drawPatch, Float2 tess, TerrainKeywords keywords = TerrainKeywords.None)
        {
            if (inputs == null) throw new ArgumentNullException(nameof(inputs));
            TerrainParams p = inputs.Params;
            if ((keywords & TerrainKeywords.PaperMode) != 0)
            {
                if ((uint)drawPatch >= (uint)inputs.PatchCount())
                    throw new ArgumentException(FormattableString.Invariant($"drawPatch ({drawPatch}) must lie in [0, {inputs.PatchCount() - 1}] in paper mode"), nameof(drawPatch));
                // Every Gregory patch over the whole range, u and v clamped.
                TerrainPoint q = RangeMapping.ToTerrainPoint(p.range, p.rangeOrigin, 1, 0, 0, tess.x, tess.y);
                Float4 region = inputs.PatchRegion(drawPatch), regionLo = inputs.PatchRegionLo(drawPatch);
                Float2 uv = RangeMapping.PatchLocalUV(q, region, regionLo);
                return EvaluatePatch(inputs, q, drawPatch, region, regionLo, new Float2(GMath.saturate(uv.x), GMath.saturate(uv.y)));
            }
            int tiles = inputs.TilesAcross();
            if (tiles < 1 || (uint)drawPatch >= (uint)(tiles * tiles))
                throw new ArgumentException(FormattableString.Invariant($"drawPatch ({drawPatch}) must lie in [0, {tiles * tiles - 1}] for {tiles} x {tiles} tiles"), nameof(drawPatch));
            // Integer tile index first; the lattice point forms k + s before dividing (watertight).
            TerrainPoint point = TileLattice.TileToTerrainPoint(p, drawPatch, tess.x, tess.y);
            return EvaluateSurfaceAt(inputs, point);
        }

        /// <summary>
        /// HLSL <c>EvaluateCellSurface(slot, tess)</c>: the surface at tess in the whole cell slot
        /// <paramref name="slot"/> holds (<see cref="TileLattice.CellToTerrainPoint"/>), where the
        /// adaptive factors sample it. Tile mode only.
        /// </summary>
        public static TerrainSurfacePoint EvaluateCellSurface(TerrainInputs inputs, int slot, Float2 tess)
        {
            if (inputs == null) throw new ArgumentNullException(nameof(inputs));
            int tiles = inputs.TilesAcross();
            if (tiles < 1 || (uint)slot >= (uint)(tiles * tiles))
                throw new ArgumentException(FormattableString.Invariant($"slot ({slot}) must lie in [0, {tiles * tiles - 1}] for {tiles} x {tiles} tiles"), nameof(slot));
            return EvaluateSurfaceAt(inputs, TileLattice.CellToTerrainPoint(inputs.Params, slot, tess.x, tess.y));
        }

        /// <summary>
        /// The tile path of <see cref="EvaluateSurface"/> after the global point is formed:
        /// <see cref="RelativeSurface.FindPatchAt"/> (on the hi/lo lines while a range origin is set),
        /// PatchLocalUV, GregoryEval of the relative points plus the patch's reference point. Use it
        /// with the q a GPU read back to compare the rest of the path at the GPU's point.
        /// </summary>
        public static TerrainSurfacePoint EvaluateSurfaceAt(TerrainInputs inputs, TerrainPoint q)
        {
            if (inputs == null) throw new ArgumentNullException(nameof(inputs));
            if (!q.originHi.IsFinite || !q.local.IsFinite)
                throw new ArgumentException($"q {q} must be finite", nameof(q));
            int patch = RelativeSurface.FindPatchAt(inputs, q);
            Float4 region = inputs.PatchRegion(patch), regionLo = inputs.PatchRegionLo(patch);
            return EvaluatePatch(inputs, q, patch, region, regionLo, RangeMapping.PatchLocalUV(q, region, regionLo));
        }

        static TerrainSurfacePoint EvaluatePatch(TerrainInputs inputs, TerrainPoint q, int patch, Float4 region, Float4 regionLo, Float2 uv)
        {
            Span<Float3> cp = stackalloc Float3[GregoryPatch.SlotCount];
            inputs.LoadGregoryPatch(patch, cp);
            GregoryEval.Evaluate(cp, uv.x, uv.y, out Float3 relative, out Float3 dPdu, out Float3 dPdv);
            Float3 position = inputs.PatchReference(patch) + relative;
            return new TerrainSurfacePoint { q = q, patch = patch, region = region, regionLo = regionLo, uv = uv, position = position, dPdu = dPdu, dPdv = dPdv };
        }

        /// <summary>HLSL <c>TerrainVertex(drawPatch, tess, ...)</c> without the camera.</summary>
        public static TerrainVertexOutput Evaluate(TerrainInputs inputs, int drawPatch, Float2 tess, TerrainKeywords keywords = TerrainKeywords.None) =>
            FinishTerrainVertex(inputs, EvaluateSurface(inputs, drawPatch, tess, keywords), keywords, null);

        /// <summary>
        /// <see cref="Evaluate"/> seen by a camera: under the
        /// continuous octave rule (<see cref="TerrainInputs.NoiseSegmentPixels"/> &gt; 0) the octave
        /// count comes from the pixel scale at the vertex (<see cref="VertexOctaveCount"/>), which needs
        /// the camera's object-to-clip matrix and the screen size in pixels.
        /// </summary>
        public static TerrainVertexOutput EvaluateWithCamera(TerrainInputs inputs, int drawPatch, Float2 tess, TerrainKeywords keywords,
                                                             Float4x4 objectToClip, Float2 screenSize) =>
            FinishTerrainVertex(inputs, EvaluateSurface(inputs, drawPatch, tess, keywords), keywords, (objectToClip, screenSize));

        /// <summary><see cref="EvaluateWithCamera"/> in tile mode from a given global point (see <see cref="EvaluateSurfaceAt"/>).</summary>
        public static TerrainVertexOutput EvaluateAtWithCamera(TerrainInputs inputs, TerrainPoint q, TerrainKeywords keywords,
                                                               Float4x4 objectToClip, Float2 screenSize)
        {
            if ((keywords & TerrainKeywords.PaperMode) != 0)
                throw new ArgumentException("keywords: EvaluateAtWithCamera is the tile path; paper mode needs the draw patch", nameof(keywords));
            return FinishTerrainVertex(inputs, EvaluateSurfaceAt(inputs, q), keywords, (objectToClip, screenSize));
        }

        /// <summary>
        /// HLSL <c>VertexOctaveCount</c>: the octaves a vertex whose surface (no noise) outputs
        /// <paramref name="surfacePosition"/> draws. The single-range rule (<see cref="TerrainInputs.NoiseOctaveCount()"/>)
        /// unless <see cref="TerrainInputs.NoiseSegmentPixels"/> &gt; 0 (the levels, tile mode): then the
        /// continuous rule at the vertex's pixel scale (<see cref="TerrainInputs.NoiseOctaveCountAt"/>),
        /// a function of q and the camera only, so both sides of a level seam agree. Throws when that
        /// rule is on and no camera is given.
        /// </summary>
        public static float VertexOctaveCount(TerrainInputs inputs, Float3 surfacePosition, TerrainKeywords keywords,
                                              (Float4x4 objectToClip, Float2 screenSize)? camera)
        {
            if (inputs == null) throw new ArgumentNullException(nameof(inputs));
            if ((keywords & TerrainKeywords.PaperMode) != 0 || !(inputs.NoiseSegmentPixels() > 0f)) return inputs.NoiseOctaveCount();
            if (camera == null)
                throw new ArgumentException(FormattableString.Invariant(
                    $"camera: noiseOctaves.z ({inputs.NoiseSegmentPixels():R} segment pixels) turns the continuous octave rule on, which needs the camera"), nameof(camera));
            float k = TessellationPolicy.PixelsPerUnit(camera.Value.objectToClip, TerrainToObject(surfacePosition), camera.Value.screenSize);
            return TerrainInputs.NoiseOctaveCountAt(inputs.Params, k);
        }

        /// <summary><see cref="Evaluate"/> in tile mode from a given global point (see <see cref="EvaluateSurfaceAt"/>).</summary>
        public static TerrainVertexOutput EvaluateAt(TerrainInputs inputs, TerrainPoint q, TerrainKeywords keywords = TerrainKeywords.None)
        {
            if ((keywords & TerrainKeywords.PaperMode) != 0)
                throw new ArgumentException("keywords: EvaluateAt is the tile path; paper mode needs the draw patch (use Evaluate)", nameof(keywords));
            return FinishTerrainVertex(inputs, EvaluateSurfaceAt(inputs, q), keywords, null);
        }

        /// <summary>
        /// The surface position a vertex outputs before noise: S(q), or, while a range origin is set
        /// (deep zoom), S(q) - S(O) from precise differences (<see cref="RelativeSurface"/>); the
        /// renderer adds S(O) (and p(O) with noise, see <see cref="OutputOffset(PatchGrid, TerrainParams, TerrainKeywords)"/>) in the object-to-world transform. Paper mode always outputs S(q).
        /// Mirrors HLSL <c>OutputSurfacePosition</c>.
        /// </summary>
        public static Float3 OutputSurfacePosition(TerrainInputs inputs, TerrainSurfacePoint s, TerrainKeywords keywords)
        {
            if ((keywords & TerrainKeywords.PaperMode) != 0) return s.position;
            Float4 origin = inputs.Params.rangeOrigin;
            return RelativeSurface.IsActive(origin) ? RelativeSurface.FromOrigin(inputs, s.q, origin) : s.position;
        }

        /// <summary>
        /// What the renderer adds back to a vertex's output position in the object-to-world transform,
        /// in double (terrain space): with a range origin (tile mode) S(O) plus, with noise, p(O) at
        /// the frame's octave count (recomputed when the range changes); else zero.
        /// </summary>
        public static Double3 OutputOffset(TerrainInputs inputs, PatchGrid grid, TerrainKeywords keywords)
        {
            if (inputs == null) throw new ArgumentNullException(nameof(inputs));
            return OutputOffset(grid, inputs.Params, keywords);
        }

        /// <summary>
        /// <see cref="OutputOffset(TerrainInputs, PatchGrid, TerrainKeywords)"/> from the constant block
        /// alone (what a renderer holds): <paramref name="p"/>'s <c>_RangeOrigin</c>, noise and octave count.
        /// </summary>
        public static Double3 OutputOffset(PatchGrid grid, TerrainParams p, TerrainKeywords keywords)
        {
            if (grid == null) throw new ArgumentNullException(nameof(grid));
            Float4 rangeOriginF = p.rangeOrigin;
            if ((keywords & TerrainKeywords.PaperMode) != 0 || !RelativeSurface.IsActive(rangeOriginF)) return Double3.zero;
            var origin = new RangeOrigin { hi = new Float2(rangeOriginF.x, rangeOriginF.y), lo = new Float2(rangeOriginF.z, rangeOriginF.w) };
            Double3 s = RelativeSurface.ReferencePoint(grid, origin);
            if ((keywords & TerrainKeywords.Noise) != 0)
            {
                Double2 o = origin.Value;
                var noise = new NoiseSettings(p.noise.x, p.noise.y, p.noise.z, p.noise.w, (int)p.noiseOctaves.x);
                s.z += OctaveNoise.Evaluate(o.x, o.y, noise, OutputOffsetOctaves(p), out _, keywords);
            }
            return s;
        }

        /// <summary>
        /// The octaves of p(O) in <see cref="OutputOffset(PatchGrid, TerrainParams, TerrainKeywords)"/>: a vertex
        /// outputs <c>p_c(q) - p_c(O)</c> at its own count c, so the offset must be O's noise at the
        /// count of the vertices the eye sees closest. Single-range rule: the frame's one count. Under
        /// the continuous rule (<c>_NoiseOctaves.z</c> &gt; 0, the levels) every octave: the feet draw them all.
        /// </summary>
        public static float OutputOffsetOctaves(TerrainParams p) =>
            p.noiseOctaves.z > 0f ? GMath.clamp(p.noiseOctaves.x, 0f, NoiseSettings.MaxOctaves) : TerrainInputs.NoiseOctaveCount(p);

        /// <summary>HLSL <c>UsesPlainPath</c>: the levels' plain path where k e &lt;= 1/4 px (internals.md, "The levels' plain path").</summary>
        public const float PlainPathPixels = 0.25f;   // HLSL GT_PLAIN_PATH_PIXELS

        public static bool UsesPlainPath(TerrainParams p, float pixelScale)
        {
            float e = p.noiseOctaves.w;
            return e > 0f && p.noiseOctaves.z > 0f && pixelScale * e <= PlainPathPixels;
        }

        /// <summary><c>_OriginSurface</c>: S(O) and p(O) (<see cref="OutputOffsetOctaves"/>) rounded to float; 0 without an origin.</summary>
        public static Float4 OriginSurface(PatchGrid grid, TerrainParams p, TerrainKeywords keywords)
        {
            if (grid == null) throw new ArgumentNullException(nameof(grid));
            Float4 o = p.rangeOrigin;
            if ((keywords & TerrainKeywords.PaperMode) != 0 || !RelativeSurface.IsActive(o)) return default;
            var origin = new RangeOrigin { hi = new Float2(o.x, o.y), lo = new Float2(o.z, o.w) };
            Double3 s = RelativeSurface.ReferencePoint(grid, origin);
            double n = 0.0;
            if ((keywords & TerrainKeywords.Noise) != 0)
            {
                var noise = new NoiseSettings(p.noise.x, p.noise.y, p.noise.z, p.noise.w, (int)p.noiseOctaves.x);
                n = OctaveNoise.Evaluate(origin.Value.x, origin.Value.y, noise, OutputOffsetOctaves(p), out _, keywords);
            }
            return new Float4((float)s.x, (float)s.y, (float)s.z, (float)n);
        }

        /// <summary><c>_NoiseOctaves.w</c>: the plain path's error bound e, terrain units (internals.md, "The levels' plain path").</summary>
        public static float PlainPathError(PatchGrid grid, TerrainParams p, TerrainKeywords keywords)
        {
            if (grid == null) throw new ArgumentNullException(nameof(grid));
            const double u = 1.0 / (1 << 24), slope = 4.0;   // float's unit roundoff; G
            double x = 0.0, z = 0.0, sum = 0.0;
            for (int i = 0; i < grid.PatchCount; i++)
                for (int c = 0; c < GregoryPatch.SlotCount; c++)
                {
                    Double3 v = grid.Patches[i][c];
                    x = Math.Max(x, Math.Max(Math.Abs(v.x), Math.Abs(v.y)));
                    z = Math.Max(z, Math.Abs(v.z));
                }
            if ((keywords & TerrainKeywords.Noise) != 0)
            {
                double a = Math.Abs(p.noise.x), beta = Math.Max(p.noise.w, 1f);
                for (int k = 0; k < (int)Math.Ceiling(GMath.clamp(p.noiseOctaves.x, 0f, NoiseSettings.MaxOctaves)); k++)
                {
                    sum += Math.Pow(beta, -k) * (p.noise.y * Math.Pow(p.noise.z, k) * x + 1.0);
                    z += a * Math.Pow(beta, -k);
                }
                sum *= 2.0 * slope * u * a;
            }
            return (float)(Math.Sqrt(3.0) * (3.0 * u * (x + z) + sum));
        }

        // HLSL FinishTerrainVertex, step for step (the HLSL takes the deep-zoom surface and noise in one branch).
                static TerrainVertexOutput FinishTerrainVertex(TerrainInputs inputs, TerrainSurfacePoint s, TerrainKeywords keywords,
                                                       (Float4x4 objectToClip, Float2 screenSize)? camera)
        {
            Float3 position = OutputSurfacePosition(inputs, s, keywords), dPdu = s.dPdu, dPdv = s.dPdv;
            float noiseHeight = 0f;   // the absolute p(q)
            // HLSL's GT_LOD branch: the levels (_NoiseOctaves.z > 0, sent only with them), an origin, a camera.
            bool levels = camera != null && (keywords & TerrainKeywords.PaperMode) == 0 && inputs.NoiseSegmentPixels() > 0f
                          && RelativeSurface.IsActive(inputs.Params.rangeOrigin);
            Float4 os = inputs.Params.originSurface;
            Float3 plainSurface = s.position - new Float3(os.x, os.y, os.z);
            float k = levels ? TessellationPolicy.PixelsPerUnit(camera.Value.objectToClip, TerrainToObject(plainSurface), camera.Value.screenSize) : 0f;
            bool plainColor = levels && UsesPlainPath(inputs.Params, k);   // the colour noise from the float point too
            if (plainColor) position = plainSurface;
            if ((keywords & TerrainKeywords.Noise) != 0)
            {
                // Noise lives on the global point; in paper mode a clamped vertex takes the noise of
                // the boundary point it collapsed onto.
                TerrainPoint noisePoint = s.q;
                if ((keywords & TerrainKeywords.PaperMode) != 0 && !s.uv.Equals(RangeMapping.PatchLocalUV(s.q, s.region, s.regionLo)))
                    noisePoint = new TerrainPoint(default, new Float2(GMath.lerp(s.region.x, s.region.z, s.uv.x), GMath.lerp(s.region.y, s.region.w, s.uv.y)));
                Float4 originF = inputs.Params.rangeOrigin;
                Float2 gradient;
                if (levels)
                {
                    if (plainColor)
                    {
                        float count = TerrainInputs.NoiseOctaveCountAt(inputs.Params, k);
                        noiseHeight = OctaveNoise.Evaluate(new TerrainPoint(default, RangeMapping.Approximate(s.q)), inputs.NoiseSettingsStruct(), count, out gradient, keywords);
                        position.z += noiseHeight - os.w;
                    }
                    else
                    {
                        float count = VertexOctaveCount(inputs, position, keywords, camera);
                        TerrainPoint origin = RelativeSurface.OriginPoint(originF);
                        float relative = OctaveNoise.Relative(s.q, origin, RelativeSurface.Difference(s.q, origin),
                                                              inputs.NoiseSettingsStruct(), count, out gradient, keywords);
                        position.z += relative;
                        noiseHeight = relative + os.w;   // for the colour: no precision needed
                    }
                }
                else if ((keywords & TerrainKeywords.PaperMode) == 0 && RelativeSurface.IsActive(originF))
                {
                    // Deep zoom: p(q) - p(O) from precise differences, like the surface (precision.md).
                    float octaves = VertexOctaveCount(inputs, position, keywords, camera);
                    TerrainPoint origin = RelativeSurface.OriginPoint(originF);
                    position.z += OctaveNoise.Relative(s.q, origin, RelativeSurface.Difference(s.q, origin),
                                                       inputs.NoiseSettingsStruct(), octaves, out gradient, keywords);
                    // The height colour needs the absolute p(q); HLSL evaluates it only with GT_HEIGHT_COLOR.
                    if ((keywords & TerrainKeywords.HeightColor) != 0)
                        noiseHeight = OctaveNoise.Evaluate(noisePoint, inputs.NoiseSettingsStruct(), octaves, out _, keywords);
                }
                else
                {
                    float octaves = VertexOctaveCount(inputs, position, keywords, camera);
                    noiseHeight = OctaveNoise.Evaluate(noisePoint, inputs.NoiseSettingsStruct(), octaves, out gradient, keywords);
                    position.z += noiseHeight;
                }
                // q = (a + u (e - a), b + v (f - b)): the chain rule scales the gradient by the region size.
                Float2 size = RangeMapping.RegionSize(s.region, s.regionLo);
                dPdu.z += gradient.x * size.x;
                dPdv.z += gradient.y * size.y;
            }
            float snowDepth = 0f;
            if ((keywords & TerrainKeywords.Snow) != 0)
            {
                // After the noise: snow lies on the detailed surface. The normal stays the terrain's
                // (the map's bilinear slope, up to cap / cell size, is no surface normal).
                snowDepth = SnowMap.Sample(inputs.Snow?.Depth ?? throw new ArgumentException("keywords: Snow needs inputs.Snow (TerrainInputs.WithSnow)", nameof(keywords)),
                                           inputs.SnowMapSize(), SnowPoint(s, keywords));
                position.z += snowDepth;
            }
            var o = new TerrainVertexOutput
            {
                surface = s,
                snowDepth = snowDepth,
                absoluteHeight = s.position.z + noiseHeight,
                position = position,
                normal = GregoryEval.NormalFromDerivatives(dPdu, dPdv),
            };
            if ((keywords & TerrainKeywords.HeightColor) != 0)
            {
                // Without a hi part the HLSL splits without TwoProduct (HeightColorNoiseAtLocal): the
                // same value bit for bit, mirrored here step for step.
                bool local = s.q.originHi.x == 0f && s.q.originHi.y == 0f;
                o.colorNoise = plainColor ? HeightColor.ColorNoiseAtLocal(RangeMapping.Approximate(s.q), inputs.HeightColorSettings(), keywords)
                             : local ? HeightColor.ColorNoiseAtLocal(s.q.local, inputs.HeightColorSettings(), keywords)
                                     : HeightColor.ColorNoise(s.q, inputs.HeightColorSettings(), keywords);
            }
            return o;
        }

        /// <summary>
        /// HLSL <c>TerrainHeightWeight</c>: s = saturate(l + z / gamma) of eq. 14 for the vertex's
        /// absolute height z and colour noise l, 0 without <see cref="TerrainKeywords.HeightColor"/>.
        /// </summary>
        public static float HeightWeight(TerrainVertexOutput v, TerrainInputs inputs, TerrainKeywords keywords) =>
            (keywords & TerrainKeywords.HeightColor) != 0 ? HeightColor.Weight(v.colorNoise, v.absoluteHeight, inputs.HeightColorSettings().gamma) : 0f;

        /// <summary>
        /// Where the snow map is read (HLSL <c>TerrainSnowPoint</c>): the global point; in paper mode the
        /// point of the patch that was evaluated (a clamped vertex sits on the patch boundary).
        /// </summary>
        static Float2 SnowPoint(TerrainSurfacePoint s, TerrainKeywords keywords) =>
            (keywords & TerrainKeywords.PaperMode) != 0
                ? new Float2(GMath.lerp(s.region.x, s.region.z, s.uv.x), GMath.lerp(s.region.y, s.region.w, s.uv.y))
                : RangeMapping.Approximate(s.q);

        // ---------------------------------------------------------------- double reference

        /// <summary>
        /// The same surface in double at the exact global point <paramref name="q"/> (terrain space):
        /// Gregory patch of the grid (double control points, double lines), plus, when
        /// <paramref name="noise"/> is given, its octave noise with <paramref name="octaveCount"/>
        /// octaves (pass the float path's <see cref="TerrainInputs.NoiseOctaveCount()"/> so the two
        /// differ only in arithmetic); <see cref="TerrainKeywords.NoiseTable"/> in <paramref name="keywords"/> makes
        /// it the tiled noise. Position (x, y, z) and unit normal.
        /// </summary>
        public static void Reference(PatchGrid grid, Double2 q, NoiseSettings? noise, double octaveCount,
                                     out Double3 position, out Double3 normal, TerrainKeywords keywords = TerrainKeywords.None)
        {
            if (grid == null) throw new ArgumentNullException(nameof(grid));
            if (!q.IsFinite) throw new ArgumentException($"q {q} must be finite", nameof(q));
            int patch = grid.FindPatch(q.x, q.y);
            Region region = grid.RegionOf(patch);
            Double2 uv = RangeMapping.LocalCoordinate(q, region);
            GregoryEval.Evaluate(grid.Patches[patch].Points, uv.x, uv.y, out position, out Double3 dPdu, out Double3 dPdv);
            if (noise.HasValue)
            {
                position.z += OctaveNoise.Evaluate(q.x, q.y, noise.Value, octaveCount, out Double2 gradient, keywords);
                dPdu.z += gradient.x * (region.e - region.a);
                dPdv.z += gradient.y * (region.f - region.b);
            }
            normal = GregoryEval.NormalFromDerivatives(dPdu, dPdv);
        }
    }
}
