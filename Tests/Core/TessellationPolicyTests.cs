using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    [TestFixture]
    public class TessellationPolicyTests
    {
        static readonly Float2 Screen = new Float2(1920f, 1080f);

        /// <summary>A right-handed perspective looking down -z (column vectors), clip w = -z_view.</summary>
        static Float4x4 Perspective(float fovY, float aspect, float near, float far)
        {
            float f = 1f / (float)Math.Tan(fovY / 2);
            return Float4x4.FromRows(
                f / aspect, 0, 0, 0,
                0, f, 0, 0,
                0, 0, (far + near) / (near - far), 2 * far * near / (near - far),
                0, 0, -1, 0);
        }

        [Test]
        public void EdgeFactorIsClamped()
        {
            Assert.That(TessellationPolicy.EdgeFactor(0f, 8f, 64f), Is.EqualTo(1f));
            Assert.That(TessellationPolicy.EdgeFactor(4f, 8f, 64f), Is.EqualTo(1f));
            Assert.That(TessellationPolicy.EdgeFactor(80f, 8f, 64f), Is.EqualTo(10f));
            Assert.That(TessellationPolicy.EdgeFactor(1e9f, 8f, 64f), Is.EqualTo(64f));
            Assert.That(TessellationPolicy.EdgeFactor(float.NaN, 8f, 64f), Is.EqualTo(64f));
            Assert.That(Assert.Throws<ArgumentException>(() => TessellationPolicy.EdgeFactor(10f, 0f, 64f)).Message, Does.Contain("targetPixels (0)"));
            Assert.That(Assert.Throws<ArgumentException>(() => TessellationPolicy.EdgeFactor(10f, 8f, 0.5f)).Message, Does.Contain("maxFactor (0.5)"));
        }

        [Test]
        public void SwappingEndpointsGivesIdenticalFactor()
        {
            var rng = new Random(31);
            Float4x4 vp = Perspective(1.0f, 16f / 9f, 0.1f, 1000f);
            for (int i = 0; i < 100000; i++)
            {
                var a = new Float3((float)(rng.NextDouble() * 20 - 10), (float)(rng.NextDouble() * 20 - 10), -(float)(rng.NextDouble() * 100));
                var b = new Float3((float)(rng.NextDouble() * 20 - 10), (float)(rng.NextDouble() * 20 - 10), -(float)(rng.NextDouble() * 100));
                Float4 ca = vp.TransformPoint(a), cb = vp.TransformPoint(b);
                float ab = TessellationPolicy.EdgeTessFactor(ca, cb, Screen, 3.7f, 64f);
                float ba = TessellationPolicy.EdgeTessFactor(cb, ca, Screen, 3.7f, 64f);
                Assert.That(BitConverter.SingleToInt32Bits(ab), Is.EqualTo(BitConverter.SingleToInt32Bits(ba)));
                float lab = TessellationPolicy.EdgeLengthPixels(ca, cb, Screen), lba = TessellationPolicy.EdgeLengthPixels(cb, ca, Screen);
                Assert.That(BitConverter.SingleToInt32Bits(lab), Is.EqualTo(BitConverter.SingleToInt32Bits(lba)));
            }
        }

        [Test]
        public void ProjectedLengthMatchesPinholeModel()
        {
            // A 1-unit edge across the view at distance 10 with a 90 degree vertical field of view on a
            // 1080-pixel-high screen covers 1080 / 2 * (1 / 10) = 54 pixels.
            Float4x4 vp = Perspective((float)(Math.PI / 2), Screen.x / Screen.y, 0.1f, 1000f);
            float f = TessellationPolicy.EdgeTessFactor(vp, new Float3(0, -0.5f, -10), new Float3(0, 0.5f, -10), Screen, 2f, 64f);
            Assert.That(f, Is.EqualTo(27f).Within(1e-3f));
            // Further away, fewer segments; an edge reaching behind the eye gets the maximum.
            float far = TessellationPolicy.EdgeTessFactor(vp, new Float3(0, -0.5f, -100), new Float3(0, 0.5f, -100), Screen, 2f, 64f);
            Assert.That(far, Is.LessThan(f));
            Assert.That(TessellationPolicy.EdgeTessFactor(vp, new Float3(0, 0, -10), new Float3(0, 0, 5), Screen, 2f, 64f), Is.EqualTo(64f));
            Assert.That(TessellationPolicy.InsideFactor(3f, 9f, 2f, 4f), Is.EqualTo(9f));
        }

        [Test]
        public void FrustumCullingKeepsStraddlingBoxesAndCullsOutsideOnes()
        {
            Float4x4 vp = Perspective((float)(Math.PI / 2), 1f, 0.1f, 1000f);
            // At z = -10 the view spans x in [-10, 10].
            Assert.That(TessellationPolicy.BoxOutsideFrustum(vp, new Float3(-1, -1, -11), new Float3(1, 1, -9), 0f), Is.False, "inside");
            Assert.That(TessellationPolicy.BoxOutsideFrustum(vp, new Float3(9, -1, -11), new Float3(12, 1, -9), 0f), Is.False, "straddles the right plane");
            Assert.That(TessellationPolicy.BoxOutsideFrustum(vp, new Float3(12, -1, -11), new Float3(14, 1, -10), 0f), Is.True, "fully right");
            Assert.That(TessellationPolicy.BoxOutsideFrustum(vp, new Float3(-14, -1, -11), new Float3(-12, 1, -10), 0f), Is.True, "fully left");
            Assert.That(TessellationPolicy.BoxOutsideFrustum(vp, new Float3(-1, -1, 5), new Float3(1, 1, 6), 0f), Is.True, "behind the eye");
            // A box larger than the view: its corners are outside different planes, so it is kept.
            Assert.That(TessellationPolicy.BoxOutsideFrustum(vp, new Float3(-100, -100, -50), new Float3(100, 100, -20), 0f), Is.False, "surrounds the view");
            // The margin keeps a box just outside (e.g. noise or snow may lift into view).
            var nearMiss = (min: new Float3(10.5f, -1, -10), max: new Float3(11, 1, -10));
            Assert.That(TessellationPolicy.BoxOutsideFrustum(vp, nearMiss.min, nearMiss.max, 0f), Is.True);
            Assert.That(TessellationPolicy.BoxOutsideFrustum(vp, nearMiss.min, nearMiss.max, 1f), Is.False);
            Assert.Throws<ArgumentException>(() => TessellationPolicy.BoxOutsideFrustum(new Float4[7], 0f));
            Assert.Throws<ArgumentException>(() => TessellationPolicy.BoxOutsideFrustum(new Float4[8], -1f));
        }

        [Test]
        public void TriangleEstimate()
        {
            Assert.That(TessellationPolicy.EstimateTriangleCount(8, 16f), Is.EqualTo(8.0 * 8 * 2 * 16 * 16));
            Assert.That(TessellationPolicy.EstimateTriangleCount(1, 1f), Is.EqualTo(2.0), "one quad, two triangles");
            Assert.Throws<ArgumentException>(() => TessellationPolicy.EstimateTriangleCount(-1, 1f));
        }
    }
}
