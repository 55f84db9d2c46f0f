using System;

namespace GregoryTerrain
{
    /// <summary>
    /// From tile and tess coordinate to the global point q and on to a patch's local (u, v)
    /// (internals.md, "The Gregory patch" and "The tile layout"). Float methods do what
    /// Shaders/Library/RangeMapping.hlsl does, step for step; double methods are the reference.
    /// </summary>
    internal static class RangeMapping
    {
        // ---------------------------------------------------------------- local coordinate (eq. 10)

        /// <summary>
        /// The corrected eq. 10: the local coordinate of the global coordinate <paramref name="q"/> in a
        /// patch spanning <c>[a, e]</c> is <c>(q - a) / (e - a)</c> (0 at a, 1 at e, outside [0,1] off the patch).
        /// </summary>
        public static double LocalCoordinate(double q, double a, double e)
        {
            CheckSpan(a, e, "a", "e");
            if (!GMath.isfinite(q)) throw new ArgumentException(FormattableString.Invariant($"q ({q:R}) must be finite"), nameof(q));
            return (q - a) / (e - a);
        }

        /// <summary>The corrected eq. 10 on both axes: <c>((q.x - a)/(e - a), (q.y - b)/(f - b))</c>.</summary>
        public static Double2 LocalCoordinate(Double2 q, Region region)
        {
            CheckSpan(region.a, region.e, "region.a", "region.e");
            CheckSpan(region.b, region.f, "region.b", "region.f");
            if (!q.IsFinite) throw new ArgumentException(FormattableString.Invariant($"q {q} must be finite"), nameof(q));
            return new Double2((q.x - region.a) / (region.e - region.a), (q.y - region.b) / (region.f - region.b));
        }

        /// <summary>
        /// Eq. 10 as printed, kept only so tests can show its error: right only when <c>c == a</c>.
        /// Use <see cref="LocalCoordinate(double, double, double)"/>.
        /// </summary>
        public static double PrintedEq10(double c, double g, double a, double e, double o)
        {
            CheckSpan(a, e, "a", "e");
            return (c - a) / (e - a) + o * (1.0 - (g - e) / (a - e));
        }

        // ---------------------------------------------------------------- tile layout

        /// <summary>
        /// The range coordinate <c>o = ((ti + s) / M, (tj + t) / M)</c> of tess coordinate (s, t) in tile
        /// (ti, tj) of an M x M tiling. <c>ti + s</c> is formed first: on a shared edge both tiles' sums are
        /// the same small integer, exactly, so they get bit-identical o.
        /// </summary>
        public static Float2 RangeCoordinate(int ti, int tj, float s, float t, int tiles)
        {
            CheckTile(ti, tj, s, t, tiles);
            float m = tiles;
            return new Float2(((float)ti + s) / m, ((float)tj + t) / m);
        }

        /// <summary>The double reference of <see cref="RangeCoordinate(int, int, float, float, int)"/>.</summary>
        public static Double2 RangeCoordinate(int ti, int tj, double s, double t, int tiles)
        {
            CheckTile(ti, tj, s, t, tiles);
            return new Double2((ti + s) / tiles, (tj + t) / tiles);
        }

        /// <summary>The reference global point <c>q = c + o (g - c)</c> per axis, all in double.</summary>
        public static Double2 GlobalPoint(TerrainRange range, int tiles, int ti, int tj, double s, double t)
        {
            range.Validate(nameof(range));
            Double2 o = RangeCoordinate(ti, tj, s, t, tiles);
            return new Double2(range.c + o.x * (range.g - range.c), range.d + o.y * (range.h - range.d));
        }

        /// <summary>
        /// The paper's float path, <c>q = c + o (g - c)</c> with a plain float4 range (<see cref="ToTerrainPoint"/>
        /// with origin 0): it jitters at deep zoom (precision.md, "What breaks").
        /// </summary>
        public static Float2 PlainGlobalPoint(Float4 range, int tiles, int ti, int tj, float s, float t)
        {
            Float2 o = RangeCoordinate(ti, tj, s, t, tiles);
            return new Float2(range.x + o.x * (range.z - range.x), range.y + o.y * (range.w - range.y));
        }

        // ---------------------------------------------------------------- range origin (deep zoom)

        /// <summary>
        /// The two constants the GPU gets: <c>_Range = (c - O.x, d - O.y, g - O.x, h - O.y)</c> formed in
        /// double, rounded to float once, and <c>_RangeOrigin = (hi.x, hi.y, lo.x, lo.y)</c>.
        /// </summary>
        public static void EncodeRange(TerrainRange range, RangeOrigin origin, out Float4 rangeF, out Float4 rangeOriginF)
        {
            range.Validate(nameof(range));
            if (!origin.hi.IsFinite || !origin.lo.IsFinite)
                throw new ArgumentException(FormattableString.Invariant($"origin {origin} must be finite"), nameof(origin));
            Double2 o = origin.Value;
            rangeF = new Float4((float)(range.c - o.x), (float)(range.d - o.y), (float)(range.g - o.x), (float)(range.h - o.y));
            rangeOriginF = origin.ToFloat4();
        }

        /// <summary>Snaps <paramref name="origin"/> with <see cref="RangeOrigin.Snap"/>, then encodes.</summary>
        public static void EncodeRange(TerrainRange range, Double2 origin, out Float4 rangeF, out Float4 rangeOriginF) =>
            EncodeRange(range, RangeOrigin.Snap(origin), out rangeF, out rangeOriginF);

