// --depth-out through the harness on lavapipe: a quad on a known depth plane, its D32 values read
// back exactly in the PNG's row order (the order --image uploads them, so a ShadowCaster pass's map
// feeds the next pass as is).
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    public partial class HarnessTests
    {
        /// <summary>Clip depth of the plane the test camera draws: z_clip = 0.25 + 0.25 x + 0.125 z, w = 1.</summary>
        static double PlaneDepth(double x, double z) => 0.25 + 0.25 * x + 0.125 * z;

        /// <summary>MakeInputs' top-down camera with depth on a sloped plane: rows (2,0,0,-1) (0,0,2,-1) (0.25,0,0.125,0.25) (0,0,0,1).</summary>
        string MakeDepthPlaneInputs(string name)
        {
            string dir = MakeInputs(name, 4, 8, new[] { 0f, 0, 1, 1 });
            float[,] m = { { 2, 0, 0, -1 }, { 0, 0, 2, -1 }, { 0.25f, 0, 0.125f, 0.25f }, { 0, 0, 0, 1 } };
            var cam = new List<float>();
            for (int c = 0; c < 4; c++) for (int r = 0; r < 4; r++) cam.Add(m[r, c]);
            for (int c = 0; c < 4; c++) for (int r = 0; r < 4; r++) cam.Add(r == c ? 1 : 0);
            cam.AddRange(new float[] { 0.5f, 2, 0.5f, 1, Size, Size, 1f / Size, 1f / Size, 0, 1, 0, 0 });
            WriteFloats(Path.Combine(dir, "camera.f32"), cam);
            return dir;
        }

        [Test]
        public void DepthOut_HoldsTheDrawnPlanesDepth_TopRowFirst_AndTheClearElsewhere()
        {
            string dir = MakeDepthPlaneInputs("in_depth_out");
            var (pos, idx) = WriteQuadMesh("depth_out");
            string depth = Path.Combine(_work, "depth_out.f32"), png = Path.Combine(_work, "depth_out.png");
            HarnessRun r = HarnessRun.Harness("--static-mesh", "--mesh", pos, idx, "--vert", Spv("mesh.vert.spv"),
                "--frag", Spv("mesh.frag.spv"), "--buffers", dir, "--width", Size.ToString(), "--height", Size.ToString(),
                "--device", "llvmpipe", "--cull", "off", "--png", png, "--depth-out", depth);
            r.AssertSucceeded();
            byte[] bytes = File.ReadAllBytes(depth);
            Assert.That(bytes.Length, Is.EqualTo(Size * Size * 4), "W * H float32");
            float[] d = Enumerable.Range(0, Size * Size).Select(i => BitConverter.ToSingle(bytes, 4 * i)).ToArray();

            // Pixel (i, j), j counted from the top: x = (i + 0.5) / Size, and clip y = 2 z - 1 is +1 at the
            // top row (negative viewport height), so z = 1 - (j + 0.5) / Size. The quad covers x, z in [0.25, 0.75].
            double worst = 0;
            int inside = 0, clearOutside = 0, outside = 0;
            for (int j = 0; j < Size; j++)
                for (int i = 0; i < Size; i++)
                {
                    double x = (i + 0.5) / Size, z = 1 - (j + 0.5) / Size;
                    float got = d[j * Size + i];
                    if (x > 0.26 && x < 0.74 && z > 0.26 && z < 0.74)
                    {
                        worst = Math.Max(worst, Math.Abs(got - PlaneDepth(x, z)));
                        inside++;
                    }
                    else if (x < 0.24 || x > 0.76 || z < 0.24 || z > 0.76)
                    {
                        outside++;
                        clearOutside += got == 0f ? 1 : 0;
                    }
                }
            TestContext.Out.WriteLine($"depth_out: {inside} pixels inside, largest |depth - plane| {worst:G3}; outside {clearOutside} of {outside} at the clear (0)");
            Assert.That(inside, Is.GreaterThan(Size * Size / 5));
            // A float32 rasteriser interpolates the plane to a few ulps of values ~0.4 (ulp 3e-8).
            Assert.That(worst, Is.LessThan(1e-6), "depth against the plane 0.25 + 0.25 x + 0.125 z, top row first");
            Assert.That(clearOutside, Is.EqualTo(outside), "pixels outside the quad hold reversed depth's clear, 0");
            Assert.That(r.Value("depth_out", depth), Is.EqualTo(new[] { Size.ToString(), Size.ToString(), "written", (Size * Size / 4).ToString() }),
                "the run names the file, its size and the pixels written (the quad: a quarter of the target)");
        }

        [Test]
        public void DepthOutNamingThePngFile_IsRefused()
        {
            string dir = MakeInputs("in_depth_out_png", 4, 8, new[] { 0f, 0, 1, 1 });
            var (pos, idx) = WriteQuadMesh("depth_out_png");
            string same = Path.Combine(_work, "depth_out_same.png");
            HarnessRun r = HarnessRun.Harness("--static-mesh", "--mesh", pos, idx, "--vert", Spv("mesh.vert.spv"),
                "--frag", Spv("mesh.frag.spv"), "--buffers", dir, "--device", "llvmpipe", "--png", same, "--depth-out", same);
            Assert.That(r.ExitCode, Is.EqualTo(1), r.Stdout + r.Stderr);
            Assert.That(r.Stderr, Does.Contain("--depth-out").And.Contain("is also the --png file"));
            Assert.That(File.Exists(same), Is.False, "refused before any work: nothing written");
        }
    }
}
