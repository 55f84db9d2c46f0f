using System;
using System.Collections.Generic;
using System.Globalization;

namespace GregoryTerrain
{
    /// <summary>A ray in terrain space (x, y, z = height): origin, direction (any length) and how far to look (terrain units).</summary>
    internal struct TerrainRay
    {
        public Double3 origin, direction;
        public double maxDistance;

        public TerrainRay(Double3 origin, Double3 direction, double maxDistance)
        {
            this.origin = origin; this.direction = direction; this.maxDistance = maxDistance;
        }
    }

    /// <summary>What a <c>TerrainSurfaceQuery.Raycast</c> found.</summary>
    internal enum TerrainRayStatus
    {
        /// <summary>The ray leaves the terrain's box (or reaches its length) without crossing the surface.</summary>
        Miss = 0,
        /// <summary>The ray crosses the surface from above; distance, point and normal are set.</summary>
        Hit = 1,
        /// <summary>The march used its step budget first (a long ray grazing the surface closer than the tolerance).</summary>
        StepLimit = 2,
    }

    /// <summary>A ray's first downward crossing of the surface (terrain space; distance along the unit direction).</summary>
    internal struct TerrainRayHit
    {
        public TerrainRayStatus status;
        public double distance;
        public Double3 point, normal;
        /// <summary>Surface evaluations the march and the refinement took.</summary>
        public int evaluations;
    }

    /// <summary>
    /// Height, normal and ray queries on the surface the GPU draws at full detail: the Gregory patches
    /// of a <see cref="PatchGrid"/> plus every noise octave the settings allow, with the shaders' noise
    /// functions, in double: <see cref="TerrainVertex.Reference"/>, the exact surface the GPU's float
    /// path approximates. Snow is not included. Terrain space: (x, y) is the global point q, z the
    /// height S(q).z + p(q); exact at (x, y) when <see cref="AffinePatches"/>. Allocation-free and
    /// thread-safe; the grid must not change while queried (internals.md, "CPU queries").
    /// </summary>
    internal sealed class TerrainSurfaceQuery
    {
        /// <summary>
        /// Largest Euclidean norm of the gradient of one noise octave K (<see cref="GradientNoise"/>),
        /// per lattice unit. Per component, d K/dx = sqrt(2) (blend of the corner gradients' x, at most 1,
        /// plus Fade'(fx) (k1 + v k3)), with Fade' &lt;= 30/16 and |k1 + v k3| &lt;= max |n10 - n00|, |n11 - n01|
        /// &lt;= |(fx - 1, fy)| + |(fx, fy)| &lt;= 1 + sqrt(2): so |dK/dx| &lt;= sqrt(2) (1 + 1.875 (1 + sqrt(2)))
        /// = 7.817, and the norm &lt;= sqrt(2) times that = 11.06. Rounded up.
        /// </summary>
        public const double NoiseSlopeBound = 11.1;

        /// <summary>Largest |K| of one octave (the noise is scaled to span [-1, 1]), with a margin for rounding.</summary>
        const double NoiseValueBound = 1.0 + 1e-9;

        const int MaxRefineIterations = 200;

        readonly PatchGrid _grid;
        readonly bool _noiseOn;
        readonly TerrainKeywords _keywords;   // NoiseTable: the tiled noise (GT_NOISE_TABLE)
        readonly NoiseSettings _noise;
        readonly double[] _frequency;        // octave k's frequency (the float sequence, widened)
        readonly Double2[] _offset;          // octave k's stream offset
        readonly double[] _amplitudeTail;    // [k]: most |noise| octaves k.. can add (k = 0 .. N)
        readonly double[] _slopeHead;        // [k]: slope bound of octaves 0 .. k-1 (k = 0 .. N)

