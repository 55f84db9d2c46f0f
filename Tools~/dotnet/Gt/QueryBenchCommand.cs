using System;
using System.Diagnostics;
using System.Threading;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// gt-cli query-bench: throughput of the CPU queries (TerrainSurfaceQuery) on one thread and on N
    /// threads, and the collider patch's sampling time and deviation from the full-detail surface, for a
    /// terrain of a given size in metres. A benchmark, not a test: it prints, it asserts nothing.
    /// </summary>
    static class QueryBenchCommand
    {
        public static int Run(Args a)
        {
            PatchGrid grid = RigScene.ReadGrid(a);
            var nv = a.Doubles("noise", 4, "0.004,16,2,2");
            int octaves = a.Int("octaves", 12);
            NoiseSettings? noise = a.Flag("no-noise") ? (NoiseSettings?)null
                : new NoiseSettings((float)nv[0], (float)nv[1], (float)nv[2], (float)nv[3], octaves);
            double size = a.Double("size", 100000);            // metres across the terrain
            double seconds = a.Double("seconds", 1.0);
            int threads = a.Int("threads", Environment.ProcessorCount);
            int colliderSamples = a.Int("collider-samples", 65);
            double colliderSpacing = a.Double("collider-spacing", 1.0);   // metres
            var query = new TerrainSurfaceQuery(grid, noise);
            Console.WriteLine(FormattableString.Invariant(
                $"# {grid.Columns}x{grid.Rows} patches, noise {(noise.HasValue ? noise.Value.ToString() : "off")}, terrain {size:R} m across; {Environment.ProcessorCount} logical CPUs"));
            Console.WriteLine(FormattableString.Invariant(
                $"# bounds: surface slope {query.SurfaceSlopeBound:G4}, noise slope {query.NoiseSlopeBoundTotal:G4}, noise amplitude {query.NoiseAmplitudeBound:G4} (terrain units)"));

            var rng = new Random(1);
            var points = new Double2[4096];
            for (int i = 0; i < points.Length; i++) points[i] = new Double2(rng.NextDouble(), rng.NextDouble());
            // Rays as a game casts them: half straight-ish down from 2 m .. 100 m above the ground, half
            // nearly horizontal from 2 m above the ground (a walker's line of sight), 200 m long.
            double metre = 1.0 / size;
            var rays = new TerrainRay[1024];
            for (int i = 0; i < rays.Length; i++)
            {
                Double2 p = new Double2(0.05 + 0.9 * rng.NextDouble(), 0.05 + 0.9 * rng.NextDouble());
                double ground = query.SampleHeight(p.x, p.y);
                double angle = 2 * Math.PI * rng.NextDouble();
                if (i % 2 == 0)
                    rays[i] = new TerrainRay(new Double3(p.x, p.y, ground + (2 + 98 * rng.NextDouble()) * metre),
                                             new Double3(0.1 * Math.Cos(angle), 0.1 * Math.Sin(angle), -1), 1e3 * metre);
                else
                    rays[i] = new TerrainRay(new Double3(p.x, p.y, ground + 2 * metre),
                                             new Double3(Math.Cos(angle), Math.Sin(angle), -0.01 * rng.NextDouble()), 200 * metre);
            }
            double tolerance = 1e-4 * metre;   // GregoryTerrainRenderer.RaycastToleranceMeters

            Console.WriteLine("query                         1 thread (/s)   " + threads + " threads (/s)");
            Report("SampleHeight", seconds, threads, () =>
            {
                double s = 0;
                foreach (Double2 p in points) s += query.SampleHeight(p.x, p.y);
                return (points.Length, s);
            });
            Report("Sample (height + normal)", seconds, threads, () =>
            {
                double s = 0;
                foreach (Double2 p in points) s += query.Sample(p.x, p.y, out Double3 n) + n.z;
                return (points.Length, s);
            });
            long evaluations = 0, hits = 0, casts = 0;
            Report("Raycast (mixed, 200 m)", seconds, threads, () =>
            {
                double s = 0;
                long e = 0, h = 0;
                foreach (TerrainRay r in rays)
                {
                    if (query.Raycast(r, out TerrainRayHit hit, tolerance) == TerrainRayStatus.Hit) { s += hit.distance; h++; }
                    e += hit.evaluations;
                }
                Interlocked.Add(ref evaluations, e);
                Interlocked.Add(ref hits, h);
                Interlocked.Add(ref casts, rays.Length);
                return (rays.Length, s);
            });
            Console.WriteLine(FormattableString.Invariant($"  rays: {(double)hits / casts:P0} hit, {(double)evaluations / casts:F1} surface evaluations per ray"));

            // The collider patch around a point: sampling time (one thread, what its worker does) and
            // deviation of the triangles from the full-detail surface, 8 x 8 points per cell.
            var patch = ColliderPatch.Around(new Double2(0.5, 0.5), colliderSpacing * metre, colliderSamples);
            var heights = new float[colliderSamples * colliderSamples];
            patch.SampleHeights(query, heights);
            var sw = Stopwatch.StartNew();
            int reps = 0;
            while (sw.Elapsed.TotalSeconds < seconds) { patch.SampleHeights(query, heights); reps++; }
            double ms = sw.Elapsed.TotalMilliseconds / reps;
            patch.Deviation(query, heights, 8, out double max, out double rms);
            Console.WriteLine(FormattableString.Invariant(
                $"collider {colliderSamples}x{colliderSamples} at {colliderSpacing:R} m: sampling {ms:F2} ms (1 thread), deviation max {max * size * 1000:F1} mm, rms {rms * size * 1000:F1} mm"));
            return 0;
        }

        /// <summary>Runs <paramref name="work"/> for about <paramref name="seconds"/> on 1 and on <paramref name="threads"/> threads; prints queries per second.</summary>
        static void Report(string name, double seconds, int threads, Func<(int count, double sink)> work)
        {
            work();   // JIT
            double one = Rate(seconds, 1, work), many = Rate(seconds, threads, work);
            Console.WriteLine(FormattableString.Invariant($"{name,-28} {one,14:N0} {many,16:N0}"));
        }

        static double Rate(double seconds, int threads, Func<(int count, double sink)> work)
        {
            long total = 0;
            var sw = Stopwatch.StartNew();
            var workers = new Thread[threads];
            for (int t = 0; t < threads; t++)
            {
                workers[t] = new Thread(() =>
                {
                    long n = 0;
                    while (sw.Elapsed.TotalSeconds < seconds) n += work().count;
                    Interlocked.Add(ref total, n);
                });
                workers[t].Start();
            }
            foreach (Thread w in workers) w.Join();
            return total / sw.Elapsed.TotalSeconds;
        }
    }
}
