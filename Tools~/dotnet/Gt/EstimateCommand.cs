using System;
using System.Diagnostics;
using System.IO;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// gt-cli estimate: what the renderer inspector's "Triangles in view" costs on the CPU
    /// (Core's TerrainTriangleEstimate, as GregoryTerrainRenderer.EstimateTrianglesInView runs it:
    /// at most 256 tiles, an even lattice of them beyond), and how far that sample is from the count
    /// over every tile. The bench's far view at 1920x1080, adaptive factors, 4 noise octaves.
    /// Usage: estimate --grid FILE [--tiles 16,32,64] [--target 0.25] [--repeat 20]
    /// A benchmark that prints figures, .NET on this machine (not Unity's Mono or IL2CPP).
    /// </summary>
    static class EstimateCommand
    {
        public static int Run(Args a)
        {
            var grid = RigScene.ReadGrid(a);
            int[] tileCounts = a.Ints("tiles", "16,32,64");
            double target = a.Double("target", 0.25);
            int repeat = a.Int("repeat", 20);
            Console.WriteLine("| tiles | target px | sampled tiles | ms per estimate (median of {0}) | estimate | every tile | difference |", repeat);
            Console.WriteLine("| ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
            foreach (int m in tileCounts)
            {
                var cfg = new BenchConfig { Method = "adaptive", Tiles = m, Target = target, Octaves = 4 };
                RigScene scene = BenchPlan.Scene(grid, cfg, BenchPlan.CameraPath[0].range, 1920, 1080);
                var inputs = TerrainInputs.Create(grid, scene.Params);
                Float4x4 clip = scene.Camera.ObjectToClipFloat();
                var screen = new Float2(scene.Camera.Width, scene.Camera.Height);
                TriangleEstimate Estimate(int maxTiles) => TerrainTriangleEstimate.InView(inputs, clip, screen, TerrainKeywords.Noise,
                    TessellationPartitioning.FractionalOdd, maxTiles);
                TriangleEstimate sample = Estimate(256);
                for (int i = 0; i < 10; i++) Estimate(256);   // warm-up: .NET's tiered JIT optimises after a few calls
                var ms = new double[repeat];
                for (int i = 0; i < repeat; i++)
                {
                    var watch = Stopwatch.StartNew();
                    Estimate(256);
                    ms[i] = watch.Elapsed.TotalMilliseconds;
                }
                Array.Sort(ms);
                TriangleEstimate all = Estimate(int.MaxValue);
                double diff = 100.0 * (sample.triangles - all.triangles) / Math.Max(1.0, all.triangles);
                Console.WriteLine(FormattableString.Invariant(
                    $"| {m} | {target} | {sample.tilesSampled} of {sample.tileCount} | {ms[repeat / 2]:F2} | {sample.triangles:N0} | {all.triangles:N0} | {diff:+0.0;-0.0;0.0}% |"));
            }
            return 0;
        }
    }
}
