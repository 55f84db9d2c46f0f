using System;

namespace GregoryTerrain
{
    /// <summary>
    /// The hull constant function's decisions (internals.md, "The tile layout"), mirrored by
    /// Shaders/Terrain/TessellationFactors.hlsl: edge factors from the screen-space length of each tile edge,
    /// the inside factor, and frustum culling of a tile's bounding box.
    /// <para>Crack-freedom: an edge's factor depends only on its own endpoints, symmetrically bit for
    /// bit (the neighbour walks the shared edge the other way round).</para>
    /// </summary>
    internal static class TessellationPolicy
    {
        /// <summary>
        /// Factor for an edge <paramref name="edgeLengthPixels"/> long on screen, aiming at
        /// <paramref name="targetPixelsPerSegment"/> pixels per segment: <c>clamp(length / target, 1, maxFactor)</c>.
        /// NaN or infinite lengths (an edge that could not be projected) give <paramref name="maxFactor"/>.
        /// </summary>
        public static float EdgeFactor(float edgeLengthPixels, float targetPixelsPerSegment, float maxFactor)
        {
            CheckTarget(targetPixelsPerSegment, maxFactor);
            return FactorFromLength(edgeLengthPixels, targetPixelsPerSegment, maxFactor);
        }

        static float FactorFromLength(float lengthPixels, float target, float maxFactor)
        {
            if (!GMath.isfinite(lengthPixels)) return maxFactor;
            return GMath.clamp(lengthPixels / target, 1f, maxFactor);
        }

        /// <summary>
        /// Clip position to normalised device coordinates times half the screen size: pixels from the
        /// screen centre. Only x and y; valid for <c>w &gt; 0</c>.
        /// </summary>
        public static Float2 ClipToPixels(Float4 clip, Float2 screenSize) =>
            new Float2(clip.x / clip.w * (0.5f * screenSize.x), clip.y / clip.w * (0.5f * screenSize.y));

        /// <summary>
        /// Screen-space length in pixels of the edge between two clip positions; symmetric bit for bit
        /// (<c>a - b == -(b - a)</c> in IEEE). +infinity when an endpoint has <c>w &lt;= 0</c>.
        /// </summary>
        public static float EdgeLengthPixels(Float4 clip0, Float4 clip1, Float2 screenSize)
        {
            if (!(clip0.w > 0f) || !(clip1.w > 0f)) return float.PositiveInfinity;
            Float2 p0 = ClipToPixels(clip0, screenSize), p1 = ClipToPixels(clip1, screenSize);
            float dx = p1.x - p0.x, dy = p1.y - p0.y;
            return GMath.sqrt(dx * dx + dy * dy);
        }

        /// <summary>The edge factor of the edge between two clip positions (HLSL <c>EdgeTessFactor</c>).</summary>
        public static float EdgeTessFactor(Float4 clip0, Float4 clip1, Float2 screenSize, float targetPixels, float maxFactor)
        {
            CheckTarget(targetPixels, maxFactor);
            CheckScreen(screenSize);
            return FactorFromLength(EdgeLengthPixels(clip0, clip1, screenSize), targetPixels, maxFactor);
        }

        /// <summary>Projects two world (object) points with <paramref name="viewProjection"/> (column vectors) and returns the edge factor.</summary>
        public static float EdgeTessFactor(Float4x4 viewProjection, Float3 p0, Float3 p1, Float2 screenSize, float targetPixels, float maxFactor)
        {
            if (!viewProjection.IsFinite) throw new ArgumentException($"viewProjection {viewProjection} must be finite", nameof(viewProjection));
            return EdgeTessFactor(viewProjection.TransformPoint(p0), viewProjection.TransformPoint(p1), screenSize, targetPixels, maxFactor);
        }

