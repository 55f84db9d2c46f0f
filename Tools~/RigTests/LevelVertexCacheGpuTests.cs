// The Horizon levels drawn from their vertex cache (Shaders/Cache/LevelVertexCacheKernels.hlsl,
// LodVertexSlots and LodCacheVertices after the factor kernels, as TerrainCache.compute compiles them
// with GT_LOD; the domain stage reading the records while _LodLevels.z = C): on lavapipe, at 100 km and
// 1,000 km from the feet. The kernels' first records are Core's layout (LevelVertexCache.TileFirstRecords
// over the camera's drawn tiles: culled tiles and tiles the camera's view culls take none); every
// record holds the vertex the domain stage draws at the kernel's point (its path for a tile without
// records), its position bit for bit (readback+lod+noise at a uniform factor, whose grid the
// readback indexes) and its packed normal within half a packing step; the cached picture is that
// domain stage's; and a buffer too small for the frame still draws it (the tiles past its end
// evaluate in the domain stage) and reports what the frame needed.
using System;
using System.Collections.Generic;
using System.IO;
using GregoryTerrain.Tests;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture, Parallelizable(ParallelScope.Self)]
    public class LevelVertexCacheGpuTests
    {
        const int Tiles = 8;
        const string Levels = "lod+noise", Readback = "readback+lod+noise", PatchIdView = "lod+noise+debug_patch_id";
        const int RecordFloats = LodFactorRecord.Stride / 4;
        string _work, _spirv;
        PatchGrid _grid;
        int _runs;

        [OneTimeSetUp]
        public void CompileShaders()
        {
            _work = ReadbackRun.PrepareWork("rigtests-level-vertex-cache");
            _spirv = ReadbackRun.CompileVariants(_work, Levels, Readback, PatchIdView);
            _grid = HardCaseGrids.Fitted();
        }

        LodScene Scene(double terrainMeters, int factor, int cacheRecords) =>
            new LodScene { Tiles = Tiles, Factor = factor, Width = 1920, Height = 1080, TerrainMeters = terrainMeters, KernelFactors = true, CacheRecords = cacheRecords }.Build(_grid);

        /// <summary>What one frame left: the factor records (binding 7), the vertex records (binding 8), the picture.</summary>
        sealed class Frame
        {
            public LodScene Scene;
            public HarnessRun Run;
            public float[] Factors;
            public uint[] Records;
            public RigPng Image;

            public Float4 Floats(int patch, int k) => new Float4(Factors[RecordFloats * patch + k], Factors[RecordFloats * patch + k + 1], Factors[RecordFloats * patch + k + 2], Factors[RecordFloats * patch + k + 3]);
            /// <summary>The patch's factors as the camera's hull draws them, rounded as the tessellator's integer partitioning does.</summary>
            public TileFactorSet IntegerFactors(int patch) { Float4 i = Floats(patch, 4); return VertexCache.IntegerFactors(new TileFactorSet(Floats(patch, 0), new Float2(i.x, i.y))); }
            public float FirstRecord(int patch) => Factors[RecordFloats * patch + 6];
            public bool CameraCulls(int patch) => Factors[RecordFloats * patch + 15] != 0f;
            /// <summary>The records the frame needed (LodVertexSlots writes them into draw patch 0's inside.w).</summary>
            public float RecordsNeeded => Factors[7];
            public long Triangles => Run.Long("stat", "clipping_invocations");
            public uint Word(long record, int k) => Records[4 * record + k];
        }

        Frame Draw(LodScene s, string variant, string name, params string[] extra)
        {
            string dir = Path.Combine(_work, (_runs++).ToString("D2") + "-" + name), v = Path.Combine(_spirv, Levels);
            s.Write(dir);
            var args = new List<string>(ReadbackRun.Stages(_spirv, variant));
            args.AddRange(s.HarnessArgs(dir));
            args.AddRange(s.KernelArgs(Path.Combine(v, "lod_pieces.spv"), Path.Combine(v, "lod_seams.spv")));
            if (s.CacheRecords > 0) args.AddRange(s.CacheKernelArgs(Path.Combine(v, "lod_slots.spv"), Path.Combine(v, "lod_vertices.spv")));
            string factors = Path.Combine(dir, "factors.f32"), records = Path.Combine(dir, "records.u32"), png = Path.Combine(dir, "image.png");
            args.AddRange(new[] { "--width", "192", "--height", "108", "--device", "llvmpipe", "--stats", "--png", png,
                                  "--dump-storage", "7:" + factors, "--dump-storage", "8:" + records });
            args.AddRange(extra);
            var f = new Frame { Scene = s, Run = HarnessRun.Harness(args.ToArray()) };
            f.Run.AssertSucceeded();
            f.Factors = ReadbackRun.ReadFloats(factors);
            f.Records = ReadbackRun.ReadUints(records);
            f.Image = RigPng.Read(png);
            return f;
        }

        /// <summary>The levels at uniform factor F through the readback variant: 12 floats a vertex on the (F+1)^2 grid of each draw patch.</summary>
        float[] ReadbackDraw(LodScene s, int factor, string name)
        {
            string dir = Path.Combine(_work, (_runs++).ToString("D2") + "-" + name), rb = Path.Combine(dir, "readback.f32");
            s.Write(dir);
            string v = Path.Combine(_spirv, Levels);
            var args = new List<string>(ReadbackRun.Stages(_spirv, Readback));
            args.AddRange(s.HarnessArgs(dir));
            args.AddRange(s.KernelArgs(Path.Combine(v, "lod_pieces.spv"), Path.Combine(v, "lod_seams.spv")));
            if (s.CacheRecords > 0) args.AddRange(s.CacheKernelArgs(Path.Combine(v, "lod_slots.spv"), Path.Combine(v, "lod_vertices.spv")));
            args.AddRange(new[] { "--width", "192", "--height", "108", "--device", "llvmpipe", "--readback", rb, "--readback-floats", (12L * s.Patches * (factor + 1) * (factor + 1)).ToString() });
            HarnessRun.Harness(args.ToArray()).AssertSucceeded();
            return ReadbackRun.ReadFloats(rb);
        }

        /// <summary>
        /// Core's float mirror of the precise path's height at draw patch p's tess (s, t) with the octave
        /// sum cut after <paramref name="octaves"/> (OctaveNoise.Relative at that count), terrain units:
        /// what lavapipe's lone last vertex of a tile outputs (its noise loop stops after octave 0).
        /// </summary>
        static float PreciseHeightAtOctaves(LodScene scene, int patch, float s, float t, float octaves)
        {
            int level = LodTiles.LevelOfPatch(patch, scene.Tiles), slot = LodTiles.SlotOfPatch(patch, scene.Tiles);
            var r = new Float4(scene.Tail[4 + 4 * level], scene.Tail[5 + 4 * level], scene.Tail[6 + 4 * level], scene.Tail[7 + 4 * level]);
            Float4 originF = scene.Inputs.Params.rangeOrigin;
            TerrainPoint q = RangeMapping.ToTerrainPoint(r, originF, scene.Tiles, slot % scene.Tiles, slot / scene.Tiles, s, t);
            Float3 surface = TerrainVertex.OutputSurfacePosition(scene.Inputs, TerrainVertex.EvaluateSurfaceAt(scene.Inputs, q), TerrainKeywords.Noise);
            TerrainPoint origin = RelativeSurface.OriginPoint(originF);
            return surface.z + OctaveNoise.Relative(q, origin, RelativeSurface.Difference(q, origin), scene.Inputs.NoiseSettingsStruct(), octaves, out _, TerrainKeywords.Noise);
        }

        /// <summary>
        /// Today's path (no cache: the tessellator's own coordinates) against the kernel's points (the
        /// cache on, its buffer holding no tile), at a uniform F = 8 whose k / 8 are exact in the
        /// tessellator's fixed point: every vertex bit for bit, except on lavapipe the tile's centre
        /// (F/2, F/2). That vertex is the last of the tile's (F+1)^2 = 81 = 10 x 8 + 1, which llvmpipe
        /// runs alone in its last 8-lane batch of the domain stage, and there OctaveNoiseRelative's
        /// [loop] stops after octave 0: its height is Core's with one octave (to 1e-8, a few float steps
        /// of heights up to 0.03 units), x and z, q and the count it computed (6) are right; in one
        /// level its x and z come out 0 instead. An NVIDIA H200 reads back both
        /// paths bit-identical, the centre at every octave (Tools~/rig/README.md, "lavapipe's lone
        /// domain-stage vertex"). Any other difference, or a centre unlike that signature, fails.
        /// </summary>
        [TestCase(1e5)]
        [TestCase(1e6)]
        public void TodaysPathIsTheKernelPointsButForLavapipesLoneCentreVertex(double terrainMeters)
        {
            const int F = 8, Centre = F / 2 * (F + 1) + F / 2;
            int perTile = (F + 1) * (F + 1);
            LodScene today = Scene(terrainMeters, F, 0), points = Scene(terrainMeters, F, DomainStageRecords);
            float[] a = ReadbackDraw(today, F, "today-uniform" + terrainMeters.ToString("0")), b = ReadbackDraw(points, F, "points-uniform" + terrainMeters.ToString("0"));
            int drawn = 0, other = 0, lone = 0, zeroed = 0, unlike = 0;
            double worstLone = 0;
            string first = null;
            for (int p = 0; p < today.Patches; p++)
                for (int k = 0; k < perTile; k++)
                {
                    int o = 12 * (p * perTile + k);
                    if (!float.IsFinite(a[o])) continue;
                    drawn++;
                    bool xz = a[o] == b[o] && a[o + 2] == b[o + 2], y = a[o + 1] == b[o + 1];
                    if (xz && y) continue;
                    if (k == Centre && a[o] == 0f && a[o + 2] == 0f) { zeroed++; continue; }
                    if (k != Centre || !xz) { other++; first ??= $"patch {p} vertex {k}: today ({a[o]}, {a[o + 1]}, {a[o + 2]}), kernel's point ({b[o]}, {b[o + 1]}, {b[o + 2]})"; continue; }
                    lone++;
                    float oneOctave = PreciseHeightAtOctaves(today, p, 0.5f, 0.5f, 1f);
                    double d = Math.Abs(a[o + 1] - oneOctave);
                    worstLone = Math.Max(worstLone, d);
                    if (d > 1e-8) { unlike++; first ??= $"patch {p} centre: today's height {a[o + 1]}, Core's at one octave {oneOctave}"; }
                }
            TestContext.Out.WriteLine($"levels' today vs kernel points, {terrainMeters / 1000:0} km, F = {F}: {drawn} vertices, {other} differ elsewhere than the centre, {lone} centres at one octave and {zeroed} with x = z = 0 (lavapipe's lone vertex), largest |height - Core's at one octave| {worstLone:G3}{(first == null ? "" : "; first " + first)}");
            Assert.That(drawn, Is.GreaterThan(10000));
            Assert.That(other, Is.EqualTo(0), first);
            Assert.That(unlike, Is.EqualTo(0), first);
        }

        /// <summary>
        /// Core's layout of the frame (<see cref="LevelVertexCache.TileFirstRecords"/> over the tiles the
        /// camera draws) against the kernels' first records, a block ending past the buffer's C records
        /// taking none. Returns the records the frame needs.
        /// </summary>
        static long AssertFirstRecordsAreCores(Frame f, out int withRecords, out int cameraCulled)
        {
            int patches = f.Scene.Patches;
            var sets = new TileFactorSet[patches];
            cameraCulled = 0;
            for (int p = 0; p < patches; p++)
            {
                sets[p] = f.CameraCulls(p) ? TileFactors.CulledTileFactors() : f.IntegerFactors(p);
                if (f.CameraCulls(p) && !f.IntegerFactors(p).IsCulled) cameraCulled++;
            }
            var first = new long[patches];
            long total = LevelVertexCache.TileFirstRecords(sets, first);
            withRecords = 0;
            string wrong = null;
            int wrongCount = 0;
            for (int p = 0; p < patches; p++)
            {
                int slots = LevelVertexCache.TileSlots(sets[p]);
                float expected = slots > 0 && first[p] + slots <= f.Scene.CacheRecords ? first[p] : -1f;
                if (expected >= 0f) withRecords++;
                if (f.FirstRecord(p) != expected) { wrongCount++; wrong ??= $"patch {p} ({sets[p]}): first record {f.FirstRecord(p)}, Core's {expected}"; }
            }
            Assert.That(wrongCount, Is.EqualTo(0), wrong);
            Assert.That(f.RecordsNeeded, Is.EqualTo((float)total), "the records the frame needed, as reported to the renderer");
            return total;
        }

        /// <summary>
        /// At a uniform factor (the readback's grid), every record holds the vertex the domain stage
        /// draws without the cache: the position's bits, and the packed normal within half a step of
        /// the domain stage's (PackCachedVaryings; the fragment reads the packed one either way).
        /// Tiles inside the finer level take no records.
        /// </summary>
        /// <summary>
        /// C for the domain stage's own draw: the cache on, its buffer too short for any tile, so every
        /// vertex is evaluated in the domain stage at the point the kernel uses (LevelVertexCachePointTess),
        /// the path of the tiles past the buffer's end and off the camera's screen.
        /// </summary>
        const int DomainStageRecords = 1;
        [TestCase(1e5)]
        [TestCase(1e6)]
        public void RecordsHoldTheDomainStagesVerticesBitForBit(double terrainMeters)
        {
            const int F = 8;
            LodScene plain = Scene(terrainMeters, F, DomainStageRecords);
            int perTile = (F + 1) * (F + 1);
            float[] domain = ReadbackDraw(plain, F, "readback" + terrainMeters.ToString("0"));

            Frame c = Draw(Scene(terrainMeters, F, plain.Patches * VertexCache.SlotsPerTile(F)), Levels, "uniform" + terrainMeters.ToString("0"));
            long total = AssertFirstRecordsAreCores(c, out int withRecords, out int cameraCulled);
            int compared = 0, differ = 0, culled = 0;
            double maxNormal = 0;
            string first = null;
            for (int p = 0; p < c.Scene.Patches; p++)
            {
                TileFactorSet f = c.IntegerFactors(p);
                if (f.IsCulled) { culled++; continue; }
                long firstRecord = (long)c.FirstRecord(p);
                foreach (var (tess, slot) in VertexCache.TilePoints(f, LevelVertexCache.TileFactorLimit(f)))
                {
                    int o = 12 * (p * perTile + (int)MathF.Round(tess.y * F) * (F + 1) + (int)MathF.Round(tess.x * F));
                    long r = firstRecord + slot;
                    bool same = true;
                    for (int k = 0; k < 3; k++) same &= c.Word(r, k) == BitConverter.SingleToUInt32Bits(domain[o + k]);
                    if (!same) { differ++; first ??= $"patch {p} tess {tess}: record ({ReadbackRun.FloatOfBits(c.Word(r, 0))}, {ReadbackRun.FloatOfBits(c.Word(r, 1))}, {ReadbackRun.FloatOfBits(c.Word(r, 2))}), domain stage ({domain[o]}, {domain[o + 1]}, {domain[o + 2]})"; }
                    Float2 e = NormalEncoding.LambertEncodeNormal(new Float3(domain[o + 4], domain[o + 5], domain[o + 6]));
                    Float3 cached = VertexCache.UnpackCachedVaryings(c.Word(r, 3));
                    maxNormal = Math.Max(maxNormal, Math.Max(Math.Abs(cached.x - e.x), Math.Abs(cached.y - e.y)));
                    compared++;
                }
            }
            TestContext.Out.WriteLine($"levels' cache, {terrainMeters / 1000:0} km, F = {F}: {c.Scene.Patches} patches, {culled} culled (no records), {withRecords} with records, {total} records; {compared} vertices against the domain stage's: {differ} positions differ{(first == null ? "" : "; first " + first)}; encoded normal {maxNormal:G3} (half step {1.0 / 1023:G3})");
            Assert.That(culled, Is.GreaterThan(0), "tiles inside the finer level");
            Assert.That(cameraCulled, Is.EqualTo(0), "a uniform factor culls no tile in the kernels, as the hull culls none");
            Assert.That(withRecords, Is.EqualTo(c.Scene.Patches - culled));
            Assert.That(compared, Is.GreaterThan(1000));
            Assert.That(differ, Is.EqualTo(0), first);
            Assert.That(maxNormal, Is.LessThan(1.0 / 1023 + 1e-4));
        }

        /// <summary>
        /// At the adaptive factors (1 px), the levels drawn from the cache show the picture of the
        /// domain stage evaluating every vertex itself at the same points, with its triangles; tiles
        /// the camera's view culls take no records; and a buffer holding half the frame's records draws
        /// the same picture (the tiles past its end evaluate in the domain stage) and reports what the
        /// frame needed. Today's path (no cache: the tessellator's own coordinates) is printed beside.
        /// </summary>
        [TestCase(1e5)]
        [TestCase(1e6)]
        public void CachedDrawShowsTheDomainStagesPictureEvenWhenTheBufferIsShort(double terrainMeters)
        {
            string km = terrainMeters.ToString("0");
            Frame today = Draw(Scene(terrainMeters, 0, 0), Levels, "today" + km);
            Frame domain = Draw(Scene(terrainMeters, 0, DomainStageRecords), Levels, "domain" + km);
            Frame full = Draw(Scene(terrainMeters, 0, 1 << 22), Levels, "cached" + km);
            long needed = AssertFirstRecordsAreCores(full, out int withRecords, out int cameraCulled);
            Frame half = Draw(Scene(terrainMeters, 0, (int)(needed / 2)), Levels, "half" + km);
            AssertFirstRecordsAreCores(half, out int halfWithRecords, out _);
            AssertFirstRecordsAreCores(domain, out int domainWithRecords, out _);
            // One 8-bit step: the domain stage's own normal is not packed (PackCachedVaryings moves a lit
            // colour by less than half a step, which can round a channel the other way).
            int fullDiffers = full.Image.PixelsDifferingFrom(domain.Image, 1), halfDiffers = half.Image.PixelsDifferingFrom(full.Image, 1);
            int todayDiffers = full.Image.PixelsDifferingFrom(today.Image, 8);
            TestContext.Out.WriteLine($"levels' cache, {terrainMeters / 1000:0} km, adaptive: {needed} records ({needed * 16 / 1e6:0.0} MB), {withRecords} tiles with records, {cameraCulled} culled by the camera's view only; triangles {domain.Triangles} domain stage, {full.Triangles} cached, {half.Triangles} half buffer ({halfWithRecords} tiles with records), {today.Triangles} today's path; pixels differing by > 1/255: cached vs domain stage {fullDiffers}, half buffer vs cached {halfDiffers}; cached vs today's path by > 8/255: {todayDiffers} of {full.Image.Width * full.Image.Height}");
            Assert.That(domainWithRecords, Is.EqualTo(0), "a one-record buffer holds no tile: the domain stage draws every vertex");
            Assert.That(withRecords, Is.GreaterThan(Tiles * Tiles), "tiles of several levels drawn from records");
            Assert.That(cameraCulled, Is.GreaterThan(0), "tiles off the camera's screen take no records");
            Assert.That(halfWithRecords, Is.GreaterThan(0).And.LessThan(withRecords), "half the buffer: some tiles from records, the rest in the domain stage");
            Assert.That(full.Triangles, Is.EqualTo(domain.Triangles));
            Assert.That(half.Triangles, Is.EqualTo(domain.Triangles));
            Assert.That(today.Triangles, Is.EqualTo(domain.Triangles));
            Assert.That(fullDiffers, Is.EqualTo(0), "the cached picture is the domain stage's");
            Assert.That(halfDiffers, Is.EqualTo(0), "the tiles past the buffer's end draw as if cached");
        }

        /// <summary>
        /// The Patch Id debug view shows the same colours from the cache as from the domain stage at the
        /// same points: a record holds no patch index, so the domain stage finds it at the kernel's point.
        /// </summary>
        [Test]
        public void ThePatchIdViewFromTheCacheIsTheDomainStages()
        {
            Frame domain = Draw(Scene(1e5, 0, DomainStageRecords), PatchIdView, "patch-id-domain");
            Frame cached = Draw(Scene(1e5, 0, 1 << 22), PatchIdView, "patch-id-cached");
            AssertFirstRecordsAreCores(cached, out int withRecords, out _);
            int differs = cached.Image.PixelsDifferingFrom(domain.Image, 1);
            TestContext.Out.WriteLine($"Patch Id view, 100 km: {withRecords} tiles with records; pixels differing by > 1/255 from the domain stage's: {differs} of {cached.Image.Width * cached.Image.Height}");
            Assert.That(withRecords, Is.GreaterThan(Tiles * Tiles), "tiles of several levels drawn from records");
            Assert.That(differs, Is.EqualTo(0), "every cached vertex carries its own patch's colour");
        }
    }
}
