using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    [TestFixture]
    public class TerrainParamsTests
    {
        static TerrainParams Make(TerrainRange range, TessellationSettings tess) =>
            TerrainParams.Create(PatchGrid.CreateFlat(5, 4), range, RangeOrigin.zero, tess,
                NoiseSettings.Default, new HeightColorSettings(0.2f, 0.1f, 16f),
                new Float3(0.2f, 0.3f, 0.1f), new Float3(0.9f, 0.9f, 0.95f));

        [Test]
        public void PackFollowsTheCbufferOrder()
        {
            var p = Make(new TerrainRange(0.25, 0.125, 0.75, 0.5), TessellationSettings.Uniform(8, 16f));
            float[] f = p.Pack();
            Assert.That(f.Length, Is.EqualTo(44), "11 float4");
            Assert.That(TerrainParams.PropertyNames[10], Is.EqualTo("_OriginSurface"), "the levels' S(O), p(O) last");
            Assert.That(TerrainParams.PropertyNames[0], Is.EqualTo("_Range"));
            // _Range with a zero origin is the paper's (c, d, g, h).
            Assert.That(new[] { f[0], f[1], f[2], f[3] }, Is.EqualTo(new[] { 0.25f, 0.125f, 0.75f, 0.5f }));
            // _GridSize = (n, m, 0, 0) sits third.
            Assert.That(new[] { f[8], f[9] }, Is.EqualTo(new[] { 5f, 4f }));
            // _Tess = (tiles, maxFactor, targetPixels, uniformFactor) sits fourth.
            Assert.That(new[] { f[12], f[13], f[15] }, Is.EqualTo(new[] { 8f, 16f, 16f }));
            // _NoiseOctaves.x is the octave count.
            Assert.That(f[20], Is.EqualTo((float)NoiseSettings.Default.octaves));
            // _TileLattice sits tenth, 0 (tiles on the range) unless anchored.
            Assert.That(TerrainParams.PropertyNames[9], Is.EqualTo("_TileLattice"));
            Assert.That(new[] { f[36], f[37], f[38], f[39] }, Is.EqualTo(new[] { 0f, 0f, 0f, 0f }));
            float[] anchored = p.WithTileLattice(p.range).Pack();
            Assert.That(new[] { anchored[36], anchored[37], anchored[38], anchored[39] }, Is.EqualTo(new[] { f[0], f[1], f[2], f[3] }));
            for (int i = 0; i < TerrainParams.Float4Count; i++)
                Assert.That(f[4 * i + 3], Is.EqualTo(p[i].w), TerrainParams.PropertyNames[i]);
        }

        [Test]
        public void AnInvertedRangeIsRejectedNamingTheField()
        {
            var e = Assert.Throws<ArgumentException>(() => Make(new TerrainRange(0.5, 0, 0.2, 1), TessellationSettings.Default));
            Assert.That(e.Message, Does.Contain("range.g").And.Contain("0.2"));
        }

        [Test]
        public void ATileCountOfZeroIsRejectedNamingTheField()
        {
            var e = Assert.Throws<ArgumentException>(() => Make(TerrainRange.full, new TessellationSettings(0, 64f, 8f, 0f)));
            Assert.That(e.Message, Does.Contain("tessellation.tiles").And.Contain("0"));
        }

        [Test]
        public void AUniformFactorAboveTheHardwareLimitIsRejected()
        {
            var e = Assert.Throws<ArgumentException>(() => Make(TerrainRange.full, TessellationSettings.Uniform(4, 65f)));
            Assert.That(e.Message, Does.Contain("65"));
        }
    }
}