        /// <summary>
        /// The two inside factors of a quad tile from its edge factors (e0: u = 0, e1: v = 0, e2: u = 1,
        /// e3: v = 1): each the max of the two edges running the same way, so a long thin tile is not
        /// over-tessellated in its short direction. Mirrors HLSL <c>TessInsideFactors</c>.
        /// </summary>
        public static Float2 InsideFactors(float e0, float e1, float e2, float e3) =>
            new Float2(Math.Max(e1, e3), Math.Max(e0, e2));

        // ------------------------------------------------- adaptive: target screen-space error

        /// <summary>
        /// The most pixels one object-space unit covers on screen at a point, in any direction: the
        /// largest singular value of the (clip -> pixels) Jacobian, from the clip positions of the point
        /// and of the point moved one unit along x, y and z. +infinity at or behind the eye plane.
        /// </summary>
        public static float PixelsPerUnit(Float4 clip, Float4 clipX, Float4 clipY, Float4 clipZ, Float2 screenSize)
        {
            if (!(clip.w > 0f)) return float.PositiveInfinity;
            float invW = 1f / clip.w;
            float sx = clip.x * invW, sy = clip.y * invW;
            // d(x/w)/dX_k = (dx_k - (x/w) dw_k) / w, per column k; then NDC -> pixels.
            Float4 ax = clipX - clip, ay = clipY - clip, az = clipZ - clip;
            float hx = 0.5f * screenSize.x * invW, hy = 0.5f * screenSize.y * invW;
            var r0 = new Float3((ax.x - sx * ax.w) * hx, (ay.x - sx * ay.w) * hx, (az.x - sx * az.w) * hx);
            var r1 = new Float3((ax.y - sy * ax.w) * hy, (ay.y - sy * ay.w) * hy, (az.y - sy * az.w) * hy);
            return LargestSingularValue(r0, r1);
        }

        /// <summary><see cref="PixelsPerUnit(Float4, Float4, Float4, Float4, Float2)"/> of object point <paramref name="p"/>.</summary>
        public static float PixelsPerUnit(Float4x4 objectToClip, Float3 p, Float2 screenSize)
        {
            if (!objectToClip.IsFinite) throw new ArgumentException($"objectToClip {objectToClip} must be finite", nameof(objectToClip));
            if (!p.IsFinite) throw new ArgumentException($"p {p} must be finite", nameof(p));
            CheckScreen(screenSize);
            return PixelsPerUnit(objectToClip.TransformPoint(p), objectToClip.TransformPoint(p + new Float3(1f, 0f, 0f)),
                objectToClip.TransformPoint(p + new Float3(0f, 1f, 0f)), objectToClip.TransformPoint(p + new Float3(0f, 0f, 1f)), screenSize);
        }

        // Largest singular value of the 2x3 matrix with rows r0, r1: sqrt of the larger eigenvalue of
        // the symmetric 2x2 J J^T = [[a, b], [b, c]].
        static float LargestSingularValue(Float3 r0, Float3 r1)
        {
            float a = GMath.dot(r0, r0), b = GMath.dot(r0, r1), c = GMath.dot(r1, r1);
            float h = 0.5f * (a - c);
            return GMath.sqrt(0.5f * (a + c) + GMath.sqrt(h * h + b * b));
        }

        /// <summary>
        /// The chord error of an edge drawn as one segment, from its points at 0, 1/4, 1/2, 3/4, 1: a
        /// chord over a span h deviates by <c>|c| h^2 / 8</c> at its middle (c the second derivative), so
        /// each half's deviation counts four times; the largest of the three also sees an S-shaped edge.
        /// The same whichever end is first: shared edges agree (crack-free).
        /// </summary>
        public static float EdgeSagitta(Float3 p0, Float3 pQuarter, Float3 pMid, Float3 pThreeQuarter, Float3 p1)
        {
            float whole = GMath.length(pMid - 0.5f * (p0 + p1));
            float first = 4f * GMath.length(pQuarter - 0.5f * (p0 + pMid));
            float second = 4f * GMath.length(pThreeQuarter - 0.5f * (pMid + p1));
            return Math.Max(whole, Math.Max(first, second));
        }

