// --depth-out through the harness on lavapipe: a quad on a known depth plane, its D32 values read
// back exactly in the PNG's row order (the order --image uploads them, so a ShadowCaster pass's map
// feeds the next pass as is); --depth-in: a pass drawn over a depth target it loads, as a prepass leaves it.
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
        public void DepthIn_IsTheTargetThePassTestsAgainst_AndKeepsWhatItDoesNotDraw()
        {
            // Loaded: 0.6 on the left half (nearer than the quad's 0.34..0.53 under reversed depth), the clear (0) on
            // the right. ZTest LEqual (reversed: GREATER_OR_EQUAL) draws the quad on the right half only, and the depth
            // after the pass is the loaded 0.6 on the left, the plane's where the quad drew.
            string dir = MakeDepthPlaneInputs("in_depth_in");
            var (pos, idx) = WriteQuadMesh("depth_in");
            string loaded = Path.Combine(_work, "depth_in.f32"), after = Path.Combine(_work, "depth_in_after.f32");
            WriteFloats(loaded, Enumerable.Range(0, Size * Size).Select(p => p % Size < Size / 2 ? 0.6f : 0f));
            HarnessRun r = HarnessRun.Harness("--static-mesh", "--mesh", pos, idx, "--vert", Spv("mesh.vert.spv"),
                "--frag", Spv("mesh.frag.spv"), "--buffers", dir, "--width", Size.ToString(), "--height", Size.ToString(),
                "--device", "llvmpipe", "--cull", "off", "--depth-in", loaded, "--depth-out", after);
            r.AssertSucceeded();
            byte[] bytes = File.ReadAllBytes(after);
            float[] d = Enumerable.Range(0, Size * Size).Select(i => BitConverter.ToSingle(bytes, 4 * i)).ToArray();
            int leftKept = Enumerable.Range(0, Size * Size).Count(p => p % Size < Size / 2 && d[p] == 0.6f);
            Assert.That(r.Value("depth_in", loaded), Is.EqualTo(new[] { Size.ToString(), Size.ToString(), "written", (Size * Size / 2).ToString() }),
                "the run names the loaded file and its pixels that differ from the clear (the left half)");
            Assert.That(leftKept, Is.EqualTo(Size * Size / 2), "the left half keeps the loaded depth: the quad failed the test there");
            Assert.That(r.Value("image", "nonsky_pixels")[0], Is.EqualTo((Size * Size / 8).ToString()), "the quad drew its right half only");
            Assert.That(r.Value("depth_out", after)[3], Is.EqualTo((Size * Size / 2 + Size * Size / 8).ToString()), "loaded plus drawn pixels");
        }

        [Test]
        public void DepthInOfAnotherSizeOrOutsideZeroToOneOrOverManyFrames_IsRefused()
        {
            string dir = MakeInputs("in_depth_in_bad", 4, 8, new[] { 0f, 0, 1, 1 });
            var (pos, idx) = WriteQuadMesh("depth_in_bad");
            string small = Path.Combine(_work, "depth_in_small.f32"), far = Path.Combine(_work, "depth_in_far.f32");
            WriteFloats(small, Enumerable.Repeat(0f, Size));
            WriteFloats(far, Enumerable.Range(0, Size * Size).Select(p => p == 5 ? 1.5f : 0f));
            foreach (var (file, frames, says) in new[] { (small, "1", "bytes; expected"), (far, "1", "pixel 5 is 1.5"), (far, "2", "--frames must be 1") })
            {
                HarnessRun r = HarnessRun.Harness("--static-mesh", "--mesh", pos, idx, "--vert", Spv("mesh.vert.spv"), "--frag", Spv("mesh.frag.spv"),
                    "--buffers", dir, "--width", Size.ToString(), "--height", Size.ToString(), "--device", "llvmpipe", "--frames", frames, "--depth-in", file);
                Assert.That(r.ExitCode, Is.EqualTo(1), r.Stdout + r.Stderr);
                Assert.That(r.Stderr, Does.Contain("--depth-in").And.Contain(says));
            }
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
