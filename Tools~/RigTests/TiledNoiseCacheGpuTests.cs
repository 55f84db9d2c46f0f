// The tiled noise (GT_NOISE_TABLE) in the vertex cache's kernels (lavapipe, through gt-harness's
// compute pre-pass) against Core: cache_factors and cache_vertices read Core's 256 x 256 cell table
// (bound at 9) and must write Core's float vertex in every slot, at octaves fine enough to wrap the
// table; the bounds are VertexCacheGpuTests' noise cache test's. Fails (never skips) when the
// harness, lavapipe, glslang or gt-cli is missing: `gt setup`.
using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture, Parallelizable(ParallelScope.Self)]
    public class TiledNoiseCacheGpuTests
    {
        const string Cached = "noise+noise_table+vertex_cache";
        const TerrainKeywords Keywords = TerrainKeywords.Noise | TerrainKeywords.NoiseTable;
        const int Tiles = 4, Factor = 15, Width = 96, Height = 64;
        // Six octaves from 16 cells across over the whole terrain: octave 4 spans the table's 256
        // cells, octave 5 wraps it twice. --noise-vertices 8192 keeps every octave in.
        const string NoiseArg = "0.004,16,2,2", Octaves = "6", VerticesAcross = "8192";
        // GPU against Core float, relative to the extent (VertexCacheGpuTests' bound).
        const double Bound = 1e-5;

        string _work, _spirv, _cli, _gridPath;
        PatchGrid _grid;

        [OneTimeSetUp]
        public void BuildGridAndShaders()
        {
            _work = ReadbackRun.PrepareWork("rigtests-tiled-noise-cache");
            _cli = ReadbackRun.Cli();
            _grid = ReadbackRun.DemoGrid(_work, out _gridPath);
            _spirv = ReadbackRun.CompileVariants(_work, Cached);
        }

        /// <summary>
        /// Every slot the kernel writes holds Core's float TerrainVertex with the tiled noise
        /// (position; the packed normal and height weight within half a step plus float error), no other slot is touched,
        /// and the same records are farther than the bound from Core's hashed noise.
        /// </summary>
        [Test]
        public void CacheHoldsTheCoreTiledNoiseVertexInEverySlotTheKernelWrites()
        {
            string dir = Path.Combine(_work, "uniform");
            ReadbackRun.Exec(_cli, new[]
            {
                "pack", "--grid", _gridPath, "--range", "0,0,1,1", "--tiles", Tiles.ToString(CultureInfo.InvariantCulture),
                "--width", Width.ToString(CultureInfo.InvariantCulture), "--height", Height.ToString(CultureInfo.InvariantCulture),
                "--factor", Factor.ToString(CultureInfo.InvariantCulture), "--noise", NoiseArg, "--octaves", Octaves,
                "--noise-vertices", VerticesAcross, "--out", dir,
            }, null);
            string table = Path.Combine(dir, "noise_cells.f32");
            ReadbackRun.WriteFloats(table, GradientNoiseTable.Floats);
            TerrainParams p = ReadbackRun.ReadParams(Path.Combine(dir, "params.f32"));
            var inputs = TerrainInputs.Create(_grid, p);
            Assert.That(TileLattice.TilesAcross(p), Is.EqualTo(Tiles));
            Assert.That(inputs.NoiseOctaveCount(), Is.EqualTo(6f), "every octave drawn, the table wrapped");
            int limit = VertexCache.FactorLimit(p.tess), slots = VertexCache.SlotsPerTile(limit), parts = VertexCache.Uint4sPerRecord(false);

            string factors = Path.Combine(dir, "tile_factors.f32"), records = Path.Combine(dir, "vertex_cache.u32");
            var args = new List<string>(ReadbackRun.Stages(_spirv, Cached));
            args.AddRange(new[]
            {
                "--buffers", dir, "--patches", (Tiles * Tiles).ToString(CultureInfo.InvariantCulture),
                "--width", Width.ToString(CultureInfo.InvariantCulture), "--height", Height.ToString(CultureInfo.InvariantCulture),
                "--device", "llvmpipe", "--stats", "--storage-data", "9:" + table,
            });
            args.AddRange(ReadbackRun.VertexCacheArgs(Path.Combine(_spirv, Cached), Tiles, limit, false, factors, records));
            HarnessRun run = HarnessRun.Harness(args.ToArray());
            run.AssertSucceeded();
            float[] f = ReadbackRun.ReadFloats(factors);
            uint[] r = ReadbackRun.ReadUints(records);
            Assert.That(r.Length, Is.EqualTo(4 * parts * Tiles * Tiles * slots));

            (uint x, uint y, uint z, uint w) Part(int tile, int slot)
            {
                int o = 4 * parts * (tile * slots + slot);
                return (r[o], r[o + 1], r[o + 2], r[o + 3]);
            }

            double extent = ReadbackRun.TerrainExtent(_grid);
            double maxPos = 0, maxHashed = 0, maxNormal = 0, maxWeight = 0;
            int compared = 0, stray = 0, sameWord = 0;
            for (int tile = 0; tile < Tiles * Tiles; tile++)
            {
                TileFactorSet t = ReadbackRun.CacheTileFactors(f, tile);
                Assert.That(t, Is.EqualTo(VertexCache.IntegerFactors(new TileFactorSet(new Float4(Factor, Factor, Factor, Factor), new Float2(Factor, Factor)))), "tile " + tile);
                var written = new HashSet<int>();
                foreach (var (tess, slot) in VertexCache.TilePoints(t, limit))
                {
                    written.Add(slot);
                    var g = Part(tile, slot);
                    var gpu = new Float3(ReadbackRun.FloatOfBits(g.x), ReadbackRun.FloatOfBits(g.y), ReadbackRun.FloatOfBits(g.z));
                    TerrainVertexOutput v = TerrainVertex.Evaluate(inputs, tile, tess, Keywords);
                    uint[] core = VertexCache.Record(v, TerrainVertex.HeightWeight(v, inputs, Keywords), false);
                    maxPos = Math.Max(maxPos, ReadbackRun.Distance(gpu, v.PositionOS) / extent);
                    TerrainVertexOutput hashed = TerrainVertex.Evaluate(inputs, tile, tess, TerrainKeywords.Noise);
                    maxHashed = Math.Max(maxHashed, ReadbackRun.Distance(gpu, hashed.PositionOS) / extent);
                    Float2 e = NormalEncoding.LambertEncodeNormal(v.NormalOS);
                    Float3 unpacked = VertexCache.UnpackCachedVaryings(g.w);
                    maxNormal = Math.Max(maxNormal, Math.Max(Math.Abs(unpacked.x - e.x), Math.Abs(unpacked.y - e.y)));
                    maxWeight = Math.Max(maxWeight, Math.Abs(unpacked.z - TerrainVertex.HeightWeight(v, inputs, Keywords)));
                    if (g.w == core[3]) sameWord++;
                    compared++;
                }
                for (int slot = 0; slot < slots; slot++)
                    if (!written.Contains(slot) && !Part(tile, slot).Equals(default((uint, uint, uint, uint)))) stray++;
            }
            TestContext.Out.WriteLine("{0} cached vertices (tiled noise) against Core: position {1:G3} of the extent, encoded normal {2:G3} (half step {3:G3}); " +
                                      "packed word equal to Core's in {4}; against Core's hashed noise: position {5:G3} of the extent",
                                      compared, maxPos, maxNormal, 1.0 / 1023, sameWord, maxHashed);
            Assert.That(compared, Is.EqualTo(Tiles * Tiles * ((Factor - 1) * (Factor - 1) + 4 * (Factor + 1))), "interior points and 4 edges of F + 1");
            Assert.That(stray, Is.EqualTo(0), "slots written that no point owns");
            Assert.That(maxPos, Is.LessThan(Bound), "GPU against Core float, relative to the extent");
            Assert.That(maxNormal, Is.LessThan(1.0 / 1023 + 1e-4));
            Assert.That(maxWeight, Is.LessThan(0.5 / 1023 + 1e-4));
            Assert.That(sameWord, Is.GreaterThan(compared * 9 / 10), "most packed words are Core's exactly");
            // The comparison tells the two noises apart: kernels that ignored their table (or a Core
            // that ignored the keyword) would fail above.
            Assert.That(maxHashed, Is.GreaterThan(Bound), "the tiled noise is another noise than the hashed one");
        }
    }
}