        /// <summary>
        /// The adaptive edge factor <c>F = clamp(sqrt(2 s / targetPixelError), 1, maxFactor)</c>: F segments
        /// leave <c>s / F^2</c>, half the target per direction of a cell (internals.md, "Shader stages
        /// and compiled files"). A non-finite sagitta gives maxFactor.
        /// </summary>
        public static float ErrorTessFactor(float sagittaPixels, float targetPixelError, float maxFactor)
        {
            CheckTarget(targetPixelError, maxFactor);
            return FactorFromSagitta(sagittaPixels, targetPixelError, maxFactor);
        }

        static float FactorFromSagitta(float sagittaPixels, float target, float maxFactor)
        {
            if (!GMath.isfinite(sagittaPixels)) return maxFactor;
            return GMath.clamp(GMath.sqrt(2f * Math.Max(sagittaPixels, 0f) / target), 1f, maxFactor);
        }

        /// <summary>
        /// The tile's bend that its edges cannot see: the deviation of the tile centre
        /// <paramref name="pCentre"/> from the middle of each diagonal of the corner quad (corners in
        /// tess order (0,0), (1,0), (0,1), (1,1)), the larger one, times the pixel scale at the centre.
        /// A twisted tile (z ~ x y) has straight edges but bent diagonals.
        /// </summary>
        public static float DiagonalSagittaPixels(Float3 p00, Float3 p10, Float3 p01, Float3 p11, Float3 pCentre, float kCentre)
        {
            float d0 = GMath.length(pCentre - 0.5f * (p00 + p11));
            float d1 = GMath.length(pCentre - 0.5f * (p10 + p01));
            return Math.Max(d0, d1) * kCentre;
        }

        /// <summary>
        /// The inside factor a diagonal sagitta asks for, <c>clamp(sqrt(s / target), 1, maxFactor)</c>:
        /// the diagonal error already holds both directions' bending, so no factor 2.
        /// </summary>
        public static float InsideErrorTessFactor(float diagonalSagittaPixels, float targetPixelError, float maxFactor)
        {
            CheckTarget(targetPixelError, maxFactor);
            if (!GMath.isfinite(diagonalSagittaPixels)) return maxFactor;
            return GMath.clamp(GMath.sqrt(Math.Max(diagonalSagittaPixels, 0f) / targetPixelError), 1f, maxFactor);
        }

        /// <summary>
        /// The edge factor of an edge given as five object-space points (parameter 0, 1/4, 1/2, 3/4, 1),
        /// projected with <paramref name="objectToClip"/> (HLSL <c>EdgeErrorTessFactor</c>): each
        /// deviation counts in pixels at the point where it is measured (<see cref="PixelsPerUnit(Float4x4, Float3, Float2)"/>).
        /// </summary>
        public static float EdgeErrorTessFactor(Float4x4 objectToClip, Float3 p0, Float3 pQuarter, Float3 pMid, Float3 pThreeQuarter, Float3 p1,
                                                Float2 screenSize, float targetPixelError, float maxFactor)
        {
            CheckTarget(targetPixelError, maxFactor);
            CheckScreen(screenSize);
            if (!objectToClip.IsFinite) throw new ArgumentException($"objectToClip {objectToClip} must be finite", nameof(objectToClip));
            float kq = PixelsPerUnit(objectToClip, pQuarter, screenSize);
            float km = PixelsPerUnit(objectToClip, pMid, screenSize);
            float kt = PixelsPerUnit(objectToClip, pThreeQuarter, screenSize);
            return FactorFromSagitta(EdgeSagittaPixels(p0, pQuarter, pMid, pThreeQuarter, p1, kq, km, kt), targetPixelError, maxFactor);
        }