        /// <summary>
        /// The domain shader's global point as a <see cref="TerrainPoint"/>:
        /// <c>local = originLo + (range.xy + o (range.zw - range.xy))</c> in float, <c>originHi</c> passed on;
        /// every term is of the local range's size. With origin 0 it is the plain <c>c + o (g - c)</c> bit for bit.
        /// </summary>
        public static TerrainPoint ToTerrainPoint(Float4 rangeF, Float4 rangeOriginF, int tiles, int ti, int tj, float s, float t)
        {
            Float2 o = RangeCoordinate(ti, tj, s, t, tiles);
            var local = new Float2(
                rangeOriginF.z + (rangeF.x + o.x * (rangeF.z - rangeF.x)),
                rangeOriginF.w + (rangeF.y + o.y * (rangeF.w - rangeF.y)));
            return new TerrainPoint(rangeOriginF.xy, local);
        }

        /// <summary>
        /// <c>q</c> rounded to float, <c>originHi + local</c>: good enough to find the patch (neighbours
        /// agree near a line), not for the local coordinate: use <see cref="PatchLocalUV(TerrainPoint, Float4, Float4)"/>.
        /// </summary>
        public static Float2 Approximate(TerrainPoint p) => p.originHi + p.local;

        /// <summary>
        /// The corrected eq. 10 in float for a <see cref="TerrainPoint"/> and a float region (a, b, e, f):
        /// <c>u = ((originHi.x - a) + local.x) / (e - a)</c>. The trap: forming <c>q = originHi + local</c>
        /// first rounds away the fine offset. Instead <c>originHi - a = d + err</c> exactly (TwoSum), the
        /// small parts are added together and only the final sum is rounded.
        /// </summary>
        public static Float2 PatchLocalUV(TerrainPoint p, Float4 region)
        {
            float du = TwoSum(p.originHi.x, -region.x, out float eu);
            float dv = TwoSum(p.originHi.y, -region.y, out float ev);
            return new Float2((du + (eu + p.local.x)) / (region.z - region.x),
                              (dv + (ev + p.local.y)) / (region.w - region.y));
        }

        /// <summary>
        /// <see cref="PatchLocalUV(TerrainPoint, Float4)"/> for a hi/lo region (as <c>_GridLines</c> holds
        /// it): <c>q - a</c> formed as <c>(originHi - a.hi) + (local - a.lo)</c>, the width by
        /// <see cref="RegionSize"/>; a one-float line is off by up to half a float step.
        /// </summary>
        public static Float2 PatchLocalUV(TerrainPoint p, Float4 region, Float4 regionLo)
        {
            float du = TwoSum(p.originHi.x, -region.x, out float eu);
            float dv = TwoSum(p.originHi.y, -region.y, out float ev);
            Float2 size = RegionSize(region, regionLo);
            return new Float2((du + (eu + (p.local.x - regionLo.x))) / size.x,
                              (dv + (ev + (p.local.y - regionLo.y))) / size.y);
        }

        /// <summary>
        /// The width and height <c>(e - a, f - b)</c> of a hi/lo region: <c>(e.hi - a.hi) + (e.lo - a.lo)</c>.
        /// The hi difference is exact for neighbouring lines (Sterbenz), else rounds relative to the width;
        /// a one-float <c>e - a</c> of a tiny patch is off by a large fraction of it.
        /// </summary>
        public static Float2 RegionSize(Float4 region, Float4 regionLo) =>
            new Float2((region.z - region.x) + (regionLo.z - regionLo.x), (region.w - region.y) + (regionLo.w - regionLo.y));

        /// <summary>
        /// Knuth's TwoSum: <c>s = fl(a + b)</c> and the exact rounding error, <c>a + b = s + err</c>,
        /// for any floats without overflow. Needs strict IEEE float steps (no reassociation, no
        /// extended precision): C# float arithmetic is; the HLSL mirror marks the steps <c>precise</c>.
        /// </summary>
        public static float TwoSum(float a, float b, out float err)
        {
            float s = a + b;
            float bv = s - a;
            float av = s - bv;
            err = (a - av) + (b - bv);
            return s;
        }

        // ---------------------------------------------------------------- checks

        static void CheckSpan(double lo, double hi, string loName, string hiName)
        {
            if (!GMath.isfinite(lo) || !GMath.isfinite(hi) || !(hi > lo))
                throw new ArgumentException(FormattableString.Invariant(
                    $"{hiName} ({hi:R}) must be finite and greater than {loName} ({lo:R})"), hiName);
        }

        static void CheckTile(int ti, int tj, double s, double t, int tiles)
        {
            if (tiles < 1 || tiles > 1 << 16)
                throw new ArgumentException(FormattableString.Invariant($"tiles ({tiles}) must lie in [1, 65536]"), nameof(tiles));
            if (ti < 0 || ti >= tiles)
                throw new ArgumentException(FormattableString.Invariant($"ti ({ti}) must lie in [0, {tiles - 1}]"), nameof(ti));
            if (tj < 0 || tj >= tiles)
                throw new ArgumentException(FormattableString.Invariant($"tj ({tj}) must lie in [0, {tiles - 1}]"), nameof(tj));
            if (!(s >= 0.0 && s <= 1.0))
                throw new ArgumentException(FormattableString.Invariant($"s ({s:R}) must lie in [0, 1]"), nameof(s));
            if (!(t >= 0.0 && t <= 1.0))
                throw new ArgumentException(FormattableString.Invariant($"t ({t:R}) must lie in [0, 1]"), nameof(t));
        }
    }
}
