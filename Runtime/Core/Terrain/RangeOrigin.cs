using System;

namespace GregoryTerrain
{
    /// <summary>
    /// The origin <c>O</c> that <c>_Range</c> is sent relative to (internals.md, "Range origin"):
    /// a double that is exactly a float pair, <c>O = hi + lo</c>, uploaded as
    /// <c>_RangeOrigin = (hi.x, hi.y, lo.x, lo.y)</c>. <see cref="zero"/> gives the paper's plain range.
    /// </summary>
    [Serializable]
    internal struct RangeOrigin : IEquatable<RangeOrigin>
    {
        public Float2 hi;
        public Float2 lo;

        public static readonly RangeOrigin zero = default;

        /// <summary>
        /// Below this range width (terrain units) <see cref="For"/> picks a snapped origin; above it
        /// the plain range is accurate enough: float <c>c + o (g - c)</c> errs by at most ~6e-8,
        /// well under a vertex spacing of <c>width / 4096</c> for widths above 1/256.
        /// </summary>
        public const double DeepWidth = 1.0 / 256.0;

        /// <summary>The origin's exact value, <c>hi + lo</c> (exact in double: 48 significant bits at most).</summary>
        public Double2 Value => new Double2((double)hi.x + lo.x, (double)hi.y + lo.y);

        /// <summary>The constant <c>_RangeOrigin = (hi.x, hi.y, lo.x, lo.y)</c>.</summary>
        public Float4 ToFloat4() => new Float4(hi.x, hi.y, lo.x, lo.y);

        /// <summary>
        /// Snaps <paramref name="point"/> to the nearest double that is a float pair: <c>hi</c> is the
        /// point rounded to float, <c>lo</c> the remainder rounded to float. The result differs from
        /// the point by at most ~2^-48 of its magnitude, which the small local range absorbs.
        /// </summary>
        public static RangeOrigin Snap(Double2 point)
        {
            if (!point.IsFinite)
                throw new ArgumentException(FormattableString.Invariant($"origin {point} must be finite"), nameof(point));
            var o = new RangeOrigin();
            o.hi = new Float2((float)point.x, (float)point.y);
            // point - hi is exact in double (Sterbenz-like: hi is the nearest float to point).
            o.lo = new Float2((float)(point.x - o.hi.x), (float)(point.y - o.hi.y));
            return o;
        }

        /// <summary>
        /// The origin for a range: <see cref="zero"/> while the range is wider than
        /// <see cref="DeepWidth"/> on both axes, otherwise the snapped centre, so the local range
        /// <c>(c - O, d - O, g - O, h - O)</c> is at most half the width in magnitude.
        /// A renderer can keep an origin across frames while the range stays near it; any origin
        /// gives a correct point, a near one gives a precise one.
        /// </summary>
        public static RangeOrigin For(TerrainRange range)
        {
            range.Validate(nameof(range));
            if (range.Width >= DeepWidth && range.Height >= DeepWidth) return zero;
            return Snap(range.Center);
        }

        public bool Equals(RangeOrigin o) => hi.Equals(o.hi) && lo.Equals(o.lo);
        public override bool Equals(object obj) => obj is RangeOrigin o && Equals(o);
        public override int GetHashCode() => HashCode.Combine(hi, lo);
        public override string ToString() => FormattableString.Invariant($"{hi} + {lo}");
    }
}
