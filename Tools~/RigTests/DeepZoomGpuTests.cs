// Deep-zoom vertex jitter on the GPU (lavapipe, readback variant), the definition of Core's ZoomJitter
// (precision.md): 4 x 4 tiles at factor 8, 8 frames panned by (k, k/2) * 0.25 px of an 800-pixel
// view, the frame-0 origin kept; one harness run per frame with --range encoded against it, the
// frames of a path in one batch process. Plain float32 (RangeOrigin.zero) against the shipped path,
// noise off and on.
using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture, Parallelizable(ParallelScope.Self), Order(11)]
    public class DeepZoomGpuTests
    {
        const int Tiles = 4, Factor = 8;   // k / 8 is exact in lavapipe's 16.16 tess coordinates
        const double Pixels = 800, PanPixels = 0.25;
        static readonly Double2 Center = new Double2(0.5137, 0.6262);
        static readonly NoiseSettings Noise = new NoiseSettings(0.004f, 16f, 2f, 2f, 6);
        string _work, _spirv;
        PatchGrid _grid;

        [OneTimeSetUp]
        public void Setup()
        {
            _work = ReadbackRun.PrepareWork("rigtests-deepzoom");
            _grid = ReadbackRun.DemoGrid(_work, out _);
            _spirv = ReadbackRun.CompileVariants(_work, "readback", "readback+noise");
        }

        static TerrainRange Square(Double2 c, double w, double dx, double dy)
        {
            double x0 = Math.Min(Math.Max(c.x + dx - 0.5 * w, 0.0), 1.0 - w);
            double y0 = Math.Min(Math.Max(c.y + dy - 0.5 * w, 0.0), 1.0 - w);
            return new TerrainRange(x0, y0, x0 + w, y0 + w);
        }

        static string R(float v) => v.ToString("R", CultureInfo.InvariantCulture);

        /// <summary>Jitter (px) of one path through the harness; <paramref name="largestError"/>: the largest |E|.</summary>
        double GpuJitter(bool shipped, double width, bool noise, out double largestError)
        {
            TerrainRange range0 = Square(Center, width, 0, 0);
            RangeOrigin origin = shipped ? RangeOrigin.For(range0) : RangeOrigin.zero;
            NoiseSettings? n = noise ? Noise : (NoiseSettings?)null;
            double scale = Pixels / width, pan = PanPixels * width / Pixels;
            string name = FormattableString.Invariant($"{(shipped ? "shipped" : "plain")}-{width:G3}{(noise ? "-noise" : "")}");
            var frames = new ReadbackRun[ZoomJitter.Frames + 1];
            var ranges = new TerrainRange[frames.Length];
            var args = new string[frames.Length][];
            for (int k = 0; k < frames.Length; k++)
            {
                ranges[k] = Square(Center, width, k * pan, 0.5 * k * pan);
                // the frame-0 buffers (origin kept), this frame's _Range encoded against that origin
                RangeMapping.EncodeRange(ranges[k], origin, out Float4 rf, out _);
                var p = ReadbackRun.UniformParams(_grid, range0, origin, Tiles, Factor, Noise);
                frames[k] = ReadbackRun.Prepare(Path.Combine(_work, name + "-f" + k), _spirv, _grid, p, n, false,
                    new[] { "--range", string.Join(",", R(rf.x), R(rf.y), R(rf.z), R(rf.w)) }, out args[k]);
            }
            HarnessRun[] runs = HarnessBatch.Run(_work, args, 1);   // one pipeline: one process draws every frame
            for (int k = 0; k < frames.Length; k++)
            {
                frames[k].Finish(runs[k]);
                frames[k].Inputs = frames[k].Inputs.WithParams(TerrainParams.Create(_grid, ranges[k], origin,
                    TessellationSettings.Uniform(Tiles, Factor), Noise, new HeightColorSettings(0.25f, 0.15f, 24f),
                    new Float3(0.2f, 0.3f, 0.1f), new Float3(0.8f, 0.8f, 0.8f)));
            }
            int across = Factor + 1, perFrame = Tiles * Tiles * across * across;
            var first = new Double3[perFrame];
            double jitter = 0;
            largestError = 0;
            for (int k = 0; k < frames.Length; k++)
            {
                ReadbackRun run = frames[k];
                Assert.That(run.NonFinite(), Is.EqualTo(0), name + ": NaN/inf in the readback");
                Double3 offset = TerrainVertex.OutputOffset(run.Inputs, _grid, run.Keywords);
                double octaves = run.Inputs.NoiseOctaveCount();
                for (int tj = 0; tj < Tiles; tj++)
                    for (int ti = 0; ti < Tiles; ti++)
                        for (int y = 0; y < across; y++)
                            for (int x = 0; x < across; x++)
                            {
                                int v = run.Index(ti, tj, y, x), o = 12 * v;
                                // readback position is object space (x, z, y)
                                var p = new Double3(run.Readback[o], run.Readback[o + 2], run.Readback[o + 1]) + offset;
                                Double2 q = RangeMapping.GlobalPoint(ranges[k], Tiles, ti, tj, (float)x / Factor, (float)y / Factor);
                                Double3 truth = RelativeSurface.SurfaceAt(_grid, q);
                                if (noise) truth.z += OctaveNoise.Evaluate(q.x, q.y, Noise, octaves, out _);
                                Double3 e = (p - truth) * scale;
                                largestError = Math.Max(largestError, GMath.length(e));
                                if (k == 0) first[v] = e;
                                else jitter = Math.Max(jitter, GMath.length(e - first[v]));
                            }
            }
            return jitter;
        }

        [Test]
        public void ShippedPathJitterStaysBelowHalfAPixelOnTheGpu()
        {
            var rows = new List<string>();
            foreach (bool noise in new[] { false, true })
                foreach (double w in new[] { 1e-2, 1e-4, 1e-6 })
                {
                    double shipped = GpuJitter(true, w, noise, out double err);
                    // above RangeOrigin.DeepWidth the shipped path is the plain path
                    double plain = w >= RangeOrigin.DeepWidth ? shipped : GpuJitter(false, w, noise, out _);
                    double cpuShipped = ZoomJitter.Measure(_grid, VertexPath.Shipped, Center, w, Pixels, Tiles, Factor, PanPixels, out _, noise ? Noise : (NoiseSettings?)null);
                    rows.Add(FormattableString.Invariant($"{w,-8:G3} {(noise ? "on" : "off"),-6} {plain,-12:G3} {shipped,-12:G3} {err,-12:G3} {cpuShipped:G3}"));
                    Assert.That(shipped, Is.LessThan(0.5), FormattableString.Invariant($"GPU shipped jitter at width {w:G3}, noise {noise}"));
                    if (w <= 1e-4 && !noise) Assert.That(plain, Is.GreaterThan(1.0), "plain float32 breaks (the test can see jitter)");
                }
            TestContext.Out.WriteLine("GPU deep-zoom jitter (px), lavapipe, 4x4 tiles at factor 8, 800-px view, pan 0.25 px, centre (0.5137, 0.6262):");
            TestContext.Out.WriteLine("width    noise  plain f32    shipped      shipped err  CPU shipped (same tiling)");
            foreach (string r in rows) TestContext.Out.WriteLine(r);
        }
    }
}
