using System;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    [TestFixture]
    public class SnowSimulationTests
    {
        static SnowSettings Settings(int r)
        {
            var s = SnowSettings.Default;
            s.resolution = r; s.scale = 0.001f; s.wind = new Float2(2f, 0f); s.fallSpeed = 1f;
            s.depthCap = 0.05f; s.meltRate = 0f;
            return s;
        }

        [Test]
        public void FlatGroundFacingUpAccumulatesScaleTimesTime()
        {
            const int r = 64;
            var sim = new SnowSimulation(Settings(r));
            var field = SnowTestTerrain.Flat(r, 0.2f);
            for (int n = 0; n < 10; n++) sim.Step(field, 0.5f);
            foreach (float l in sim.Exposure) Assert.That(l, Is.EqualTo(1f));
            // 10 steps of 0.001 * 0.5 each: 0.005, with float rounding of 10 additions.
            foreach (float d in sim.Depth) Assert.That(d, Is.EqualTo(0.005).Within(1e-8));
        }

        [Test]
        public void LeeFaceBehindARidgeGetsLessThanItsWindFacingTwin()
        {
            const int r = 128;
            var s = Settings(r);
            s.edgeStrength = 0f;  // compare the faces, not the crest
            var sim = new SnowSimulation(s);
            var field = SnowTestTerrain.Ridge(r, 0.1f, 0.1f);
            for (int n = 0; n < 20; n++) sim.Step(field, 1f);
            int j = 40;
            // Twin cells mirror each other about the crest: same height, mirrored normal, same catch.
            int windward = SnowTestTerrain.Column(r, 0.45), lee = r - 1 - windward;
            Assert.That(field.Height(lee, j), Is.EqualTo(field.Height(windward, j)));
            Assert.That(field.Normal(lee, j).z, Is.EqualTo(field.Normal(windward, j).z));
            float dw = sim.Depth[j * r + windward], dl = sim.Depth[j * r + lee];
            TestContext.Out.WriteLine($"after 20 s: windward depth {dw}, lee depth {dl}, level ground {sim.Depth[j * r + 2]}");
            Assert.That(dw, Is.GreaterThan(0f));
            Assert.That(dl, Is.LessThan(0.25f * dw));
            // The face catches less than level ground (catch = cos 45 degrees).
            Assert.That(dw, Is.EqualTo(sim.Depth[j * r + 2] * Math.Sqrt(0.5)).Within(1e-6));
        }

        [Test]
        public void SmoothVerticalFaceCatchesNothingItsDetailNormalCatchesOnlyOnTheWindwardSide()
        {
            // A block (x in [0.5, 0.625], height 0.1) on level ground. The two cells at the block's
            // sides stand for its walls: half height, wall normal. Wind along +x.
            const int r = 64;
            int west = 31, east = 40;
            SnowField Block(float detailTilt)
            {
                var f = SnowTestTerrain.Flat(r);
                for (int j = 0; j < r; j++)
                {
                    for (int i = west + 1; i < east; i++) f.Set(i, j, new Float3(0f, 0f, 1f), 0.1f);
                    f.Set(west, j, GMath.normalize(new Float3(-1f, 0f, detailTilt)), 0.05f);  // faces the wind
                    f.Set(east, j, GMath.normalize(new Float3(1f, 0f, detailTilt)), 0.05f);   // lee wall
                }
                return f;
            }
            var s = Settings(r);
            s.edgeStrength = 0f;
            var smooth = new SnowSimulation(s);
            smooth.Step(Block(0f), 1f);
            var detail = new SnowSimulation(s);
            detail.Step(Block(0.5f), 1f);
            int j0 = 20;
            Assert.That(smooth.Depth[j0 * r + west], Is.EqualTo(0f), "plain N.Gn: a vertical face gets nothing");
            Assert.That(detail.Depth[j0 * r + west], Is.GreaterThan(0.3f * s.scale), "detail normal: the windward wall catches snow");
            Assert.That(detail.Exposure[j0 * r + east], Is.EqualTo(0f));
            Assert.That(detail.Depth[j0 * r + east], Is.EqualTo(0f), "the lee wall is shielded by the block");
            foreach (float d in smooth.Depth) Assert.That(GMath.isfinite(d), Is.True);
        }

        [Test]
        public void DepthNeverExceedsTheCap()
        {
            const int r = 64;
            var s = Settings(r);
            s.scale = 0.01f; s.depthCap = 0.02f;
            var sim = new SnowSimulation(s);
            var field = SnowTestTerrain.Ridge(r, 0.1f, 0.2f);
            float max = 0f;
            for (int n = 0; n < 500; n++)
            {
                sim.Step(field, 0.37f);
                foreach (float d in sim.Depth) { Assert.That(d, Is.LessThanOrEqualTo(s.depthCap)); max = Math.Max(max, d); }
            }
            Assert.That(max, Is.EqualTo(s.depthCap), "level ground fills up to the cap");
        }

        [Test]
        public void MeltReducesDepthAndStopsAtZero()
        {
            const int r = 64;
            var s = Settings(r);
            var sim = new SnowSimulation(s);
            var field = SnowTestTerrain.Flat(r);
            for (int n = 0; n < 10; n++) sim.Step(field, 1f);
            float before = sim.Depth[100];
            s.scale = 0f; s.meltRate = 0.002f;
            sim.Settings = s;
            sim.Step(field, 1f);
            Assert.That(sim.Depth[100], Is.EqualTo(before - 0.002).Within(1e-8));
            for (int n = 0; n < 10; n++) sim.Step(field, 1f);
            Assert.That(sim.Depth[100], Is.EqualTo(0f));
            // Snowfall weaker than the melt: nothing lies.
            s.scale = 0.001f;
            sim.Settings = s;
            sim.Step(field, 1f);
            Assert.That(sim.Depth[100], Is.EqualTo(0f));
        }

        [Test]
        public void NoNaNAtZeroWindOrOnVerticalAndOverhangingFaces()
        {
            const int r = 64;
            var s = Settings(r);
            s.wind = new Float2(0f, 0f);
            var sim = new SnowSimulation(s);
            var field = SnowTestTerrain.Ridge(r, 0.5f, 0.01f);
            for (int i = 0; i < r; i++)
            {
                field.Set(i, 5, new Float3(1f, 0f, 0f), 0.3f);
                field.Set(i, 6, new Float3(0f, 0f, -1f), 0.3f);
            }
            sim.Step(field, 1f);
            foreach (float l in sim.Exposure) Assert.That(l, Is.EqualTo(1f));
            foreach (float d in sim.Depth) Assert.That(GMath.isfinite(d) && d >= 0f, Is.True, "depth " + d);
            Assert.That(sim.Depth[5 * r + 3], Is.EqualTo(0f));
            Assert.That(sim.Depth[6 * r + 3], Is.EqualTo(0f));
        }

        [Test]
        public void ExposureIsRecomputedOnlyWhenTheWindOrTheTerrainChanges()
        {
            const int r = 64;
            var s = Settings(r);
            var sim = new SnowSimulation(s);
            var field = SnowTestTerrain.Ridge(r, 0.1f, 0.1f);
            Assert.That(sim.NeedsExposureUpdate(field), Is.True, "never computed");
            sim.Step(field, 1f);
            sim.Step(field, 1f);
            Assert.That(sim.ExposureUpdates, Is.EqualTo(1));
            Assert.That(sim.NeedsExposureUpdate(field), Is.False);

            s.scale *= 2f; s.meltRate = 0.0001f; s.depthCap *= 2f; s.edgeStrength = 0.5f;
            sim.Settings = s;
            Assert.That(sim.NeedsExposureUpdate(field), Is.False, "rate, melt, cap and edge do not touch exposure");

            s.wind = new Float2(1f, 1f);
            sim.Settings = s;
            Assert.That(sim.NeedsExposureUpdate(field), Is.True, "wind changed");
            sim.Step(field, 1f);
            Assert.That(sim.ExposureUpdates, Is.EqualTo(2));

            field.Set(3, 3, new Float3(0f, 0f, 1f), 0.05f);
            Assert.That(sim.NeedsExposureUpdate(field), Is.True, "terrain changed");
            sim.UpdateExposure(field);
            Assert.That(sim.NeedsExposureUpdate(field), Is.False);
            Assert.That(sim.NeedsExposureUpdate(SnowTestTerrain.Ridge(r, 0.1f, 0.1f)), Is.True, "another field");
        }

        [Test]
        public void BadInputThrowsNamingTheFieldAndLeavesTheSimulationAsItWas()
        {
            var s = Settings(64);
            var sim = new SnowSimulation(s);
            var field = SnowTestTerrain.Flat(64);
            sim.Step(field, 1f);
            float before = sim.Depth[0];
            Assert.That(Assert.Throws<ArgumentException>(() => sim.Step(field, float.NaN)).Message, Does.Contain("dt (NaN)"));
            Assert.That(Assert.Throws<ArgumentException>(() => sim.Step(SnowTestTerrain.Flat(128), 1f)).Message, Does.Contain("field.Resolution (128)"));
            var bad = s; bad.resolution = 128;
            Assert.That(Assert.Throws<ArgumentException>(() => sim.Settings = bad).Message, Does.Contain("snow.resolution (128)"));
            bad = s; bad.depthCap = -1f;
            Assert.That(Assert.Throws<ArgumentException>(() => sim.Settings = bad).Message, Does.Contain("snow.depthCap (-1)"));
            Assert.That(sim.Settings, Is.EqualTo(s));
            Assert.That(sim.Depth[0], Is.EqualTo(before));
            Assert.Throws<ArgumentException>(() => new SnowField(100));
            Assert.Throws<ArgumentException>(() => field.Set(64, 0, new Float3(0f, 0f, 1f), 0f));
            Assert.Throws<ArgumentException>(() => field.Set(0, 0, new Float3(0f, 0f, 1f), float.PositiveInfinity));
        }
    }
}
