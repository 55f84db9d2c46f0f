using System;
using System.IO;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// gt-cli jitter: the deep-zoom table of precision.md. For each range width, the vertex jitter
    /// (pixels; ZoomJitter.cs here defines it) of the plain float path, the origin-only path and the
    /// shipped path, on the CPU with the float arithmetic the shaders use.
    /// Options: --grid FILE (default: the demo grid fitted here), --center x,y, --widths w1,w2,...,
    /// --pixels W (800), --tiles M (8), --factor F (16), --pan P (0.25 pixel),
    /// --noise amplitude,frequency,alpha,beta (default: none; e.g. 0.004,16,2,2) with --octaves N (6):
    /// the height then includes the octave noise (GT_NOISE), relative too on the shipped path.
    /// </summary>
    static class JitterCommand
    {
        public static int Run(Args a)
        {
            PatchGrid grid = a.Flag("grid")
                ? RigScene.ReadGrid(a)
                : HeightmapFitter.Fit(DemoGridCommand.Heightmap(129), 129, 129, 5, 5).Grid;
            var c = a.Doubles("center", 2, "0.5137,0.6262");
            double[] widths = a.Doubles("widths", 0, "1e-2,1e-4,1e-6");
            double pixels = a.Double("pixels", 800), pan = a.Double("pan", 0.25);
            int tiles = a.Int("tiles", 8), factor = a.Int("factor", 16);
            NoiseSettings? noise = null;
            if (a.Flag("noise"))
            {
                var n = a.Doubles("noise", 4, "0.004,16,2,2");
                noise = new NoiseSettings((float)n[0], (float)n[1], (float)n[2], (float)n[3], a.Int("octaves", 6));
            }
            Console.WriteLine(FormattableString.Invariant(
                $"jitter (px) of a {pixels:R}-pixel zoom view, {tiles}x{tiles} tiles at factor {factor}, pan {pan:R} px, centre ({c[0]:R}, {c[1]:R}), noise {(noise.HasValue ? noise.Value.ToString() : "off")}"));
            Console.WriteLine("width     plain      origin-only  shipped    (shipped largest error px)");
            foreach (double w in widths)
            {
                var center = new Double2(c[0], c[1]);
                double plain = ZoomJitter.Measure(grid, VertexPath.Plain, center, w, pixels, tiles, factor, pan, out _, noise);
                double origin = ZoomJitter.Measure(grid, VertexPath.OriginOnly, center, w, pixels, tiles, factor, pan, out _, noise);
                double shipped = ZoomJitter.Measure(grid, VertexPath.Shipped, center, w, pixels, tiles, factor, pan, out double err, noise);
                Console.WriteLine(FormattableString.Invariant($"{w,-9:G3} {plain,-10:G3} {origin,-12:G3} {shipped,-10:G3} {err:G3}"));
            }
            return 0;
        }
    }
}
