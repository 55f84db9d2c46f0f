using System;
using System.Globalization;

namespace GregoryTerrain
{
    /// <summary>
    /// The pure part of the terrain collider (Runtime/GregoryTerrainCollider.cs): an N x N grid of
    /// height samples around a target, in terrain space, triangulated like the renderer's fallback grid.
    /// <list type="bullet">
    /// <item>The samples lie on a lattice fixed in the terrain, <c>k * spacing</c> from the terrain's
    /// corner, so re-centring moves the patch but never a shared sample: the physics surface under a
    /// walking character does not change when the patch follows it.</item>
    /// <item>The patch is kept inside the unit square when the terrain is wider than the patch (at the
    /// terrain's edge the target is then off-centre rather than the patch half off the terrain).</item>
    /// <item>Cell (i, j) is split along its v01 - v10 diagonal: triangles (v00, v01, v10) and
    /// (v10, v01, v11), clockwise seen from above in Unity's object space (x, height, y), so the top is
    /// the front face that physics queries hit.</item>
    /// </list>
    /// Immutable; every method is allocation-free except <see cref="Triangles"/>.
    /// </summary>
    internal readonly struct ColliderPatch
    {
        /// <summary>Samples per side N (at least 2).</summary>
        public readonly int samples;
        /// <summary>Distance between samples, terrain units.</summary>
        public readonly double spacing;
        /// <summary>Lattice index of sample (0, 0).</summary>
        public readonly long firstX, firstY;

        ColliderPatch(int samples, double spacing, long firstX, long firstY)
        {
            this.samples = samples; this.spacing = spacing; this.firstX = firstX; this.firstY = firstY;
        }

        /// <summary>
        /// The patch of <paramref name="samples"/>^2 samples <paramref name="spacing"/> apart whose centre
        /// is the lattice point nearest <paramref name="target"/> (terrain space), moved inside the unit
        /// square where the terrain is wide enough.
        /// </summary>
        public static ColliderPatch Around(Double2 target, double spacing, int samples)
        {
            if (samples < 2 || samples > 1025)
                throw new ArgumentException(Invariant($"samples ({samples}) must lie in [2, 1025]"), nameof(samples));
            if (!(spacing > 0.0) || double.IsInfinity(spacing) || spacing * (samples - 1) > 1e6)
                throw new ArgumentException(Invariant($"spacing ({spacing:R}) must be finite and greater than 0"), nameof(spacing));
            if (!target.IsFinite) throw new ArgumentException($"target {target} must be finite", nameof(target));
            return new ColliderPatch(samples, spacing, First(target.x, spacing, samples), First(target.y, spacing, samples));
        }

        static long First(double target, double spacing, int samples)
        {
            long half = (samples - 1) / 2;
            long first = (long)Math.Round(GMath.clamp(target, -1e6, 1e6) / spacing) - half;
            long last = (long)Math.Floor(1.0 / spacing + 1e-9);   // the last lattice point inside [0, 1]
            if (last >= samples - 1) first = Math.Max(0, Math.Min(first, last - (samples - 1)));
            return first;
        }

        /// <summary>Terrain-space point of sample (i, j) (clamped to the unit square).</summary>
        public Double2 Point(int i, int j) =>
            new Double2(GMath.clamp((firstX + i) * spacing, 0.0, 1.0), GMath.clamp((firstY + j) * spacing, 0.0, 1.0));

        /// <summary>Centre of the patch (terrain space, not clamped).</summary>
        public Double2 Center => new Double2((firstX + 0.5 * (samples - 1)) * spacing, (firstY + 0.5 * (samples - 1)) * spacing);

        /// <summary>Side of the patch, terrain units.</summary>
        public double Size => spacing * (samples - 1);

        /// <summary>Whether the patch is the same lattice window as <paramref name="other"/>.</summary>
        public bool SameWindow(ColliderPatch other) =>
            samples == other.samples && spacing == other.spacing && firstX == other.firstX && firstY == other.firstY;

        /// <summary>
        /// Whether a target at <paramref name="target"/> needs a new patch: it is more than
        /// <paramref name="threshold"/> (a fraction of the half size, in (0, 1]) from the centre along
        /// either axis, and the patch it would get differs from this one (at the terrain's edge it does not).
        /// </summary>
        public bool NeedsRebuild(Double2 target, double threshold)
        {
            if (!(threshold > 0.0 && threshold <= 1.0))
                throw new ArgumentException(Invariant($"threshold ({threshold:R}) must lie in (0, 1]"), nameof(threshold));
            if (!target.IsFinite) return false;
            Double2 c = Center;
            double limit = threshold * 0.5 * Size;
            if (Math.Abs(target.x - c.x) <= limit && Math.Abs(target.y - c.y) <= limit) return false;
            return !SameWindow(Around(target, spacing, samples));
        }

        /// <summary>The full-detail heights at the samples, row by row (<c>j N + i</c>), from <paramref name="query"/>.</summary>
        public void SampleHeights(TerrainSurfaceQuery query, Span<float> heights)
        {
            if (query == null) throw new ArgumentNullException(nameof(query));
            if (heights.Length != samples * samples)
                throw new ArgumentException(Invariant($"heights.Length ({heights.Length}) must be {samples * samples}"), nameof(heights));
            for (int j = 0; j < samples; j++)
                for (int i = 0; i < samples; i++)
                {
                    Double2 p = Point(i, j);
                    heights[j * samples + i] = (float)query.SampleHeight(p.x, p.y);
                }
        }

        /// <summary>Triangle indices (6 per cell, vertex <c>j N + i</c>), see the class comment for the split and winding.</summary>
        public static int[] Triangles(int samples)
        {
            if (samples < 2 || samples > 1025)
                throw new ArgumentException(Invariant($"samples ({samples}) must lie in [2, 1025]"), nameof(samples));
            var t = new int[6 * (samples - 1) * (samples - 1)];
            int k = 0;
            for (int j = 0; j < samples - 1; j++)
                for (int i = 0; i < samples - 1; i++)
                {
                    int v = j * samples + i;
                    t[k++] = v; t[k++] = v + samples; t[k++] = v + 1;
                    t[k++] = v + 1; t[k++] = v + samples; t[k++] = v + samples + 1;
                }
            return t;
        }

        /// <summary>
        /// The collider's height at (x, y) inside the patch: the triangle of <see cref="Triangles"/> that
        /// holds the point, linearly interpolated; NaN outside the patch.
        /// </summary>
        public double ColliderHeight(ReadOnlySpan<float> heights, double x, double y)
        {
            double gx = x / spacing - firstX, gy = y / spacing - firstY;
            if (!(gx >= 0.0 && gx <= samples - 1 && gy >= 0.0 && gy <= samples - 1)) return double.NaN;
            int i = Math.Min((int)gx, samples - 2), j = Math.Min((int)gy, samples - 2);
            double s = gx - i, t = gy - j;
            double h00 = heights[j * samples + i], h10 = heights[j * samples + i + 1];
            double h01 = heights[(j + 1) * samples + i], h11 = heights[(j + 1) * samples + i + 1];
            return s + t <= 1.0 ? h00 + s * (h10 - h00) + t * (h01 - h00)
                                : h11 + (1.0 - s) * (h01 - h11) + (1.0 - t) * (h10 - h11);
        }

        /// <summary>
        /// Largest and RMS |collider height - full-detail height| over <paramref name="perCell"/>^2
        /// points per cell (interior of the terrain only), terrain units: how far the physics surface
        /// lies from the drawn one at this resolution.
        /// </summary>
        public void Deviation(TerrainSurfaceQuery query, ReadOnlySpan<float> heights, int perCell, out double max, out double rms)
        {
            if (query == null) throw new ArgumentNullException(nameof(query));
            if (perCell < 1) throw new ArgumentException(Invariant($"perCell ({perCell}) must be at least 1"), nameof(perCell));
            max = 0.0;
            double sum = 0.0;
            long count = 0;
            int m = (samples - 1) * perCell;
            for (int b = 0; b <= m; b++)
                for (int a = 0; a <= m; a++)
                {
                    double x = (firstX + (double)a / perCell) * spacing, y = (firstY + (double)b / perCell) * spacing;
                    if (!(x >= 0.0 && x <= 1.0 && y >= 0.0 && y <= 1.0)) continue;
                    double e = Math.Abs(ColliderHeight(heights, x, y) - query.SampleHeight(x, y));
                    max = Math.Max(max, e);
                    sum += e * e;
                    count++;
                }
            rms = count > 0 ? Math.Sqrt(sum / count) : 0.0;
        }

        public override string ToString() => Invariant($"{samples} x {samples} samples {spacing:R} apart from lattice ({firstX}, {firstY})");

        static string Invariant(FormattableString s) => s.ToString(CultureInfo.InvariantCulture);
    }
}
