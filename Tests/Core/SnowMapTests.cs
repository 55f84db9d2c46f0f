using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// The snow map as the terrain reads it (SnowMap), the snow step of TerrainVertex (GT_SNOW) and
    /// the terrain field the simulation reads (SnowFieldTerrain).
    /// </summary>
    [TestFixture]
    public class SnowMapTests
    {
        static readonly NoiseSettings Noise = new NoiseSettings(0.004f, 16f, 2f, 2f, 6);
        PatchGrid _grid;

        [OneTimeSetUp]
        public void Fit() => _grid = HeightmapFitter.Fit(HeightmapFitterTests.Samples(33, 33), 33, 33, 4, 3).Grid;

        TerrainInputs Inputs(TerrainRange range, int tiles = 4, float factor = 8f) =>
            TerrainInputs.Create(_grid, TerrainParams.Create(_grid, range, RangeOrigin.For(range),
                TessellationSettings.Uniform(tiles, factor), Noise, new HeightColorSettings(0.25f, 0.1f, 8f),
                new Float3(0, 0, 0), new Float3(1, 1, 1)));

        /// <summary>A map whose depth is a known function of the cell: d(i, j) = cap * (i + 2 j) / (3 R).</summary>
        static SnowMap Ramp(int r, float cap)
        {
            var d = new float[r * r];
            for (int j = 0; j < r; j++)
                for (int i = 0; i < r; i++)
                    d[j * r + i] = cap * (i + 2f * j) / (3f * r);
            return new SnowMap(d, r, cap);
        }

        [Test]
        public void SampleIsTheCellValueAtCentresAndBilinearBetween()
        {
            const int r = 64;
            SnowMap map = Ramp(r, 0.02f);
            var field = new SnowField(r);
            // At a cell centre: the cell's own value.
            foreach (var (i, j) in new[] { (0, 0), (5, 9), (63, 63), (31, 17) })
                Assert.That(map.Sample(field.CellCentre(i, j)), Is.EqualTo(map.Depth[j * r + i]).Within(1e-9), $"cell ({i}, {j})");
            // Between centres the ramp is linear, so bilinear interpolation reproduces it.
            var rnd = new Random(5);
            for (int n = 0; n < 200; n++)
            {
                double x = (0.5 + rnd.NextDouble() * (r - 1)) / r, y = (0.5 + rnd.NextDouble() * (r - 1)) / r;
                double want = 0.02 * ((x * r - 0.5) + 2 * (y * r - 0.5)) / (3.0 * r);
                Assert.That(map.Sample(new Float2((float)x, (float)y)), Is.EqualTo(want).Within(1e-8), $"({x}, {y})");
            }
            // Outside the outermost centres the edge cells are repeated (no extrapolation, no wrap).
            Assert.That(map.Sample(new Float2(0f, 0f)), Is.EqualTo(map.Depth[0]));
            Assert.That(map.Sample(new Float2(1f, 1f)), Is.EqualTo(map.Depth[r * r - 1]));
            Assert.That(map.Sample(new Float2(0.3f, 1f)), Is.EqualTo(map.Sample(new Float2(0.3f, (r - 0.5f) / r))).Within(1e-9));
        }

        [Test]
        public void CoverageGoesFromBareToWhiteByHalfTheCap()
        {
            const float cap = 0.02f;
            Assert.That(SnowMap.Coverage(0f, cap), Is.EqualTo(0f));
            Assert.That(SnowMap.Coverage(SnowMap.FullCoverFraction * cap, cap), Is.EqualTo(1f));
            Assert.That(SnowMap.Coverage(cap, cap), Is.EqualTo(1f));
            float last = 0f;
            for (int k = 1; k <= 20; k++)
            {
                float c = SnowMap.Coverage(k * 0.01f * SnowMap.FullCoverFraction * cap, cap);
                Assert.That(c, Is.GreaterThan(last));
                last = c;
            }
            Assert.That(SnowMap.PackMapSize(512, cap), Is.EqualTo(new Float4(512f, 1f / 512f, cap, 0f)));
        }

        [Test]
        public void BadMapsAreRefusedByName()
        {
            Assert.That(Assert.Throws<ArgumentException>(() => new SnowMap(new float[100 * 100], 100, 0.02f)).Message, Does.Contain("resolution (100)"));
            Assert.That(Assert.Throws<ArgumentException>(() => new SnowMap(new float[10], 64, 0.02f)).Message, Does.Contain("depth.Length (10)"));
            Assert.That(Assert.Throws<ArgumentException>(() => new SnowMap(new float[64 * 64], 64, 0f)).Message, Does.Contain("depthCap (0)"));
            Assert.That(Assert.Throws<ArgumentException>(() => new SnowMap(new float[64 * 64], 64, float.NaN)).Message, Does.Contain("depthCap (NaN)"));
            Assert.Throws<ArgumentNullException>(() => new SnowMap(null, 64, 0.02f));
        }

        [Test]
        public void SnowRaisesTheVertexByTheMapDepthAndKeepsItsNormal()
        {
            TerrainInputs bare = Inputs(new TerrainRange(0.1, 0.2, 0.9, 0.8));
            SnowMap map = Ramp(128, 0.02f);
            TerrainInputs snowy = bare.WithSnow(map);
            var k = TerrainKeywords.Noise;
            double maxDepth = 0;
            for (int tile = 0; tile < 16; tile++)
                for (int j = 0; j <= 4; j++)
                    for (int i = 0; i <= 4; i++)
                    {
                        var tess = new Float2(i / 4f, j / 4f);
                        TerrainVertexOutput a = TerrainVertex.Evaluate(bare, tile, tess, k);
                        TerrainVertexOutput b = TerrainVertex.Evaluate(snowy, tile, tess, k | TerrainKeywords.Snow);
                        // The depth from the map at q, by the map's own definition (double, from the ramp).
                        Float2 q = RangeMapping.Approximate(a.surface.q);
                        double cx = Math.Min(Math.Max(q.x * 128.0 - 0.5, 0), 127), cy = Math.Min(Math.Max(q.y * 128.0 - 0.5, 0), 127);
                        double want = 0.02 * (cx + 2 * cy) / (3.0 * 128);
                        Assert.That(b.snowDepth, Is.EqualTo(want).Within(1e-8));
                        Assert.That(b.position.z - a.position.z, Is.EqualTo(b.snowDepth).Within(1e-7));
                        Assert.That(b.position.x, Is.EqualTo(a.position.x));
                        Assert.That(b.normal, Is.EqualTo(a.normal));
                        Assert.That(a.snowDepth, Is.EqualTo(0f));
                        maxDepth = Math.Max(maxDepth, b.snowDepth);
                    }
            Assert.That(maxDepth, Is.GreaterThan(0.01));
            // Snow without a map is a caller error, named.
            Assert.That(Assert.Throws<ArgumentException>(() => TerrainVertex.Evaluate(bare, 0, new Float2(0, 0), TerrainKeywords.Snow)).Message,
                        Does.Contain("Snow"));
            // The snow map survives a new range.
            Assert.That(snowy.WithParams(bare.Params).Snow, Is.SameAs(map));
        }

        [Test]
        public void SnowedSharedTileEdgesStayBitIdentical()
        {
            var d = new float[64 * 64];
            var rnd = new Random(3);
            for (int n = 0; n < d.Length; n++) d[n] = (float)rnd.NextDouble() * 0.02f;
            TerrainInputs inputs = Inputs(new TerrainRange(0.13, 0.27, 0.91, 0.83), tiles: 5).WithSnow(new SnowMap(d, 64, 0.02f));
            var k = TerrainKeywords.Noise | TerrainKeywords.Snow;
            for (int tj = 0; tj < 5; tj++)
                for (int ti = 0; ti < 4; ti++)
                    for (int s = 0; s <= 8; s++)
                    {
                        TerrainVertexOutput left = TerrainVertex.Evaluate(inputs, tj * 5 + ti, new Float2(1f, s / 8f), k);
                        TerrainVertexOutput right = TerrainVertex.Evaluate(inputs, tj * 5 + ti + 1, new Float2(0f, s / 8f), k);
                        Assert.That(right.position, Is.EqualTo(left.position));
                        Assert.That(right.snowDepth, Is.GreaterThan(0f));
                    }
        }

        /// <summary>
        /// The field is the whole terrain without an origin: the levels' per-camera <c>_OriginSurface</c> must not
        /// reach its parameters, or every origin re-snap (or camera switch) would run the field again.
        /// </summary>
        [Test]
        public void TheFieldsParamsDoNotFollowTheLevelsOrigin()
        {
            TerrainParams drawn = Inputs(new TerrainRange(0.4, 0.4, 0.5, 0.5)).Params, moved = drawn;
            moved.originSurface = new Float4(0.25f, 0.5f, 0.125f, 0.01f);
            Assert.That(SnowFieldTerrain.ParamsFor(moved, 64).Pack(), Is.EqualTo(SnowFieldTerrain.ParamsFor(drawn, 64).Pack()));
        }

        [TestCase(false)]
        [TestCase(true)]
        public void FieldCellsAreTheTerrainAtTheCellCentres(bool noise)
        {
            const int r = 64;
            var keywords = noise ? TerrainKeywords.Noise : TerrainKeywords.None;
            TerrainInputs terrain = Inputs(new TerrainRange(0.4, 0.4, 0.5, 0.5));   // any drawn range: replaced
            var field = new SnowField(r);
            int version = field.Version;
            SnowFieldTerrain.Evaluate(terrain, field, keywords);
            Assert.That(field.Version, Is.Not.EqualTo(version), "the field must report the change");

            // The octave count the field uses: wavelengths of at least two cells.
            TerrainParams fp = SnowFieldTerrain.ParamsFor(terrain.Params, r);
            double octaves = terrain.WithParams(fp).NoiseOctaveCount();
            double expected = Math.Min(Noise.octaves, 1 + Math.Log(r / (2.0 * Noise.frequency)) / Math.Log(Noise.alpha));
            Assert.That(octaves, Is.EqualTo(expected).Within(1e-5));

            double worstH = 0, worstN = 0;
            for (int j = 0; j < r; j++)
                for (int i = 0; i < r; i++)
                {
                    // Independent of the tile trick: the double surface at the exact centre.
                    Double2 centre = new Double2((i + 0.5) / r, (j + 0.5) / r);
                    TerrainVertex.Reference(_grid, centre, noise ? Noise : (NoiseSettings?)null, octaves, out Double3 p, out Double3 n);
                    Float3 fn = field.Normal(i, j);
                    worstH = Math.Max(worstH, Math.Abs(field.Height(i, j) - p.z));
                    worstN = Math.Max(worstN, GMath.length(new Double3(fn.x, fn.y, fn.z) - n));
                    Assert.That(fn.z, Is.GreaterThan(0f), "the detail normal points up");
                }
            TestContext.Out.WriteLine($"field R {r}, noise {noise}: max |height - double| {worstH:G3}, max |normal - double| {worstN:G3}");
            Assert.That(worstH, Is.LessThan(2e-6));
            Assert.That(worstN, Is.LessThan(2e-5));
            // And it is the float path the GPU runs: EvaluateAt at the cell centre under the field params.
            TerrainInputs fi = terrain.WithParams(fp);
            TerrainVertexOutput v = TerrainVertex.EvaluateAt(fi, new TerrainPoint(default, field.CellCentre(17, 40)), keywords);
            Assert.That(field.Height(17, 40), Is.EqualTo(v.position.z));
            Assert.That(field.Normal(17, 40), Is.EqualTo(v.normal));
        }

        [Test]
        public void FieldRefusesSnowAndPaperModeAndOddResolutions()
        {
            TerrainInputs terrain = Inputs(TerrainRange.full);
            var field = new SnowField(64);
            Assert.That(Assert.Throws<ArgumentException>(() => SnowFieldTerrain.Evaluate(terrain, field, TerrainKeywords.Snow)).Message, Does.Contain("keywords"));
            Assert.That(Assert.Throws<ArgumentException>(() => SnowFieldTerrain.Evaluate(terrain, field, TerrainKeywords.PaperMode)).Message, Does.Contain("keywords"));
            Assert.That(Assert.Throws<ArgumentException>(() => SnowFieldTerrain.ParamsFor(terrain.Params, 96)).Message, Does.Contain("resolution (96)"));
        }
    }
}