        /// <summary>
        /// <see cref="EdgeSagitta"/> with each of its three deviations converted to pixels by the scale
        /// at its own point (kQuarter, kMid, kThreeQuarter: <see cref="PixelsPerUnit(Float4, Float4, Float4, Float4, Float2)"/>).
        /// </summary>
        public static float EdgeSagittaPixels(Float3 p0, Float3 pQuarter, Float3 pMid, Float3 pThreeQuarter, Float3 p1,
                                              float kQuarter, float kMid, float kThreeQuarter)
        {
            float whole = GMath.length(pMid - 0.5f * (p0 + p1)) * kMid;
            float first = 4f * GMath.length(pQuarter - 0.5f * (p0 + pMid)) * kQuarter;
            float second = 4f * GMath.length(pThreeQuarter - 0.5f * (pMid + p1)) * kThreeQuarter;
            return Math.Max(whole, Math.Max(first, second));
        }

        /// <summary>
        /// Segments per tile edge the adaptive estimate samples (HLSL <c>GT_EDGE_SEGMENTS</c>) at its
        /// <c>EdgeSegments - 1</c> inner points (Tools~/bench/records.md, "Choices in the shaders, measured").
        /// </summary>
        public const int EdgeSegments = 8;

        /// <summary>
        /// The chord error, in pixels, of a curve drawn as one segment, from <c>n + 1</c> points at
        /// <c>k / n</c> (n even) and the pixel scale at each (the ends' unused): point k's deviation from
        /// the chord of its neighbours at distance d counts <c>(n / 2d)^2</c> times (sagitta ~ span^2);
        /// the largest over all levels and points. Shared edges agree bit for bit (the hull walks them
        /// lower tess coordinate first).
        /// </summary>
        public static float EdgeSagittaPixels(Float3[] points, float[] pixelScales)
        {
            if (points == null || points.Length < 3 || (points.Length - 1) % 2 != 0 || !IsPowerOfTwo(points.Length - 1))
                throw new ArgumentException(FormattableString.Invariant($"points (length {points?.Length ?? 0}) must hold 2^k + 1 >= 3 points"), nameof(points));
            if (pixelScales == null || pixelScales.Length != points.Length)
                throw new ArgumentException(FormattableString.Invariant($"pixelScales (length {pixelScales?.Length ?? 0}) must hold {points.Length} values"), nameof(pixelScales));
            int n = points.Length - 1;
            float s = 0f;
            for (int d = n / 2; d >= 1; d /= 2)
            {
                float weight = (float)(n / (2 * d)) * (n / (2 * d));   // (span 1 / span 2d/n)^2, exact in float
                for (int k = d; k < n; k += 2 * d)
                    s = Math.Max(s, weight * GMath.length(points[k] - 0.5f * (points[k - d] + points[k + d])) * pixelScales[k]);
            }
            return s;
        }

        static bool IsPowerOfTwo(int n) => n > 0 && (n & (n - 1)) == 0;

        /// <summary>
        /// Bound on the second derivative of <see cref="GradientNoise"/> along a lattice axis, per unit
        /// lattice (|d^2 n / dx^2| and |d^2 n / dy^2| &lt;= this): the largest value found on a dense grid
        /// of 256 x 256 lattice cells (11.26; Tests/Core/TessellationErrorTests.cs checks it), rounded up.
        /// </summary>
        public const float GradientNoiseCurvature = 12f;

        /// <summary>
        /// Bound on the second derivative of <see cref="OctaveNoise"/> along x or y, in terrain units per
        /// (terrain unit)^2, for the octaves a frame draws (<paramref name="octaveCount"/>, the fraction
        /// weighting the last one as in OctaveNoise): <c>|amplitude| * GradientNoiseCurvature * sum_k
        /// fade_k beta^-k (frequency alpha^k)^2</c>. Octave k's curvature grows as <c>(alpha^2 / beta)^k</c>,
        /// so for the default alpha = beta = 2 the finest drawn octave dominates. Mirrors HLSL <c>NoiseCurvatureBound</c>.
        /// </summary>
        public static float NoiseCurvatureBound(NoiseSettings settings, float octaveCount)
        {
            settings.Validate(nameof(settings));
            if (float.IsNaN(octaveCount)) throw new ArgumentException("octaveCount (NaN) must be a number", nameof(octaveCount));
            float f = settings.frequency, w = 1f, invBeta = 1f / settings.beta, sum = 0f;
            for (int k = 0; k < NoiseSettings.MaxOctaves; k++)
            {
                float fade = GMath.saturate(octaveCount - k);
                if (fade <= 0f) break;
                sum += fade * w * (f * f);
                f *= settings.alpha;
                w *= invBeta;
            }
            return Math.Abs(settings.amplitude) * GradientNoiseCurvature * sum;
        }

