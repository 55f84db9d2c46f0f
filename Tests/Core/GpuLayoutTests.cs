using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    [TestFixture]
    public class GpuLayoutTests
    {
        [Test]
        public void ControlPointsOffsetsReadBackAChosenPatchAndSlot()
        {
            var g = HeightmapFitter.Fit(HeightmapFitterTests.Samples(33, 33), 33, 33, 4, 3).Grid;
            float[] cp = GpuLayout.PackControlPoints(g);
            Assert.That(cp.Length, Is.EqualTo(4 * 3 * 20 * 4));
            // Patch (2, 1) = index 1 * 4 + 2 = 6; slot P211 = 18: float4 number 6 * 20 + 18.
            int f4 = 6 * 20 + 18;
            Double3 expect = g.Patch(2, 1)[GregoryPatch.P211];
            Assert.That(cp[4 * f4 + 0], Is.EqualTo((float)expect.x));
            Assert.That(cp[4 * f4 + 1], Is.EqualTo((float)expect.y));
            Assert.That(cp[4 * f4 + 2], Is.EqualTo((float)expect.z));
            Assert.That(cp[4 * f4 + 3], Is.EqualTo(1f));
            Assert.That(GpuLayout.ControlPointOffset(6, 18), Is.EqualTo(4 * f4));
            // Every element: w = 1, xyz = the rounded point.
            for (int p = 0; p < g.PatchCount; p++)
                for (int s = 0; s < 20; s++)
                {
                    int o = (p * 20 + s) * 4;
                    Assert.That(new Float3(cp[o], cp[o + 1], cp[o + 2]), Is.EqualTo((Float3)g.Patches[p][s]));
                    Assert.That(cp[o + 3], Is.EqualTo(1f));
                }
        }

        [Test]
        public void RegionsLinesAndSize()
        {
            var g = PatchGrid.CreateFlat(3, 2, new[] { 0.0, 0.1, 0.7, 1.0 }, new[] { 0.0, 0.3, 1.0 });
            float[] reg = GpuLayout.PackRegions(g);
            // Patch (1, 1) = index 4: [0.1, 0.7] x [0.3, 1].
            Assert.That(new[] { reg[16], reg[17], reg[18], reg[19] }, Is.EqualTo(new[] { 0.1f, 0.3f, 0.7f, 1f }));
            float[] lines = GpuLayout.PackGridLines(g);
            Assert.That(lines, Is.EqualTo(new[] { 0f, 0.1f, 0.7f, 1f, 0f, 0.3f, 1f }));
            Assert.That(GpuLayout.YLinesOffset(3), Is.EqualTo(4));
            Assert.That(GpuLayout.GridSize(g), Is.EqualTo(new[] { 3f, 2f, 0f, 0f }));
            // The float lines give the same FindPatch as the double grid (GPU mirror) at lines and between.
            foreach (double x in new[] { 0.0, 0.05, 0.1, 0.5, 0.7, 0.9, 1.0 })
                foreach (double y in new[] { 0.0, 0.3, 0.6, 1.0 })
                {
                    int i = PatchGrid.FindInterval(lines.AsSpan(0, 4), (float)x), j = PatchGrid.FindInterval(lines.AsSpan(4, 3), (float)y);
                    Assert.That(j * 3 + i, Is.EqualTo(g.FindPatch(x, y)), $"({x}, {y})");
                }
        }

        [Test]
        public void RejectsGridsTooLargeOrNotRepresentable()
        {
            var ex = Assert.Throws<ArgumentException>(() => GpuLayout.CheckSize(4096, 4097));
            Assert.That(ex.Message, Does.Contain("16781312"));
            ex = Assert.Throws<ArgumentException>(() => GpuLayout.CheckSize(3000, 3000));
            Assert.That(ex.Message, Does.Contain("9000000").And.Contain("2 GiB"));
            Assert.DoesNotThrow(() => GpuLayout.CheckSize(2000, 3000));

            var g = PatchGrid.CreateFlat(2, 1, new[] { 0.0, 0.5, 1.0 }, new[] { 0.0, 1.0 });
            g.Patch(1, 0)[GregoryPatch.P121] = new Double3(0.7, 0.5, 1e39);
            ex = Assert.Throws<ArgumentException>(() => GpuLayout.PackControlPoints(g));
            Assert.That(ex.Message, Does.Contain("patch (1, 0) slot 17").And.Contain("1E+39"));

            var h = PatchGrid.CreateFlat(3, 1, new[] { 0.0, 0.5, 0.5 + 1e-12, 1.0 }, new[] { 0.0, 1.0 });
            // One rule for every entry point: Validate refuses what the GPU cannot hold (issue 25).
            ex = Assert.Throws<ArgumentException>(h.Validate);
            Assert.That(ex.Message, Does.Contain("xLines[2]").And.Contain("same float"));
            ex = Assert.Throws<ArgumentException>(() => GpuLayout.PackGridLines(h));
            Assert.That(ex.Message, Does.Contain("xLines[2]").And.Contain("same float"));
        }
    }
}