        /// <summary>The grid queried.</summary>
        public PatchGrid Grid => _grid;
        /// <summary>The noise added, or null when the surface is the Gregory patches alone.</summary>
        public NoiseSettings? Noise => _noiseOn ? _noise : (NoiseSettings?)null;
        /// <summary>Octaves evaluated (all the settings allow; 0 without noise).</summary>
        public int Octaves => _noiseOn ? _noise.octaves : 0;
        /// <summary>Lowest and highest control point height (the Gregory patches lie in their hull).</summary>
        public double MinControlHeight { get; }
        public double MaxControlHeight { get; }
        /// <summary>Most the noise can move a height: |amplitude| sum_k beta^-k.</summary>
        public double NoiseAmplitudeBound => _amplitudeTail[0];
        /// <summary>Largest |grad z| of the Gregory patches over q, terrain units per unit (<see cref="PatchSlopeBound"/>).</summary>
        public double SurfaceSlopeBound { get; }
        /// <summary>Slope bound of all the noise octaves together: |amplitude| sum_k beta^-k f_k <see cref="NoiseSlopeBound"/>.</summary>
        public double NoiseSlopeBoundTotal => _slopeHead[_slopeHead.Length - 1];
        /// <summary>True when every patch's x, y are affine in (u, v), so the slope bound and the height field hold as stated.</summary>
        public bool AffinePatches { get; }

        /// <summary>
        /// A query over <paramref name="grid"/> (validated), with <paramref name="noise"/> (validated;
        /// null: no noise; <see cref="TerrainKeywords.NoiseTable"/> in <paramref name="keywords"/>: the tiled noise, the only keyword it reads). Precomputes the ray march's bounds.
        /// </summary>
        public TerrainSurfaceQuery(PatchGrid grid, NoiseSettings? noise, TerrainKeywords keywords = TerrainKeywords.None)
        {
            if (grid == null) throw new ArgumentNullException(nameof(grid));
            grid.Validate();
            _grid = grid;
            _noiseOn = noise.HasValue;
            _keywords = keywords;
            int n = 0;
            if (_noiseOn)
            {
                _noise = noise.Value;
                _noise.Validate("noise");
                n = _noise.octaves;
            }
            _frequency = new double[n];
            _offset = new Double2[n];
            _amplitudeTail = new double[n + 1];
            _slopeHead = new double[n + 1];
            float f = n > 0 ? _noise.frequency : 0f;
            double w = 1.0, invBeta = n > 0 ? 1.0 / _noise.beta : 0.0;
            var weight = new double[n];
            for (int k = 0; k < n; k++)
            {
                _frequency[k] = f;
                _offset[k] = GradientNoise.StreamOffset((uint)k);
                weight[k] = w;
                f *= _noise.alpha;
                w *= invBeta;
            }
            double amplitude = n > 0 ? Math.Abs((double)_noise.amplitude) : 0.0;
            for (int k = n - 1; k >= 0; k--) _amplitudeTail[k] = _amplitudeTail[k + 1] + amplitude * weight[k] * NoiseValueBound;
            for (int k = 0; k < n; k++) _slopeHead[k + 1] = _slopeHead[k] + amplitude * weight[k] * _frequency[k] * NoiseSlopeBound;

            (MinControlHeight, MaxControlHeight, SurfaceSlopeBound, AffinePatches) =
                WidenedBounds(grid, AllPatches(grid.PatchCount), double.MaxValue, double.MinValue, 0.0, true);
        }

        static IEnumerable<int> AllPatches(int count)
        {
            for (int p = 0; p < count; p++) yield return p;
        }

        /// <summary>
        /// The control-height range, the slope bound and whether every patch is affine, from the given
        /// ones widened by <paramref name="patches"/> of <paramref name="grid"/>.
        /// </summary>
        static (double lo, double hi, double slope, bool affine) WidenedBounds(PatchGrid grid, IEnumerable<int> patches,
            double lo, double hi, double slope, bool affine)
        {
            foreach (int p in patches)
            {
                foreach (Double3 c in grid.Patches[p].Points) { lo = Math.Min(lo, c.z); hi = Math.Max(hi, c.z); }
                slope = Math.Max(slope, PatchSlopeBound(grid.Patches[p], grid.RegionOf(p)));
                affine &= IsAffine(grid.Patches[p], grid.RegionOf(p));
            }
            return (lo, hi, slope, affine);
        }

        /// <summary>
        /// This query's noise over <paramref name="grid"/>, which differs from <see cref="Grid"/> in
        /// <paramref name="changed"/> patches only (validated). The bounds are widened by the changed
        /// patches, never narrowed, so still bounds. This query is not changed (another thread may use it).
        /// </summary>
        public TerrainSurfaceQuery WithPatches(PatchGrid grid, IReadOnlyList<int> changed) => new TerrainSurfaceQuery(this, grid, changed);