        /// <summary>
        /// The chord error the noise can add to an edge <paramref name="edgeLength"/> long (terrain units,
        /// along x or y) drawn as one segment: <c>curvature * L^2 / 8</c>, in pixels at the edge's largest
        /// pixel scale <paramref name="maxPixelsPerUnit"/>. Added to the surface's sagitta (second
        /// derivatives add) before <see cref="ErrorTessFactor"/>, so the factor counts the noise the frame
        /// shows. Mirrors HLSL <c>NoiseSagittaPixels</c>.
        /// </summary>
        public static float NoiseSagittaPixels(float noiseCurvature, float edgeLength, float maxPixelsPerUnit) =>
            noiseCurvature * (edgeLength * edgeLength) * 0.125f * maxPixelsPerUnit;

        // ------------------------------------------------------------ culling

        /// <summary>
        /// True when clip position <paramref name="c"/> is outside plane <paramref name="plane"/> of the
        /// widened clip volume <c>-w - m &lt;= x, y &lt;= w + m</c>, <c>w &gt;= -m</c> (0: left, 1: right,
        /// 2: bottom, 3: top, 4: behind the eye); m in clip units. Near/far are not tested (their z
        /// convention differs between APIs; the rasteriser clips them).
        /// </summary>
        public static bool OutsidePlane(Float4 c, int plane, float margin)
        {
            switch (plane)
            {
                case 0: return c.x < -c.w - margin;
                case 1: return c.x > c.w + margin;
                case 2: return c.y < -c.w - margin;
                case 3: return c.y > c.w + margin;
                case 4: return c.w < -margin;
                default: throw new ArgumentException(FormattableString.Invariant($"plane ({plane}) must lie in [0, 4]"), nameof(plane));
            }
        }

        /// <summary>Number of planes <see cref="OutsidePlane"/> tests.</summary>
        public const int PlaneCount = 5;

        /// <summary>
        /// True when the box whose 8 corners are <paramref name="clipCorners"/> lies entirely outside one
        /// plane (conservative: never culls anything visible).
        /// </summary>
        public static bool BoxOutsideFrustum(Float4[] clipCorners, float margin)
        {
            if (clipCorners == null || clipCorners.Length != 8)
                throw new ArgumentException(FormattableString.Invariant($"clipCorners (length {clipCorners?.Length ?? 0}) must hold 8 corners"), nameof(clipCorners));
            if (!GMath.isfinite(margin) || margin < 0f)
                throw new ArgumentException(FormattableString.Invariant($"margin ({margin:R}) must be finite and >= 0"), nameof(margin));
            for (int plane = 0; plane < PlaneCount; plane++)
            {
                bool allOut = true;
                for (int i = 0; i < 8 && allOut; i++) allOut = OutsidePlane(clipCorners[i], plane, margin);
                if (allOut) return true;
            }
            return false;
        }

