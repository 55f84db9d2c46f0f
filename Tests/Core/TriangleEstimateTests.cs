using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// The renderer's triangle estimate: the tessellator's triangles per patch for both
    /// partitionings, and Core's mirror of the tile factors (TileFactors.hlsl) reacting to the
    /// settings and the camera as the knob promises. Tools~/RigTests/TriangleEstimateGpuTests.cs
    /// checks both against the GPU.
    /// </summary>
    [TestFixture]
    public class TriangleEstimateTests
    {
        const int Width = 640, Height = 360;
        internal static readonly Float2 Screen = new Float2(Width, Height);
        static PatchGrid _grid;
        internal static PatchGrid Grid => _grid ??= HardCaseGrids.Fitted(4, 4, 3, 17);

        // The sample settings on Grid; range: the whole terrain unless given; lattice: 0 (tiles on the range) unless given.
        internal static TerrainInputs Inputs(TessellationSettings tess, NoiseSettings? noise = null, TerrainRange? range = null, Float4 lattice = default) =>
            TerrainInputs.Create(Grid, TerrainParams.Create(Grid, range ?? TerrainRange.full, RangeOrigin.zero, tess, noise ?? NoiseSettings.Default,
                new HeightColorSettings(0.5f, 0.1f, 16f), new Float3(0.2f, 0.3f, 0.1f), new Float3(0.9f, 0.9f, 0.9f)).WithTileLattice(lattice));

        // Object space is (x, height, y). Clip = (x t / a, y t, depth, depth) seen from eye towards target.
        static Float4x4 Camera(Double3 eye, Double3 target, double fovYDegrees = 50)
        {
            Double3 f = GMath.normalize(target - eye);
            Double3 r = GMath.normalize(GMath.cross(f, new Double3(0, 1, 0)));
            Double3 u = GMath.cross(r, f);
            double t = 1.0 / Math.Tan(0.5 * fovYDegrees * Math.PI / 180.0), a = (double)Width / Height;
            const double near = 0.01, far = 10, k = far / (far - near);
            return Float4x4.FromRows(
                (float)(r.x * t / a), (float)(r.y * t / a), (float)(r.z * t / a), (float)(-GMath.dot(r, eye) * t / a),
                (float)(u.x * t), (float)(u.y * t), (float)(u.z * t), (float)(-GMath.dot(u, eye) * t),
                (float)(f.x * k), (float)(f.y * k), (float)(f.z * k), (float)(-(GMath.dot(f, eye) + near) * k),
                (float)f.x, (float)f.y, (float)f.z, (float)-GMath.dot(f, eye));
        }

        internal static readonly Float4x4 Oblique = Camera(new Double3(0.5, 0.45, -0.35), new Double3(0.5, 0.0, 0.55));
        internal static readonly Float4x4 Low = Camera(new Double3(0.5, 0.15, 0.2), new Double3(0.55, 0.0, 0.6), 40);

        static double Estimate(TessellationSettings tess, Float4x4 camera, TessellationPartitioning p = TessellationPartitioning.FractionalOdd,
                               int maxTiles = 4096) =>
            TerrainTriangleEstimate.InView(Inputs(tess), camera, Screen, TerrainKeywords.Noise, p, maxTiles).triangles;

        [Test]
        public void SegmentsFollowThePartitioning()
        {
            var odd = TessellationPartitioning.FractionalOdd;
            var integer = TessellationPartitioning.Integer;
            Assert.That(TerrainTriangleEstimate.Segments(0.5f, odd), Is.EqualTo(1));
            Assert.That(TerrainTriangleEstimate.Segments(1f, odd), Is.EqualTo(1));
            Assert.That(TerrainTriangleEstimate.Segments(1.01f, odd), Is.EqualTo(3));
            Assert.That(TerrainTriangleEstimate.Segments(3f, odd), Is.EqualTo(3));
            Assert.That(TerrainTriangleEstimate.Segments(3.5f, odd), Is.EqualTo(5));
            Assert.That(TerrainTriangleEstimate.Segments(64f, odd), Is.EqualTo(63), "fractional_odd stops at 63");
            Assert.That(TerrainTriangleEstimate.Segments(1.01f, integer), Is.EqualTo(2));
            Assert.That(TerrainTriangleEstimate.Segments(16f, integer), Is.EqualTo(16));
            Assert.That(TerrainTriangleEstimate.Segments(70f, integer), Is.EqualTo(64));
            Assert.Throws<ArgumentException>(() => TerrainTriangleEstimate.Segments(float.NaN, integer));
        }

        [Test]
        public void PatchTrianglesCountGridsAndTransitionRings()
        {
            TileFactorSet Uniform(float f) => new TileFactorSet(new Float4(f, f, f, f), new Float2(f, f));
            for (int n = 1; n <= 64; n++)
                Assert.That(TerrainTriangleEstimate.PatchTriangles(Uniform(n), TessellationPartitioning.Integer), Is.EqualTo(2L * n * n), "uniform " + n);
            Assert.That(TerrainTriangleEstimate.PatchTriangles(Uniform(4f), TessellationPartitioning.FractionalOdd), Is.EqualTo(2L * 5 * 5));
            Assert.That(TerrainTriangleEstimate.PatchTriangles(default, TessellationPartitioning.Integer), Is.EqualTo(0), "culled");
            // Inside 1 beside subdivided edges: raised to 2 (integer) or 3 (fractional_odd).
            var mixed = new TileFactorSet(new Float4(3f, 3f, 3f, 3f), new Float2(1f, 1f));
            Assert.That(TerrainTriangleEstimate.PatchTriangles(mixed, TessellationPartitioning.Integer), Is.EqualTo(12));
            Assert.That(TerrainTriangleEstimate.PatchTriangles(mixed, TessellationPartitioning.FractionalOdd), Is.EqualTo(2 * 3 * 3));
            // A finer edge on one side only adds its extra segments' triangles.
            var oneFine = new TileFactorSet(new Float4(8f, 4f, 4f, 4f), new Float2(4f, 4f));
            Assert.That(TerrainTriangleEstimate.PatchTriangles(oneFine, TessellationPartitioning.Integer), Is.EqualTo(2 * 16 + 4));
        }

        [Test]
        public void UniformFactorsCountEveryTile()
        {
            var e = TerrainTriangleEstimate.InView(Inputs(TessellationSettings.Uniform(8, 7f)), Oblique, Screen, TerrainKeywords.None,
                                                   TessellationPartitioning.Integer);
            Assert.That(e.triangles, Is.EqualTo(64 * 2 * 49));
            Assert.That(e.tilesSampledDrawn, Is.EqualTo(64), "uniform factors cull nothing");
        }

        [Test]
        public void AdaptiveFactorsMatchTheHullStagesRules()
        {
            var inputs = Inputs(new TessellationSettings(8, 64f, 2f, 0f));
            int drawn = 0;
            for (int tile = 0; tile < 64; tile++)
            {
                TileFactorSet f = TileFactors.ComputeTileFactors(inputs, tile, Low, Screen, TerrainKeywords.Noise);
                if (f.IsCulled) continue;
                drawn++;
                foreach (float x in new[] { f.edge.x, f.edge.y, f.edge.z, f.edge.w, f.inside.x, f.inside.y })
                    Assert.That(x, Is.InRange(1f, 64f), "tile " + tile + ": " + f);
                Assert.That(f.inside.x, Is.GreaterThanOrEqualTo(Math.Max(f.edge.y, f.edge.w)), "inside along u follows the u edges");
                Assert.That(f.inside.y, Is.GreaterThanOrEqualTo(Math.Max(f.edge.x, f.edge.z)), "inside along v follows the v edges");
                TileFactorSet right = tile % 8 < 7 ? TileFactors.ComputeTileFactors(inputs, tile + 1, Low, Screen, TerrainKeywords.Noise) : default;
                if (!right.IsCulled)
                    Assert.That(f.edge.z, Is.EqualTo(right.edge.x), "tile " + tile + ": a shared edge's factor depends on that edge only");
            }
            Assert.That(drawn, Is.GreaterThan(8).And.LessThan(64), "the low view leaves some tiles out");
        }

        [Test]
        public void ThePixelTargetAndTheCameraSetTheCount()
        {
            double coarse = Estimate(new TessellationSettings(8, 64f, 8f, 0f), Oblique);
            double fine = Estimate(new TessellationSettings(8, 64f, 2f, 0f), Oblique);
            double capped = Estimate(new TessellationSettings(8, 4f, 2f, 0f), Oblique);
            TestContext.Out.WriteLine("8 px {0:N0}, 2 px {1:N0}, 2 px with max factor 4 {2:N0}", coarse, fine, capped);
            Assert.That(fine, Is.GreaterThan(2 * coarse), "a quarter of the pixel error costs well over twice the triangles");
            Assert.That(capped, Is.LessThan(fine).And.LessThanOrEqualTo(64 * 2 * 5 * 5), "the max factor caps the count");
            Float4x4 away = Camera(new Double3(0.5, 0.3, -0.5), new Double3(0.5, 0.3, -2.0));
            Assert.That(Estimate(new TessellationSettings(8, 64f, 2f, 0f), away), Is.EqualTo(0), "looking away culls every tile");
            Assert.That(Estimate(new TessellationSettings(8, 64f, 2f, 0f), Low), Is.Not.EqualTo(fine), "the camera decides the factors");
        }

        // A bool, not the enum: NUnit runs only public test methods, and TessellationPartitioning is internal.
        [TestCase(true)]
        [TestCase(false)]
        public void TilesHeldAtTheMaxFactorAreCounted(bool integer)
        {
            var p = integer ? TessellationPartitioning.Integer : TessellationPartitioning.FractionalOdd;
            TriangleEstimate At(TessellationSettings tess) =>
                TerrainTriangleEstimate.InView(Inputs(tess), Oblique, Screen, TerrainKeywords.Noise, p, 4096);
            var coarse = At(new TessellationSettings(8, 64f, 32f, 0f));
            var capped = At(new TessellationSettings(8, 4f, 2f, 0f));
            var uniform = At(TessellationSettings.Uniform(8, 64f));
            TestContext.Out.WriteLine("{0}: 32 px {1}; 2 px, max factor 4: {2}", p, coarse, capped);
            Assert.That(coarse.tilesSampledDrawn, Is.GreaterThan(0));
            Assert.That(coarse.tilesSampledAtMaxFactor, Is.EqualTo(0), "a coarse target needs no tile at 64");
            Assert.That(capped.tilesSampledAtMaxFactor, Is.EqualTo(capped.tilesSampledDrawn).And.GreaterThan(0), "a 2 px target wants more than 4 segments everywhere");
            Assert.That(uniform.tilesSampledAtMaxFactor, Is.EqualTo(0), "a uniform factor is no cap");
            // More tiles for the same target: fewer tiles (or none) held at the cap.
            var more = At(new TessellationSettings(32, 4f, 2f, 0f));
            Assert.That((double)more.tilesSampledAtMaxFactor / more.tilesSampledDrawn,
                        Is.LessThan((double)capped.tilesSampledAtMaxFactor / capped.tilesSampledDrawn), "smaller tiles need smaller factors");
        }

        [Test]
        public void ASampleOfTheTilesEstimatesTheWhole()
        {
            var tess = new TessellationSettings(32, 64f, 1f, 0f);
            var full = TerrainTriangleEstimate.InView(Inputs(tess), Oblique, Screen, TerrainKeywords.Noise, TessellationPartitioning.Integer, 1024);
            var sample = TerrainTriangleEstimate.InView(Inputs(tess), Oblique, Screen, TerrainKeywords.Noise, TessellationPartitioning.Integer, 128);
            TestContext.Out.WriteLine("all 1,024 tiles: {0}; 128: {1}", full, sample);
            Assert.That(full.tilesSampled, Is.EqualTo(1024));
            Assert.That(sample.tilesSampled, Is.EqualTo(121), "11 x 11, the largest square within 128");
            Assert.That(sample.triangles, Is.EqualTo(full.triangles).Within(5).Percent);
        }

        [Test]
        public void BadInputNamesTheField()
        {
            var inputs = Inputs(TessellationSettings.Default);
            var nan = Float4x4.FromRows(float.NaN, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1);
            var e = Assert.Throws<ArgumentException>(() => TerrainTriangleEstimate.InView(inputs, nan, Screen, TerrainKeywords.None, TessellationPartitioning.Integer));
            StringAssert.Contains("objectToClip", e.Message);
            e = Assert.Throws<ArgumentException>(() => TerrainTriangleEstimate.InView(inputs, Oblique, new Float2(0f, 10f), TerrainKeywords.None, TessellationPartitioning.Integer));
            StringAssert.Contains("screenSize", e.Message);
            e = Assert.Throws<ArgumentException>(() => TerrainTriangleEstimate.InView(inputs, Oblique, Screen, TerrainKeywords.None, TessellationPartitioning.Integer, 0));
            StringAssert.Contains("maxTiles (0)", e.Message);
            e = Assert.Throws<ArgumentException>(() => TileFactors.ComputeTileFactors(inputs, 0, Oblique, Screen, TerrainKeywords.PaperMode));
            StringAssert.Contains("paper mode", e.Message);
        }
    }
}
