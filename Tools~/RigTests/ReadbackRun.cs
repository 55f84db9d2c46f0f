// One readback draw through gt-harness on lavapipe and its comparison with Core's float mirror of the
// shaders (Runtime/Core/Terrain/TerrainVertex.cs): the helpers every GPU-vs-Core test shares (TerrainGpuTests,
// HardCaseGpuTests). They fail (never skip) when the harness, lavapipe, glslang or gt-cli is
// missing: `gt setup` provides them.
using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>GPU-vs-Core figures of one or more readback runs.</summary>
    public sealed class ReadbackComparison
    {
        public int Vertices, Unmatched, PositionBitIdentical, NormalBitIdentical, QEqual, Nan;
        /// <summary>Largest |GPU - Core float| (terrain units, absolute), largest normal difference,
        /// largest |Core float - double reference| (terrain units).</summary>
        public double MaxPosition, MaxNormal, MaxReference;
        public HashSet<int> Patches = new HashSet<int>();

        public void Add(ReadbackComparison o)
        {
            Vertices += o.Vertices; Unmatched += o.Unmatched; PositionBitIdentical += o.PositionBitIdentical;
            NormalBitIdentical += o.NormalBitIdentical; QEqual += o.QEqual; Nan += o.Nan;
            MaxPosition = Math.Max(MaxPosition, o.MaxPosition); MaxNormal = Math.Max(MaxNormal, o.MaxNormal);
            MaxReference = Math.Max(MaxReference, o.MaxReference);
            Patches.UnionWith(o.Patches);
        }
    }

    /// <summary>
    /// A readback draw: M x M tiles at an integer uniform factor F with the GT_READBACK variant, every
    /// vertex read back (Tools~/rig/README.md, "Rig-only readback"), and the Core float path at the GPU's own
    /// tess coordinates to compare it with.
    /// </summary>
    internal sealed class ReadbackRun
    {
        public PatchGrid Grid;
        public TerrainInputs Inputs;
        public TerrainKeywords Keywords;
        public NoiseSettings? Noise;
        public int Tiles, Factor;
        public float[] Readback;
        public HarnessRun Harness;

        public int VerticesPerTile => (Factor + 1) * (Factor + 1);
        public int VertexCount => Tiles * Tiles * VerticesPerTile;

        // ---- setup --------------------------------------------------------------------------------

        /// <summary>A fresh work folder under .build (asserts the harness and lavapipe are there).</summary>
        public static string PrepareWork(string name)
        {
            string root = HarnessRun.PackageRoot();
            Assert.That(File.Exists(HarnessRun.HarnessPath()), Is.True, "gt-harness not built at " + HarnessRun.HarnessPath() + " (run Tools~/gt setup)");
            Assert.That(File.Exists(HarnessRun.LavapipeIcd), Is.True, "lavapipe is not installed (" + HarnessRun.LavapipeIcd + ")");
            string work = Path.Combine(root, ".build", name);
            if (Directory.Exists(work)) Directory.Delete(work, true);
            Directory.CreateDirectory(work);
            return work;
        }

        /// <summary>gt-cli (built by gt setup).</summary>
        public static string Cli()
        {
            string cli = Path.Combine(HarnessRun.PackageRoot(), ".build", "gt-cli", "gt-cli");
            Assert.That(File.Exists(cli), Is.True, "gt-cli not built at " + cli + " (run Tools~/gt setup)");
            return cli;
        }

        /// <summary>
        /// The sample grid (<c>gt-cli demo-grid</c>, 129 samples) written to <paramref name="work"/>/grid.json,
        /// read back; its path in <paramref name="path"/>.
        /// </summary>
        public static PatchGrid DemoGrid(string work, out string path)
        {
            path = Path.Combine(work, "grid.json");
            Exec(Cli(), new[] { "demo-grid", "--samples", "129", "--out", path }, null);
            return PatchGridJson.Read(File.ReadAllText(path));
        }

        /// <summary>The variants that have a GT_RANGE_ORIGIN sibling (Tools~/rig/shader_variants.txt).</summary>
        static readonly string[] OriginSiblings = { "base", "noise+height_color", "readback", "readback+noise", "factor_readback", "factor_readback+noise",
                                                    "readback+noise+noise_table", "noise+height_color+noise_table" };

        /// <summary>
        /// The variant a draw with range origin <paramref name="rangeOriginF"/> needs, by the renderer's
        /// rule (RelativeSurface.NeedsRangeOriginKeyword): <paramref name="variant"/>, or its
        /// GT_RANGE_ORIGIN sibling while an origin is set; without that keyword the stages compile no
        /// origin code and would draw the origin as 0. Levels and cache variants compile it already.
        /// </summary>
        public static string ForOrigin(string variant, Float4 rangeOriginF)
        {
            if (!RelativeSurface.NeedsRangeOriginKeyword(rangeOriginF, variant.Contains("lod"), variant.Contains("vertex_cache"))) return variant;
            Assert.That(OriginSiblings, Does.Contain(variant), variant + " has no GT_RANGE_ORIGIN variant in shader_variants.txt");
            return variant == "base" ? "range_origin" : variant + "+range_origin";
        }

        /// <summary>
        /// Compiles the named shader variants, and their GT_RANGE_ORIGIN siblings (<see cref="ForOrigin"/>),
        /// into <paramref name="work"/>/spirv and returns that folder.
        /// </summary>
        public static string CompileVariants(string work, params string[] variants)
        {
            var args = new List<string> { Path.Combine(HarnessRun.PackageRoot(), "Tools~", "gt"), "shaders", "--spirv-only" };
            foreach (string v in variants.Concat(variants.Where(v => OriginSiblings.Contains(v)).Select(v => v == "base" ? "range_origin" : v + "+range_origin")))
            { args.Add("--only"); args.Add(v); }
            Exec("bash", args.ToArray(), new Dictionary<string, string> { ["GT_BUILD_DIR"] = work });
            return Path.Combine(work, "spirv");
        }

        public static string Exec(string file, string[] args, Dictionary<string, string> env)
        {
            var psi = new ProcessStartInfo(file) { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
            foreach (string a in args) psi.ArgumentList.Add(a);
            if (env != null) foreach (var kv in env) psi.Environment[kv.Key] = kv.Value;
            Process started;
            try { started = Process.Start(psi); }
            catch (Exception e) { Assert.Fail($"cannot run {file}: {e.Message} (run Tools~/gt setup)"); return null; }
            using (var p = started)
            {
                var err = p.StandardError.ReadToEndAsync();
                string output = p.StandardOutput.ReadToEnd();
                p.WaitForExit();
                Assert.That(p.ExitCode, Is.EqualTo(0), file + " " + string.Join(" ", args) + " failed:\n" + output + err.Result);
                return output;
            }
        }

        public static void WriteFloats(string path, float[] values)
        {
            var bytes = new byte[values.Length * 4];
            Buffer.BlockCopy(values, 0, bytes, 0, bytes.Length);   // little-endian on every .NET the rig runs
            File.WriteAllBytes(path, bytes);
        }

        /// <summary>The float whose bits a record word holds (the vertex cache's uint4 records).</summary>
        public static float FloatOfBits(uint bits) => BitConverter.Int32BitsToSingle((int)bits);

        /// <summary>A dump's 32-bit words as they are (records holding bits, not floats).</summary>
        public static uint[] ReadUints(string path)
        {
            byte[] b = File.ReadAllBytes(path);
            var u = new uint[b.Length / 4];
            Buffer.BlockCopy(b, 0, u, 0, u.Length * 4);
            return u;
        }

        /// <summary>A params.f32 written by gt-cli pack, back as the TerrainParams it packed (the 11 float4 of TerrainParams.Pack).</summary>
        public static TerrainParams ReadParams(string path)
        {
            float[] f = ReadFloats(path);
            Float4 F(int i) => new Float4(f[4 * i], f[4 * i + 1], f[4 * i + 2], f[4 * i + 3]);
            return new TerrainParams { range = F(0), rangeOrigin = F(1), gridSize = F(2), tess = F(3), noise = F(4),
                                       noiseOctaves = F(5), heightColor = F(6), colorLow = F(7), colorHigh = F(8), tileLattice = F(9) };
        }

        public static float[] ReadFloats(string path)
        {
            byte[] b = File.ReadAllBytes(path);
            var f = new float[b.Length / 4];
            Buffer.BlockCopy(b, 0, f, 0, f.Length * 4);
            return f;
        }

        /// <summary>
        /// RigCamera block (Tools~/rig/README.md, binding 1): a top-down orthographic camera over the unit
        /// square (object (x, z) -> clip). The readback does not depend on it.
        /// </summary>
        public static float[] TopDownCamera() => TopDownCameraOver(0, 0, 1, 1, 64, 64);

        /// <summary>
        /// RigCamera block: orthographic, straight down, the object rectangle [x0, x1] x [z0, z1]
        /// filling the view as a Unity camera above sees it (+x right, +z up); clip z = 0.5 + 0.01
        /// height, reversed depth (higher is nearer; heights within +-50 stay inside the depth range).
        /// </summary>
        public static float[] TopDownCameraOver(double x0, double z0, double x1, double z1, int width, int height)
        {
            float sx = (float)(2 / (x1 - x0)), sz = (float)(2 / (z1 - z0));
            float[,] m = { { sx, 0, 0, (float)(-1 - sx * x0) }, { 0, 0, sz, (float)(-1 - sz * z0) }, { 0, 0.01f, 0, 0.5f }, { 0, 0, 0, 1 } };
            return CameraBlock(m, new[] { (float)(0.5 * (x0 + x1)), 2f, (float)(0.5 * (z0 + z1)) }, width, height);
        }

        /// <summary>
        /// RigCamera block: orthographic, straight up from below, the object rectangle [x0, x1] x
        /// [z0, z1] filling the view as a Unity camera below sees it (turned to look up with +z up,
        /// so +x is on its left); clip z = 0.5 - 0.01 height, reversed depth (lower is nearer).
        /// </summary>
        public static float[] BottomUpCameraOver(double x0, double z0, double x1, double z1, int width, int height)
        {
            float sx = (float)(2 / (x1 - x0)), sz = (float)(2 / (z1 - z0));
            float[,] m = { { -sx, 0, 0, (float)(1 + sx * x0) }, { 0, 0, sz, (float)(-1 - sz * z0) }, { 0, -0.01f, 0, 0.5f }, { 0, 0, 0, 1 } };
            return CameraBlock(m, new[] { (float)(0.5 * (x0 + x1)), -2f, (float)(0.5 * (z0 + z1)) }, width, height);
        }

        /// <summary>
        /// RigCamera block of a perspective camera at object-space <paramref name="eye"/> looking at
        /// <paramref name="target"/> (object space is Unity's (x, height, y), identity object-to-world):
        /// RigCamera.LookAt's, so a Unity camera's view (left-handed world, y up, reversed depth).
        /// </summary>
        public static float[] PerspectiveCamera(Double3 eye, Double3 target, double fovYDegrees, int width, int height, double near, double far)
        {
            double[,] d = RigCamera.LookAt(new[] { eye.x, eye.y, eye.z }, new[] { target.x, target.y, target.z }, fovYDegrees,
                                           width, height, near, far, RigCamera.Scale(1, 1, 1)).ObjectToClip();
            var m = new float[4, 4];
            for (int i = 0; i < 4; i++) for (int j = 0; j < 4; j++) m[i, j] = (float)d[i, j];
            return CameraBlock(m, new[] { (float)eye.x, (float)eye.y, (float)eye.z }, width, height);
        }

        static float[] CameraBlock(float[,] objectToClip, float[] eye, int width, int height)
        {
            var cam = new List<float>();
            for (int c = 0; c < 4; c++) for (int r = 0; r < 4; r++) cam.Add(objectToClip[r, c]);   // column-major
            for (int c = 0; c < 4; c++) for (int r = 0; r < 4; r++) cam.Add(r == c ? 1 : 0);
            cam.AddRange(new[] { eye[0], eye[1], eye[2], 1f, width, height, 1f / width, 1f / height, 0f, 1f, 0f, 0f });
            return cam.ToArray();
        }

        /// <summary>The packed inputs of one scene written to <paramref name="dir"/> for --buffers.</summary>
        public static void WriteBuffers(string dir, TerrainInputs inputs, float[] camera)
        {
            Directory.CreateDirectory(dir);
            WriteFloats(Path.Combine(dir, "control_points.f32"), inputs.ControlPoints);
            WriteFloats(Path.Combine(dir, "regions.f32"), inputs.Regions);
            WriteFloats(Path.Combine(dir, "grid_lines.f32"), inputs.GridLines);
            WriteFloats(Path.Combine(dir, "params.f32"), inputs.Params.Pack());
            WriteFloats(Path.Combine(dir, "camera.f32"), camera);
        }

        /// <summary>The four tessellated stages of a compiled variant, as harness arguments.</summary>
        public static string[] Stages(string spirv, string variant)
        {
            string v = Path.Combine(spirv, variant);
            return new[] { "--vert", Path.Combine(v, "vert.spv"), "--tesc", Path.Combine(v, "tesc.spv"),
                           "--tese", Path.Combine(v, "tese.spv"), "--frag", Path.Combine(v, "frag.spv") };
        }

        /// <summary>Tile t's integer factors in a <c>_TileFactors</c> dump (its TileFactorRecord: edges, then inside).</summary>
        public static TileFactorSet CacheTileFactors(float[] dump, int tile)
        {
            long i = (long)tile * TileFactorRecord.Stride / 4;
            return new TileFactorSet(new Float4(dump[i], dump[i + 1], dump[i + 2], dump[i + 3]), new Float2(dump[i + 4], dump[i + 5]));
        }

        /// <summary>
        /// The harness options of the vertex cache (GT_VERTEX_CACHE) for M = <paramref name="tiles"/>
        /// and factor limit <paramref name="limit"/>: its three buffers (sized by Core's
        /// VertexCacheBudget), both kernels of <paramref name="variantDir"/> each frame
        /// (CacheTileFactors over M x M groups, CacheTileVertices over M x M x G), and dumps of both
        /// buffers after the last frame.
        /// </summary>
        public static string[] VertexCacheArgs(string variantDir, int tiles, int limit, bool snow, string factorsDump, string recordsDump,
                                               string cellsDump = null)
        {
            string m = tiles.ToString(CultureInfo.InvariantCulture);
            string[] cells = cellsDump == null ? Array.Empty<string>() : new[] { "--dump-storage", "10:" + cellsDump };
            return new[]
            {
                "--storage", "7:" + VertexCacheBudget.TileFactorsBytes(tiles).ToString(CultureInfo.InvariantCulture),
                "--storage", "8:" + VertexCacheBudget.VertexCacheBytes(tiles, limit, snow).ToString(CultureInfo.InvariantCulture),
                "--storage", "10:" + VertexCacheBudget.TileCellsBytes(tiles).ToString(CultureInfo.InvariantCulture),
                "--compute", Path.Combine(variantDir, "cache_factors.spv") + ":" + m + "," + m + ",1",
                "--compute", Path.Combine(variantDir, "cache_vertices.spv") + ":" + m + "," + m + "," + VertexCache.GroupsPerTile(limit).ToString(CultureInfo.InvariantCulture),
                "--dump-storage", "7:" + factorsDump, "--dump-storage", "8:" + recordsDump,
            }.Concat(cells).ToArray();
        }

        // ---- the draw -----------------------------------------------------------------------------

        /// <summary>
        /// Draws <paramref name="grid"/> with <paramref name="p"/> (uniform integer factor, tile mode) in
        /// the readback variant (<c>readback+noise</c> when <paramref name="noise"/> is given) and
        /// reads every vertex back. <paramref name="extra"/>: more harness options (e.g. --range).
        /// </summary>
        public static ReadbackRun Draw(string dir, string spirv, PatchGrid grid, TerrainParams p, NoiseSettings? noise,
                                       params string[] extra) => Draw(dir, spirv, grid, p, noise, false, extra);

        /// <summary>
        /// <see cref="Draw(string, string, PatchGrid, TerrainParams, NoiseSettings?, string[])"/>; with
        /// <paramref name="tiledNoise"/> the tiled noise (<c>readback+noise+noise_table</c>), Core's
        /// table written to <paramref name="dir"/>/noise_cells.f32 and bound at 9 (--storage-data).
        /// </summary>
        public static ReadbackRun Draw(string dir, string spirv, PatchGrid grid, TerrainParams p, NoiseSettings? noise,
                                       bool tiledNoise, params string[] extra)
        {
            ReadbackRun run = Prepare(dir, spirv, grid, p, noise, tiledNoise, extra, out string[] args);
            run.Finish(HarnessRun.Harness(args));
            return run;
        }

        /// <summary>
        /// A draw's inputs written to <paramref name="dir"/> and its harness options in <paramref name="args"/>;
        /// <see cref="Finish"/> reads the run back (<see cref="Draw(string, string, PatchGrid, TerrainParams, NoiseSettings?, bool, string[])"/>
        /// in two steps, so many draws can go through one <see cref="HarnessBatch"/>).
        /// </summary>
        public static ReadbackRun Prepare(string dir, string spirv, PatchGrid grid, TerrainParams p, NoiseSettings? noise,
                                          bool tiledNoise, string[] extra, out string[] args)
        {
            Assert.That(!tiledNoise || noise.HasValue, Is.True, "the tiled noise needs noise");
            var inputs = TerrainInputs.Create(grid, p);
            int tiles = inputs.TilesAcross(), factor = (int)inputs.UniformTessFactor();
            Assert.That(factor, Is.InRange(1, 64), "readback needs an integer uniform factor");
            Assert.That((float)factor, Is.EqualTo(inputs.UniformTessFactor()), "readback needs an integer uniform factor");
            WriteBuffers(dir, inputs, TopDownCamera());
            var run = new ReadbackRun { Grid = grid, Inputs = inputs, Noise = noise, Tiles = tiles, Factor = factor,
                                        Keywords = !noise.HasValue ? TerrainKeywords.None
                                                 : tiledNoise ? TerrainKeywords.Noise | TerrainKeywords.NoiseTable : TerrainKeywords.Noise };
            run._readbackPath = Path.Combine(dir, "readback.f32");
            string variant = !noise.HasValue ? "readback" : tiledNoise ? "readback+noise+noise_table" : "readback+noise";
            var list = new List<string>(Stages(spirv, ForOrigin(variant, p.rangeOrigin)));
            if (tiledNoise)
            {
                string table = Path.Combine(dir, "noise_cells.f32");
                WriteFloats(table, GradientNoiseTable.Floats);
                list.AddRange(new[] { "--storage-data", "9:" + table });
            }
            list.AddRange(new[] { "--buffers", dir, "--patches", (tiles * tiles).ToString(), "--width", "64", "--height", "64",
                                  "--device", "llvmpipe", "--stats", "--readback", run._readbackPath, "--readback-floats", (12 * run.VertexCount).ToString() });
            list.AddRange(extra);
            args = list.ToArray();
            return run;
        }

        string _readbackPath;

        /// <summary>Reads back the draw <see cref="Prepare"/> set up, from its harness run.</summary>
        public void Finish(HarnessRun harness)
        {
            Harness = harness;
            Harness.AssertSucceeded();
            Assert.That(Harness.Value("readback", _readbackPath), Is.Not.Null, "no readback line:\n" + Harness.Stdout);
            Readback = ReadFloats(_readbackPath);
            Assert.That(Readback.Length, Is.EqualTo(12 * VertexCount));
        }

        /// <summary>Uniform tessellation settings: M x M tiles at integer factor F.</summary>
        public static TerrainParams UniformParams(PatchGrid grid, TerrainRange range, RangeOrigin origin, int tiles, int factor,
                                                  NoiseSettings? noise, float noiseVerticesAcross = 0f)
        {
            return TerrainParams.Create(grid, range, origin, TessellationSettings.Uniform(tiles, factor),
                noise ?? new NoiseSettings(0.004f, 16f, 2f, 2f, 6), new HeightColorSettings(0.25f, 0.15f, 24f),
                new Float3(0.2f, 0.3f, 0.1f), new Float3(0.8f, 0.8f, 0.8f), noiseVerticesAcross);
        }

        /// <summary>Readback index of vertex (row, col) of tile (ti, tj).</summary>
        public int Index(int ti, int tj, int row, int col) => (tj * Tiles + ti) * VerticesPerTile + row * (Factor + 1) + col;

        /// <summary>How many read-back floats are NaN or infinite.</summary>
        public int NonFinite() => Readback.Count(x => !float.IsFinite(x));

        // ---- comparison with Core -----------------------------------------------------------------

        /// <summary>
        /// The tess coordinate lavapipe used on one axis. Its tessellator works in 16.16 fixed point,
        /// so s is a multiple of 2^-16 near index/F (26/63 reads 0.41259765625): the candidate whose
        /// q and u, through Core's float TileToTerrainPoint (the range's tiles or anchored ones) and
        /// PatchLocalUV, are the GPU's bit for bit. NaN when none is.
        /// </summary>
        public float GpuTessCoordinate(bool xAxis, int slot, int index, float gpuQ, float gpuLocal)
        {
            double nominal = (double)index / Factor;
            int centre = (int)Math.Round(nominal * 65536);
            for (int k = 0; k <= 64; k++)
                foreach (int sign in k == 0 ? new[] { 1 } : new[] { 1, -1 })
                {
                    int fx = centre + sign * k;
                    if (fx < 0 || fx > 65536) continue;
                    float s = fx / 65536f;
                    TerrainPoint q = xAxis
                        ? TileLattice.TileToTerrainPoint(Inputs.Params, slot, s, 0f)
                        : TileLattice.TileToTerrainPoint(Inputs.Params, slot, 0f, s);
                    Float2 approx = RangeMapping.Approximate(q);
                    int patch = RelativeSurface.FindPatchAt(Inputs, q);
                    Float2 uv = RangeMapping.PatchLocalUV(q, Inputs.PatchRegion(patch), Inputs.PatchRegionLo(patch));
                    if (xAxis ? approx.x == gpuQ && uv.x == gpuLocal : approx.y == gpuQ && uv.y == gpuLocal) return s;
                }
            return float.NaN;
        }

        /// <summary>Core's float path at the GPU's tess coordinates, vertex by vertex, against the readback (absolute terrain units).</summary>
        public ReadbackComparison Compare()
        {
            var c = new ReadbackComparison();
            float[] v = Readback;
            var sCache = new Dictionary<(bool, int, int, float, float), float>();
            double octaves = Inputs.NoiseOctaveCount();
            Double3 offset = TerrainVertex.OutputOffset(Inputs, Grid, Keywords);
            for (int k = 0; k < VertexCount; k++)
            {
                int o = 12 * k;
                bool nan = false;
                for (int i = o; i < o + 12; i++) nan |= !float.IsFinite(v[i]);
                if (nan) { c.Nan++; continue; }
                int tile = k / VerticesPerTile, row = k % VerticesPerTile / (Factor + 1), col = k % (Factor + 1);
                int ti = tile % Tiles, tj = tile / Tiles;
                var gpuQ = new Float2(v[o + 8], v[o + 9]);
                // A column's x (a row's y) is the same in every tile of it: cached per column and row.
                float s = Cached(sCache, (true, ti, col, gpuQ.x, v[o + 10]), () => GpuTessCoordinate(true, tile, col, gpuQ.x, v[o + 10]));
                float t = Cached(sCache, (false, tj, row, gpuQ.y, v[o + 11]), () => GpuTessCoordinate(false, tile, row, gpuQ.y, v[o + 11]));
                if (float.IsNaN(s) || float.IsNaN(t))
                {
                    c.Unmatched++;
                    s = float.IsNaN(s) ? (float)col / Factor : s;
                    t = float.IsNaN(t) ? (float)row / Factor : t;
                }
                TerrainVertexOutput core = TerrainVertex.Evaluate(Inputs, tile, new Float2(s, t), Keywords);
                Float3 gp = new Float3(v[o], v[o + 1], v[o + 2]), gn = new Float3(v[o + 4], v[o + 5], v[o + 6]);
                Float3 cp = core.PositionOS, cn = core.NormalOS;
                c.Vertices++;
                c.Patches.Add(core.surface.patch);
                if (gp.Equals(cp)) c.PositionBitIdentical++;
                if (gn.Equals(cn)) c.NormalBitIdentical++;
                if (RangeMapping.Approximate(core.surface.q).Equals(gpuQ)) c.QEqual++;
                c.MaxPosition = Math.Max(c.MaxPosition, Distance(gp, cp));
                c.MaxNormal = Math.Max(c.MaxNormal, Distance(gn, cn));
                // And the float path against the double reference at the same exact point.
                TerrainVertex.Reference(Grid, core.surface.q.ToDouble(), Noise, octaves, out Double3 rp, out _, Keywords);
                rp -= offset;
                c.MaxReference = Math.Max(c.MaxReference, GMath.length(new Double3(core.position.x, core.position.y, core.position.z) - rp));
            }
            return c;
        }

        static float Cached(Dictionary<(bool, int, int, float, float), float> cache, (bool, int, int, float, float) key, Func<float> f)
        {
            if (!cache.TryGetValue(key, out float s)) cache[key] = s = f();
            return s;
        }

        public static double Distance(Float3 a, Float3 b)
        {
            double dx = (double)a.x - b.x, dy = (double)a.y - b.y, dz = (double)a.z - b.z;
            return Math.Sqrt(dx * dx + dy * dy + dz * dz);
        }

        // ---- shared tile edges --------------------------------------------------------------------

        /// <summary>
        /// Every vertex on a shared tile edge against its neighbour's copy: pairs checked, and pairs that
        /// differ in any bit of position, normal, q or u, v.
        /// </summary>
        public (int pairs, int differing) SharedEdges()
        {
            int pairs = 0, differing = 0;
            for (int tj = 0; tj < Tiles; tj++)
                for (int ti = 0; ti < Tiles; ti++)
                    for (int i = 0; i <= Factor; i++)
                    {
                        if (ti + 1 < Tiles)   // right edge of (ti, tj) = left edge of (ti + 1, tj)
                        {
                            pairs++;
                            if (!SameBits(Index(ti, tj, i, Factor), Index(ti + 1, tj, i, 0))) differing++;
                        }
                        if (tj + 1 < Tiles)   // top edge of (ti, tj) = bottom edge of (ti, tj + 1)
                        {
                            pairs++;
                            if (!SameBits(Index(ti, tj, Factor, i), Index(ti, tj + 1, 0, i))) differing++;
                        }
                    }
            return (pairs, differing);
        }

        bool SameBits(int a, int b)
        {
            for (int k = 0; k < 12; k++)
                if (k % 4 != 3 && BitConverter.SingleToInt32Bits(Readback[12 * a + k]) != BitConverter.SingleToInt32Bits(Readback[12 * b + k])) return false;
            return true;
        }

        /// <summary>The diagonal of the control points' bounding box: the terrain's extent.</summary>
        public static double TerrainExtent(PatchGrid grid)
        {
            var (lo, hi) = ControlPointBox(grid);
            return GMath.length(hi - lo);
        }

        /// <summary>The control points' bounding box, in terrain space (x, y, height).</summary>
        public static (Double3 lo, Double3 hi) ControlPointBox(PatchGrid grid)
        {
            var lo = new Double3(double.MaxValue, double.MaxValue, double.MaxValue);
            var hi = new Double3(double.MinValue, double.MinValue, double.MinValue);
            foreach (GregoryPatch p in grid.Patches)
                foreach (Double3 q in p.Points)
                {
                    lo = new Double3(Math.Min(lo.x, q.x), Math.Min(lo.y, q.y), Math.Min(lo.z, q.z));
                    hi = new Double3(Math.Max(hi.x, q.x), Math.Max(hi.y, q.y), Math.Max(hi.z, q.z));
                }
            return (lo, hi);
        }
    }
}
