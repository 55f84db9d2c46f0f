using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    [TestFixture]
    public class GpuLayoutTests
    {
        /// <summary>The records the renderer uploads hold the floats Core and the rig read, point k at float 80 p + 4 k.</summary>
        [Test]
        public void PatchRecordsAreTheControlPointFloats()
        {
            var g = HeightmapFitter.Fit(HeightmapFitterTests.Samples(33, 33), 33, 33, 4, 3).Grid;
            GregoryPatchRecord[] records = GpuLayout.PackPatchRecords(g);
            float[] cp = GpuLayout.PackControlPoints(g);
            Assert.That(records.Length, Is.EqualTo(g.PatchCount));
            Assert.That(GpuLayout.ControlPointBytes(g.PatchCount), Is.EqualTo((long)records.Length * GregoryPatchRecord.Stride));
            for (int p = 0; p < g.PatchCount; p++)
                for (int k = 0; k < GregoryPatchRecord.PointCount; k++)
                {
                    long o = GpuLayout.ControlPointOffset(p, k);
                    Assert.That(records[p][k], Is.EqualTo(new Float4(cp[o], cp[o + 1], cp[o + 2], cp[o + 3])), $"patch {p} point {k}");
                }
            Assert.That(records[6][GregoryPatch.P211].x, Is.Not.EqualTo(0f), "a record holds the point, not zeros");
            Assert.Throws<ArgumentOutOfRangeException>(() => { var x = records[0][20]; });
            Assert.Throws<ArgumentOutOfRangeException>(() => records[0][-1] = default);
        }

        [Test]
        public void ControlPointsOffsetsReadBackAChosenPatchAndSlot()
        {
            var g = HeightmapFitter.Fit(HeightmapFitterTests.Samples(33, 33), 33, 33, 4, 3).Grid;
            float[] cp = GpuLayout.PackControlPoints(g);
            Assert.That(cp.Length, Is.EqualTo(4 * 3 * 20 * 4));
            // Patch (2, 1) = index 1 * 4 + 2 = 6; slot P211 = 18: float4 number 6 * 20 + 18.
            int f4 = 6 * 20 + 18;
            Double3 expect = g.Patch(2, 1)[GregoryPatch.P211];
            Float3 r = (Float3)g.Patch(2, 1)[0];
            Assert.That(cp[4 * f4 + 0], Is.EqualTo((float)(expect.x - r.x)));
            Assert.That(cp[4 * f4 + 1], Is.EqualTo((float)(expect.y - r.y)));
            Assert.That(cp[4 * f4 + 2], Is.EqualTo((float)(expect.z - r.z)));
            Assert.That(cp[4 * f4 + 3], Is.EqualTo(0f));
            Assert.That(GpuLayout.ControlPointOffset(6, 18), Is.EqualTo(4 * f4));
            // Every element: xyz = the point minus the reference (slot 0 as float), to float's precision
            // of the difference; w of slots 0..2 = the reference, 0 elsewhere.
            for (int p = 0; p < g.PatchCount; p++)
            {
                Float3 reference = (Float3)g.Patches[p][0];
                int o0 = p * 20 * 4;
                Assert.That(new Float3(cp[o0 + 3], cp[o0 + 7], cp[o0 + 11]), Is.EqualTo(reference), "patch " + p);
                for (int s = 0; s < 20; s++)
                {
                    int o = (p * 20 + s) * 4;
                    Double3 d = g.Patches[p][s] - new Double3(reference.x, reference.y, reference.z);
                    Assert.That(new Float3(cp[o], cp[o + 1], cp[o + 2]), Is.EqualTo((Float3)d));
                    if (s > 2) Assert.That(cp[o + 3], Is.EqualTo(0f));
                }
            }
            // Core reads it back as the GPU does: R_p + relative points = the rounded absolute point to float's precision.
            TerrainInputs inputs = TerrainInputs.ForGrid(g);
            Span<Float3> pts = stackalloc Float3[20];
            inputs.LoadGregoryPatch(6, pts);
            Float3 back = inputs.PatchReference(6) + pts[18];
            Assert.That(back.x, Is.EqualTo(expect.x).Within(1e-7));
            Assert.That(back.z, Is.EqualTo(expect.z).Within(1e-7));
        }

        [Test]
        public void GridLinesAreHiLoPairsExactTo1e16()
        {
            // 0.13 as one float is off by 4.8e-9 (9% of a range 1e-7 wide); the pair keeps it to ~1e-16.
            var g = PatchGrid.CreateFlat(2, 2, new[] { 0.0, 0.13, 1.0 }, new[] { 0.0, 0.7000000001, 1.0 });
            float[] lines = GpuLayout.PackGridLines(g);
            Assert.That(lines.Length, Is.EqualTo(12));
            int lo = GpuLayout.GridLinesLoOffset(2, 2);
            Assert.That(lo, Is.EqualTo(6));
            Assert.That(Math.Abs((double)lines[1] - 0.13), Is.GreaterThan(4e-9));
            Assert.That(Math.Abs((double)lines[1] + lines[lo + 1] - 0.13), Is.LessThan(1e-15));
            Assert.That(Math.Abs((double)lines[4] + lines[lo + 4] - 0.7000000001), Is.LessThan(1e-15));
            TerrainInputs inputs = TerrainInputs.ForGrid(g);
            // Patch (0, 1) = index 2: [0, 0.13] x [0.7000000001, 1].
            Float4 region = inputs.PatchRegion(2), regionLo = inputs.PatchRegionLo(2);
            Assert.That((double)region.z + regionLo.z, Is.EqualTo(0.13).Within(1e-15));
            Assert.That((double)region.y + regionLo.y, Is.EqualTo(0.7000000001).Within(1e-15));
            Assert.That(regionLo.x, Is.EqualTo(0f));
            Assert.That(regionLo.w, Is.EqualTo(0f));
            // A point 1e-12 left of the true line 0.13 (but right of its float, 0.129999995) is in patch (0, 1) = 2 with u ~ 1.
            Assert.That((double)0.13f, Is.LessThan(0.13 - 1e-12));   // 0.129999995
            var q = new TerrainPoint(new Float2(0.13f, 0.75f), new Float2((float)(0.13 - 1e-12 - 0.13f), 0f));
            Assert.That(inputs.FindPatch(RangeMapping.Approximate(q)), Is.EqualTo(3), "the float point alone lands right of the line");
            Assert.That(RelativeSurface.FindPatchPrecise(inputs, q), Is.EqualTo(2));
            Float2 uv = RangeMapping.PatchLocalUV(q, inputs.PatchRegion(2), inputs.PatchRegionLo(2));
            Assert.That((double)uv.x, Is.EqualTo(1 - 1e-12 / 0.13).Within(1e-7));
        }

        [Test]
        public void TilePathLookupIsPreciseOnlyWhileThePointHasAHiPart()
        {
            // A point 1e-12 left of the true line 0.13 (right of its float 0.129999995): with a hi part
            // (a range origin) the precise rule puts it in patch (0, 1) = 2, FindPatch on the rounded
            // point in (1, 1) = 3. Without one the point is one float and the tile path takes FindPatch.
            var g = PatchGrid.CreateFlat(2, 2, new[] { 0.0, 0.13, 1.0 }, new[] { 0.0, 0.7000000001, 1.0 });
            TerrainInputs inputs = TerrainInputs.ForGrid(g);
            var split = new TerrainPoint(new Float2(0.13f, 0.75f), new Float2((float)(0.13 - 1e-12 - 0.13f), 0f));
            Assert.That(inputs.FindPatch(RangeMapping.Approximate(split)), Is.EqualTo(3));
            Assert.That(RelativeSurface.FindPatchAt(inputs, split), Is.EqualTo(2), "a hi part: the precise rule");
            Assert.That(TerrainVertex.EvaluateSurfaceAt(inputs, split).patch, Is.EqualTo(2));
            var rng = new Random(3);
            for (int k = 0; k < 2000; k++)
            {
                var local = new Float2(k < 2 ? 0.13f : (float)rng.NextDouble(), k == 1 ? 0.7f : (float)rng.NextDouble());
                var plain = new TerrainPoint(new Float2(0f, 0f), local);
                Assert.That(RelativeSurface.FindPatchAt(inputs, plain), Is.EqualTo(inputs.FindPatch(local)), $"no hi part at {local}");
                Assert.That(TerrainVertex.EvaluateSurfaceAt(inputs, plain).patch, Is.EqualTo(inputs.FindPatch(local)));
            }
        }

        [Test]
        public void FloatFindIntervalGuessGivesTheBinarySearchsAnswer()
        {
            // The uniform guess is only a shortcut: on uniform and uneven lines, on the lines themselves,
            // between them, outside [0, 1] and at NaN, the answer is the largest i with lines[i] <= x.
            var rng = new Random(5);
            float[][] sets =
            {
                new[] { 0f, 0.25f, 0.5f, 0.75f, 1f },
                new[] { 0f, 0.01f, 0.02f, 0.6f, 0.61f, 0.9f, 1f },
                new[] { 0f, 1f },
                new[] { 0f, 0.999f, 1f },
            };
            foreach (float[] lines in sets)
            {
                var xs = new System.Collections.Generic.List<float> { -1f, -0f, 1f, 2f, float.NaN, float.PositiveInfinity, float.NegativeInfinity };
                foreach (float l in lines) { xs.Add(l); xs.Add(Step(l, -1)); xs.Add(Step(l, 1)); }
                for (int k = 0; k < 2000; k++) xs.Add((float)rng.NextDouble());
                foreach (float x in xs)
                {
                    int expect = 0;
                    for (int i = 1; i < lines.Length - 1; i++) if (lines[i] <= x) expect = i;
                    Assert.That(PatchGrid.FindInterval(new ReadOnlySpan<float>(lines), x), Is.EqualTo(expect),
                                $"x = {x:R} on lines {string.Join(", ", lines)}");
                }
            }
        }

        // The float next to l >= 0 (dir = 1 up, -1 down).
        static float Step(float l, int dir) =>
            l == 0f ? dir * float.Epsilon : BitConverter.Int32BitsToSingle(BitConverter.SingleToInt32Bits(l) + dir);

        [Test]
        public void RegionsLinesAndSize()
        {
            var g = PatchGrid.CreateFlat(3, 2, new[] { 0.0, 0.1, 0.7, 1.0 }, new[] { 0.0, 0.3, 1.0 });
            float[] reg = GpuLayout.PackRegions(g);
            // Patch (1, 1) = index 4: [0.1, 0.7] x [0.3, 1].
            Assert.That(new[] { reg[16], reg[17], reg[18], reg[19] }, Is.EqualTo(new[] { 0.1f, 0.3f, 0.7f, 1f }));
            float[] lines = GpuLayout.PackGridLines(g);
            Assert.That(lines.AsSpan(0, 7).ToArray(), Is.EqualTo(new[] { 0f, 0.1f, 0.7f, 1f, 0f, 0.3f, 1f }));
            Assert.That(lines.AsSpan(7, 7).ToArray(), Is.EqualTo(new[] { 0f, (float)(0.1 - 0.1f), (float)(0.7 - 0.7f), 0f, 0f, (float)(0.3 - 0.3f), 0f }));
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
            // One rule for every entry point: Validate refuses what the GPU cannot hold.
            ex = Assert.Throws<ArgumentException>(h.Validate);
            Assert.That(ex.Message, Does.Contain("xLines[2]").And.Contain("same float"));
            ex = Assert.Throws<ArgumentException>(() => GpuLayout.PackGridLines(h));
            Assert.That(ex.Message, Does.Contain("xLines[2]").And.Contain("same float"));
        }
    }
}