        TerrainSurfaceQuery(TerrainSurfaceQuery previous, PatchGrid grid, IReadOnlyList<int> changed)
        {
            if (grid == null) throw new ArgumentNullException(nameof(grid));
            if (changed == null) throw new ArgumentNullException(nameof(changed));
            PatchGrid old = previous._grid;
            if (grid.Columns != old.Columns || grid.Rows != old.Rows)
                throw new ArgumentException($"grid is {grid.Columns} x {grid.Rows} patches, the query's {old.Columns} x {old.Rows}.", nameof(grid));
            _grid = grid;
            _noiseOn = previous._noiseOn;
            _keywords = previous._keywords;
            _noise = previous._noise;
            _frequency = previous._frequency;
            _offset = previous._offset;
            _amplitudeTail = previous._amplitudeTail;
            _slopeHead = previous._slopeHead;
            (MinControlHeight, MaxControlHeight, SurfaceSlopeBound, AffinePatches) = WidenedBounds(grid, changed,
                previous.MinControlHeight, previous.MaxControlHeight, previous.SurfaceSlopeBound, previous.AffinePatches);
        }

        // ---------------------------------------------------------------- heights and normals

        /// <summary>Height of the surface at the global point (x, y); NaN outside the unit square or for a non-finite point.</summary>
        public double SampleHeight(double x, double y) => Sample(x, y, false, out _);

        /// <summary>Unit normal (terrain space, z up) at (x, y); zero outside the unit square.</summary>
        public Double3 SampleNormal(double x, double y)
        {
            Sample(x, y, true, out Double3 normal);
            return normal;
        }

        /// <summary>Height and unit normal at (x, y) in one evaluation (NaN and zero outside the unit square).</summary>
        public double Sample(double x, double y, out Double3 normal) => Sample(x, y, true, out normal);

        /// <summary>Heights at many points: <paramref name="heights"/>[i] for <paramref name="points"/>[i].</summary>
        public void SampleHeights(ReadOnlySpan<Double2> points, Span<double> heights)
        {
            if (heights.Length < points.Length)
                throw new ArgumentException(Invariant($"heights.Length ({heights.Length}) must be at least points.Length ({points.Length})"), nameof(heights));
            for (int i = 0; i < points.Length; i++) heights[i] = Sample(points[i].x, points[i].y, false, out _);
        }

        /// <summary>Heights and normals at many points.</summary>
        public void Sample(ReadOnlySpan<Double2> points, Span<double> heights, Span<Double3> normals)
        {
            if (heights.Length < points.Length)
                throw new ArgumentException(Invariant($"heights.Length ({heights.Length}) must be at least points.Length ({points.Length})"), nameof(heights));
            if (normals.Length < points.Length)
                throw new ArgumentException(Invariant($"normals.Length ({normals.Length}) must be at least points.Length ({points.Length})"), nameof(normals));
            for (int i = 0; i < points.Length; i++) heights[i] = Sample(points[i].x, points[i].y, true, out normals[i]);
        }

        double Sample(double x, double y, bool wantNormal, out Double3 normal)
        {
            normal = Double3.zero;
            if (!(x >= 0.0 && x <= 1.0 && y >= 0.0 && y <= 1.0)) return double.NaN;
            int patch = _grid.FindPatch(x, y);
            Region region = _grid.RegionOf(patch);
            Double2 uv = RangeMapping.LocalCoordinate(new Double2(x, y), region);
            GregoryEval.Evaluate(_grid.Patches[patch].Points, uv.x, uv.y, out Double3 position, out Double3 dPdu, out Double3 dPdv);
            double z = position.z;
            if (_noiseOn)
            {
                z += NoiseHeight(x, y, out Double2 gradient);
                dPdu.z += gradient.x * (region.e - region.a);
                dPdv.z += gradient.y * (region.f - region.b);
            }
            if (wantNormal) normal = GregoryEval.NormalFromDerivatives(dPdu, dPdv);
            return z;
        }

