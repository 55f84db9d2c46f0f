using System;
using System.IO;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// gt-cli lod-scene: the harness inputs of a ground-level view drawn with the levels of detail
    /// (<see cref="LodScene"/>): a terrain --terrain-m metres wide (default 100 km), the camera --eye-m
    /// above the surface (default 2 m), M = --tiles, adaptive factors at --target-pixels (or a uniform
    /// --factor), the continuous octave rule at --segment-pixels, the camera's screen --width x --height,
    /// over --grid FILE or the demo grid (gt demo's terrain, fitted to 129 x 129 samples), with the
    /// relief in metres of a --relief-m wide terrain (default 100 km; 0: the grid stretched to --terrain-m).
    /// Writes the --buffers folder and lod_tail.f32 (--params-tail) into --out, and prints
    /// "levels L", "patches N" and "ranges ..." for Tools~/rig/lod-bench.sh. --no-origin: the levels
    /// absolute (no range origin; the renderer always sets one near the camera); --no-plain: every vertex
    /// on the precise path (no levels' plain path). With --factors FILE
    /// (the GPU's GT_FACTOR_READBACK of that draw) it also prints one "lod_error ..." line: the drawn
    /// triangles against the double full-detail surface (LodError, internals.md "Levels of detail").
    /// </summary>
    static class LodSceneCommand
    {
        public static int Run(Args a)
        {
            string dir = a.String("out");
            PatchGrid grid = a.Flag("grid") ? PatchGridJson.ReadFile(a.String("grid"))
                : DemoGridCommand.GroundViewGrid();
            var s = new LodScene
            {
                TerrainMeters = a.Double("terrain-m", 100000),
                EyeMeters = a.Double("eye-m", 2),
                FinestMeters = a.Double("finest-m", 16),
                Tiles = a.Int("tiles", 16),
                Factor = a.Int("factor", 0),
                TargetPixels = (float)a.Double("target-pixels", 1),
                SegmentPixels = (float)a.Double("segment-pixels", 2),
                Width = a.Int("width", 1920),
                Height = a.Int("height", 1080),
                ReliefMeters = a.Double("relief-m", 100000),
                UseOrigin = !a.Flag("no-origin"),
                PlainPath = !a.Flag("no-plain"),
            };
            double[] ground = a.Doubles("ground", 2, "0.37,0.52");
            s.Ground = new Double2(ground[0], ground[1]);
            s.Build(grid).Write(dir);
            Console.WriteLine($"levels {s.LevelCount}");
            Console.WriteLine($"patches {s.Patches}");
            Console.WriteLine($"level0_m {s.TerrainMeters * s.Levels[0].Width:G6}");
            Console.WriteLine($"tail {Path.Combine(dir, "lod_tail.f32")}");
            Console.WriteLine(FormattableString.Invariant($"origin {s.Origin.Value.Value.x:R},{s.Origin.Value.Value.y:R}"));
            if (a.Flag("factors"))
            {
                PatchFactors[] f = PatchFactors.FromReadback(BufferFiles.Read(a.String("factors")), s.Patches);
                Console.WriteLine(a.Flag("per-level") ? LodError.MeasureLevels(s, f, a.Int("max-cells", 1 << 20)) : LodError.Measure(s, f, a.Int("max-cells", 1 << 20)));
            }
            return 0;
        }
    }
}