        /// <summary>The axis-aligned box [min, max] projected with <paramref name="viewProjection"/>, then <see cref="BoxOutsideFrustum(Float4[], float)"/>.</summary>
        public static bool BoxOutsideFrustum(Float4x4 viewProjection, Float3 min, Float3 max, float margin)
        {
            if (!viewProjection.IsFinite) throw new ArgumentException($"viewProjection {viewProjection} must be finite", nameof(viewProjection));
            if (!min.IsFinite || !max.IsFinite || min.x > max.x || min.y > max.y || min.z > max.z)
                throw new ArgumentException($"box [{min}, {max}] must be finite with min <= max", nameof(min));
            var corners = new Float4[8];
            for (int i = 0; i < 8; i++)
                corners[i] = viewProjection.TransformPoint(new Float3(
                    (i & 1) == 0 ? min.x : max.x, (i & 2) == 0 ? min.y : max.y, (i & 4) == 0 ? min.z : max.z));
            return BoxOutsideFrustum(corners, margin);
        }

        /// <summary>
        /// Bound on |OctaveNoise| (HLSL <c>NoiseHeightBound</c> in TerrainInputs.hlsl):
        /// <c>|amplitude| * sum_k beta^-k</c> over all <c>settings.octaves</c> octaves (GradientNoise stays
        /// within [-1, 1]); the height margin of the tile culling box.
        /// </summary>
        public static float NoiseHeightBound(NoiseSettings settings)
        {
            settings.Validate(nameof(settings));
            float beta = Math.Max(settings.beta, 1f), n = settings.octaves;
            float sum = beta > 1f ? (1f - (float)Math.Pow(beta, -n)) / (1f - 1f / beta) : n;
            return Math.Abs(settings.amplitude) * sum;
        }

        /// <summary>
        /// Bound on the gradient of <see cref="GradientNoise"/>, per unit lattice (|grad n| &lt;= this,
        /// Euclidean): the largest value found on a dense grid of 256 x 256 lattice cells
        /// (2.81; Tests/Core/TessellationErrorTests.cs checks it), rounded up.
        /// </summary>
        public const float GradientNoiseSlope = 3f;

        /// <summary>
        /// Bound on |p(q) - p(O)| for every q within <paramref name="distance"/> (terrain units) of the
        /// range origin O: per octave k the smaller of twice its amplitude and its slope bound times the
        /// distance (<c>a_k GradientNoiseSlope frequency alpha^k d</c>), over <paramref name="octaveCount"/>
        /// octaves (a fraction weights the last). Mirrors HLSL <c>NoiseDifferenceBound</c>.
        /// </summary>
        public static float NoiseDifferenceBound(NoiseSettings settings, float octaveCount, float distance)
        {
            settings.Validate(nameof(settings));
            if (float.IsNaN(octaveCount)) throw new ArgumentException("octaveCount (NaN) must be a number", nameof(octaveCount));
            if (!(distance >= 0f)) throw new ArgumentException(FormattableString.Invariant($"distance ({distance:R}) must be >= 0"), nameof(distance));
            float a = Math.Abs(settings.amplitude), f = settings.frequency, invBeta = 1f / settings.beta, sum = 0f;
            for (int k = 0; k < NoiseSettings.MaxOctaves; k++)
            {
                float fade = GMath.saturate(octaveCount - k);
                if (fade <= 0f) break;
                sum += fade * Math.Min(2f * a, a * GradientNoiseSlope * f * distance);
                f *= settings.alpha;
                a *= invBeta;
            }
            return sum;
        }

