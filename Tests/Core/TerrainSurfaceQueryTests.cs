using System;
using System.Threading;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// CPU height, normal and ray queries (TerrainSurfaceQuery): the surface the GPU draws at full
    /// detail (every octave), against the double reference and the float path; allocation-free,
    /// thread-safe; the ray march's bounds hold and it finds thin ridges at grazing angles.
    /// </summary>
    [TestFixture]
    public class TerrainSurfaceQueryTests
    {
        static readonly NoiseSettings Noise = new NoiseSettings(0.004f, 16f, 2f, 2f, 8);
        PatchGrid _grid;
        TerrainSurfaceQuery _query, _plain;

        [OneTimeSetUp]
        public void Fit()
        {
            _grid = HeightmapFitter.Fit(HeightmapFitterTests.Samples(33, 33), 33, 33, 4, 3).Grid;
            _query = new TerrainSurfaceQuery(_grid, Noise);
            _plain = new TerrainSurfaceQuery(_grid, null);
        }

        static Double2[] RandomPoints(int count, int seed)
        {
            var r = new Random(seed);
            var p = new Double2[count];
            for (int i = 0; i < count; i++) p[i] = new Double2(r.NextDouble(), r.NextDouble());
            // Grid lines, corners and the far border too.
            p[0] = new Double2(0, 0); p[1] = new Double2(1, 1); p[2] = new Double2(0.25, 1.0 / 3.0); p[3] = new Double2(1, 0.5);
            return p;
        }

        [TestCase(false)]
        [TestCase(true)]
        public void HeightsAndNormalsAreTheDoubleReferenceAtFullDetail(bool noise)
        {
            TerrainSurfaceQuery q = noise ? _query : _plain;
            double worstP = 0, worstN = 0;
            foreach (Double2 p in RandomPoints(2000, 7))
            {
                double h = q.Sample(p.x, p.y, out Double3 n);
                TerrainVertex.Reference(_grid, p, noise ? Noise : (NoiseSettings?)null, noise ? Noise.octaves : 0, out Double3 rp, out Double3 rn);
                worstP = Math.Max(worstP, Math.Abs(h - rp.z));
                worstN = Math.Max(worstN, GMath.length(n - rn));
                Assert.That(q.SampleHeight(p.x, p.y), Is.EqualTo(h), "SampleHeight and Sample agree");
            }
            TestContext.WriteLine($"query vs double reference: height {worstP:G3}, normal {worstN:G3} (terrain units)");
            Assert.That(worstP, Is.LessThanOrEqualTo(1e-15));
            Assert.That(worstN, Is.LessThanOrEqualTo(1e-15));
        }

        [Test]
        public void TheGpuFloatPathAtFullOctavesStaysNearTheQuery()
        {
            // The float path the shaders run, with the octave count forced to every octave (a huge
            // vertex count): what the GPU draws where the range is narrow enough to show all octaves.
            var p = TerrainParams.Create(_grid, TerrainRange.full, RangeOrigin.zero, TessellationSettings.Uniform(4, 8f), Noise,
                new HeightColorSettings(0.25f, 0.1f, 8f), new Float3(0, 0, 0), new Float3(1, 1, 1), 1e9f);
            var inputs = TerrainInputs.Create(_grid, p);
            Assert.That(inputs.NoiseOctaveCount(), Is.EqualTo((float)Noise.octaves));
            double worst = 0;
            foreach (Double2 q in RandomPoints(2000, 11))
            {
                var tp = TerrainPoint.FromFloat((Float2)q);
                TerrainVertexOutput f = TerrainVertex.EvaluateAt(inputs, tp, TerrainKeywords.Noise);
                Double2 at = tp.ToDouble();
                worst = Math.Max(worst, Math.Abs(f.position.z - _query.SampleHeight(at.x, at.y)));
            }
            TestContext.WriteLine($"float path vs query at the same points: {worst:G3} terrain units");
            // Float rounding of a height ~0.1 plus 8 octaves: a few float ulps of the extent.
            Assert.That(worst, Is.LessThan(1e-6));
        }

        [Test]
        public void OutsideTheUnitSquareIsNaNAndBatchesMatchSingleCalls()
        {
            Assert.That(_query.SampleHeight(-1e-9, 0.5), Is.NaN);
            Assert.That(_query.SampleHeight(0.5, double.NaN), Is.NaN);
            Assert.That(_query.SampleNormal(1.5, 0.5), Is.EqualTo(Double3.zero));
            Double2[] pts = RandomPoints(300, 3);
            var h = new double[pts.Length];
            var hn = new double[pts.Length];
            var n = new Double3[pts.Length];
            _query.SampleHeights(pts, h);
            _query.Sample(pts, hn, n);
            for (int i = 0; i < pts.Length; i++)
            {
                Assert.That(h[i], Is.EqualTo(_query.SampleHeight(pts[i].x, pts[i].y)));
                Assert.That(hn[i], Is.EqualTo(h[i]));
                Assert.That(n[i], Is.EqualTo(_query.SampleNormal(pts[i].x, pts[i].y)));
            }
            var ex = Assert.Throws<ArgumentException>(() => _query.SampleHeights(pts, new double[3]));
            StringAssert.Contains("heights.Length (3)", ex.Message);
        }

        [Test]
        public void QueriesAllocateNothing()
        {
            Double2[] pts = RandomPoints(256, 5);
            var h = new double[pts.Length];
            var n = new Double3[pts.Length];
            TerrainRay[] rays = Rays(64, 9);
            var hits = new TerrainRayHit[rays.Length];
            void Run()
            {
                _query.SampleHeights(pts, h);
                _query.Sample(pts, h, n);
                _query.Raycast(rays, hits);
                _query.SampleHeight(0.3, 0.4);
                _query.SampleNormal(0.3, 0.4);
                _query.Raycast(rays[0], out _);
            }
            Run();   // JIT and statics first
            // The runtime may allocate a few bytes once on this thread (tiered JIT installing a
            // method); an allocation per query would cost at least 24 bytes x 579 queries a run.
            long least = long.MaxValue, most = 0;
            for (int rep = 0; rep < 10; rep++)
            {
                long before = GC.GetAllocatedBytesForCurrentThread();
                Run();
                long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
                least = Math.Min(least, allocated);
                most = Math.Max(most, allocated);
            }
            TestContext.WriteLine($"bytes allocated per run of 256 heights, 256 samples and 65 rays: {least} .. {most}");
            Assert.That(least, Is.EqualTo(0));
            Assert.That(most, Is.LessThan(64));
        }

        [Test]
        public void ThreadsGetTheSingleThreadedResults()
        {
            Double2[] pts = RandomPoints(4096, 13);   // a power of two: every odd stride below visits each point once
            TerrainRay[] rays = Rays(200, 17);
            var h0 = new double[pts.Length];
            var n0 = new Double3[pts.Length];
            var r0 = new TerrainRayHit[rays.Length];
            _query.Sample(pts, h0, n0);
            _query.Raycast(rays, r0);
            const int threads = 4;
            var failures = new int[threads];
            var workers = new Thread[threads];
            for (int k = 0; k < threads; k++)
            {
                int id = k;
                workers[k] = new Thread(() =>
                {
                    var h = new double[pts.Length];
                    var n = new Double3[pts.Length];
                    var r = new TerrainRayHit[rays.Length];
                    for (int rep = 0; rep < 3; rep++)
                    {
                        // Each thread in its own order, so state shared between calls would mix the threads' points.
                        for (int i0 = 0; i0 < pts.Length; i0++)
                        {
                            int i = (i0 * (2 * id + 1) + 997 * id) % pts.Length;
                            h[i] = _query.Sample(pts[i].x, pts[i].y, out n[i]);
                        }
                        _query.Raycast(rays, r);
                        for (int i = 0; i < pts.Length; i++)
                            if (!h[i].Equals(h0[i]) || !n[i].Equals(n0[i])) failures[id]++;
                        for (int i = 0; i < rays.Length; i++)
                            if (r[i].status != r0[i].status || !r[i].distance.Equals(r0[i].distance)) failures[id]++;
                    }
                });
                workers[k].Start();
            }
            foreach (Thread t in workers) t.Join();
            Assert.That(failures, Is.All.EqualTo(0), "results differing from the single-threaded ones, per thread");
        }

        // ------------------------------------------------------------------ bounds

        [Test]
        public void PatchSlopeBoundHoldsOnEveryPatch()
        {
            // Gregory patches with distinct pairs (random heights on thirds x, y) and the fitted grid.
            var r = new Random(21);
            double worstRatio = 0;
            for (int trial = 0; trial < 40; trial++)
            {
                PatchGrid g = PatchGrid.CreateFlat(1, 1);
                GregoryPatch p = g.Patches[0];
                for (int s = 0; s < GregoryPatch.SlotCount; s++) p[s] = new Double3(p[s].x, p[s].y, r.NextDouble() - 0.5);
                var region = g.RegionOf(0);
                double bound = TerrainSurfaceQuery.PatchSlopeBound(p, region);
                for (int k = 0; k < 400; k++)
                {
                    double u = r.NextDouble(), v = r.NextDouble();
                    if (k < 4) { u = k & 1; v = k >> 1; }
                    GregoryEval.Evaluate(p.Points, u, v, out _, out Double3 du, out Double3 dv);
                    double slope = Math.Sqrt(du.z * du.z / (region.Width * region.Width) + dv.z * dv.z / (region.Height * region.Height));
                    worstRatio = Math.Max(worstRatio, slope / bound);
                }
            }
            TestContext.WriteLine($"largest sampled slope / bound: {worstRatio:F3}");
            Assert.That(worstRatio, Is.LessThanOrEqualTo(1.0));
            Assert.That(_plain.AffinePatches, Is.True, "fitted grids have affine x, y");
        }

        [Test]
        public void NoiseSlopeBoundHoldsForOneOctave()
        {
            var r = new Random(4);
            double worst = 0;
            for (int k = 0; k < 200000; k++)
            {
                GradientNoise.Evaluate(r.NextDouble() * 512 - 256, r.NextDouble() * 512 - 256, out Double2 g);
                worst = Math.Max(worst, GMath.length(g));
            }
            TestContext.WriteLine($"largest sampled |grad K| {worst:F3}, bound {TerrainSurfaceQuery.NoiseSlopeBound}");
            Assert.That(worst, Is.LessThanOrEqualTo(TerrainSurfaceQuery.NoiseSlopeBound));
        }

        // ------------------------------------------------------------------ rays

        TerrainRay[] Rays(int count, int seed)
        {
            var r = new Random(seed);
            var rays = new TerrainRay[count];
            for (int i = 0; i < count; i++)
            {
                var o = new Double3(r.NextDouble(), r.NextDouble(), _plain.MaxControlHeight + 0.05 + 0.2 * r.NextDouble());
                var target = new Double3(r.NextDouble(), r.NextDouble(), _plain.MinControlHeight);
                rays[i] = new TerrainRay(o, target - o, 3.0);
            }
            return rays;
        }

        /// <summary>The first downward crossing by brute force: steps of h along the ray, then bisection.</summary>
        double BruteForce(TerrainSurfaceQuery q, TerrainRay ray, double h)
        {
            Double3 d = ray.direction / GMath.length(ray.direction);
            double Gap(double t)
            {
                Double3 p = ray.origin + d * t;
                double z = q.SampleHeight(GMath.clamp(p.x, 0, 1), GMath.clamp(p.y, 0, 1));
                return p.z - z;
            }
            double prev = Gap(0);
            for (double t = h; t <= ray.maxDistance; t += h)
            {
                Double3 p = ray.origin + d * t;
                if (p.x < 0 || p.x > 1 || p.y < 0 || p.y > 1) break;
                double g = Gap(t);
                if (prev > 0 && g <= 0)
                {
                    double a = t - h, b = t;
                    for (int i = 0; i < 80; i++) { double m = 0.5 * (a + b); if (Gap(m) > 0) a = m; else b = m; }
                    return b;
                }
                prev = g;
            }
            return double.NaN;
        }

        [Test]
        public void RaysHitWhereBruteForceFindsTheSurface()
        {
            TerrainRay[] rays = Rays(60, 23);
            int hits = 0;
            foreach (TerrainRay ray in rays)
            {
                _query.Raycast(ray, out TerrainRayHit hit);
                double expected = BruteForce(_query, ray, 2e-5);
                Assert.That(hit.status, Is.EqualTo(double.IsNaN(expected) ? TerrainRayStatus.Miss : TerrainRayStatus.Hit), $"ray {ray.origin} -> {ray.direction}");
                if (hit.status != TerrainRayStatus.Hit) continue;
                hits++;
                Assert.That(hit.distance, Is.EqualTo(expected).Within(1e-10));
                Assert.That(Math.Abs(hit.point.z - _query.SampleHeight(hit.point.x, hit.point.y)), Is.LessThan(1e-12));
                Assert.That(hit.normal.z, Is.GreaterThan(0));
            }
            Assert.That(hits, Is.GreaterThan(50));
        }

        [Test]
        public void GrazingRaysFindThinRidgesAboveTheTolerance()
        {
            // Horizontal rays just below the highest point of the surface along their line: only a
            // sliver of the ridge (depth 5e-9 .. 1e-7) pokes above them. The march must not step over it.
            var r = new Random(31);
            int checkedRays = 0;
            for (int k = 0; k < 30; k++)
            {
                double y = 0.05 + 0.9 * r.NextDouble();
                // The highest surface point along y, to 1e-12 (dense sampling, then golden refinement).
                double best = 0, bestZ = double.MinValue;
                for (double x = 0; x <= 1; x += 1e-4)
                {
                    double z = _query.SampleHeight(x, y);
                    if (z > bestZ) { bestZ = z; best = x; }
                }
                double lo = Math.Max(0, best - 1e-4), hi = Math.Min(1, best + 1e-4);
                for (int i = 0; i < 100; i++)
                {
                    double m1 = lo + (hi - lo) * 0.382, m2 = lo + (hi - lo) * 0.618;
                    if (_query.SampleHeight(m1, y) > _query.SampleHeight(m2, y)) hi = m2; else lo = m1;
                }
                double peakX = 0.5 * (lo + hi), peak = _query.SampleHeight(peakX, y);
                if (peakX < 0.01 || peakX > 0.99) continue;
                double depth = 5e-9 * Math.Pow(20, r.NextDouble());
                var ray = new TerrainRay(new Double3(0, y, peak - depth), new Double3(1, 0, 0), 2);
                var status = _query.Raycast(ray, out TerrainRayHit hit, 1e-9);
                Assert.That(status, Is.EqualTo(TerrainRayStatus.Hit), $"ray at y {y:R}, {depth:G3} below the ridge at x {peakX:R}");
                Assert.That(hit.point.x, Is.LessThanOrEqualTo(peakX + 1e-9));
                checkedRays++;
            }
            Assert.That(checkedRays, Is.GreaterThan(20));
        }

        [Test]
        public void RaysThatMissOrStartBelowTheSurface()
        {
            Assert.That(_query.Raycast(new TerrainRay(new Double3(0.5, 0.5, 1), new Double3(0, 0, 1), 10), out _), Is.EqualTo(TerrainRayStatus.Miss));
            Assert.That(_query.Raycast(new TerrainRay(new Double3(-1, 0.5, 0), new Double3(-1, 0, 0), 10), out _), Is.EqualTo(TerrainRayStatus.Miss));
            double z = _query.SampleHeight(0.5, 0.5);
            // Straight down from above: the hit is the height there.
            Assert.That(_query.Raycast(new TerrainRay(new Double3(0.5, 0.5, z + 0.3), new Double3(0, 0, -1), 10), out TerrainRayHit down), Is.EqualTo(TerrainRayStatus.Hit));
            Assert.That(down.distance, Is.EqualTo(0.3).Within(1e-12));
            // From below, going down: never crosses from above.
            Assert.That(_query.Raycast(new TerrainRay(new Double3(0.5, 0.5, z - 0.01), new Double3(0, 0, -1), 10), out _), Is.EqualTo(TerrainRayStatus.Miss));
            // Too short to reach.
            Assert.That(_query.Raycast(new TerrainRay(new Double3(0.5, 0.5, z + 0.3), new Double3(0, 0, -1), 0.29), out _), Is.EqualTo(TerrainRayStatus.Miss));
        }

        [Test]
        public void BadRaysAndSettingsNameTheField()
        {
            var ex = Assert.Throws<ArgumentException>(() => _query.Raycast(new TerrainRay(new Double3(0, double.NaN, 0), new Double3(0, 0, -1), 1), out _));
            StringAssert.Contains("ray (origin", ex.Message);
            ex = Assert.Throws<ArgumentException>(() => _query.Raycast(new TerrainRay(new Double3(0, 0, 0), Double3.zero, 1), out _));
            StringAssert.Contains("ray.direction", ex.Message);
            ex = Assert.Throws<ArgumentException>(() => _query.Raycast(new TerrainRay(new Double3(0, 0, 0), new Double3(0, 0, -1), 1), out _, 0));
            StringAssert.Contains("tolerance (0)", ex.Message);
            ex = Assert.Throws<ArgumentException>(() => new TerrainSurfaceQuery(_grid, new NoiseSettings(0.01f, -1f, 2f, 2f, 4)));
            StringAssert.Contains("noise.frequency (-1)", ex.Message);
        }

        // ------------------------------------------------------------------ collider patch

        [Test]
        public void ColliderPatchStaysOnTheLatticeAndRebuildsOnlyWhenTheTargetLeavesItsMiddle()
        {
            var a = ColliderPatch.Around(new Double2(0.4, 0.6), 1.0 / 512, 65);
            Assert.That(a.Center.x, Is.EqualTo(0.4).Within(0.5 / 512));
            Assert.That(a.Point(0, 0).x * 512, Is.EqualTo(Math.Round(a.Point(0, 0).x * 512)).Within(1e-9), "samples on the lattice");
            Assert.That(a.NeedsRebuild(new Double2(0.4 + 0.2 * a.Size, 0.6), 0.5), Is.False);
            Assert.That(a.NeedsRebuild(new Double2(0.4 + 0.3 * a.Size, 0.6), 0.5), Is.True);
            var b = ColliderPatch.Around(new Double2(0.4 + 0.3 * a.Size, 0.6), 1.0 / 512, 65);
            // A shared sample is the same point in both windows.
            int shift = (int)(b.firstX - a.firstX);
            Assert.That(shift, Is.GreaterThan(0));
            Assert.That(b.Point(0, 5), Is.EqualTo(a.Point(shift, 5)));
            // At the terrain's corner the window stays inside and is not rebuilt for moves there.
            var c = ColliderPatch.Around(new Double2(0.001, 0.001), 1.0 / 512, 65);
            Assert.That(c.firstX, Is.EqualTo(0));
            Assert.That(c.NeedsRebuild(new Double2(0.0, 0.0), 0.5), Is.False);
            var ex = Assert.Throws<ArgumentException>(() => ColliderPatch.Around(new Double2(0, 0), 0, 65));
            StringAssert.Contains("spacing (0)", ex.Message);
            ex = Assert.Throws<ArgumentException>(() => a.NeedsRebuild(new Double2(0, 0), 1.5));
            StringAssert.Contains("threshold (1.5)", ex.Message);
        }

        [Test]
        public void ColliderTrianglesInterpolateTheSamplesAndFaceUp()
        {
            var patch = ColliderPatch.Around(new Double2(0.5, 0.5), 1.0 / 256, 9);
            var h = new float[81];
            patch.SampleHeights(_query, h);
            int[] tri = ColliderPatch.Triangles(9);
            Assert.That(tri.Length, Is.EqualTo(6 * 64));
            for (int k = 0; k < tri.Length; k += 3)
            {
                // Unity object space (x, height, y): seen from above, clockwise = negative signed area in (x, y).
                Double2 p0 = Pt(patch, tri[k]), p1 = Pt(patch, tri[k + 1]), p2 = Pt(patch, tri[k + 2]);
                double area = (p1.x - p0.x) * (p2.y - p0.y) - (p1.y - p0.y) * (p2.x - p0.x);
                Assert.That(area, Is.LessThan(0), "clockwise from above (Unity's front face)");
                // The interpolation at the triangle's centroid is the mean of its corners.
                Double2 c = new Double2((p0.x + p1.x + p2.x) / 3, (p0.y + p1.y + p2.y) / 3);
                double expected = ((double)h[tri[k]] + h[tri[k + 1]] + h[tri[k + 2]]) / 3.0;
                Assert.That(patch.ColliderHeight(h, c.x, c.y), Is.EqualTo(expected).Within(1e-12));
            }
            Assert.That(patch.ColliderHeight(h, patch.Point(3, 4).x, patch.Point(3, 4).y), Is.EqualTo(h[4 * 9 + 3]).Within(1e-15));
        }

        static Double2 Pt(ColliderPatch p, int v) => p.Point(v % p.samples, v / p.samples);

        [Test]
        public void ColliderDeviationShrinksWithTheSpacing()
        {
            // Without noise the Gregory surface is smooth: halving the spacing quarters the deviation.
            double previous = double.MaxValue;
            foreach (int per in new[] { 64, 128, 256 })
            {
                var patch = ColliderPatch.Around(new Double2(0.5, 0.5), 1.0 / per, 33);
                var h = new float[33 * 33];
                patch.SampleHeights(_plain, h);
                patch.Deviation(_plain, h, 4, out double max, out double rms);
                TestContext.WriteLine($"spacing 1/{per}: max {max:G3}, rms {rms:G3}");
                Assert.That(max, Is.LessThan(previous / 3), "second-order convergence");
                previous = max;
            }
        }
    }
}