        /// <summary>
        /// p(x, y) with every octave and its gradient d p / d q: <see cref="OctaveNoise.Evaluate(double, double, NoiseSettings, double, out Double2, TerrainKeywords)"/>
        /// at the full count, same sums in the same order, from precomputed octave constants.
        /// </summary>
        double NoiseHeight(double x, double y, out Double2 gradient)
        {
            double n = 0.0, w = 1.0, invBeta = 1.0 / _noise.beta;
            var g = new Double2(0.0, 0.0);
            for (int k = 0; k < _frequency.Length; k++)
            {
                double f = _frequency[k];
                double nk = GradientNoise.Evaluate(f * x + _offset[k].x, f * y + _offset[k].y, out Double2 gk, _keywords);
                n += w * nk;
                g += gk * (w * f);
                w *= invBeta;
            }
            gradient = g * _noise.amplitude;
            return _noise.amplitude * n;
        }

        /// <summary>
        /// The Gregory height at (x, y) (inside the unit square) and the noise's partial sums:
        /// <paramref name="partial"/>[k] = octaves 0 .. k-1 (k = 0 .. N). The march's lower bounds use them.
        /// </summary>
        double SurfaceAndPartialNoise(double x, double y, Span<double> partial)
        {
            int patch = _grid.FindPatch(x, y);
            Double2 uv = RangeMapping.LocalCoordinate(new Double2(x, y), _grid.RegionOf(patch));
            GregoryEval.Evaluate(_grid.Patches[patch].Points, uv.x, uv.y, out Double3 position, out _, out _);
            partial[0] = 0.0;
            if (_noiseOn)
            {
                double n = 0.0, w = 1.0, invBeta = 1.0 / _noise.beta;
                for (int k = 0; k < _frequency.Length; k++)
                {
                    double f = _frequency[k];
                    n += w * GradientNoise.Evaluate(f * x + _offset[k].x, f * y + _offset[k].y, out _, _keywords);
                    w *= invBeta;
                    partial[k + 1] = _noise.amplitude * n;
                }
            }
            return position.z;
        }

        // ---------------------------------------------------------------- rays

        /// <summary>
        /// The ray's first crossing of the surface from above, within its length: clipped to the
        /// terrain's box, then marched with steps that cannot pass a crossing: with <c>g_k = ray z - S - p_{&lt;k}</c>,
        /// <c>A_k</c> the amplitude of octaves k and up and <c>L_k</c> the slope bound of S and octaves below k,
        /// the surface stays below the ray for <c>s &lt; (g_k - A_k) / (|d_z| + L_k |d_xy|)</c>; the step is the
        /// largest such s, at least <c>tolerance / (|d_z| + L_N |d_xy|)</c>. Anything rising more than
        /// <paramref name="tolerance"/> (terrain units, vertically) above the ray is found, at any angle;
        /// crossings are refined by Illinois regula falsi. A ray starting below first marches up (one-sided
        /// surface). At most <paramref name="maxSteps"/> steps (then <see cref="TerrainRayStatus.StepLimit"/>);
        /// internals.md, "Raycast".
        /// </summary>
        public TerrainRayStatus Raycast(TerrainRay ray, out TerrainRayHit hit, double tolerance = 1e-9, int maxSteps = 1 << 20)
        {
            hit = default;
            if (!ray.origin.IsFinite || !ray.direction.IsFinite || double.IsNaN(ray.maxDistance) || ray.maxDistance < 0.0)
                throw new ArgumentException(Invariant($"ray (origin {ray.origin}, direction {ray.direction}, maxDistance {ray.maxDistance:R}) must be finite with maxDistance >= 0"), nameof(ray));
            if (!(tolerance > 0.0) || double.IsInfinity(tolerance))
                throw new ArgumentException(Invariant($"tolerance ({tolerance:R}) must be finite and greater than 0"), nameof(tolerance));
            double len = GMath.length(ray.direction);
            if (!(len > 0.0)) throw new ArgumentException(Invariant($"ray.direction {ray.direction} must not be zero"), nameof(ray));
            Double3 o = ray.origin, d = ray.direction / len;
            double zLo = MinControlHeight - NoiseAmplitudeBound, zHi = MaxControlHeight + NoiseAmplitudeBound;
            double t0 = 0.0, t1 = ray.maxDistance;
            if (!Slab(o.x, d.x, 0.0, 1.0, ref t0, ref t1) || !Slab(o.y, d.y, 0.0, 1.0, ref t0, ref t1) || !Slab(o.z, d.z, zLo, zHi, ref t0, ref t1))
                return hit.status = TerrainRayStatus.Miss;

            int n = _frequency.Length;
            Span<double> partial = stackalloc double[NoiseSettings.MaxOctaves + 1];
            double dz = Math.Abs(d.z), dh = Math.Sqrt(d.x * d.x + d.y * d.y);
            double fullRate = dz + (SurfaceSlopeBound + _slopeHead[n]) * dh;
            double minStep = tolerance / fullRate;
            double t = t0;
            double gap = Gap(o, d, t, partial, n);
            bool above = gap > 0.0;
            int steps = 0;
            while (true)
            {
                // The largest step that keeps the sign of the gap, from every split of the octaves.
                double step = minStep;
                for (int k = 0; k <= n; k++)
                {
                    double gk = above ? gap + (partial[n] - partial[k]) : -(gap + (partial[n] - partial[k]));
                    double rate = dz + (SurfaceSlopeBound + _slopeHead[k]) * dh;
                    double s = (gk - _amplitudeTail[k]) / rate;
                    if (s > step) step = s;
                }
                if (t >= t1) return Finish(ref hit, TerrainRayStatus.Miss, steps);
                double tNext = Math.Min(t + step, t1);
                double gapNext = Gap(o, d, tNext, partial, n);
                steps++;
                if (above && gapNext <= 0.0)
                {
                    double tHit = Refine(o, d, t, gap, tNext, gapNext, partial, n, ref steps);
                    hit.distance = tHit;
                    hit.point = o + d * tHit;
                    hit.point.z = Sample(hit.point.x, hit.point.y, true, out hit.normal);
                    return Finish(ref hit, TerrainRayStatus.Hit, steps + 1);
                }
                above |= gapNext > 0.0;
                t = tNext;
                gap = gapNext;
                if (steps >= maxSteps) return Finish(ref hit, TerrainRayStatus.StepLimit, steps);
            }
        }

