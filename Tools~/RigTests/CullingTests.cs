// Back-face culling as a Unity camera sees the terrain: every pass of GregoryTerrain.shader that
// draws it is Cull Back, and Unity's front faces are clockwise in the picture. The tessellated
// path (hull outputtopology) and the fallback (the renderer's index buffer, which the harness draws)
// are drawn through the harness, with the forward pass's state, from above and from below: from
// above both must cover the terrain, the same pixels; from below a heightfield shows only back
// faces, so both must cover none. A winding that faces down fails it either way.
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture, Parallelizable(ParallelScope.Self)]
    public class CullingTests
    {
        const int Size = 128;
        // An odd factor: the shipped partitioning (fractional_odd) then draws exactly F segments per
        // edge, as the fallback's F x F grid does; the two differ only in the cells' diagonals.
        const int Tiles = 4, Factor = 9;
        // Pixels the two paths may cover differently, as a fraction of the covered ones: the
        // tessellator splits some cells along the other diagonal than the fallback grid, which can
        // move a silhouette by a pixel. Measured on lavapipe: 0 in every view here.
        const double PathTolerance = 0.005;

        string _work, _spirv, _buffers;

        [OneTimeSetUp]
        public void BuildSceneAndShaders()
        {
            _work = ReadbackRun.PrepareWork("rigtests-culling");
            PatchGrid grid = ReadbackRun.DemoGrid(_work, out _);
            _spirv = ReadbackRun.CompileVariants(_work, "base");
            TerrainParams p = ReadbackRun.UniformParams(grid, TerrainRange.full, RangeOrigin.zero, Tiles, Factor, null);
            _buffers = Path.Combine(_work, "scene");
            ReadbackRun.WriteBuffers(_buffers, TerrainInputs.Create(grid, p), ReadbackRun.TopDownCamera());
        }

        /// <summary>The views: a camera straight above and straight below the unit square
        /// (orthographic), and perspective ones above and below, each as a Unity camera sees it.</summary>
        static readonly Dictionary<string, float[]> Views = new Dictionary<string, float[]>
        {
            ["above"] = ReadbackRun.TopDownCameraOver(0, 0, 1, 1, Size, Size),
            ["below"] = ReadbackRun.BottomUpCameraOver(0, 0, 1, 1, Size, Size),
            ["above-oblique"] = ReadbackRun.PerspectiveCamera(new Double3(0.5, 0.9, -0.45), new Double3(0.5, 0.05, 0.45), 60, Size, Size, 0.01, 10),
            ["below-perspective"] = ReadbackRun.PerspectiveCamera(new Double3(0.5, -1.4, 0.5), new Double3(0.5, 0.1, 0.5), 60, Size, Size, 0.01, 10),
        };

        /// <summary>One draw of the scene from <paramref name="view"/>: its covered (non-sky) pixels.</summary>
        bool[] Draw(string view, bool tessellated, string cull)
        {
            string dir = Path.Combine(_work, view);
            if (!Directory.Exists(dir))
            {
                Directory.CreateDirectory(dir);
                foreach (string f in Directory.GetFiles(_buffers)) File.Copy(f, Path.Combine(dir, Path.GetFileName(f)));
                ReadbackRun.WriteFloats(Path.Combine(dir, "camera.f32"), Views[view]);
            }
            string v = Path.Combine(_spirv, "base"), png = Path.Combine(_work, $"{view}_{(tessellated ? "tess" : "fallback")}_{cull}.png");
            var args = new List<string>();
            if (tessellated) args.AddRange(ReadbackRun.Stages(_spirv, "base"));
            else args.AddRange(new[] { "--vert", Path.Combine(v, "fallback.spv"), "--frag", Path.Combine(v, "frag.spv"),
                                       "--grid-factor", Factor.ToString(), "--instances", (Tiles * Tiles).ToString() });
            args.AddRange(new[] { "--buffers", dir, "--width", Size.ToString(), "--height", Size.ToString(), "--device", "llvmpipe", "--png", png });
            if (tessellated) args.AddRange(new[] { "--patches", (Tiles * Tiles).ToString() });
            if (cull != null) args.AddRange(new[] { "--cull", cull });   // else the forward pass's (Cull Back)
            HarnessRun r = HarnessRun.Harness(args.ToArray());
            r.AssertSucceeded();
            Assert.That(r.Value("state", "cull")[0], Is.EqualTo(cull ?? "back"), "the forward pass is Cull Back");
            bool[] covered = Covered(RigPng.Read(png));
            Assert.That(covered.Count(c => c), Is.EqualTo(r.Long("image", "nonsky_pixels")), "PNG against the harness's count");
            return covered;
        }

        /// <summary>Pixels that differ from the harness's sky colour by more than 2/255 (its nonsky rule).</summary>
        static bool[] Covered(RigPng png)
        {
            byte[] sky = { (byte)Math.Round(0.55 * 255), (byte)Math.Round(0.70 * 255), (byte)Math.Round(0.90 * 255) };
            var c = new bool[png.Width * png.Height];
            for (int p = 0; p < c.Length; p++)
                for (int k = 0; k < 3; k++) c[p] |= Math.Abs(png.Rgba[4 * p + k] - sky[k]) > 2;
            return c;
        }

        static int Count(bool[] mask) => mask.Count(c => c);

        static int Differing(bool[] a, bool[] b) => a.Zip(b, (x, y) => x != y).Count(d => d);

        [TestCase("above")]
        [TestCase("above-oblique")]
        public void FromAbove_BothPathsCoverTheTerrain_TheSamePixels(string view)
        {
            bool[] tess = Draw(view, true, null), fallback = Draw(view, false, null);
            int t = Count(tess), f = Count(fallback), differ = Differing(tess, fallback);
            TestContext.Out.WriteLine($"{view}, Cull Back: tessellated {t} px, fallback {f} px of {Size * Size}; {differ} px covered by one only");
            // Straight above, the unit square fills the view; the oblique view shows it in over a quarter.
            int least = view == "above" ? Size * Size : Size * Size / 4;
            Assert.That(f, Is.GreaterThanOrEqualTo(least), "the fallback grid faces the camera above");
            Assert.That(t, Is.GreaterThanOrEqualTo(least), "the tessellated triangles face the camera above");
            Assert.That(differ, Is.LessThanOrEqualTo(PathTolerance * f), "the two paths cover the same pixels");
        }

        [TestCase("below")]
        [TestCase("below-perspective")]
        public void FromBelow_BothPathsAreCulled_TheirBackFacesShowOnlyWithCullFront(string view)
        {
            bool[] tess = Draw(view, true, null), fallback = Draw(view, false, null);
            bool[] tessFront = Draw(view, true, "front"), fallbackFront = Draw(view, false, "front");
            bool[] tessOff = Draw(view, true, "off"), fallbackOff = Draw(view, false, "off");
            TestContext.Out.WriteLine($"{view}: Cull Back tessellated {Count(tess)} px, fallback {Count(fallback)} px; " +
                                      $"Cull Front {Count(tessFront)} / {Count(fallbackFront)} px; Cull Off {Count(tessOff)} / {Count(fallbackOff)} px");
            // What Unity draws of a heightfield from below: nothing, every triangle shows its back.
            Assert.That(Count(fallback), Is.EqualTo(0), "the fallback grid seen from below is culled");
            Assert.That(Count(tess), Is.EqualTo(0), "the tessellated triangles seen from below are culled");
            // The camera does see the terrain: its back faces, all of what Cull Off draws.
            Assert.That(Count(fallbackOff), Is.GreaterThan(Size * Size / 4), "the terrain is in view");
            Assert.That(Differing(fallbackFront, fallbackOff), Is.EqualTo(0), "every fallback triangle in view is a back face");
            Assert.That(Differing(tessFront, tessOff), Is.EqualTo(0), "every tessellated triangle in view is a back face");
            Assert.That(Differing(tessOff, fallbackOff), Is.LessThanOrEqualTo(PathTolerance * Count(fallbackOff)), "the two paths cover the same pixels");
        }
    }
}
