using System;

namespace GregoryTerrain
{
    /// <summary>
    /// The hull constant function's decisions (DESIGN section 2), mirrored by
    /// Shaders/TessellationFactors.hlsl: edge factors from the screen-space length of each tile edge,
    /// the inside factor, and frustum culling of a tile's bounding box.
    /// <para>Crack-freedom: an edge's factor is computed only from that edge's two endpoints (their
    /// clip positions), never from the tile it belongs to, so the two tiles sharing an edge compute the
    /// same factor, provided they pass the same endpoints (the tile layout makes shared corners
    /// bit-identical). The functions are also symmetric bit for bit in the two endpoints, because the
    /// neighbour walks the shared edge the other way round.</para>
    /// </summary>
    public static class TessellationPolicy
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
        /// Screen-space length in pixels of the edge between two clip positions. Symmetric bit for bit:
        /// each endpoint is projected on its own, and <c>a - b == -(b - a)</c> exactly in IEEE arithmetic,
        /// so the squares are equal. An endpoint at or behind the eye plane (<c>w &lt;= 0</c>) makes the
        /// length +infinity (the edge crosses the camera plane; treated as "as fine as allowed").
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

        /// <summary>The inside factor: the largest of the four edge factors (never coarser than any edge).</summary>
        public static float InsideFactor(float e0, float e1, float e2, float e3) => Math.Max(Math.Max(e0, e1), Math.Max(e2, e3));

        // ------------------------------------------------------------ culling

        /// <summary>
        /// True when clip position <paramref name="c"/> is outside plane <paramref name="plane"/> of the
        /// widened clip volume <c>-w - m &lt;= x, y &lt;= w + m</c>, <c>w &gt;= -m</c>
        /// (0: left, 1: right, 2: bottom, 3: top, 4: behind the eye). The margin m is in clip units
        /// (roughly world units for a projection with focal scale ~1, as in the chunk culling of seed 004:
        /// a bounding diameter there). Depth near/far are not tested: their clip z convention differs
        /// between graphics APIs, and terrain to the horizon is clipped by the rasteriser anyway.
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
        /// plane, so it can be culled (factor 0). A box straddling a plane, or outside different
        /// planes with different corners, is kept: conservative, never culls anything visible.
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

        /// <summary>Triangles drawn by <paramref name="tiles"/>^2 quad tiles at a uniform factor F: <c>2 F^2</c> each.</summary>
        public static double EstimateTriangleCount(int tiles, float factor)
        {
            if (tiles < 0) throw new ArgumentException(FormattableString.Invariant($"tiles ({tiles}) must be >= 0"), nameof(tiles));
            if (!GMath.isfinite(factor) || factor < 0f) throw new ArgumentException(FormattableString.Invariant($"factor ({factor:R}) must be finite and >= 0"), nameof(factor));
            return (double)tiles * tiles * 2.0 * factor * factor;
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