        /// <summary>Many rays: <paramref name="hits"/>[i] for <paramref name="rays"/>[i] (each with the same tolerance).</summary>
        public void Raycast(ReadOnlySpan<TerrainRay> rays, Span<TerrainRayHit> hits, double tolerance = 1e-9, int maxSteps = 1 << 20)
        {
            if (hits.Length < rays.Length)
                throw new ArgumentException(Invariant($"hits.Length ({hits.Length}) must be at least rays.Length ({rays.Length})"), nameof(hits));
            for (int i = 0; i < rays.Length; i++) Raycast(rays[i], out hits[i], tolerance, maxSteps);
        }

        static TerrainRayStatus Finish(ref TerrainRayHit hit, TerrainRayStatus status, int evaluations)
        {
            hit.status = status;
            hit.evaluations = evaluations;
            return status;
        }

        /// <summary>Ray height minus surface height at t (all octaves), and the partial noise sums there.</summary>
        double Gap(Double3 o, Double3 d, double t, Span<double> partial, int n)
        {
            double x = GMath.clamp(o.x + t * d.x, 0.0, 1.0), y = GMath.clamp(o.y + t * d.y, 0.0, 1.0);
            return o.z + t * d.z - (SurfaceAndPartialNoise(x, y, partial) + partial[n]);
        }

        /// <summary>Regula falsi (Illinois) on [a, b] with gap(a) &gt; 0 &gt;= gap(b), bisecting when it stalls.</summary>
        double Refine(Double3 o, Double3 d, double a, double ga, double b, double gb, Span<double> partial, int n, ref int steps)
        {
            int side = 0;
            for (int i = 0; i < MaxRefineIterations && b - a > 1e-13 * Math.Max(1.0, b); i++)
            {
                double m = b - gb * (b - a) / (gb - ga);   // the secant's zero; ga > 0 >= gb
                if (!(m > a && m < b) || i % 8 == 7) m = 0.5 * (a + b);
                double gm = Gap(o, d, m, partial, n);
                steps++;
                if (gm > 0.0)
                {
                    a = m; ga = gm;
                    if (side == -1) gb *= 0.5;
                    side = -1;
                }
                else
                {
                    b = m; gb = gm;
                    if (side == +1) ga *= 0.5;
                    side = +1;
                }
            }
            return b;
        }

        /// <summary>Clips [t0, t1] to the slab lo &lt;= o + t d &lt;= hi; false when nothing is left.</summary>
        static bool Slab(double o, double d, double lo, double hi, ref double t0, ref double t1)
        {
            if (d == 0.0) return o >= lo && o <= hi && t0 <= t1;
            double a = (lo - o) / d, b = (hi - o) / d;
            if (a > b) { double s = a; a = b; b = s; }
            if (a > t0) t0 = a;
            if (b < t1) t1 = b;
            return t0 <= t1;
        }