        /// <summary>
        /// The tile culling test of <c>hull_const</c> (HLSL <c>TileCulled</c>): the box of the four
        /// corners (object space, y up), grown in height by their spread plus <paramref name="noiseHeightBound"/>
        /// and upwards only by <paramref name="raiseBound"/> (snow only raises), is outside the view.
        /// </summary>
        public static bool TileCulled(Float4x4 objectToClip, Float3[] cornersOS, float noiseHeightBound, float raiseBound = 0f)
        {
            if (cornersOS == null || cornersOS.Length != 4)
                throw new ArgumentException(FormattableString.Invariant($"cornersOS (length {cornersOS?.Length ?? 0}) must hold 4 corners"), nameof(cornersOS));
            if (!GMath.isfinite(noiseHeightBound) || noiseHeightBound < 0f)
                throw new ArgumentException(FormattableString.Invariant($"noiseHeightBound ({noiseHeightBound:R}) must be finite and >= 0"), nameof(noiseHeightBound));
            if (!GMath.isfinite(raiseBound) || raiseBound < 0f)
                throw new ArgumentException(FormattableString.Invariant($"raiseBound ({raiseBound:R}) must be finite and >= 0"), nameof(raiseBound));
            Float3 lo = cornersOS[0], hi = lo;
            for (int c = 1; c < 4; c++)
            {
                lo = new Float3(Math.Min(lo.x, cornersOS[c].x), Math.Min(lo.y, cornersOS[c].y), Math.Min(lo.z, cornersOS[c].z));
                hi = new Float3(Math.Max(hi.x, cornersOS[c].x), Math.Max(hi.y, cornersOS[c].y), Math.Max(hi.z, cornersOS[c].z));
            }
            float margin = hi.y - lo.y + noiseHeightBound;
            lo.y -= margin;
            hi.y += margin;
            hi.y += raiseBound;   // a separate add, as the shader adds it
            return BoxOutsideFrustum(objectToClip, lo, hi, 0f);
        }

        /// <summary>Triangles drawn by <paramref name="tiles"/>^2 quad tiles at a uniform factor F: <c>2 F^2</c> each.</summary>
        public static double EstimateTriangleCount(int tiles, float factor)
        {
            if (tiles < 0) throw new ArgumentException(FormattableString.Invariant($"tiles ({tiles}) must be >= 0"), nameof(tiles));
            if (!GMath.isfinite(factor) || factor < 0f) throw new ArgumentException(FormattableString.Invariant($"factor ({factor:R}) must be finite and >= 0"), nameof(factor));
            return (double)tiles * tiles * 2.0 * factor * factor;
        }

        /// <summary>
        /// Triangles the adaptive policy draws, estimated from the range's sagitta S (pixels):
        /// <c>F = clamp(sqrt(2 S / target) / M, 1, maxFactor)</c>, <c>2 M^2 F^2</c> triangles (unclamped
        /// <c>4 S / target</c>, whatever M). Uniform factor, or S = +infinity: the uniform count, resp. the most.
        /// </summary>
        public static double EstimateTriangleCount(TessellationSettings settings, double rangeSagittaPixels)
        {
            settings.Validate(nameof(settings));
            if (double.IsNaN(rangeSagittaPixels) || rangeSagittaPixels < 0.0)
                throw new ArgumentException(FormattableString.Invariant($"rangeSagittaPixels ({rangeSagittaPixels:R}) must be >= 0"), nameof(rangeSagittaPixels));
            if (settings.IsUniform) return EstimateTriangleCount(settings.tiles, settings.uniformFactor);
            double f = double.IsPositiveInfinity(rangeSagittaPixels) ? settings.maxFactor
                : GMath.clamp(Math.Sqrt(2.0 * rangeSagittaPixels / settings.targetPixels) / settings.tiles, 1.0, settings.maxFactor);
            return 2.0 * settings.tiles * settings.tiles * f * f;
        }

        static void CheckTarget(float target, float maxFactor)
        {
            if (!GMath.isfinite(target) || !(target > 0f))
                throw new ArgumentException(FormattableString.Invariant($"targetPixels ({target:R}) must be finite and greater than 0"), nameof(target));
            if (!GMath.isfinite(maxFactor) || !(maxFactor >= 1f))
                throw new ArgumentException(FormattableString.Invariant($"maxFactor ({maxFactor:R}) must be finite and at least 1"), nameof(maxFactor));
        }

        static void CheckScreen(Float2 screenSize)
        {
            if (!screenSize.IsFinite || !(screenSize.x > 0f) || !(screenSize.y > 0f))
                throw new ArgumentException($"screenSize {screenSize} must be finite and positive", nameof(screenSize));
        }
    }
}
