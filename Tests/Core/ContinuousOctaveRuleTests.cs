using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// The continuous octave rule of the levels of detail (internals.md, "The continuous octave
    /// rule"): a count from the vertex's pixel scale, not from a range's width, so both sides of a
    /// level seam agree and a camera step changes it continuously; the single-range rule is kept bit
    /// for bit when the rule is off (<c>_NoiseOctaves.z = 0</c>).
    /// </summary>
    [TestFixture]
    public class ContinuousOctaveRuleTests
    {
        static readonly NoiseSettings Noise = new NoiseSettings(0.004f, 16f, 2f, 2f, 6);
        PatchGrid _grid;

        [OneTimeSetUp]
        public void Fit() => _grid = HeightmapFitter.Fit(HeightmapFitterTests.Samples(33, 33), 33, 33, 4, 3).Grid;

        TerrainInputs Inputs(TerrainRange range, float segmentPixels)
        {
            TerrainParams p = TerrainParams.Create(_grid, range, RangeOrigin.zero, TessellationSettings.Uniform(4, 8f), Noise,
                new HeightColorSettings(0.25f, 0.1f, 8f), new Float3(0, 0, 0), new Float3(1, 1, 1));
            p.noiseOctaves = new Float4(p.noiseOctaves.x, p.noiseOctaves.y, segmentPixels, 0f);
            return TerrainInputs.Create(_grid, p);
        }

        // A camera 0.02 terrain units above (0.5, 0.1) looking along +y over the terrain, 1920 x 1080, 60 degrees.
        static Float4x4 Camera(double eyeY = 0.1)
        {
            double x = 0.5, h = 0.02, t = 1.0 / Math.Tan(Math.PI / 6), a = 1920.0 / 1080.0, near = 1e-4, far = 10;
            // object space (x, height, y); view: right = +x, up = +height, forward = +y (object z).
            double k = far / (far - near);
            return Float4x4.FromRows(
                (float)(t / a), 0f, 0f, (float)(-x * t / a),
                0f, (float)t, 0f, (float)(-h * t),
                0f, 0f, (float)k, (float)(-(eyeY + near) * k),
                0f, 0f, 1f, (float)-eyeY);
        }

        static readonly Float2 Screen = new Float2(1920f, 1080f);

        [Test]
        public void RuleIsTheFrameRuleAtTheVertexSpacing()
        {
            // 1 + log2(k / (2 seg f)): k = 2 * 2 px * 16 * 2^3 -> 1 + 3 = 4 octaves.
            Assert.That(OctaveNoise.OctaveCountAtPixelScale(2 * 2 * 16 * 8, 2, Noise), Is.EqualTo(4.0).Within(1e-12));
            Assert.That(OctaveNoise.OctaveCountAtPixelScale(1234.5, 3, Noise), Is.EqualTo(OctaveNoise.OctaveCount(3 / 1234.5, 1, Noise)).Within(1e-12));
            Assert.That(OctaveNoise.OctaveCountAtPixelScale(double.PositiveInfinity, 2, Noise), Is.EqualTo(6.0), "at or behind the eye plane: every octave");
            Assert.That(OctaveNoise.OctaveCountAtPixelScale(0, 2, Noise), Is.EqualTo(0.0), "no pixels: no octave");
            Assert.That(OctaveNoise.OctaveCountAtPixelScale(1e12, 2, Noise), Is.EqualTo(6.0), "clamped to the settings' octaves");
            Assert.That(Assert.Throws<ArgumentException>(() => OctaveNoise.OctaveCountAtPixelScale(100, 0, Noise)).Message, Does.Contain("segmentPixels (0)"));
            Assert.That(Assert.Throws<ArgumentException>(() => OctaveNoise.OctaveCountAtPixelScale(double.NaN, 2, Noise)).Message, Does.Contain("pixelsPerUnit (NaN)"));
        }

        [Test]
        public void FloatMirrorFollowsTheDoubleAndIsContinuous()
        {
            TerrainParams p = Inputs(TerrainRange.full, 2f).Params;
            float previous = -1f;
            for (double k = 1; k < 1e7; k *= 1.0001 + 0.01)
            {
                float f = TerrainInputs.NoiseOctaveCountAt(p, (float)k);
                Assert.That(f, Is.EqualTo(OctaveNoise.OctaveCountAtPixelScale(k, 2, Noise)).Within(1e-5), "pixel scale " + k);
                Assert.That(f, Is.GreaterThanOrEqualTo(previous), "more pixels, never fewer octaves");
                previous = f;
                // A 1e-4 relative change of the scale (a small camera step) moves the count by about
                // log2(1 + 1e-4) = 1.44e-4, never by a step.
                float g = TerrainInputs.NoiseOctaveCountAt(p, (float)(k * 1.0001));
                Assert.That(g - f, Is.InRange(0f, 2e-4f), "continuous at scale " + k);
            }
            Assert.That(TerrainInputs.NoiseOctaveCountAt(p, float.PositiveInfinity), Is.EqualTo(6f));
            Assert.That(TerrainInputs.NoiseOctaveCountAt(p, 0f), Is.EqualTo(0f));
        }

        [Test]
        public void SingleRangeRuleKeptBitForBitWhenOff()
        {
            TerrainInputs off = Inputs(new TerrainRange(0.25, 0.25, 0.75, 0.75), 0f);
            for (int tile = 0; tile < 16; tile += 3)
                for (int i = 0; i <= 4; i++)
                {
                    var st = new Float2(i / 4f, 1f - i / 4f);
                    TerrainVertexOutput a = TerrainVertex.Evaluate(off, tile, st, TerrainKeywords.Noise);
                    TerrainVertexOutput b = TerrainVertex.EvaluateWithCamera(off, tile, st, TerrainKeywords.Noise, Camera(), Screen);
                    Assert.That(b.position, Is.EqualTo(a.position), "z = 0: the camera changes nothing");
                    Assert.That(b.normal, Is.EqualTo(a.normal));
                }
            TerrainInputs on = Inputs(TerrainRange.full, 2f);
            Assert.That(Assert.Throws<ArgumentException>(() => TerrainVertex.Evaluate(on, 0, new Float2(0.5f, 0.5f), TerrainKeywords.Noise)).Message,
                        Does.Contain("camera").And.Contain("noiseOctaves.z (2"));
        }

        [Test]
        public void BothSidesOfALevelSeamAgree()
        {
            // The same q drawn by a level and by the level twice as wide around it: the single-range
            // rule gives each its own count (its width), so the seam's vertices differ; the
            // continuous rule gives both the count at q, bit for bit.
            var fine = new TerrainRange(0.375, 0.125, 0.625, 0.375);
            var coarse = new TerrainRange(0.25, 0.0, 0.75, 0.5);
            int differing = 0, counted = 0;
            for (int i = 0; i <= 16; i++)
            {
                TerrainPoint q = TerrainPoint.FromFloat(new Float2(0.375f + i / 64f, 0.375f));
                TerrainVertexOutput f0 = TerrainVertex.EvaluateAt(Inputs(fine, 0f), q, TerrainKeywords.Noise);
                TerrainVertexOutput c0 = TerrainVertex.EvaluateAt(Inputs(coarse, 0f), q, TerrainKeywords.Noise);
                if (!f0.position.Equals(c0.position)) differing++;
                TerrainVertexOutput f1 = TerrainVertex.EvaluateAtWithCamera(Inputs(fine, 2f), q, TerrainKeywords.Noise, Camera(), Screen);
                TerrainVertexOutput c1 = TerrainVertex.EvaluateAtWithCamera(Inputs(coarse, 2f), q, TerrainKeywords.Noise, Camera(), Screen);
                Assert.That(c1.position, Is.EqualTo(f1.position), "seam vertex " + i);
                Assert.That(c1.normal, Is.EqualTo(f1.normal), "seam normal " + i);
                counted++;
            }
            Assert.That(differing, Is.GreaterThan(counted / 2), "the single-range rule does crack such a seam (else this test shows nothing)");
        }

        [Test]
        public void CountFallsWithDistanceFromTheCamera()
        {
            // 16 px segments: 0.02 ahead about 46,800 px per unit (every octave), 0.9 ahead about 1,040 (two).
            TerrainInputs on = Inputs(TerrainRange.full, 16f);
            float near = TerrainVertex.VertexOctaveCount(on, new Float3(0.5f, 0.12f, 0f), TerrainKeywords.Noise, (Camera(), Screen));
            float far = TerrainVertex.VertexOctaveCount(on, new Float3(0.5f, 1.0f, 0f), TerrainKeywords.Noise, (Camera(), Screen));
            Assert.That(near, Is.GreaterThan(far + 2f), "the feet draw more octaves than the distance");
            Assert.That(TerrainVertex.VertexOctaveCount(on, new Float3(0.5f, 0.12f, 0f), TerrainKeywords.Noise | TerrainKeywords.PaperMode, null),
                        Is.EqualTo(on.NoiseOctaveCount()), "paper mode keeps the single-range rule");
        }
    }
}