        // ---------------------------------------------------------------- bounds

        /// <summary>
        /// A bound on |grad z| over the patch (terrain units per unit of q), valid when its x, y are affine
        /// in (u, v) (then dz/dx = dz/du / (e - a)). From the control point heights alone:
        /// dS/du = sum B'_i(u) B_j(v) Q_ij + sum B_i B_j dQ_ij/du. The first sum is
        /// 3 sum B2_i B_j (Q_{i+1,j} - Q_ij), each Q a blend of its pair, so it is at most 3 D_u, D_u the
        /// largest difference between neighbouring (i, i+1) heights, pairs counted at both their points.
        /// The second is, per interior pair, W dt/du (z0 - z1) = sigma K (a s) s (z0 - z1)
        /// (<see cref="GregoryBasis"/>) with a s &lt;= a, s &lt;= 1, K a &lt;= 9 max u (1 - u)^2 = 4/3: at most
        /// 4/3 |z0 - z1| per pair. Likewise along v.
        /// </summary>
        public static double PatchSlopeBound(GregoryPatch patch, Region region)
        {
            if (patch == null) throw new ArgumentNullException(nameof(patch));
            double du = 0.0, dv = 0.0, pairs = 0.0;
            for (int i = 0; i < 4; i++)
                for (int j = 0; j < 4; j++)
                {
                    if (i < 3) du = Math.Max(du, LargestDifference(patch, i, j, i + 1, j));
                    if (j < 3) dv = Math.Max(dv, LargestDifference(patch, i, j, i, j + 1));
                }
            foreach (int first in PairFirstSlots)
                pairs += Math.Abs(patch[first].z - patch[GregoryPatch.SecondOfPair(first)].z);
            double gu = (3.0 * du + 4.0 / 3.0 * pairs) / region.Width;
            double gv = (3.0 * dv + 4.0 / 3.0 * pairs) / region.Height;
            return Math.Sqrt(gu * gu + gv * gv);
        }

        static readonly int[] PairFirstSlots = { GregoryPatch.P110, GregoryPatch.P120, GregoryPatch.P210, GregoryPatch.P220 };

        /// <summary>Largest |z_a - z_b| over the values at net positions (i0, j0) and (i1, j1) (two at an interior position).</summary>
        static double LargestDifference(GregoryPatch p, int i0, int j0, int i1, int j1)
        {
            int a = GregoryPatch.Slot(i0, j0), b = GregoryPatch.Slot(i1, j1);
            int a2 = GregoryPatch.IsInteriorSlot(a) ? GregoryPatch.SecondOfPair(a) : a;
            int b2 = GregoryPatch.IsInteriorSlot(b) ? GregoryPatch.SecondOfPair(b) : b;
            double m = Math.Abs(p[a].z - p[b].z);
            m = Math.Max(m, Math.Abs(p[a2].z - p[b].z));
            m = Math.Max(m, Math.Abs(p[a].z - p[b2].z));
            return Math.Max(m, Math.Abs(p[a2].z - p[b2].z));
        }

        /// <summary>Whether every control point's x, y is on the thirds of the region (both points of a pair), to 1e-12 of its size.</summary>
        static bool IsAffine(GregoryPatch p, Region r)
        {
            double tolX = 1e-12 * r.Width, tolY = 1e-12 * r.Height;
            for (int i = 0; i < 4; i++)
                for (int j = 0; j < 4; j++)
                {
                    int s = GregoryPatch.Slot(i, j);
                    double x = PatchGrid.Third(r.a, r.e, i), y = PatchGrid.Third(r.b, r.f, j);
                    if (Math.Abs(p[s].x - x) > tolX || Math.Abs(p[s].y - y) > tolY) return false;
                    if (GregoryPatch.IsInteriorSlot(s))
                    {
                        Double3 q = p[GregoryPatch.SecondOfPair(s)];
                        if (Math.Abs(q.x - x) > tolX || Math.Abs(q.y - y) > tolY) return false;
                    }
                }
            return true;
        }

        static string Invariant(FormattableString s) => s.ToString(CultureInfo.InvariantCulture);
    }
}
