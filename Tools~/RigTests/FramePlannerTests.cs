using System;
using NUnit.Framework;
using GregoryTerrain.Tests;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// The renderer's per-frame rules (Core's <see cref="FramePlanner"/>), each as the mask of what a
    /// frame sends: the steady state sends only the range (index.md, "What is sent per frame"), nothing
    /// is allocated per planned frame, and each change sends what it changed. Kept with the rig's
    /// tests, out of the shipped package (its size limit).
    /// </summary>
    [TestFixture]
    public class FramePlannerTests
    {
        static readonly PatchGrid Grid = HardCaseGrids.WithLines(new[] { 0.0, 0.25, 0.5, 0.75, 1.0 }, new[] { 0.0, 0.25, 0.5, 0.75, 1.0 });
        static readonly TerrainRange Wide = new TerrainRange(0.2, 0.2, 0.6, 0.6);
        static readonly TerrainRange Deep = new TerrainRange(0.3, 0.3, 0.3 + 1e-4, 0.3 + 1e-4);

        static FrameSettings Settings(int tiles = 16, bool levels = false, bool anchor = true, float uniform = 0f) => new FrameSettings
        {
            tess = new TessellationSettings(tiles, 64f, 8f, uniform),
            noise = new NoiseSettings(0.02f, 16f, 2f, 2f, 6),
            heightColor = new HeightColorSettings(0.5f, 0.1f, 64f),
            colorLow = new Float3(0.1f, 0.2f, 0.1f), colorHigh = new Float3(0.9f, 0.9f, 0.9f),
            anchorTiles = anchor, levels = levels,
        };

        static FrameInputs Inputs(TerrainRange range, FrameSettings settings, int camera = 1, double groundX = 0.5) => new FrameInputs
        {
            grid = Grid, settings = settings, range = range,
            localToWorld = Float4x4.identity, terrainSize = new Double2(100000.0, 100000.0), heightScale = 1000.0,
            hasCamera = true, camera = camera, ground = new Double2(groundX, 0.5),
            finestExponent = LodLevels.FinestExponent(100000.0, 16.0),
        };

        /// <summary>Bytes a mask sends (index.md's tables): the block 160, a float4 16, the matrices 128, the levels 320.</summary>
        static int Bytes(FrameChange c)
        {
            if ((c & FrameChange.Params) != 0) c &= ~(FrameChange.Range | FrameChange.RangeOrigin);
            int bytes = 0;
            if ((c & FrameChange.Params) != 0) bytes += TerrainParams.Bytes;
            foreach (FrameChange one in new[] { FrameChange.Range, FrameChange.RangeOrigin, FrameChange.TileLattice, FrameChange.LevelCount })
                if ((c & one) != 0) bytes += 16;
            if ((c & FrameChange.Matrices) != 0) bytes += 128;
            if ((c & FrameChange.Levels) != 0) bytes += 16 * LodTiles.MaxLevels;
            return bytes;
        }

        [Test]
        public void TheFirstFrameSendsTheBlockAndTheMatrices()
        {
            var s = new FrameState();
            FrameChange c = FramePlanner.Plan(s, Inputs(Wide, Settings()));
            Assert.That(c, Is.EqualTo(FrameChange.Params | FrameChange.Matrices | FrameChange.TileLattice), "anchored tiles anchor at the range");
            Assert.That(s.error, Is.Null);
            Assert.That(s.parameters.tess.x, Is.EqualTo(16f));
        }

        // The manual's modes (the Compute cache plans as the domain stage: its pass is VertexCachePass's).
        [TestCase(false, false, 16)]
        [TestCase(true, false, 16 + 16 * LodTiles.MaxLevels)]
        [TestCase(false, true, 16)]
        public void TheSteadyStateSendsOnlyTheRange(bool levels, bool fallback, int bytes)
        {
            var s = new FrameState();
            FrameSettings settings = Settings(levels: levels, uniform: fallback ? 16f : 0f);
            settings.fallback = fallback;
            FrameInputs f = Inputs(Wide, settings);
            FramePlanner.Plan(s, f);
            for (int frame = 0; frame < 3; frame++)
            {
                FrameChange c = FramePlanner.Plan(s, f);
                Assert.That(c, Is.EqualTo(levels ? FrameChange.Range | FrameChange.Levels : FrameChange.Range), $"frame {frame}");
                Assert.That(Bytes(c), Is.EqualTo(bytes), "bytes per frame (index.md)");
            }
        }

        [TestCase(false)]
        [TestCase(true)]
        public void APlannedFrameAllocatesNothing(bool levels)
        {
            var s = new FrameState();
            FrameInputs f = Inputs(Wide, Settings(levels: levels)), g = Inputs(Wide, Settings(levels: levels), camera: 2, groundX: 0.2);
            FramePlanner.Plan(s, f); FramePlanner.Plan(s, g);   // first frames of both cameras allocate (params, origins)
            // Two runs of 1,000 and 3,000 frame pairs: a constant cost of the measurement (the JIT's
            // tiering of this loop) cancels, a cost per frame does not.
            long[] bytes = new long[2];
            for (int run = 0; run < 2; run++)
            {
                long before = GC.GetAllocatedBytesForCurrentThread();
                for (int k = 0; k < 1000 + 2000 * run; k++)
                {
                    f.range = new TerrainRange(0.2 + 1e-5 * (k % 10), 0.2, 0.6 + 1e-5 * (k % 10), 0.6);   // a pan within a cell
                    FramePlanner.Plan(s, f);
                    FramePlanner.Plan(s, g);
                }
                bytes[run] = GC.GetAllocatedBytesForCurrentThread() - before;
            }
            Assert.That(bytes[1] - bytes[0], Is.EqualTo(0), $"bytes allocated by 4,000 more planned frames ({bytes[0]} for the first 2,000)");
        }

        [Test]
        public void APanKeepsTheLatticeAZoomAnchorsAgain()
        {
            var s = new FrameState();
            FramePlanner.Plan(s, Inputs(Wide, Settings()));
            Float4 lattice = s.parameters.tileLattice;
            Assert.That(FramePlanner.Plan(s, Inputs(new TerrainRange(0.21, 0.2, 0.61, 0.6), Settings())), Is.EqualTo(FrameChange.Range));
            Assert.That(s.parameters.tileLattice, Is.EqualTo(lattice), "kept while panning");
            Assert.That(FramePlanner.Plan(s, Inputs(new TerrainRange(0.3, 0.3, 0.5, 0.5), Settings())), Is.EqualTo(FrameChange.Range | FrameChange.TileLattice), "a zoom");
            Assert.That(FramePlanner.Plan(s, Inputs(Wide, Settings(anchor: false))), Is.EqualTo(FrameChange.Params | FrameChange.Matrices), "not anchored: the block's 0 lattice stays");
            Assert.That(s.parameters.tileLattice, Is.EqualTo(default(Float4)));
        }

        [Test]
        public void ASettingChangeSendsTheBlockAndNothingElseChangesIt()
        {
            var s = new FrameState();
            FramePlanner.Plan(s, Inputs(Wide, Settings()));
            Assert.That(FramePlanner.Plan(s, Inputs(Wide, Settings(tiles: 8))), Is.EqualTo(FrameChange.Params | FrameChange.Matrices | FrameChange.TileLattice));
            Assert.That(s.parameters.tess.x, Is.EqualTo(8f));
            FrameSettings noisier = Settings(tiles: 8);
            noisier.noise.amplitude = 0.05f;
            Assert.That(FramePlanner.Plan(s, Inputs(Wide, noisier)) & FrameChange.Params, Is.EqualTo(FrameChange.Params), "noise amplitude");
            Assert.That(FramePlanner.Plan(s, Inputs(Wide, noisier)), Is.EqualTo(FrameChange.Range), "the same settings again");
        }

        [Test]
        public void TheTransformSizeAndFloatingOriginResendOnlyTheMatrices()
        {
            var s = new FrameState();
            FrameInputs f = Inputs(Wide, Settings());
            FramePlanner.Plan(s, f);
            Float4x4 before = s.objectToWorld;
            f.localToWorld = new Float4x4(Float4x4.identity.c0, Float4x4.identity.c1, Float4x4.identity.c2, new Float4(5f, 0f, 0f, 1f));
            Assert.That(FramePlanner.Plan(s, f), Is.EqualTo(FrameChange.Range | FrameChange.Matrices), "the Transform moved");
            Assert.That(s.objectToWorld.c3.x - before.c3.x, Is.EqualTo(5f));
            f.terrainSize = new Double2(50000.0, 50000.0);
            Assert.That(FramePlanner.Plan(s, f), Is.EqualTo(FrameChange.Range | FrameChange.Matrices), "Terrain Size");
            f.worldOffset = new Double3(-100.0, 0.0, 0.0);
            Assert.That(FramePlanner.Plan(s, f), Is.EqualTo(FrameChange.Range | FrameChange.Matrices), "ShiftOrigin");
            Assert.That(FramePlanner.Plan(s, f), Is.EqualTo(FrameChange.Range));
        }

        [Test]
        public void ADeepZoomSnapsTheOriginAndMovesTheOutputOffset()
        {
            var s = new FrameState();
            FramePlanner.Plan(s, Inputs(Wide, Settings()));
            Assert.That(s.outputOffset, Is.EqualTo(Double3.zero), "a wide view has no origin");
            FrameChange c = FramePlanner.Plan(s, Inputs(Deep, Settings()));
            Assert.That(c, Is.EqualTo(FrameChange.Range | FrameChange.RangeOrigin | FrameChange.TileLattice | FrameChange.Matrices), "the re-snap");
            Assert.That(s.origin, Is.EqualTo(RangeOrigin.For(Deep)));
            Assert.That(s.outputOffset, Is.EqualTo(RelativeSurface.ReferencePoint(Grid, s.origin)), "S(O), no noise keyword");
            Assert.That(FramePlanner.Plan(s, Inputs(Deep, Settings())), Is.EqualTo(FrameChange.Range), "steady, deep");
            FrameInputs noisy = Inputs(Deep, Settings());
            noisy.noiseKeywords = TerrainKeywords.Noise;
            Assert.That(FramePlanner.Plan(s, noisy), Is.EqualTo(FrameChange.Range | FrameChange.Matrices), "GT_NOISE adds p(O)");
            Assert.That(FramePlanner.Keywords(s, cache: false, snow: false), Is.EqualTo(FrameKeywords.RangeOrigin));
            Assert.That(FramePlanner.Keywords(s, cache: true, snow: true), Is.EqualTo(FrameKeywords.VertexCache | FrameKeywords.Snow), "the cache's kernels read the origin themselves");
        }

        [Test]
        public void WithTheLevelsEachCameraKeepsItsOriginAndTheCountIsSentOnce()
        {
            var s = new FrameState();
            FrameInputs a = Inputs(Wide, Settings(levels: true), camera: 1, groundX: 0.3), b = Inputs(Wide, Settings(levels: true), camera: 2, groundX: 0.4);
            Assert.That(FramePlanner.Plan(s, a), Is.EqualTo(FrameChange.Params | FrameChange.Matrices | FrameChange.Levels | FrameChange.LevelCount));
            RangeOrigin originA = s.origin;
            Assert.That(originA, Is.EqualTo(RangeOrigin.For(s.levelRanges[0])), "the finest level's origin on a 100 km terrain");
            // Each camera's origin has its own _OriginSurface (the levels' plain path): the block goes again.
            Assert.That(FramePlanner.Plan(s, b), Is.EqualTo(FrameChange.Params | FrameChange.Range | FrameChange.RangeOrigin | FrameChange.Matrices | FrameChange.Levels), "another camera's origin");
            Assert.That(FramePlanner.Plan(s, a), Is.EqualTo(FrameChange.Params | FrameChange.Range | FrameChange.RangeOrigin | FrameChange.Matrices | FrameChange.Levels), "back");
            Assert.That(s.origin, Is.EqualTo(originA), "camera 1 kept its origin");
            Assert.That(FramePlanner.Keywords(s, cache: false, snow: false), Is.EqualTo(FrameKeywords.Levels));
            s.Forget();   // the property block cleared
            Assert.That(FramePlanner.Plan(s, a), Is.EqualTo(FrameChange.Params | FrameChange.Matrices | FrameChange.Levels | FrameChange.LevelCount), "everything again");
        }

        /// <summary>
        /// Review finding: the levels' plain-path bound (<c>_NoiseOctaves.w</c>) was made only with the settings, but
        /// GT_NOISE is the material's: noise turned on later kept the no-noise bound, about 6x too small, so vertices
        /// 6x nearer took the plain path. The bound follows the keywords, and it is not made again when the origin moves.
        /// </summary>
        [Test]
        public void TheLevelsPlainPathBoundFollowsTheMaterialsNoise()
        {
            var s = new FrameState();
            FrameInputs plain = Inputs(Wide, Settings(levels: true));
            FramePlanner.Plan(s, plain);
            float quiet = s.parameters.noiseOctaves.w;
            Assert.That(quiet, Is.EqualTo(TerrainVertex.PlainPathError(Grid, s.parameters, TerrainKeywords.None)).And.GreaterThan(0f));
            FrameInputs noisy = plain;
            noisy.noiseKeywords = TerrainKeywords.Noise;
            Assert.That(FramePlanner.Plan(s, noisy) & FrameChange.Params, Is.EqualTo(FrameChange.Params), "the block with the new bound");
            Assert.That(s.parameters.noiseOctaves.w, Is.EqualTo(TerrainVertex.PlainPathError(Grid, s.parameters, TerrainKeywords.Noise)));
            Assert.That(s.parameters.noiseOctaves.w, Is.GreaterThan(2f * quiet), "noise widens the bound");
            Assert.That(FramePlanner.Plan(s, noisy), Is.EqualTo(FrameChange.Range | FrameChange.Levels), "steady: not made again");
        }

        /// <summary>
        /// Review finding: a Transform of scale 0 threw after the plan had marked the block as sent, so once
        /// the scale was fixed the terrain drew without its TerrainParams until a setting changed.
        /// </summary>
        [Test]
        public void AFrameWithoutMatricesIsToldOnceAndTheNextGoodFrameSendsEverything()
        {
            var s = new FrameState();
            FrameInputs flat = Inputs(Wide, Settings());
            flat.localToWorld = new Float4x4(Float4x4.identity.c0, new Float4(0f, 0f, 0f, 0f), Float4x4.identity.c2, Float4x4.identity.c3);
            Assert.That(FramePlanner.Plan(s, flat), Is.EqualTo(FrameChange.Error));
            Assert.That(s.error, Does.Contain("invertible"));
            Assert.That(FramePlanner.Plan(s, flat), Is.EqualTo(FrameChange.None), "told once");
            Assert.That(FramePlanner.Plan(s, Inputs(Wide, Settings())), Is.EqualTo(FrameChange.Params | FrameChange.Matrices | FrameChange.TileLattice));
            Assert.That(s.error, Is.Null);
            Assert.That(FramePlanner.Plan(s, Inputs(Wide, Settings())), Is.EqualTo(FrameChange.Range));
        }

        [Test]
        public void BadSettingsAreToldOnceAndNothingIsSentUntilFixed()
        {
            var s = new FrameState();
            FrameChange c = FramePlanner.Plan(s, Inputs(Wide, Settings(tiles: 7, levels: true)));
            Assert.That(c, Is.EqualTo(FrameChange.Error));
            Assert.That(s.error, Does.Contain("tiles (7) must be even"));
            Assert.That(FramePlanner.Plan(s, Inputs(Wide, Settings(tiles: 7, levels: true))), Is.EqualTo(FrameChange.None), "told once");
            FrameSettings bad = Settings();
            bad.noise.amplitude = float.NaN;
            Assert.That(FramePlanner.Plan(s, Inputs(Wide, bad)), Is.EqualTo(FrameChange.Error), "another message");
            Assert.That(s.error, Does.Contain("amplitude"));
            Assert.That(FramePlanner.Plan(s, Inputs(Wide, Settings())), Is.EqualTo(FrameChange.Params | FrameChange.Matrices | FrameChange.TileLattice), "fixed");
            Assert.That(s.error, Is.Null);
        }
    }
}
