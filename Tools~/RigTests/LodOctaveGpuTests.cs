// The continuous octave rule of the levels of detail on the GPU (lavapipe, readback+noise+range_origin): with
// _NoiseOctaves.z > 0 every vertex takes its octave count from its own pixel scale under the rig's
// perspective camera (HLSL VertexOctaveCount), and Core's float mirror (TerrainVertex.EvaluateAtWithCamera)
// computes the same at the q the GPU read back. Helpers: ReadbackRun.cs.
using System;
using System.IO;
using System.Linq;
using GregoryTerrain.Tests;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture, Parallelizable(ParallelScope.Self)]
    public class LodOctaveGpuTests
    {
        static readonly NoiseSettings Noise = new NoiseSettings(0.004f, 16f, 2f, 2f, 6);
        string _work, _spirv;

        [OneTimeSetUp]
        public void CompileShaders()
        {
            _work = ReadbackRun.PrepareWork("rigtests-lod-octaves");
            _spirv = ReadbackRun.CompileVariants(_work, "readback+noise");
        }

        [Test]
        public void GpuOctaveCountPerVertexMatchesCore()
        {
            const int tiles = 4, factor = 16, width = 192, height = 108;
            PatchGrid grid = HardCaseGrids.Fitted();
            TerrainParams p = ReadbackRun.UniformParams(grid, TerrainRange.full, RangeOrigin.zero, tiles, factor, Noise);
            p.noiseOctaves = new Float4(p.noiseOctaves.x, p.noiseOctaves.y, 2f, 0f);   // the continuous rule, 2 px segments
            var inputs = TerrainInputs.Create(grid, p);
            // Low over the terrain looking across it: the counts run from all 6 octaves at the feet to a few far away.
            var eye = new Double3(0.5, 0.06, 0.02);
            float[] camera = ReadbackRun.PerspectiveCamera(eye, new Double3(0.5, 0.0, 0.6), 60, width, height, 1e-4, 10);
            var objectToClip = Float4x4.FromRows(camera[0], camera[4], camera[8], camera[12], camera[1], camera[5], camera[9], camera[13],
                                                 camera[2], camera[6], camera[10], camera[14], camera[3], camera[7], camera[11], camera[15]);
            var screen = new Float2(width, height);
            string dir = Path.Combine(_work, "continuous");
            ReadbackRun.WriteBuffers(dir, inputs, camera);
            int vertices = tiles * tiles * (factor + 1) * (factor + 1);
            string rb = Path.Combine(dir, "readback.f32");
            // The origin sibling: the continuous rule is compiled only with the origin's code
            // (GT_RANGE_ORIGIN_CODE, which the levels' GT_LOD sets); the origin stays 0 here.
            var args = ReadbackRun.Stages(_spirv, "readback+noise+range_origin").Concat(new[] { "--buffers", dir, "--patches", (tiles * tiles).ToString(),
                "--width", width.ToString(), "--height", height.ToString(), "--device", "llvmpipe", "--readback", rb,
                "--readback-floats", (12 * vertices).ToString() }).ToArray();
            HarnessRun h = HarnessRun.Harness(args);
            h.AssertSucceeded();
            float[] v = ReadbackRun.ReadFloats(rb);
            double worst = 0, worstSingleRange = 0;
            float lo = float.MaxValue, hi = float.MinValue;
            int compared = 0;
            var off = p;
            off.noiseOctaves = new Float4(p.noiseOctaves.x, p.noiseOctaves.y, 0f, 0f);
            var singleRange = TerrainInputs.Create(grid, off);
            for (int k = 0; k < vertices; k++)
            {
                int o = 12 * k;
                Assert.That(v.Skip(o).Take(12).All(float.IsFinite), "vertex " + k + ": NaN/inf in the readback");
                TerrainPoint q = TerrainPoint.FromFloat(new Float2(v[o + 8], v[o + 9]));
                TerrainVertexOutput core = TerrainVertex.EvaluateAtWithCamera(inputs, q, TerrainKeywords.Noise, objectToClip, screen);
                var gpu = new Float3(v[o], v[o + 1], v[o + 2]);
                worst = Math.Max(worst, ReadbackRun.Distance(gpu, core.PositionOS));
                worstSingleRange = Math.Max(worstSingleRange, ReadbackRun.Distance(gpu, TerrainVertex.EvaluateAt(singleRange, q, TerrainKeywords.Noise).PositionOS));
                float count = TerrainVertex.VertexOctaveCount(inputs, core.surface.position, TerrainKeywords.Noise, (objectToClip, screen));
                lo = Math.Min(lo, count);
                hi = Math.Max(hi, count);
                compared++;
            }
            TestContext.Out.WriteLine($"continuous octave rule: {compared} vertices, counts {lo:F3} .. {hi:F3}, |gpu - core| {worst:G3} " +
                                      $"(against the single-range rule: {worstSingleRange:G3})");
            Assert.That(hi - lo, Is.GreaterThan(2f), "the vertices span several octave counts (else the rule is not exercised)");
            Assert.That(worst, Is.LessThanOrEqualTo(1e-6), "GPU per-vertex count vs Core's");
            Assert.That(worstSingleRange, Is.GreaterThan(1e-5), "the single-range rule draws another surface (the comparison can fail)");
        }
    }
}
