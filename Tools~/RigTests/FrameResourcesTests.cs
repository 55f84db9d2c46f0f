using System;
using NUnit.Framework;
using GregoryTerrain.Tests;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// The rules by which the renderer makes its GPU objects and draw material again (Core's
    /// <see cref="FrameResources"/> and the bindings <see cref="FrameState"/> remembers): each names
    /// what a Unity-side memo field of the renderer used to decide, so they run in dotnet test.
    /// </summary>
    [TestFixture]
    public class FrameResourcesTests
    {
        static readonly GridVersionKey GridV1 = new GridVersionKey(101, 1), GridV2 = new GridVersionKey(101, 2), OtherGrid = new GridVersionKey(202, 1);

        [Test]
        public void AGridIsUploadedOnceAndAgainOnANewVersionOrAnotherGrid()
        {
            var r = new FrameResources();
            Assert.That(r.Upload(GridV1, buffersHeld: false), Is.EqualTo(UploadAction.Upload));
            r.Uploaded(GridV1, 0f, 1f);
            Assert.That(r.Upload(GridV1, buffersHeld: true), Is.EqualTo(UploadAction.Keep));
            Assert.That(r.Upload(GridV1, buffersHeld: false), Is.EqualTo(UploadAction.Upload), "buffers freed: upload again");
            Assert.That(r.Upload(GridV2, buffersHeld: true), Is.EqualTo(UploadAction.Upload));
            Assert.That(r.Upload(OtherGrid, buffersHeld: true), Is.EqualTo(UploadAction.Upload));
            Assert.That(r.HeldGrid, Is.EqualTo(GridV1), "the held version, for the patches edited since");
            r.Released();
            Assert.That(r.Upload(GridV1, buffersHeld: true), Is.EqualTo(UploadAction.Upload), "released: nothing is held");
        }

        [Test]
        public void AFailedUploadIsNotRetriedUntilTheVersionChanges()
        {
            var r = new FrameResources();
            r.UploadFailed(GridV1);
            Assert.That(r.Upload(GridV1, false), Is.EqualTo(UploadAction.Skip), "every camera of every frame would log it again");
            r.Released();   // the buffers freed (the grid field set to another asset and back): still known bad
            Assert.That(r.Upload(GridV1, false), Is.EqualTo(UploadAction.Skip));
            Assert.That(r.Upload(GridV2, false), Is.EqualTo(UploadAction.Upload), "the fixed version is tried");
            Assert.That(r.Upload(OtherGrid, false), Is.EqualTo(UploadAction.Upload));
            r.Uploaded(GridV2, 0f, 1f);
            Assert.That(r.Upload(GridV1, false), Is.EqualTo(UploadAction.Upload), "an upload forgets the failure");
        }

        /// <summary>The draw's bounds hold the grid: a whole upload sets the height range, an edit only widens it.</summary>
        [Test]
        public void AnEditWidensTheGridsHeightRangeAndAWholeUploadSetsIt()
        {
            var r = new FrameResources();
            r.Uploaded(GridV1, -5f, 5f);
            Assert.That((r.GridMinZ, r.GridMaxZ), Is.EqualTo((-5f, 5f)));
            GregoryPatch edited = EditedGrid.Patches[0];
            float lo = float.MaxValue, hi = float.MinValue;
            foreach (Double3 c in edited.Points) { lo = Math.Min(lo, (float)c.z); hi = Math.Max(hi, (float)c.z); }
            Assert.That(lo > -5f && hi < 5f && hi > lo, "the edited patch lies inside the first range");
            r.PatchesUploaded(GridV2, EditedGrid, new[] { 0 });
            Assert.That((r.GridMinZ, r.GridMaxZ), Is.EqualTo((-5f, 5f)), "an edit inside the range keeps it: other patches may still reach it");
            Assert.That(r.HeldGrid, Is.EqualTo(GridV2));
            float mid = 0.5f * (lo + hi);
            r.Uploaded(GridV1, mid, mid);
            r.PatchesUploaded(GridV2, EditedGrid, new[] { 0 });
            Assert.That((r.GridMinZ, r.GridMaxZ), Is.EqualTo((lo, hi)), "the edited patch's points widen the range both ways");
            r.Uploaded(OtherGrid, 0.25f, 0.5f);
            Assert.That((r.GridMinZ, r.GridMaxZ), Is.EqualTo((0.25f, 0.5f)), "a whole upload tightens it");
        }

        static readonly PatchGrid EditedGrid = HardCaseGrids.Fitted(3, 3, seed: 2, samples: 17);

        [Test]
        public void TheFallbackIndexGridIsBuiltOncePerFactor()
        {
            var r = new FrameResources();
            Assert.That(r.RebuildFallbackIndices(16, held: false), Is.True);
            Assert.That(r.RebuildFallbackIndices(16, held: true), Is.False);
            Assert.That(r.RebuildFallbackIndices(8, held: true), Is.True);
            Assert.That(r.RebuildFallbackIndices(8, held: false), Is.True, "released elsewhere: build again");
            r.Released();
            Assert.That(r.RebuildFallbackIndices(8, held: true), Is.True);
        }

        [Test]
        public void TheDrawModeIsReadAgainWhenWhatUnityPicksTheSubShaderByChanges()
        {
            var r = new FrameResources();
            var key = new DrawModeKey(1, 2, 600, 600, 0);
            Assert.That(r.TryDrawMode(key, out _), Is.False);
            r.DrawModeRead(key, fallback: true);
            Assert.That(r.TryDrawMode(key, out bool fallback), Is.True);
            Assert.That(fallback, Is.True);
            foreach (DrawModeKey other in new[]
                     { new DrawModeKey(9, 2, 600, 600, 0), new DrawModeKey(1, 9, 600, 600, 0), new DrawModeKey(1, 2, 100, 600, 0),
                       new DrawModeKey(1, 2, 600, 100, 0), new DrawModeKey(1, 2, 600, 600, 7) })
                Assert.That(r.TryDrawMode(other, out _), Is.False, "material, shader, global LOD, shader LOD, pipeline");
            r.Released();
            Assert.That(r.TryDrawMode(key, out _), Is.False, "the buffers freed: the tag read again");
            Assert.That(r.LastDrawFallback, Is.True, "the last mode read stands until then");
        }

        [Test]
        public void AMaterialEditRecopiesTheDrawMaterialOnce()
        {
            var r = new FrameResources();
            var asset = new MaterialSourceKey(5, crc: 1000, keywords: 1);
            Assert.That(r.CopyStale(asset, frame: 1), Is.True, "never copied");
            r.Copied(asset);
            Assert.That(r.MaterialComparedThisFrame(5, 1), Is.True, "the frame's other cameras reuse the comparison");
            Assert.That(r.MaterialComparedThisFrame(5, 2), Is.False);
            Assert.That(r.MaterialComparedThisFrame(6, 1), Is.False, "another asset");
            Assert.That(r.CopyStale(asset, frame: 2), Is.False, "steady: nothing copied");
            var edited = new MaterialSourceKey(5, crc: 2000, keywords: 1);
            Assert.That(r.CopyStale(edited, frame: 3), Is.True, "a property edit");
            r.Copied(edited);
            Assert.That(r.CopyStale(edited, frame: 4), Is.False, "copied once");
            Assert.That(r.CopyStale(new MaterialSourceKey(5, 2000, 3), 5), Is.True, "a package keyword toggled (whatever the CRC covers)");
            Assert.That(r.CopyStale(new MaterialSourceKey(6, 2000, 1), 5), Is.True, "another asset");
        }

        [Test]
        public void InEditModeEveryCallComparesTheMaterial()
        {
            var r = new FrameResources();
            var asset = new MaterialSourceKey(5, 1000, 1);
            r.CopyStale(asset, frame: -1);
            r.Copied(asset);
            Assert.That(r.MaterialComparedThisFrame(5, -1), Is.False, "an inspector edit shows at once; frameCount does not advance between repaints");
            r.CopyStale(asset, frame: 7);
            r.CopyReleased();
            Assert.That(r.MaterialComparedThisFrame(5, 7), Is.False, "a new copy is compared");
            Assert.That(r.CopyStale(asset, 7), Is.True);
        }

        [Test]
        public void TheCacheSizeCheckIsMadeOncePerSettingAndToldOnce()
        {
            var r = new FrameResources();
            long tiny = 1024;
            string error = r.CheckCacheFits(16, 64, false, tiny, out bool fresh);
            Assert.That(error, Does.StartWith("vertexEvaluation = ComputeCache: "));
            Assert.That(fresh, Is.True);
            Assert.That(r.CheckCacheFits(16, 64, false, tiny, out fresh), Is.EqualTo(error));
            Assert.That(fresh, Is.False, "logged once, not every camera of every frame");
            Assert.That(r.CacheError, Is.EqualTo(error));
            Assert.That(r.CheckCacheFits(16, 64, false, 0, out fresh), Is.Null, "0: the device tells no limit, GpuLayout's 2 GiB stands");
            Assert.That(fresh, Is.True);
            r.CheckCacheFits(16, 64, false, tiny, out _);
            r.CacheNotUsed(null);
            Assert.That(r.CacheError, Is.Null, "the cache not used: no verdict stands");
            r.CheckCacheFits(16, 64, false, tiny, out fresh);
            Assert.That(fresh, Is.True, "checked afresh when it is used again");
        }

        [Test]
        public void AFallbackReasonIsToldOncePerReason()
        {
            var r = new FrameResources();
            Assert.That(r.CacheNotUsed("no compute shaders"), Is.True);
            Assert.That(r.CacheNotUsed("no compute shaders"), Is.False);
            Assert.That(r.CacheFallbackReason, Is.EqualTo("no compute shaders"));
            Assert.That(r.CacheNotUsed("no LOD camera"), Is.True);
            r.CacheUsed();
            Assert.That(r.CacheFallbackReason, Is.Null);
            Assert.That(r.CacheNotUsed("no LOD camera"), Is.True, "told again after the cache ran");
            Assert.That(r.CacheNotUsed(null), Is.False);
            Assert.That(r.CacheFallbackReason, Is.Null, "chosen off: no reason");
        }

        /// <summary>
        /// The levels' factor kernels: the hull reads their records only in a frame that dispatched them
        /// (LevelKernelsUsed); a reason they cannot run is warned once, again after they ran; a release
        /// turns the hull's switch off.
        /// </summary>
        [Test]
        public void TheLevelKernelsSwitchAndTheirReasonFollowTheLastVerdict()
        {
            var r = new FrameResources();
            Assert.That(r.UsesLevelKernels, Is.False, "nothing dispatched yet");
            r.LevelKernelsUsed();
            Assert.That(r.UsesLevelKernels, Is.True);
            Assert.That(r.LevelKernelsNotUsed("no kernels"), Is.True);
            Assert.That(r.UsesLevelKernels, Is.False, "the hull computes the factors again");
            Assert.That(r.LevelKernelsNotUsed("no kernels"), Is.False, "warned once");
            r.LevelKernelsUsed();
            Assert.That(r.LevelKernelsNotUsed("no kernels"), Is.True, "warned again after the kernels ran");
            Assert.That(r.LevelKernelsNotUsed(null), Is.False, "levels off: nothing to warn");
            r.LevelKernelsUsed();
            r.Released();
            Assert.That(r.UsesLevelKernels, Is.False, "a release drops the buffer the hull would read");
        }

        /// <summary>The draw reads the cache only once a dispatch filled it this frame; every other verdict turns it off.</summary>
        [Test]
        public void TheCacheIsDrawnOnlyWhenUsedAndFilled()
        {
            var r = new FrameResources();
            Assert.That(r.UsesCache, Is.False);
            r.CacheUsed();
            Assert.That(r.UsesCache, Is.False, "not filled yet: GT_VERTEX_CACHE would read empty buffers");
            Assert.That(r.CacheFilled(true), Is.True);
            Assert.That(r.UsesCache, Is.True);
            r.CacheUsed();
            Assert.That(r.UsesCache, Is.False, "a new frame: on again only once filled (the size check may fail first)");
            Assert.That(r.CacheFilled(false), Is.False, "an LOD camera without pixels: nothing evaluated");
            Assert.That(r.UsesCache, Is.False);
            r.CacheUsed(); r.CacheFilled(true);
            r.CacheNotUsed("no LOD camera");
            Assert.That(r.UsesCache, Is.False, "the domain stage draws");
            r.CacheUsed(); r.CacheFilled(true);
            r.CacheNotUsed(null);
            Assert.That(r.UsesCache, Is.False, "chosen off");
            r.CacheUsed(); r.CacheFilled(true);
            r.Released();
            Assert.That(r.UsesCache, Is.False, "the buffers freed");
        }

        static readonly PatchGrid Grid = HardCaseGrids.WithLines(new[] { 0.0, 0.5, 1.0 }, new[] { 0.0, 0.5, 1.0 });
        static readonly NoiseSettings Noise = new NoiseSettings(0.02f, 16f, 2f, 2f, 6);

        [Test]
        public void AQueryIsRebuiltWhenItsGridVersionNoiseOrKeywordsChangeAndCatchesUpOnEdits()
        {
            var r = new FrameResources();
            var v1 = new QuerySourceKey(GridV1, Noise, TerrainKeywords.Noise);
            Assert.That(r.TryQuery(v1, out _), Is.False, "never built");
            var q = new TerrainSurfaceQuery(Grid, Noise);
            r.QueryBuilt(v1, q);
            Assert.That(r.TryQuery(v1, out TerrainSurfaceQuery held), Is.True);
            Assert.That(held, Is.SameAs(q));
            Assert.That(r.TryQuery(new QuerySourceKey(GridV1, null, TerrainKeywords.None), out _), Is.False, "GT_NOISE off");
            Assert.That(r.TryQuery(new QuerySourceKey(GridV1, Noise, TerrainKeywords.Noise | TerrainKeywords.NoiseTable), out _), Is.False, "tiled noise");
            Assert.That(r.TryQuery(new QuerySourceKey(GridV1, new NoiseSettings(0.02f, 16f, 2f, 2f, 5), TerrainKeywords.Noise), out _), Is.False);

            var v2 = new QuerySourceKey(GridV2, Noise, TerrainKeywords.Noise);
            Assert.That(r.TryQuery(v2, out _), Is.False, "an edit");
            Assert.That(r.QueryToCatchUp(v2, out int version), Is.SameAs(q), "same grid and noise: the edited patches only");
            Assert.That(version, Is.EqualTo(1));
            Assert.That(r.QueryToCatchUp(new QuerySourceKey(OtherGrid, Noise, TerrainKeywords.Noise), out _), Is.Null, "another grid: rebuilt");
            Assert.That(r.QueryToCatchUp(new QuerySourceKey(GridV2, null, TerrainKeywords.None), out _), Is.Null, "other noise: rebuilt");
        }

        [Test]
        public void AQueryThatFailedIsNotRebuiltUntilItsInputsChange()
        {
            var r = new FrameResources();
            var v1 = new QuerySourceKey(GridV1, null, TerrainKeywords.None);
            r.QueryBuilt(v1, null);
            Assert.That(r.TryQuery(v1, out TerrainSurfaceQuery q), Is.True, "the collider asks every frame: logged once per version");
            Assert.That(q, Is.Null);
            Assert.That(r.QueryToCatchUp(new QuerySourceKey(GridV2, null, TerrainKeywords.None), out _), Is.Null, "nothing to catch up from");
            r.Released();
            Assert.That(r.TryQuery(v1, out _), Is.True, "the query does not hang on the GPU buffers");
        }

        [Test]
        public void TheEstimatePacksTheGridOncePerGridAndUpload()
        {
            var r = new FrameResources();
            var p = new TerrainParams { gridSize = new Float4(Grid.Columns, Grid.Rows, 0f, 0f) };
            TerrainInputs first = r.EstimateInputs(Grid, p);
            p.range = new Float4(0.1f, 0.1f, 0.5f, 0.5f);
            TerrainInputs second = r.EstimateInputs(Grid, p);
            Assert.That(second.ControlPoints, Is.SameAs(first.ControlPoints), "same grid: not packed again");
            Assert.That(second.Params.range, Is.EqualTo(p.range), "the constants taken each time");
            r.Released();
            Assert.That(r.EstimateInputs(Grid, p).ControlPoints, Is.Not.SameAs(first.ControlPoints), "released: the CPU copy dropped");
            PatchGrid other = HardCaseGrids.WithLines(new[] { 0.0, 1.0 }, new[] { 0.0, 1.0 });
            var q = new TerrainParams { gridSize = new Float4(other.Columns, other.Rows, 0f, 0f) };
            Assert.That(r.EstimateInputs(other, q).ControlPoints, Is.Not.SameAs(second.ControlPoints), "another grid");
        }

        [Test]
        public void BindingsAreSetOnChangeAndAgainAfterTheBlockIsCleared()
        {
            var s = new FrameState();
            object table = new object(), depth = new object();
            var size = new Float3(256f, 256f, 0.01f);
            Assert.That(s.BindNoiseCells(null), Is.False, "no table: nothing read");
            Assert.That(s.BindNoiseCells(table), Is.True);
            Assert.That(s.BindNoiseCells(table), Is.False, "steady: not sent");
            Assert.That(s.BindSnow(depth, size), Is.True);
            Assert.That(s.BindSnow(depth, size), Is.False);
            Assert.That(s.BindSnow(depth, new Float3(256f, 256f, 0.02f)), Is.True, "a deeper cap");
            Assert.That(s.BindSnow(new object(), new Float3(256f, 256f, 0.02f)), Is.True, "a new depth buffer");
            s.Forget();
            Assert.That(s.BindNoiseCells(table), Is.True, "the block was cleared: bound again");
            Assert.That(s.BindSnow(depth, size), Is.True);
        }
    }
}
