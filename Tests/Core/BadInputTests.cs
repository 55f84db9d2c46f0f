using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// Bad input to every public entry point and loader: each raises ArgumentException (or
    /// FormatException for files) whose message names the field and the value, and leaves the state it
    /// was given unchanged (checked against a snapshot taken before the call).
    /// </summary>
    [TestFixture]
    public class BadInputTests
    {
        static int _cases;

        [OneTimeTearDown]
        public void Count() => TestContext.Out.WriteLine($"bad-input cases checked: {_cases}");

        static void Expect<T>(TestDelegate call, params string[] mentions) where T : Exception
        {
            var e = Assert.Throws(Is.InstanceOf<T>(), call);
            foreach (string m in mentions)
                Assert.That(e.Message, Does.Contain(m), "the message should name " + m);
            _cases++;
            TestContext.Out.WriteLine($"bad input -> {e.GetType().Name}: {e.Message}");
        }

        /// <summary>Every line and control point as text (round-trip doubles; works on invalid grids too).</summary>
        static string Snapshot(PatchGrid g)
        {
            var sb = new System.Text.StringBuilder();
            foreach (double x in g.XLines) sb.Append(x.ToString("R")).Append(' ');
            foreach (double y in g.YLines) sb.Append(y.ToString("R")).Append(' ');
            foreach (GregoryPatch p in g.Patches)
                foreach (Double3 c in p.Points) sb.Append(c.ToString()).Append(' ');
            return sb.ToString();
        }

        static PatchGrid Grid() => HardCaseGrids.Fitted(3, 3, 2, 17);

        // ---- grids
        [Test]
        public void NaNControlPoint()
        {
            PatchGrid g = Grid();
            g.Patches[4][7] = new Double3(double.NaN, 0, 0);
            Expect<ArgumentException>(() => g.Validate(), "slot 7", "NaN");
        }

        [Test]
        public void InfiniteControlPoint()
        {
            PatchGrid g = Grid();
            g.Patches[0][16] = new Double3(0, double.PositiveInfinity, 0);
            Expect<ArgumentException>(() => g.Validate(), "slot 16", "Infinity");
        }

        [Test]
        public void RegionsWithAGap() =>   // the last line stops short of 1: a gap at the terrain's edge
            Expect<ArgumentException>(() => PatchGrid.CreateFlat(2, 1, new[] { 0.0, 0.5, 0.9 }, new[] { 0.0, 1.0 }).Validate(), "xLines[2]", "0.9");

        [Test]
        public void RegionsOverlapping() =>
            Expect<ArgumentException>(() => PatchGrid.CreateFlat(3, 1, new[] { 0.0, 0.6, 0.4, 1.0 }, new[] { 0.0, 1.0 }).Validate(), "xLines[2]", "0.4");

        [Test]
        public void RegionOfZeroSize() =>
            Expect<ArgumentException>(() => PatchGrid.CreateFlat(1, 2, new[] { 0.0, 1.0 }, new[] { 0.0, 0.5, 0.5, 1.0 }.AsSpan(0, 3).ToArray()).Validate(), "yLines");

        [Test]
        public void MismatchedSharedEdge()
        {
            PatchGrid g = Grid();
            g.Patches[0][12] = g.Patches[0][12] + new Double3(0, 0, 1e-3);
            Expect<ArgumentException>(() => g.Validate(), "slot 12");
        }

        [Test]
        public void WrongLineArrayLength() =>
            Expect<ArgumentException>(() => new PatchGrid(2, 2, new[] { 0.0, 1.0 }, new[] { 0.0, 0.5, 1.0 }, new GregoryPatch[4]), "xLines.Length", "2");

        [Test]
        public void WrongPatchArrayLength() =>
            Expect<ArgumentException>(() => new PatchGrid(2, 2, PatchGrid.UniformLines(2), PatchGrid.UniformLines(2), new GregoryPatch[3]), "patches.Length", "3");

        [Test]
        public void GridTooLargeForTheGpuBuffers() =>
            Expect<ArgumentException>(() => GpuLayout.CheckSize(8192, 4096), "columns * rows", "33554432");

        [Test]
        public void GridLinesThatCollapseInFloat()
        {
            PatchGrid g = PatchGrid.CreateFlat(3, 1, new[] { 0.0, 0.5, 0.5 + 1e-12, 1.0 }, new[] { 0.0, 1.0 });
            Expect<ArgumentException>(() => GpuLayout.PackControlPoints(g), "xLines[2]", "0.500000000001");
        }

        [Test]
        public void ControlPointOverflowingFloat()
        {
            PatchGrid g = Grid();
            string before = Snapshot(g);
            foreach (GregoryPatch p in g.Patches) p[5] = new Double3(p[5].x, p[5].y, 1e39);
            Expect<ArgumentException>(() => GpuLayout.PackRegions(g), "slot 5", "1E+39");
            Assert.That(Snapshot(g), Is.Not.EqualTo(before));   // the caller's edit stays; the packer changed nothing else
        }

        // ---- G1 builder and fitter: no half-changed state
        [Test]
        public void MakeG1OnAnInvalidGridLeavesItUnchanged()
        {
            PatchGrid g = Grid();
            g.Patches[2][0] = new Double3(double.NaN, 0, 0);
            string before = Snapshot(g);
            Expect<ArgumentException>(() => G1Builder.MakeG1(g), "NaN");
            Assert.That(Snapshot(g), Is.EqualTo(before), "grid unchanged after the failed call");
        }

        [Test]
        public void HeightmapOfTheWrongSize()
        {
            var h = HardCaseGrids.Heightmap(17, 1);
            var copy = (double[])h.Clone();
            Expect<ArgumentException>(() => HeightmapFitter.Fit(h, 17, 16, 2, 2), "heights", "289");
            Assert.That(h, Is.EqualTo(copy), "fitter input unchanged");
        }

        [Test]
        public void HeightmapWithNaN()
        {
            var h = HardCaseGrids.Heightmap(17, 1);
            h[40] = double.NaN;
            var copy = (double[])h.Clone();
            Expect<ArgumentException>(() => HeightmapFitter.Fit(h, 17, 17, 2, 2), "40", "NaN");
            Assert.That(h, Is.EqualTo(copy));
        }

        [Test]
        public void FitterWithZeroColumns() =>
            Expect<ArgumentException>(() => HeightmapFitter.Fit(HardCaseGrids.Heightmap(17, 1), 17, 17, 0, 2), "columns", "0");

        // ---- ranges and origins
        [Test]
        public void InvertedRange() =>
            Expect<ArgumentException>(() => new TerrainRange(0.6, 0.1, 0.4, 0.2).Validate(), "range.g", "0.4");

        [Test]
        public void RangeOutsideTheTerrain() =>
            Expect<ArgumentException>(() => new TerrainRange(-0.1, 0.1, 0.4, 0.2).Validate(), "range.c", "-0.1");

        [Test]
        public void RangeWithNaN() =>
            Expect<ArgumentException>(() => RangeOrigin.For(new TerrainRange(0.1, double.NaN, 0.4, 0.2)), "range.d", "NaN");

        [Test]
        public void EmptyRange() =>
            Expect<ArgumentException>(() => RangeMapping.EncodeRange(new TerrainRange(0.3, 0.3, 0.3, 0.4), RangeOrigin.zero, out _, out _), "range.g", "0.3");

        [Test]
        public void OriginNotFinite() =>
            Expect<ArgumentException>(() => RangeOrigin.Snap(new Double2(double.PositiveInfinity, 0)), "origin", "Infinity");

        [Test]
        public void TileIndexOutOfRange() =>
            Expect<ArgumentException>(() => RangeMapping.RangeCoordinate(8, 0, 0f, 0f, 8), "ti", "8");

        [Test]
        public void TessCoordinateOutsideTheUnitSquare() =>
            Expect<ArgumentException>(() => RangeMapping.RangeCoordinate(0, 0, 1.5f, 0f, 8), "s", "1.5");

        // ---- evaluation
        [Test]
        public void WrongControlPointCount() =>
            Expect<ArgumentException>(() => GregoryEval.Evaluate(new Double3[16], 0.5, 0.5, out _, out _, out _), "cp.Length", "16");

        [Test]
        public void WrongDifferenceControlPointCount() =>
            Expect<ArgumentException>(() => GregoryDifference.Evaluate(new Float3[19], 0.5f, 0.5f, 0f, 0f), "cp.Length", "19");

        [Test]
        public void WeightSpansTooShort() =>
            Expect<ArgumentException>(() => GregoryBasis.Weights(0.5, 0.5, new double[20], new double[12], new double[20]), "wu.Length", "12");

        [Test]
        public void FindPatchAtNaN() =>
            Expect<ArgumentException>(() => Grid().FindPatch(double.NaN, 0.5), "x", "NaN");

        // ---- files
        [Test]
        public void TruncatedJson()
        {
            string json = PatchGridJson.Write(Grid());
            Expect<FormatException>(() => PatchGridJson.Read(json.Substring(0, json.Length / 2)), "line");
        }

        [Test]
        public void WrongVersionJson()
        {
            string json = PatchGridJson.Write(Grid()).Replace("\"version\":1", "\"version\":7");
            Expect<FormatException>(() => PatchGridJson.Read(json), "version", "7");
        }

        // ---- settings
        [Test]
        public void NegativeOctaveCount() =>
            Expect<ArgumentException>(() => new NoiseSettings(0.01f, 8f, 2f, 2f, -1).Validate(), "noise.octaves", "-1");

        [Test]
        public void NoiseAlphaNotAboveOne() =>
            Expect<ArgumentException>(() => new NoiseSettings(0.01f, 8f, 1f, 2f, 4).Validate(), "noise.alpha", "1");

        [Test]
        public void NoiseFrequencyNaN() =>
            Expect<ArgumentException>(() => OctaveNoise.OctaveCount(1.0, 64, new NoiseSettings(0.01f, float.NaN, 2f, 2f, 4)), "settings.frequency", "NaN");

        [Test]
        public void OctaveCountOfAZeroWidthRange() =>
            Expect<ArgumentException>(() => OctaveNoise.OctaveCount(0.0, 64, NoiseSettings.Default), "rangeWidth", "0");

        [Test]
        public void TessellationTilesZero() =>
            Expect<ArgumentException>(() => new TessellationSettings(0, 64f, 8f, 0f).Validate(), "tessellation.tiles", "0");

        [Test]
        public void TessellationFactorAbove64() =>
            Expect<ArgumentException>(() => new TessellationSettings(8, 65f, 8f, 0f).Validate(), "tessellation.maxFactor", "65");

        [Test]
        public void UniformFactorBetween0And1() =>
            Expect<ArgumentException>(() => new TessellationSettings(8, 64f, 8f, 0.5f).Validate(), "tessellation.uniformFactor", "0.5");

        [Test]
        public void EdgeFactorWithZeroTarget() =>
            Expect<ArgumentException>(() => TessellationPolicy.EdgeFactor(10f, 0f, 64f), "targetPixels", "0");

        [Test]
        public void HeightColorGammaZero() =>
            Expect<ArgumentException>(() => new HeightColorSettings(0f, 0.1f, 4f).Validate(), "heightColor.gamma", "0");

        [Test]
        public void ColourNotFinite() =>
            Expect<ArgumentException>(() => TerrainParams.Create(Grid(), TerrainRange.full, RangeOrigin.zero, TessellationSettings.Default,
                NoiseSettings.Default, new HeightColorSettings(0.25f, 0.1f, 4f), new Float3(float.NaN, 0, 0), new Float3(1, 1, 1), 0f), "colorLow", "NaN");
    }
}
