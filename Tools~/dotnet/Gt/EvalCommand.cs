using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// gt-cli eval: position and normal of the terrain at global points, from Core's float path
    /// (TerrainVertex, what the shaders do), Core's double reference and, with --gpu, the GPU itself
    /// through the harness. Each point is drawn as the corner of a 1 x 1 tile at factor 1 whose range
    /// starts (or, at the far border, ends) exactly at the point, and read back (GT_READBACK).
    /// All values are in terrain space (x, y, z = height).
    /// </summary>
    static class EvalCommand
    {
        public static int Run(Args a)
        {
            var grid = RigScene.ReadGrid(a);
            List<Double2> points = ReadPoints(a);
            bool noiseOn = !a.Flag("no-noise");
            var n = a.Doubles("noise", 4, "0.004,16,2,2");
            var noise = new NoiseSettings((float)n[0], (float)n[1], (float)n[2], (float)n[3], a.Int("octaves", 4));
            double span = a.Double("span", 1.0 / 64.0);
            Harness gpu = null;
            string work = null;
            if (a.Flag("gpu"))
            {
                gpu = new Harness { Executable = a.String("harness"), SpirvDir = a.String("spirv"), Device = a.String("device", ""),
                                    PassState = Harness.ReadPassState(a.String("pass-state")) };
                if (gpu.Device.Length == 0) gpu.Device = null;
                work = Path.Combine(Path.GetTempPath(), "gt-eval-" + Guid.NewGuid().ToString("N"));
            }
            var keywords = noiseOn ? TerrainKeywords.Noise : TerrainKeywords.None;
            string variant = noiseOn ? "readback+noise" : "readback";
            Console.WriteLine("# terrain space (x, y, z = height); normals are unit; noise " + (noiseOn ? noise.ToString() : "off"));
            Console.WriteLine(FormattableString.Invariant($"# {"source",-12} {"x",12} {"y",12} {"z",14} {"nx",12} {"ny",12} {"nz",12}   {"|dp|",9} {"|dn|",9}"));
            double worstFloat = 0, worstGpu = 0;
            try
            {
                for (int k = 0; k < points.Count; k++)
                {
                    var at = Corner(points[k], span, grid, noise, noiseOn);
                    var inputs = TerrainInputs.Create(grid, at.Params);
                    TerrainVertexOutput f = TerrainVertex.Evaluate(inputs, 0, at.Tess, keywords);
                    TerrainVertex.Reference(grid, points[k], noiseOn ? noise : (NoiseSettings?)null, inputs.NoiseOctaveCount(), out Double3 rp, out Double3 rn);
                    Console.WriteLine(FormattableString.Invariant(
                        $"point {k} q ({points[k].x:R}, {points[k].y:R}) patch {f.surface.patch} uv ({f.surface.uv.x:R}, {f.surface.uv.y:R}) octaves {(noiseOn ? inputs.NoiseOctaveCount() : 0f):R}"));
                    Line("core-double", rp, rn, null, null);
                    Line("core-float", ToD(f.position), ToD(f.normal), rp, rn);
                    worstFloat = Math.Max(worstFloat, GMath.length(ToD(f.position) - rp));
                    if (gpu != null)
                    {
                        ReadGpu(gpu, work, variant, grid, at, k, out Double3 gp, out Double3 gn, out Double2 gq);
                        if (!gq.Equals(new Double2((double)RangeMapping.Approximate(f.surface.q).x, (double)RangeMapping.Approximate(f.surface.q).y)))
                            Console.WriteLine(FormattableString.Invariant($"  note: GPU q ({gq.x:R}, {gq.y:R}) differs from Core's float q"));
                        Line("gpu", gp, gn, rp, rn);
                        Line("gpu-float", gp, gn, ToD(f.position), ToD(f.normal));
                        worstGpu = Math.Max(worstGpu, GMath.length(gp - ToD(f.position)));
                    }
                }
            }
            finally
            {
                if (work != null && Directory.Exists(work)) Directory.Delete(work, true);
            }
            Console.WriteLine(FormattableString.Invariant($"max |core-float - core-double| position {worstFloat:G3}"));
            if (gpu != null) Console.WriteLine(FormattableString.Invariant($"max |gpu - core-float| position {worstGpu:G3}"));
            return 0;
        }

        /// <summary>Vertices across the whole terrain that the noise's octave count is budgeted for (8 tiles of 64).</summary>
        const double VerticesPerUnit = 512;

        sealed class CornerRun { public TerrainParams Params; public Float2 Tess; public TerrainRange Range; }

        /// <summary>
        /// A range of size span whose corner (s, t) = (0, 0) is the point, or, per axis where that would
        /// leave the unit square, whose corner 1 is. Tiles 1, uniform factor 1: four vertices.
        /// </summary>
        static CornerRun Corner(Double2 q, double span, PatchGrid grid, NoiseSettings noise, bool noiseOn)
        {
            // At the far corner the GPU forms q = c + 1 (g - c). With g the float of the point and
            // c = g - span (exact for a power-of-two span), g - c is exact, so q is that float exactly,
            // just as q = c is at the near corner.
            double c = q.x, d = q.y, s = 0, t = 0, g, h;
            if (c + span > 1) { g = (float)q.x; c = g - span; s = 1; } else g = c + span;
            if (d + span > 1) { h = (float)q.y; d = h - span; t = 1; } else h = d + span;
            var range = new TerrainRange(c, d, g, h);
            // The octave count follows the range; budget it as a view of the whole terrain with
            // VerticesPerUnit vertices across would (the span's share of them), so the point gets the
            // noise such a view shows, not the few octaves a 1 x 1 tile alone would allow.
            var p = TerrainParams.Create(grid, range, RangeOrigin.For(range), TessellationSettings.Uniform(1, 1f),
                noiseOn ? noise : new NoiseSettings(0f, noise.frequency, noise.alpha, noise.beta, 0),
                new HeightColorSettings(0.25f, 0.15f, 24f), new Float3(0.2f, 0.3f, 0.1f), new Float3(0.8f, 0.8f, 0.8f),
                (float)(VerticesPerUnit * span));
            return new CornerRun { Params = p, Tess = new Float2((float)s, (float)t), Range = range };
        }

        static void ReadGpu(Harness gpu, string work, string variant, PatchGrid grid, CornerRun at, int k,
                            out Double3 position, out Double3 normal, out Double2 q)
        {
            string dir = Path.Combine(work, "p" + k.ToString(CultureInfo.InvariantCulture));
            var camera = RigCamera.LookAt(new[] { 0.5, 2.0, -0.5 }, new[] { 0.5, 0.0, 0.5 }, 60, 64, 64, 0.01, 10, RigCamera.Scale(1, 1, 1));
            Directory.CreateDirectory(dir);
            BufferFiles.Write(Path.Combine(dir, "control_points.f32"), GpuLayout.PackControlPoints(grid));
            BufferFiles.Write(Path.Combine(dir, "regions.f32"), GpuLayout.PackRegions(grid));
            BufferFiles.Write(Path.Combine(dir, "grid_lines.f32"), GpuLayout.PackGridLines(grid));
            BufferFiles.Write(Path.Combine(dir, "params.f32"), at.Params.Pack());
            BufferFiles.Write(Path.Combine(dir, "camera.f32"), camera.Pack());
            string readback = Path.Combine(dir, "readback.f32");
            // A set range origin needs the stages that compile its code (GT_RANGE_ORIGIN), as the renderer draws it.
            var args = gpu.TessellatedStages(RelativeSurface.NeedsRangeOriginKeyword(at.Params.rangeOrigin, false, false) ? variant + "+range_origin" : variant);
            args.AddRange(new[] { "--buffers", dir, "--patches", "1", "--width", "64", "--height", "64",
                                  "--readback", readback, "--readback-floats", (12 * 4).ToString(CultureInfo.InvariantCulture) });
            gpu.Run(args);
            float[] r = BufferFiles.Read(readback);
            int v = 12 * ((int)at.Tess.y * 2 + (int)at.Tess.x);
            // Readback: (position.xyz, 1), (normal.xyz, 0), (q.xy, u, v); object space is (x, z, y).
            position = new Double3(r[v], r[v + 2], r[v + 1]);
            normal = new Double3(r[v + 4], r[v + 6], r[v + 5]);
            q = new Double2(r[v + 8], r[v + 9]);
        }

        static void Line(string source, Double3 p, Double3 n, Double3? refP, Double3? refN)
        {
            string diff = refP.HasValue
                ? FormattableString.Invariant($"   {GMath.length(p - refP.Value),9:G3} {GMath.length(n - refN.Value),9:G3}")
                : "";
            Console.WriteLine(FormattableString.Invariant(
                $"  {source,-12} {p.x,12:F9} {p.y,12:F9} {p.z,14:F11} {n.x,12:F9} {n.y,12:F9} {n.z,12:F9}{diff}"));
        }

        static Double3 ToD(Float3 v) => new Double3(v.x, v.y, v.z);

        const long MaxPointsFileBytes = 16L << 20;

        /// <summary>--points "x,y;x,y;..." or --points-file FILE (one "x y" or "x,y" per line, # comments).</summary>
        static List<Double2> ReadPoints(Args a)
        {
            string text;
            string file = a.String("points-file", "");
            string option = file.Length > 0 ? "--points-file" : "--points";
            if (file.Length > 0)
            {
                InputLimits.CheckFileToRead(file, MaxPointsFileBytes);
                text = File.ReadAllText(file).Replace('\n', ';');
            }
            else text = a.String("points");
            var r = new List<Double2>();
            foreach (string raw in text.Split(';'))
            {
                string item = raw.Split('#')[0].Trim();
                if (item.Length == 0) continue;
                string[] xy = item.Split(new[] { ',', ' ', '\t' }, StringSplitOptions.RemoveEmptyEntries);
                if (xy.Length != 2 || !double.TryParse(xy[0], NumberStyles.Float, CultureInfo.InvariantCulture, out double x)
                    || !double.TryParse(xy[1], NumberStyles.Float, CultureInfo.InvariantCulture, out double y))
                    throw new UsageException($"{option}: point '{InputLimits.Quote(item)}' is not 'x,y' (two numbers)");
                if (!(x >= 0 && x <= 1 && y >= 0 && y <= 1))
                    throw new ArgumentException($"{option}: point '{InputLimits.Quote(item)}' must lie in the unit square [0,1]^2");
                r.Add(new Double2(x, y));
            }
            if (r.Count == 0) throw new ArgumentException("no points given (--points \"x,y;x,y\" or --points-file FILE)");
            return r;
        }
    }
}
