using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// Core's float mirror of the shaders' evaluation path (TerrainVertex) against its double
    /// reference, and the properties the GPU relies on: shared tile edges bit-identical, corners
    /// exact, octave count per frame, paper-mode clamping, bad input.
    /// </summary>
    [TestFixture]
    public class TerrainVertexTests
    {
        static readonly NoiseSettings Noise = new NoiseSettings(0.004f, 16f, 2f, 2f, 6);
        PatchGrid _grid;

        [OneTimeSetUp]
        public void Fit() => _grid = HeightmapFitter.Fit(HeightmapFitterTests.Samples(33, 33), 33, 33, 4, 3).Grid;

        TerrainInputs Inputs(TerrainRange range, int tiles = 4, float factor = 8f, float verticesAcross = 0f) =>
            TerrainInputs.Create(_grid, TerrainParams.Create(_grid, range, RangeOrigin.For(range),
                TessellationSettings.Uniform(tiles, factor), Noise, new HeightColorSettings(0.25f, 0.1f, 8f),
                new Float3(0, 0, 0), new Float3(1, 1, 1), verticesAcross));

        [TestCase(false)]
        [TestCase(true)]
        public void FloatPathFollowsTheDoubleReference(bool noise)
        {
            var keywords = noise ? TerrainKeywords.Noise : TerrainKeywords.None;
            double worstP = 0, worstN = 0;
            foreach (var range in new[] { TerrainRange.full, new TerrainRange(0.3, 0.1, 0.7, 0.5), new TerrainRange(0.61, 0.22, 0.6105, 0.2205) })
            {
                TerrainInputs inputs = Inputs(range);
                int tiles = inputs.TileCountInt();
                for (int tile = 0; tile < tiles * tiles; tile++)
                    for (int j = 0; j <= 8; j++)
                        for (int i = 0; i <= 8; i++)
                        {
                            TerrainVertexOutput f = TerrainVertex.Evaluate(inputs, tile, new Float2(i / 8f, j / 8f), keywords);
                            TerrainVertex.Reference(_grid, f.surface.q.ToDouble(), noise ? Noise : (NoiseSettings?)null,
                                inputs.NoiseOctaveCount(), out Double3 p, out Double3 n);
                            p -= TerrainVertex.OutputOffset(inputs, _grid, keywords);
                            worstP = Math.Max(worstP, GMath.length(new Double3(f.position.x, f.position.y, f.position.z) - p));
                            worstN = Math.Max(worstN, GMath.length(new Double3(f.normal.x, f.normal.y, f.normal.z) - n));
                            Assert.That(GMath.length(f.normal), Is.EqualTo(1.0).Within(1e-6));
                        }
            }
            TestContext.Out.WriteLine("noise {0}: max |float - double| position {1:G3}, normal {2:G3}", noise, worstP, worstN);
            Assert.That(worstP, Is.LessThan(2e-6));
            Assert.That(worstN, Is.LessThan(2e-5));
            Assert.That(worstP, Is.GreaterThan(0.0), "a float path identical to double would mean the reference is not independent");
        }

        /// <summary>
        /// Under the levels' continuous octave rule (_NoiseOctaves.z &gt; 0) the vertices near the feet
        /// output p(q) - p(O) at every octave, so the offset added back must be O's noise at every
        /// octave, not at the frame's count from the range width (fewer here: the whole terrain at a
        /// high frequency); that left the drawn ground metres off under the camera at 1,000 km.
        /// </summary>
        [Test]
        public void OutputOffsetCarriesEveryOctaveUnderTheContinuousRule()
        {
            var noise = new NoiseSettings(0.0004f, 160f, 2f, 2f, 6);
            var origin = RangeOrigin.For(new TerrainRange(0.37, 0.52, 0.37 + 1.0 / 32768, 0.52 + 1.0 / 32768));
            TerrainParams p = TerrainParams.Create(_grid, TerrainRange.full, origin, new TessellationSettings(16, 64f, 1f, 0f), noise,
                new HeightColorSettings(0.25f, 0.1f, 8f), new Float3(0, 0, 0), new Float3(1, 1, 1));
            Assume.That(TerrainInputs.NoiseOctaveCount(p), Is.LessThan(5f), "the frame's count must leave octaves out for this check");
            p.noiseOctaves = new Float4(p.noiseOctaves.x, p.noiseOctaves.y, 2f, 0f);
            Double2 o = origin.Value;
            double expected = RelativeSurface.ReferencePoint(_grid, origin).z + OctaveNoise.Evaluate(o.x, o.y, noise, 6f, out _);
            Assert.That(TerrainVertex.OutputOffset(_grid, p, TerrainKeywords.Noise).z, Is.EqualTo(expected).Within(1e-12));
        }

        [Test]
        public void SharedTileEdgesAreBitIdentical()
        {
            TerrainInputs inputs = Inputs(new TerrainRange(0.13, 0.27, 0.91, 0.83), tiles: 5);
            var k = TerrainKeywords.Noise | TerrainKeywords.HeightColor;
            int pairs = 0;
            for (int tj = 0; tj < 5; tj++)
                for (int ti = 0; ti < 4; ti++)
                    for (int r = 0; r <= 8; r++)
                    {
                        float t = r / 8f;
                        TerrainVertexOutput a = TerrainVertex.Evaluate(inputs, tj * 5 + ti, new Float2(1f, t), k);
                        TerrainVertexOutput b = TerrainVertex.Evaluate(inputs, tj * 5 + ti + 1, new Float2(0f, t), k);
                        Assert.That(a.surface.q, Is.EqualTo(b.surface.q));
                        Assert.That(a.position, Is.EqualTo(b.position));
                        Assert.That(a.normal, Is.EqualTo(b.normal));
                        Assert.That(a.colorNoise, Is.EqualTo(b.colorNoise));
                        pairs++;
                    }
            Assert.That(pairs, Is.EqualTo(5 * 4 * 9));
        }

        [Test]
        public void RangeCornerEvaluatesTheGridCornerControlPointExactly()
        {
            // q = (0, 0) is patch 0's corner: position = its slot-0 control point, in float.
            TerrainInputs inputs = Inputs(TerrainRange.full);
            TerrainVertexOutput o = TerrainVertex.Evaluate(inputs, 0, new Float2(0f, 0f));
            Assert.That(o.surface.patch, Is.EqualTo(0));
            Assert.That(o.position, Is.EqualTo((Float3)_grid.Patches[0][0]));
            Assert.That(o.PositionOS, Is.EqualTo(new Float3(o.position.x, o.position.z, o.position.y)), "object space is (x, z, y)");
        }

        [Test]
        public void OctaveCountFollowsTheRangeWidthAndIsClamped()
        {
            // 1 + log2(across / (2 width frequency)) with alpha = 2: across 512, width 1, f 16 -> 1 + 4 = 5.
            Assert.That(Inputs(TerrainRange.full, verticesAcross: 512f).NoiseOctaveCount(), Is.EqualTo(5f).Within(1e-5f));
            // A quarter of the width: two more octaves... clamped to the 6 the settings allow.
            Assert.That(Inputs(new TerrainRange(0, 0, 0.25, 0.25), verticesAcross: 512f).NoiseOctaveCount(), Is.EqualTo(6f));
            // The float count agrees with Core's double OctaveCount.
            double d = OctaveNoise.OctaveCount(0.7, 300, Noise);
            Assert.That(Inputs(new TerrainRange(0, 0, 0.7, 0.7), verticesAcross: 300f).NoiseOctaveCount(), Is.EqualTo(d).Within(1e-5));
        }

        [Test]
        public void PaperModeClampsToThePatchBoundary()
        {
            // Range wider than patch 0: points beyond it collapse onto its boundary (u, v in [0, 1]).
            TerrainInputs inputs = Inputs(TerrainRange.full);
            TerrainSurfacePoint s = TerrainVertex.EvaluateSurface(inputs, 0, new Float2(1f, 1f), TerrainKeywords.PaperMode);
            Assert.That(s.patch, Is.EqualTo(0));
            Assert.That(s.uv, Is.EqualTo(new Float2(1f, 1f)));
            Region r = _grid.RegionOf(0);
            Assert.That((double)s.position.x, Is.EqualTo(r.e).Within(1e-6));
            Assert.That((double)s.position.y, Is.EqualTo(r.f).Within(1e-6));
        }

        [Test]
        public void BadInputThrowsNamingTheField()
        {
            TerrainInputs inputs = Inputs(TerrainRange.full);
            var e = Assert.Throws<ArgumentException>(() => TerrainVertex.Evaluate(inputs, 16, new Float2(0, 0)));
            Assert.That(e.Message, Does.Contain("drawPatch").And.Contain("16"));
            e = Assert.Throws<ArgumentException>(() => TerrainVertex.Evaluate(inputs, 0, new Float2(1.5f, 0)));
            Assert.That(e.Message, Does.Contain("s").And.Contain("1.5"));
            e = Assert.Throws<ArgumentException>(() => new TerrainInputs(new float[80], inputs.Regions, inputs.GridLines, inputs.Params));
            Assert.That(e.Message, Does.Contain("controlPoints.Length").And.Contain("80"));
            var lines = (float[])inputs.GridLines.Clone();
            lines[2] = lines[1];
            e = Assert.Throws<ArgumentException>(() => new TerrainInputs(inputs.ControlPoints, inputs.Regions, lines, inputs.Params));
            Assert.That(e.Message, Does.Contain("gridLines[2]"));
            // A lo part larger than the hi part's rounding is no hi/lo pair.
            lines = (float[])inputs.GridLines.Clone();
            int lo = lines.Length / 2;
            lines[lo + 1] = 0.01f;
            e = Assert.Throws<ArgumentException>(() => new TerrainInputs(inputs.ControlPoints, inputs.Regions, lines, inputs.Params));
            Assert.That(e.Message, Does.Contain($"gridLines[{lo + 1}]").And.Contain("lo part"));
            e = Assert.Throws<ArgumentException>(() => new TerrainInputs(inputs.ControlPoints, inputs.Regions, inputs.GridLines.AsSpan(0, lo).ToArray(), inputs.Params));
            Assert.That(e.Message, Does.Contain("gridLines.Length").And.Contain("hi and lo"));
            e = Assert.Throws<ArgumentException>(() => TerrainVertex.EvaluateAt(inputs, TerrainPoint.FromFloat(new Float2(float.NaN, 0)), TerrainKeywords.None));
            Assert.That(e.Message, Does.Contain("q"));
            Assert.Throws<ArgumentException>(() => TerrainVertex.Reference(_grid, new Double2(double.NaN, 0), null, 0, out _, out _));
        }
    }
}
