// The vertex cache (GT_VERTEX_CACHE, internals.md "Vertex cache") on the GPU (lavapipe, through
// gt-harness's compute pre-pass): the kernels' records against Core's float path, the cached draw
// against the direct one, and the adaptive cache's factors and shared edges. They fail (never skip)
// when the harness, lavapipe, glslang or gt-cli is missing: `gt setup` provides them.
using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture, Parallelizable(ParallelScope.Self), Order(7)]
    public class VertexCacheGpuTests
    {
        const string Cached = "noise+height_color+vertex_cache";
        const string Direct = "noise+height_color";
        const string CachedPatchIdView = "debug_patch_id+vertex_cache", DirectPatchIdView = "debug_patch_id";
        // The domain-stage path's hull_const writing its factors (GT_FACTOR_READBACK), same noise.
        const string HullFactors = "factor_readback+noise";
        const TerrainKeywords Keywords = TerrainKeywords.Noise | TerrainKeywords.HeightColor;

        string _work, _spirv, _cli, _gridPath;
        PatchGrid _grid;

        [OneTimeSetUp]
        public void BuildGridAndShaders()
        {
            _work = ReadbackRun.PrepareWork("rigtests-vertexcache");
            _cli = ReadbackRun.Cli();
            _grid = ReadbackRun.DemoGrid(_work, out _gridPath);
            _spirv = ReadbackRun.CompileVariants(_work, Cached, Direct, HullFactors, CachedPatchIdView, DirectPatchIdView);
        }

        /// <summary>What one cached frame left in the two cache buffers.</summary>
        sealed class CacheFrame
        {
            public HarnessRun Run;
            public TerrainInputs Inputs;
            public float[] Factors, Cells;
            public uint[] Records;
            public int Tiles, Limit, Slots;

            // Float k of the tile's TileFactorRecord (edge, inside, slotsKey, cellKey).
            float Record(int tile, int k) => Factors[tile * TileFactorRecord.Stride / 4 + k];

            /// <summary>The key the tile's slots were last evaluated at (TileFactorRecord.slotsKey).</summary>
            public Float4 SlotsKey(int tile) => new Float4(Record(tile, 8), Record(tile, 9), Record(tile, 10), Record(tile, 11));

            public TileFactorSet FactorsOf(int tile) => ReadbackRun.CacheTileFactors(Factors, tile);

            public bool Culled(int tile) => Record(tile, 6) != 0f;

            /// <summary>The kernel (re)evaluated the tile's slots in the last frame.</summary>
            public bool Evaluated(int tile) => Record(tile, 7) != 0f;

            /// <summary>How the last frame decided the tile's cell factors (VertexCache.CellFactorsSampled, ...).</summary>
            public float CellFactorsWay(int tile) => Cells[tile * TileCellRecord.Stride / 4 + 6];   // inside.z

            /// <summary>uint4 part of the record at a slot of a tile, as <see cref="VertexCache.Record"/> lays it out (no snow: one part).</summary>
            public (uint x, uint y, uint z, uint w) Part(int tile, int slot, int part)
            {
                int o = 4 * (VertexCache.Uint4sPerRecord(false) * (tile * Slots + slot) + part);
                return (Records[o], Records[o + 1], Records[o + 2], Records[o + 3]);
            }

            /// <summary>The record's object-space position (its first three words' float bits).</summary>
            public Float3 PositionOS(int tile, int slot)
            {
                var r = Part(tile, slot, 0);
                return new Float3(ReadbackRun.FloatOfBits(r.x), ReadbackRun.FloatOfBits(r.y), ReadbackRun.FloatOfBits(r.z));
            }
        }

        /// <summary>
        /// Packs a scene with gt-cli (zoom-view camera) and draws one frame of the cached variant:
        /// both kernels, then the tile draw; dumps both cache buffers.
        /// </summary>
        CacheFrame DrawCached(string name, string range, int tiles, string[] tessArgs, int width, int height, float[] camera = null,
                              params string[] extra) => DrawCachedVariant(Cached, name, range, tiles, tessArgs, width, height, camera, extra);

        CacheFrame DrawCachedVariant(string variant, string name, string range, int tiles, string[] tessArgs, int width, int height,
                                     float[] camera, string[] extra)
        {
            string dir = Path.Combine(_work, name);
            var pack = new List<string> { "pack", "--grid", _gridPath, "--range", range, "--tiles", tiles.ToString(CultureInfo.InvariantCulture),
                                          "--width", width.ToString(CultureInfo.InvariantCulture), "--height", height.ToString(CultureInfo.InvariantCulture), "--out", dir };
            pack.AddRange(tessArgs);
            ReadbackRun.Exec(_cli, pack.ToArray(), null);
            if (camera != null) ReadbackRun.WriteFloats(Path.Combine(dir, "camera.f32"), camera);
            var p = ReadbackRun.ReadParams(Path.Combine(dir, "params.f32"));
            tiles = TileLattice.TilesAcross(p);   // M, or M + 1 with --anchor-at
            var frame = new CacheFrame { Tiles = tiles, Inputs = TerrainInputs.Create(_grid, p), Limit = VertexCache.FactorLimit(p.tess) };
            frame.Slots = VertexCache.SlotsPerTile(frame.Limit);
            string factors = Path.Combine(dir, "tile_factors.f32"), records = Path.Combine(dir, "vertex_cache.u32"), cells = Path.Combine(dir, "tile_cells.f32");
            var args = new List<string>(ReadbackRun.Stages(_spirv, variant));
            args.AddRange(new[]
            {
                "--buffers", dir, "--patches", (tiles * tiles).ToString(CultureInfo.InvariantCulture),
                "--width", width.ToString(CultureInfo.InvariantCulture), "--height", height.ToString(CultureInfo.InvariantCulture),
                "--device", "llvmpipe", "--stats", "--png", Path.Combine(dir, "image.png"),
            });
            args.AddRange(ReadbackRun.VertexCacheArgs(Path.Combine(_spirv, variant), tiles, frame.Limit, false, factors, records, cells));
            args.AddRange(extra);
            frame.Run = HarnessRun.Harness(args.ToArray());
            frame.Run.AssertSucceeded();
            frame.Factors = ReadbackRun.ReadFloats(factors);
            frame.Cells = ReadbackRun.ReadFloats(cells);
            frame.Records = ReadbackRun.ReadUints(records);
            Assert.That(frame.Factors.Length, Is.EqualTo(VertexCacheBudget.TileFactorsBytes(tiles) / 4), "factors and keys of every tile");
            Assert.That(frame.Cells.Length, Is.EqualTo(VertexCacheBudget.TileCellsBytes(tiles) / 4), "cell factors, inputs and samples of every tile");
            Assert.That(frame.Records.Length, Is.EqualTo(4 * VertexCache.Uint4sPerRecord(false) * tiles * tiles * frame.Slots));
            return frame;
        }

        /// <summary>
        /// Draws a DrawCached scene (its folder <paramref name="name"/>) through the domain-stage path
        /// with hull_const writing its factors (GT_FACTOR_READBACK): 2 float4 a tile (the factors, then
        /// culled in the third float of the second), read with <see cref="HullFactorsOf"/>.
        /// </summary>
        float[] DrawHullFactors(string name, int tiles, int width, int height, out HarnessRun run)
        {
            string dir = Path.Combine(_work, name), file = Path.Combine(dir, "hull_factors.f32");
            run = HarnessRun.Harness(ReadbackRun.Stages(_spirv, HullFactors).Concat(new[]
            {
                "--buffers", dir, "--patches", (tiles * tiles).ToString(CultureInfo.InvariantCulture),
                "--width", width.ToString(CultureInfo.InvariantCulture), "--height", height.ToString(CultureInfo.InvariantCulture),
                "--device", "llvmpipe", "--stats", "--readback", file, "--readback-floats", (8 * tiles * tiles).ToString(CultureInfo.InvariantCulture),
            }).ToArray());
            run.AssertSucceeded();
            return ReadbackRun.ReadFloats(file);
        }

        static TileFactorSet HullFactorsOf(float[] h, int tile) =>
            new TileFactorSet(new Float4(h[8 * tile], h[8 * tile + 1], h[8 * tile + 2], h[8 * tile + 3]), new Float2(h[8 * tile + 4], h[8 * tile + 5]));

        /// <summary>
        /// Every slot the kernel writes holds Core's float TerrainVertex at that point (position; the
        /// packed world normal and height weight within half a step of Core's, plus float error), and
        /// no other slot is touched.
        /// </summary>
        [Test]
        public void CacheHoldsTheCoreVertexInEverySlotTheKernelWrites()
        {
            // F = 31: 1,028 points a tile, more than two groups' 128 x 4, so three groups share each tile.
            CacheFrame f = DrawCached("uniform", "0.2,0.15,0.7,0.65", 4, new[] { "--factor", "31" }, 96, 64);
            Assert.That(VertexCache.GroupsPerTile(f.Limit), Is.EqualTo(3));
            double extent = ReadbackRun.TerrainExtent(_grid);
            double maxPos = 0, maxNormal = 0, maxWeight = 0;
            int compared = 0, stray = 0, sameWord = 0;
            for (int tile = 0; tile < f.Tiles * f.Tiles; tile++)
            {
                Assert.That(f.FactorsOf(tile), Is.EqualTo(VertexCache.IntegerFactors(new TileFactorSet(new Float4(31, 31, 31, 31), new Float2(31, 31)))), "tile " + tile);
                var written = new HashSet<int>();
                foreach (var (tess, slot) in VertexCache.TilePoints(f.FactorsOf(tile), f.Limit))
                {
                    written.Add(slot);
                    TerrainVertexOutput v = TerrainVertex.Evaluate(f.Inputs, tile, tess, Keywords);
                    uint[] core = VertexCache.Record(v, TerrainVertex.HeightWeight(v, f.Inputs, Keywords), false);
                    maxPos = Math.Max(maxPos, ReadbackRun.Distance(f.PositionOS(tile, slot), v.PositionOS) / extent);
                    // The encoded normal and the weight before packing (Core's), against the GPU's unpacked.
                    Float2 e = NormalEncoding.LambertEncodeNormal(v.NormalOS);
                    Float3 gpu = VertexCache.UnpackCachedVaryings(f.Part(tile, slot, 0).w);
                    maxNormal = Math.Max(maxNormal, Math.Max(Math.Abs(gpu.x - e.x), Math.Abs(gpu.y - e.y)));
                    maxWeight = Math.Max(maxWeight, Math.Abs(gpu.z - TerrainVertex.HeightWeight(v, f.Inputs, Keywords)));
                    if (f.Part(tile, slot, 0).w == core[3]) sameWord++;
                    compared++;
                }
                for (int slot = 0; slot < f.Slots; slot++)
                    if (!written.Contains(slot) && !f.Part(tile, slot, 0).Equals(default((uint, uint, uint, uint)))) stray++;
            }
            TestContext.Out.WriteLine("{0} cached vertices against Core: position {1:G3} of the extent, encoded normal {2:G3} (half step {3:G3}), height weight {4:G3} (half step {5:G3}); packed word equal to Core's in {6}",
                compared, maxPos, maxNormal, 1.0 / 1023, maxWeight, 0.5 / 1023, sameWord);
            Assert.That(compared, Is.EqualTo(16 * (30 * 30 + 4 * 32)), "4 x 4 tiles, 30 x 30 interior points and 4 edges of 32 at F = 31");
            Assert.That(stray, Is.EqualTo(0), "slots written that no point owns");
            Assert.That(maxPos, Is.LessThan(1e-5));
            // Half a step, plus the float difference of the unpacked value's inputs (1e-4 on the normal
            // and the colour noise before this change).
            Assert.That(maxNormal, Is.LessThan(1.0 / 1023 + 1e-4));
            Assert.That(maxWeight, Is.LessThan(0.5 / 1023 + 1e-4));
            Assert.That(sameWord, Is.GreaterThan(compared * 9 / 10), "most packed words are Core's exactly");
        }

        /// <summary>
        /// At an odd integer uniform factor, fractional_odd and integer partitioning make the same
        /// vertices, so the cached draw must show the direct draw's picture (the domain stage evaluates
        /// at the tessellator's fixed-point coordinates, the kernel at exact k / F: sub-pixel shifts).
        /// </summary>
        [Test]
        public void CachedDrawShowsTheDirectDrawsPicture()
        {
            CacheFrame cached = DrawCached("compare", "0,0,1,1", 8, new[] { "--factor", "7" }, 192, 128);
            string dir = Path.Combine(_work, "compare");
            string png = Path.Combine(dir, "direct.png");
            HarnessRun direct = HarnessRun.Harness(ReadbackRun.Stages(_spirv, Direct).Concat(new[]
            {
                "--buffers", dir, "--patches", "64", "--width", "192", "--height", "128", "--device", "llvmpipe", "--stats", "--png", png,
            }).ToArray());
            direct.AssertSucceeded();
            RigPng a = RigPng.Read(Path.Combine(dir, "image.png")), b = RigPng.Read(png);
            int differing = a.PixelsDifferingFrom(b, 8);
            long nonsky = direct.Long("image", "nonsky_pixels");
            TestContext.Out.WriteLine("cached vs direct: {0} of {1} pixels differ by more than 8/255; non-sky {2} vs {3}; triangles {4} vs {5}",
                differing, 192 * 128, cached.Run.Long("image", "nonsky_pixels"), nonsky,
                cached.Run.Long("stat", "clipping_invocations"), direct.Long("stat", "clipping_invocations"));
            Assert.That(nonsky, Is.GreaterThan(192 * 128 / 5), "the terrain fills the view");
            Assert.That(cached.Run.Long("stat", "clipping_invocations"), Is.EqualTo(direct.Long("stat", "clipping_invocations")), "same triangles");
            Assert.That(differing, Is.LessThan(192 * 128 / 200), "at most 0.5% of the pixels differ");
        }

        /// <summary>
        /// The Patch Id debug view over the cache: a record holds no patch index, so the domain stage
        /// finds it at the vertex's point, which must give the direct draw's colours (whole tiles and
        /// tiles the anchored range clips). Before: patch 0 on every cached vertex.
        /// </summary>
        [TestCase("0,0,1,1", null)]
        [TestCase("0.1,0.1,0.9,0.9", "0.155,0.135,0.955,0.935")]
        public void ThePatchIdViewOverTheCacheIsTheDirectDraws(string range, string anchor)
        {
            string name = anchor == null ? "patch-id" : "patch-id-anchored";
            string[] tess = anchor == null ? new[] { "--factor", "7" } : new[] { "--factor", "7", "--anchor-at", anchor };
            CacheFrame cached = DrawCachedVariant(CachedPatchIdView, name, range, 8, tess, 192, 128, null, Array.Empty<string>());
            string dir = Path.Combine(_work, name), png = Path.Combine(dir, "direct.png");
            HarnessRun direct = HarnessRun.Harness(ReadbackRun.Stages(_spirv, DirectPatchIdView).Concat(new[]
            {
                "--buffers", dir, "--patches", (cached.Tiles * cached.Tiles).ToString(CultureInfo.InvariantCulture),
                "--width", "192", "--height", "128", "--device", "llvmpipe", "--stats", "--png", png,
            }).ToArray());
            direct.AssertSucceeded();
            RigPng a = RigPng.Read(Path.Combine(dir, "image.png")), b = RigPng.Read(png);
            int differing = a.PixelsDifferingFrom(b, 8), colours = a.DistinctColours();
            TestContext.Out.WriteLine("Patch Id view, cached vs direct ({0}): {1} of {2} pixels differ by more than 8/255; {3} colours in the cached picture",
                                      name, differing, 192 * 128, colours);
            Assert.That(direct.Long("image", "nonsky_pixels"), Is.GreaterThan(192 * 128 / 5), "the terrain fills the view");
            Assert.That(colours, Is.GreaterThan(8), "many patches' colours in view");
            Assert.That(differing, Is.LessThan(192 * 128 / 200), "at most 0.5% of the pixels (patch borders moved by sub-pixel shifts) differ");
        }

        /// <summary>
        /// Two runs of the 8 x 8 tiles at uniform F = 7 that must end alike: the same picture, pixel
        /// for pixel, and the same cache. Returns the second run.
        /// </summary>
        CacheFrame AssertSamePictureAndCache(string nameA, string[] extraA, string nameB, string[] extraB)
        {
            CacheFrame a = DrawCached(nameA, "0,0,1,1", 8, new[] { "--factor", "7" }, 192, 128, null, extraA);
            CacheFrame b = DrawCached(nameB, "0,0,1,1", 8, new[] { "--factor", "7" }, 192, 128, null, extraB);
            RigPng pa = RigPng.Read(Path.Combine(_work, nameA, "image.png")), pb = RigPng.Read(Path.Combine(_work, nameB, "image.png"));
            Assert.That(pb.PixelsDifferingFrom(pa, 0), Is.EqualTo(0), nameB + " against " + nameA);
            Assert.That(b.Records, Is.EqualTo(a.Records), "the last frame's cache, " + nameB + " against " + nameA);
            Assert.That(b.Run.Long("image", "nonsky_pixels"), Is.GreaterThan(192 * 128 / 5));
            return b;
        }

        /// <summary>
        /// A frame where nothing changed reuses the cache (the renderer dispatches nothing then; the
        /// harness's --compute-once): later frames without the kernels draw the first frame's picture.
        /// </summary>
        [Test]
        public void FramesThatReuseTheCacheDrawTheSamePicture()
        {
            AssertSamePictureAndCache("every-frame", new[] { "--frames", "3" }, "compute-once", new[] { "--frames", "3", "--compute-once" });
        }

        /// <summary>
        /// Frames in flight (harness --in-flight 2: frames queued back to back, each slot its own
        /// TerrainParams and cache, ordered by timeline semaphores): with the range changing every
        /// frame, the last frame (slot 1, the copies) draws the picture and holds the cache that frames
        /// run one at a time end with. A slot reading the other's range or cache would differ.
        /// </summary>
        [Test]
        public void FramesInFlightEndWithThePictureAndCacheOfFramesOneAtATime()
        {
            string[] moving = { "--frames", "4", "--update-range-per-frame" };
            CacheFrame two = AssertSamePictureAndCache("one-at-a-time", moving, "in-flight", moving.Concat(new[] { "--in-flight", "2" }).ToArray());
            Assert.That(two.Run.Value("time", "in_flight"), Is.EqualTo(new[] { "2", "async_compute", "0" }));
        }

        /// <summary>
        /// --update-range-per-frame shifts the range in every frame but the last, which draws the
        /// inputs' own range: the run ends with the picture and cache of a single frame there.
        /// </summary>
        [Test]
        public void RangeMovingRunsEndAtTheirInputsRange()
        {
            AssertSamePictureAndCache("single-frame", new[] { "--frames", "1" }, "range-moving", new[] { "--frames", "5", "--update-range-per-frame" });
        }

        /// <summary>
        /// --compute-once with frames in flight: each slot's cache is built in its own first frame, so
        /// the fourth frame (slot 1) still draws the whole terrain.
        /// </summary>
        [Test]
        public void FramesInFlightBuildEachSlotsCacheOnce()
        {
            AssertSamePictureAndCache("every-frame-2", new[] { "--frames", "4" }, "in-flight-once", new[] { "--frames", "4", "--compute-once", "--in-flight", "2" });
        }

        /// <summary>
        /// The layout the kernels and the domain stage address (Shaders/Cache/VertexCache.hlsl, the sample
        /// count of TileFactors.hlsl) is Core's, run on lavapipe through VertexCacheLayoutProbe.hlsl:
        /// slots, groups and points a tile for every factor limit 1-64, the factor samples and inputs,
        /// the group's lanes and passes (the records' layout: ShaderContractTests).
        /// </summary>
        [Test]
        public void ShaderLayoutIsCoresLayout()
        {
            string dir = Path.Combine(_work, "layout-probe");
            Directory.CreateDirectory(dir);
            string spv = Path.Combine(dir, "probe.spv"), output = Path.Combine(dir, "layout.u32");
            ComputeRunner.Run("glslangValidator", "-D", "-V", "-S", "comp", "-e", "VertexCacheLayoutProbe", "--hlsl-iomap",
                "--shift-cbuffer-binding", "0", "--shift-texture-binding", "2", "--shift-UAV-binding", "5", "-o", spv,
                PackageRoot.Combine("Tools~", "RigTests", "VertexCacheLayoutProbe.hlsl"));
            ComputeRunner.Run("spirv-val", spv);
            string o = ComputeRunner.Run(ComputeRunner.Runner(), "--spv", spv, "--entry", "VertexCacheLayoutProbe", "--device", "llvmpipe",
                "--groups", "1", "--zeros", "9=" + (64 * 64).ToString(CultureInfo.InvariantCulture), "--out", "9=" + output);
            Assert.That(o, Does.Contain("device llvmpipe"));
            byte[] bytes = File.ReadAllBytes(output);
            uint U(int lane, int k) => BitConverter.ToUInt32(bytes, 4 * (16 * lane + k));
            for (int lane = 0; lane < 64; lane++)
            {
                int limit = lane + 1;
                string at = "L = " + limit + ", tile " + lane;
                Assert.That(U(lane, 0), Is.EqualTo(VertexCache.SlotsPerTile(limit)), at + ": slots a tile");
                Assert.That(U(lane, 1), Is.EqualTo(VertexCache.GroupsPerTile(limit)), at + ": groups a tile");
                Assert.That(U(lane, 2), Is.EqualTo(VertexCache.MaxTilePoints(limit)), at + ": points a tile");
                Assert.That(U(lane, 3), Is.EqualTo(VertexCache.FactorSamplesPerTile), "factor samples a tile");
                Assert.That(U(lane, 6), Is.EqualTo(VertexCache.FactorThreadsPerGroup), "lanes a factors group");
                Assert.That(U(lane, 7), Is.EqualTo(VertexCache.PassesPerGroup), "passes a vertex group");
                Assert.That(U(lane, 9), Is.EqualTo(VertexCache.VertexThreadsPerGroup), "lanes a vertex group");
                Assert.That(U(lane, 13), Is.EqualTo(TileCellRecord.InputCount), "float4 of factor inputs");
            }
        }

        /// <summary>
        /// A camera move (harness --camera-path, the orbit of gt-cli pack) re-evaluates only the tiles
        /// whose integer factors changed: frame 0 builds every tile at the path's first camera, frame 1,
        /// turned by 3 degrees, updates. It ends with the picture, factors and slots of a cache built
        /// from scratch at the second camera. With the range moving too, every drawn tile is evaluated.
        /// </summary>
        [Test]
        public void CameraMoveReevaluatesOnlyTheTilesWhoseFactorsChanged()
        {
            const string range = "0.1,0.1,0.9,0.9";
            const int tiles = 8, width = 160, height = 120;
            string[] tess = { "--target-pixels", "1", "--max-factor", "16" }, orbit = tess.Concat(new[] { "--orbit", "4,3" }).ToArray();
            string CameraPathOf(string name) => Path.Combine(_work, name, PackCommandCameraPath);
            CacheFrame moved = DrawCached("orbit", range, tiles, orbit, width, height, null, "--frames", "2", "--camera-path", CameraPathOf("orbit"));
            float[] path = ReadbackRun.ReadFloats(CameraPathOf("orbit"));
            float[] Camera(int k) => path.Skip(44 * k).Take(44).ToArray();
            CacheFrame first = DrawCached("orbit-first", range, tiles, tess, width, height, Camera(0));
            CacheFrame fresh = DrawCached("orbit-fresh", range, tiles, tess, width, height, Camera(1));

            RigPng pm = RigPng.Read(Path.Combine(_work, "orbit", "image.png")), pf = RigPng.Read(Path.Combine(_work, "orbit-fresh", "image.png"));
            Assert.That(pm.PixelsDifferingFrom(pf, 0), Is.EqualTo(0), "the updated frame against one built from scratch");
            Float4 planRange = ReadbackRun.ReadParams(Path.Combine(_work, "orbit", "params.f32")).range;
            int drawn = 0, evaluated = 0, slots = 0;
            for (int tile = 0; tile < tiles * tiles; tile++)
            {
                Assert.That(moved.FactorsOf(tile), Is.EqualTo(fresh.FactorsOf(tile)), "tile " + tile);
                if (!first.Culled(tile))
                    Assert.That(moved.SlotsKey(tile), Is.EqualTo(planRange),
                                "tile " + tile + ": the range its slots were evaluated at");
                Assert.That(moved.Culled(tile), Is.EqualTo(fresh.Culled(tile)), "tile " + tile);
                if (fresh.Culled(tile)) { Assert.That(moved.Evaluated(tile), Is.False, "culled tile " + tile); continue; }
                drawn++;
                Assert.That(moved.CellFactorsWay(tile), Is.EqualTo(VertexCache.CellFactorsRescaled), "tile " + tile + ": its cell's factors from its kept samples");
                bool changed = first.Culled(tile) || !first.FactorsOf(tile).Equals(fresh.FactorsOf(tile));
                Assert.That(moved.Evaluated(tile), Is.EqualTo(changed), "tile " + tile + ": evaluated exactly when its factors changed");
                if (changed) evaluated++;
                foreach (var (_, slot) in VertexCache.TilePoints(fresh.FactorsOf(tile), fresh.Limit))
                    for (int part = 0; part < VertexCache.Uint4sPerRecord(false); part++, slots++)
                        Assert.That(moved.Part(tile, slot, part), Is.EqualTo(fresh.Part(tile, slot, part)), "tile " + tile + " slot " + slot);
            }
            TestContext.Out.WriteLine("camera turned 3 degrees: {0} of {1} drawn tiles evaluated again, {2} record parts equal to a fresh build", evaluated, drawn, slots);
            Assert.That(evaluated, Is.GreaterThan(0).And.LessThan(drawn), "some tiles kept their factors, some did not");

            // Three frames: the harness shifts the range in frame 1 and draws the plan's in the last.
            CacheFrame ranged = DrawCached("orbit-range", range, tiles, orbit, width, height, null,
                                           "--frames", "3", "--camera-path", CameraPathOf("orbit-range"), "--update-range-per-frame");
            for (int tile = 0; tile < tiles * tiles; tile++)
            {
                Assert.That(ranged.Evaluated(tile), Is.EqualTo(!ranged.Culled(tile)), "range moved: tile " + tile);
                Assert.That(ranged.CellFactorsWay(tile), Is.EqualTo(VertexCache.CellFactorsSampled), "range moved: tile " + tile + " samples its cell");
            }
        }

        /// <summary>
        /// Anchored tiles (TileLattice), the range panning: the cache holds whole cells
        /// (ClippedCell), so a frame evaluates only the cells the pan brings in (none while the first
        /// cells hold: the renderer then dispatches nothing at all), keeps every other cell's factors
        /// and slots, and ends with the picture and cache of one frame built from scratch at its
        /// range. Crossing: the lattice is placed so that frame 1's pan crosses a lattice line (the
        /// first cell changes, and the cell leaving takes the slot of the one entering).
        /// </summary>
        [TestCase(false, 0f)]
        [TestCase(true, 0f)]
        [TestCase(false, 0.1f)]   // harness --range-pan 0.1: frame 1 moves the range by 0.1 sin(2 pi / 100) of its size
        public void AnchoredPanEvaluatesOnlyTheCellsItBringsIn(bool crossing, float rangePan)
        {
            const string range = "0.1,0.1,0.9,0.9";
            const int tiles = 8, width = 160, height = 120;
            // A cell is 0.1 wide; frame 1 moves the range by 8e-5: with the lattice 4e-5 past the
            // range's corner, line 1 (0.10004) falls between the two frames' c.
            string lattice = crossing ? "0.00004,0.00004,0.80004,0.80004" : range;
            string name = crossing ? "anchored-cross" : rangePan > 0f ? "anchored-range-pan" : "anchored-pan";
            string[] tess = { "--target-pixels", "1", "--max-factor", "16", "--anchor-at", lattice };
            // Three frames: the harness shifts the range by 1e-4 of its size in frame 1 and draws the
            // plan's range in the last; the lattice stays where --anchor-at put it.
            string[] frames = { "--frames", "3", "--update-range-per-frame" };
            if (rangePan > 0f) frames = frames.Concat(new[] { "--range-pan", rangePan.ToString("R", CultureInfo.InvariantCulture) }).ToArray();
            CacheFrame panned = DrawCached(name, range, tiles, tess, width, height, null, frames);
            CacheFrame fresh = DrawCached(name + "-fresh", range, tiles, tess, width, height);
            Assert.That(panned.Tiles, Is.EqualTo(tiles + 1), "(M + 1)^2 tiles");

            RigPng pp = RigPng.Read(Path.Combine(_work, name, "image.png")), pf = RigPng.Read(Path.Combine(_work, name + "-fresh", "image.png"));
            Assert.That(pp.PixelsDifferingFrom(pf, 0), Is.EqualTo(0), "after the pan against one frame built from scratch");
            Assert.That(panned.Run.Long("stat", "clipping_invocations"), Is.EqualTo(fresh.Run.Long("stat", "clipping_invocations")));

            TerrainParams p = ReadbackRun.ReadParams(Path.Combine(_work, name, "params.f32"));
            TerrainParams shifted = p;
            // Harness frameRange, frame 1: the tiny shift, or the pan's first step.
            float k = rangePan > 0f ? rangePan * (float)Math.Sin(2.0 * 3.14159265358979 * 1 / 100.0) : 1e-4f * 1f;
            float dx = (p.range.z - p.range.x) * k, dy = (p.range.w - p.range.y) * k;
            shifted.range = new Float4(p.range.x + dx, p.range.y + dy, p.range.z + dx, p.range.w + dy);
            int drawn = 0, evaluated = 0, slots = 0, held = 0, clipped = 0;
            for (int tile = 0; tile < panned.Tiles * panned.Tiles; tile++)
            {
                Assert.That(panned.FactorsOf(tile), Is.EqualTo(fresh.FactorsOf(tile)), "tile " + tile);
                Assert.That(panned.Culled(tile), Is.EqualTo(fresh.Culled(tile)), "tile " + tile);
                // The camera held: a cell the last frame also had keeps its factors, samples no surface.
                bool sameCell = TileLattice.CellSpan(p, tile).Equals(TileLattice.CellSpan(shifted, tile));
                Assert.That(panned.CellFactorsWay(tile), Is.EqualTo(sameCell ? VertexCache.CellFactorsHeld : VertexCache.CellFactorsSampled),
                            "tile " + tile + (sameCell ? ": same cell, factors held" : ": a new cell in its slot"));
                if (sameCell) held++;
                if (fresh.Culled(tile)) continue;
                drawn++;
                if (!ClippedCell.CellKeptWhole(TileLattice.TileKeptCellSpan(shifted, tile))) clipped++;
                Assert.That(panned.Evaluated(tile), Is.EqualTo(!sameCell), "tile " + tile + ": evaluated exactly when the pan brought its cell in");
                if (!sameCell) evaluated++;
                Assert.That(panned.SlotsKey(tile),
                            Is.EqualTo(TileLattice.CellSpan(p, tile)), "tile " + tile + ": its record holds the cell its slots hold");
                foreach (var (_, slot) in VertexCache.TilePoints(fresh.FactorsOf(tile), fresh.Limit, anchored: true))
                    for (int part = 0; part < VertexCache.Uint4sPerRecord(false); part++, slots++)
                        Assert.That(panned.Part(tile, slot, part), Is.EqualTo(fresh.Part(tile, slot, part)), "tile " + tile + " slot " + slot);
            }
            int k0 = TileLattice.FirstCell(p.range.x, p.tileLattice.x, p.tileLattice.z, p.tess.x);
            int k1 = TileLattice.FirstCell(shifted.range.x, p.tileLattice.x, p.tileLattice.z, p.tess.x);
            Assert.That(k1 - k0, Is.EqualTo(crossing ? 1 : 0), "frame 1's first cell");
            TestContext.Out.WriteLine("anchored pan{0}: {1} of {2} drawn tiles evaluated again, {3} of them clipped in frame 1, {4} record parts equal to a fresh build, {5} cells' factors held",
                                      crossing ? " across a lattice line" : "", evaluated, drawn, clipped, slots, held);
            Assert.That(clipped, Is.GreaterThan(0), "frame 1 clipped tiles");
            Assert.That(held, Is.GreaterThan(drawn / 2), "most cells held their factors");
            // Crossing a line diagonally brings in (and, back, out) one column and one row of cells.
            if (crossing) Assert.That(evaluated, Is.GreaterThan(0).And.LessThanOrEqualTo(2 * (tiles + 1) - 1), "the cells the pan brought in");
            else Assert.That(evaluated, Is.EqualTo(0), "a pan inside the cells evaluates nothing");
        }

        /// <summary>
        /// Clipped tiles leave no gap on the GPU: the lattice anchored off the range on both axes, so
        /// the range's edges cut the first and last cells (the domain stage blends their records,
        /// ClippedCell.hlsl). Seen straight from above over a rectangle just inside the range's
        /// footprint, every pixel is terrain; over a rectangle wider than the terrain, sky shows.
        /// What it catches: a tile whose drawn part leaves its neighbour's edge in x or z (a domain
        /// stage that shrank clipped tiles by 10% showed 3,687 sky pixels). A crack in height only
        /// has no width from above: the Core test NeighboursReadTheSameRecordsForEveryVertexOfTheirSharedEdge
        /// covers the records and fractions both sides read.
        /// </summary>
        [Test]
        public void ClippedTilesLeaveNoGapSeenFromAbove()
        {
            const string range = "0.1,0.1,0.9,0.9";
            const int tiles = 8, size = 384;
            // Cells 0.1 wide, lines at 0.055 + 0.1 k (u) and 0.035 + 0.1 k (v): the range keeps 55% and
            // 45% of the first and last cells along u, 35% and 65% along v.
            string[] tess = { "--target-pixels", "2", "--max-factor", "32", "--anchor-at", "0.155,0.135,0.955,0.935" };
            // The grid's object (x, z) (terrain (x, y); object space is (x, height, y)) spans its control
            // points' box; the range's part of it, less a margin of 2% of the box (the surface's x, y
            // follow its parameters to far less).
            var (lo, hi) = ReadbackRun.ControlPointBox(_grid);
            double x0 = lo.x, z0 = lo.y, x1 = hi.x, z1 = hi.y, w = x1 - x0, d = z1 - z0;
            float[] inside = ReadbackRun.TopDownCameraOver(x0 + 0.12 * w, z0 + 0.12 * d, x0 + 0.88 * w, z0 + 0.88 * d, size, size);
            float[] wider = ReadbackRun.TopDownCameraOver(x0 - 0.05 * w, z0 - 0.05 * d, x1 + 0.05 * w, z1 + 0.05 * d, size, size);
            CacheFrame f = DrawCached("clipped-above", range, tiles, tess, size, size, inside);
            CacheFrame g = DrawCached("clipped-above-wider", range, tiles, tess, size, size, wider);

            TerrainParams p = ReadbackRun.ReadParams(Path.Combine(_work, "clipped-above", "params.f32"));
            int clipped = 0;
            var factors = new HashSet<float>();
            for (int tile = 0; tile < f.Tiles * f.Tiles; tile++)
            {
                if (f.Culled(tile)) continue;
                if (!ClippedCell.CellKeptWhole(TileLattice.TileKeptCellSpan(p, tile))) clipped++;
                factors.Add(f.FactorsOf(tile).inside.x);
            }
            long covered = f.Run.Long("image", "nonsky_pixels"), coveredWider = g.Run.Long("image", "nonsky_pixels");
            TestContext.Out.WriteLine("clipped tiles from above: {0} of {1} tiles clipped, inside factors {2}; terrain pixels {3} of {4} over the range, {5} over a wider view",
                                      clipped, f.Tiles * f.Tiles, string.Join(" ", factors.OrderBy(x => x)), covered, size * size, coveredWider);
            Assert.That(f.Tiles, Is.EqualTo(tiles + 1), "(M + 1)^2 tiles");
            Assert.That(clipped, Is.EqualTo(4 * tiles), "the ring of cells the range's edges cut");
            Assert.That(factors.Count, Is.GreaterThan(1), "neighbours at different factors");
            Assert.That(covered, Is.EqualTo((long)size * size), "sky shows through the terrain: a gap");
            Assert.That(coveredWider, Is.LessThan((long)size * size * 3 / 4), "the wider view sees past the terrain");
        }

        // gt-cli pack --orbit's file (Tools~/dotnet/Gt/PackCommand.cs, CameraPathFile).
        const string PackCommandCameraPath = "camera_path.f32";

        /// <summary>
        /// Adaptive factors through the cache: integers within the limit, the inside rule, some tiles
        /// culled, shared edges with equal factors and bit-identical vertices on both sides.
        /// </summary>
        [Test]
        public void AdaptiveCacheIsIntegerAndWatertight()
        {
            // A low, narrow view into the range (object space is (x, height, y)): the tiles beside and
            // behind it are out of the frustum.
            float[] camera = ReadbackRun.PerspectiveCamera(new Double3(0.45, 0.12, 0.28), new Double3(0.47, 0.0, 0.6), 30, 192, 128, 0.01, 10);
            CacheFrame f = DrawCached("adaptive", "0.25,0.3,0.65,0.7", 8, new[] { "--target-pixels", "1", "--max-factor", "16" }, 192, 128, camera);
            int culled = 0, edgePairs = 0, vertexPairs = 0, differingVertices = 0;
            var distinct = new HashSet<float>();
            for (int tile = 0; tile < 64; tile++)
            {
                TileFactorSet t = f.FactorsOf(tile);
                if (f.Culled(tile)) { culled++; Assert.That(t.IsCulled, Is.True); continue; }
                foreach (float x in new[] { t.edge.x, t.edge.y, t.edge.z, t.edge.w, t.inside.x, t.inside.y })
                {
                    Assert.That(x, Is.EqualTo(MathF.Round(x)).And.InRange(1f, 16f), "tile " + tile + ": " + t);
                    distinct.Add(x);
                }
                Assert.That(VertexCache.IntegerFactors(t), Is.EqualTo(t), "tile " + tile + ": already integer factors");
            }
            for (int tj = 0; tj < 8; tj++)
                for (int ti = 0; ti < 8; ti++)
                {
                    int a = tj * 8 + ti;
                    // (right neighbour: my edge 2 is its edge 0), (upper neighbour: my edge 3 is its edge 1)
                    foreach (var (b, mine, theirs, ok) in new[] { (a + 1, 2, 0, ti + 1 < 8), (a + 8, 3, 1, tj + 1 < 8) })
                    {
                        if (!ok || f.Culled(a) || f.Culled(b)) continue;
                        float fa = mine == 2 ? f.FactorsOf(a).edge.z : f.FactorsOf(a).edge.w;
                        float fb = theirs == 0 ? f.FactorsOf(b).edge.x : f.FactorsOf(b).edge.y;
                        edgePairs++;
                        Assert.That(fa, Is.EqualTo(fb), $"shared edge of tiles {a} and {b}");
                        for (int k = 0; k <= (int)fa; k++)
                        {
                            vertexPairs++;
                            for (int part = 0; part < VertexCache.Uint4sPerRecord(false); part++)
                                if (!f.Part(a, VertexCache.EdgeSlot(mine, k, f.Limit), part).Equals(f.Part(b, VertexCache.EdgeSlot(theirs, k, f.Limit), part)))
                                { differingVertices++; break; }
                        }
                    }
                }
            // The kernel spreads each tile's factor pieces over lanes; hull_const computes them in
            // one thread: the same factors, rounded up as the kernel rounds.
            float[] h = DrawHullFactors("adaptive", 8, 192, 128, out _);
            for (int tile = 0; tile < 64; tile++)
            {
                TileFactorSet fromHull = HullFactorsOf(h, tile);
                Assert.That(f.FactorsOf(tile), Is.EqualTo(VertexCache.IntegerFactors(fromHull)), "tile " + tile + ": the kernel's factors against hull_const's");
            }
            int nan = f.Records.Where((w, i) => i % 4 != 3).Count(w => !float.IsFinite(ReadbackRun.FloatOfBits(w)));   // position words
            TestContext.Out.WriteLine("adaptive cache: {0} of 64 tiles culled, factors used {1}, {2} shared edges, {3} shared-edge vertex pairs, {4} differ; {5} triangles",
                culled, string.Join(" ", distinct.OrderBy(x => x)), edgePairs, vertexPairs, differingVertices, f.Run.Long("stat", "clipping_invocations"));
            Assert.That(nan, Is.EqualTo(0));
            Assert.That(culled, Is.GreaterThan(0), "the view leaves tiles out");
            Assert.That(distinct.Count, Is.GreaterThan(2), "adaptive factors vary across the view");
            Assert.That(edgePairs, Is.GreaterThan(20));
            Assert.That(differingVertices, Is.EqualTo(0), "vertices on shared edges, bit for bit");
            Assert.That(f.Run.Long("image", "nonsky_pixels"), Is.GreaterThan(192 * 128 / 5));
        }

        /// <summary>
        /// The inspector's triangle estimate (Core's TerrainTriangleEstimate) is what the GPU draws:
        /// Core's mirror of the factors against hull_const's readback tile by tile, the tessellator's
        /// triangles of those factors against the clipping invocations of both paths (fractional_odd
        /// domain stage, integer cache).
        /// </summary>
        [Test]
        [TestCase(false)]
        [TestCase(true)]   // anchored tiles, the lattice 0.03 off the range: (M + 1)^2 tiles, clipped ones at the edges
        public void TriangleEstimateIsWhatTheGpuDraws(bool anchored)
        {
            const int width = 320, height = 180, m = 8;
            float[] camera = ReadbackRun.PerspectiveCamera(new Double3(0.45, 0.14, 0.22), new Double3(0.5, 0.0, 0.62), 40, width, height, 0.01, 10);
            string name = anchored ? "estimate-anchored" : "estimate";
            string[] tess = { "--target-pixels", "2", "--max-factor", "32" };
            if (anchored) tess = tess.Concat(new[] { "--anchor-at", "0.13,0.07,0.93,0.87" }).ToArray();
            CacheFrame f = DrawCached(name, "0.1,0.1,0.9,0.9", m, tess, width, height, camera);
            int tiles = f.Tiles;
            Assert.That(tiles, Is.EqualTo(anchored ? m + 1 : m));
            var objectToClip = Float4x4.FromRows(camera[0], camera[4], camera[8], camera[12], camera[1], camera[5], camera[9], camera[13],
                                                 camera[2], camera[6], camera[10], camera[14], camera[3], camera[7], camera[11], camera[15]);
            var screen = new Float2(width, height);
            float[] h = DrawHullFactors(name, tiles, width, height, out HarnessRun hull);
            long hullModel = 0, cacheModel = 0;
            int culled = 0;
            double worst = 0;
            for (int tile = 0; tile < tiles * tiles; tile++)
            {
                TileFactorSet gpu = HullFactorsOf(h, tile);
                TileFactorSet core = TileFactors.ComputeTileFactors(f.Inputs, tile, objectToClip, screen, TerrainKeywords.Noise);
                Assert.That(core.IsCulled, Is.EqualTo(h[8 * tile + 6] != 0f), "tile " + tile + ": culled on the GPU and in Core alike");
                if (core.IsCulled) { culled++; continue; }
                float[] a = { gpu.edge.x, gpu.edge.y, gpu.edge.z, gpu.edge.w, gpu.inside.x, gpu.inside.y };
                float[] b = { core.edge.x, core.edge.y, core.edge.z, core.edge.w, core.inside.x, core.inside.y };
                for (int k = 0; k < 6; k++) worst = Math.Max(worst, Math.Abs(a[k] - b[k]) / a[k]);
                hullModel += TerrainTriangleEstimate.PatchTriangles(gpu, TessellationPartitioning.FractionalOdd);
                // The kernel keeps the cell's factors; the hull draws the part of the cell the tile keeps.
                TileFactorSet drawn = ClippedCell.ClippedTileFactors(f.FactorsOf(tile), TileLattice.TileKeptCellSpan(f.Inputs.Params, tile));
                Assert.That(drawn, Is.EqualTo(TileFactors.ComputeCachedTileFactors(f.Inputs, tile, objectToClip, screen, TerrainKeywords.Noise)),
                            "tile " + tile + ": Core's cached factors");
                if (drawn.IsCulled) continue;
                cacheModel += TerrainTriangleEstimate.PatchTriangles(drawn, TessellationPartitioning.Integer);
            }
            var domain = TerrainTriangleEstimate.InView(f.Inputs, objectToClip, screen, TerrainKeywords.Noise, TessellationPartitioning.FractionalOdd);
            var cached = TerrainTriangleEstimate.InView(f.Inputs, objectToClip, screen, TerrainKeywords.Noise, TessellationPartitioning.Integer);
            long hullDrawn = hull.Long("stat", "clipping_invocations"), cacheDrawn = f.Run.Long("stat", "clipping_invocations");
            TestContext.Out.WriteLine("{0} of {1} tiles culled; factors: largest relative difference GPU vs Core {2:E2}", culled, tiles * tiles, worst);
            TestContext.Out.WriteLine("domain stage: GPU {0:N0} triangles, model of its factors {1:N0}, Core's estimate {2:N0}", hullDrawn, hullModel, domain.triangles);
            TestContext.Out.WriteLine("vertex cache: GPU {0:N0} triangles, model of its factors {1:N0}, Core's estimate {2:N0}", cacheDrawn, cacheModel, cached.triangles);
            Assert.That(culled, Is.GreaterThan(0).And.LessThan(tiles * tiles - 8), "the view leaves some tiles out, not most");
            Assert.That(worst, Is.LessThan(1e-3), "Core's factors are the GPU's to float rounding");
            Assert.That(cacheModel, Is.EqualTo(cacheDrawn), "integer partitioning: the model counts what the tessellator made");
            Assert.That(hullModel, Is.EqualTo(hullDrawn), "fractional_odd: the model counts what the tessellator made");
            // Core's factors may round differently from another GPU's; here they agree bit for bit.
            Assert.That(domain.triangles, Is.EqualTo(hullDrawn).Within(0.5).Percent);
            Assert.That(cached.triangles, Is.EqualTo(cacheDrawn).Within(0.5).Percent);
        }

        /// <summary>
        /// gt-cli estimate (the estimate's CPU cost, a benchmark that prints figures) runs, counts
        /// every tile when there are at most 256, and its 256-tile sample of 1,024 stays near the count
        /// over every tile.
        /// </summary>
        [Test]
        public void EstimateBenchmarkPrintsItsTable()
        {
            string o = ReadbackRun.Exec(_cli, new[] { "estimate", "--grid", _gridPath, "--tiles", "8,32", "--repeat", "2" }, null);
            TestContext.Out.WriteLine(o);
            Assert.That(o, Does.Match(@"\| 8 \| 0\.25 \| 64 of 64 \| [0-9.]+ \| [0-9,]+ \| [0-9,]+ \| 0\.0% \|"), "8 x 8 tiles: every tile, no difference");
            var row = System.Text.RegularExpressions.Regex.Match(o, @"\| 32 \| 0\.25 \| 256 of 1024 \| [0-9.]+ \| ([0-9,]+) \| ([0-9,]+) \| ([-+0-9.]+)% \|");
            Assert.That(row.Success, Is.True, "32 x 32 tiles: a 256-tile sample");
            Assert.That(Math.Abs(double.Parse(row.Groups[3].Value, CultureInfo.InvariantCulture)), Is.LessThan(5), "the sample against every tile, percent");
        }
    }
}
