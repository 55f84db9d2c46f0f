// Snow on the terrain (GT_SNOW) in the rig: the snow-off build is the build without snow code, the
// snow stages against Core (readback), the field kernel against Core, and the whole chain
// (SnowFieldKernel -> SnowExposureKernel -> SnowAccumulateKernel) on lavapipe against the CPU
// reference on a ridge across the wind. They fail (never skip) when glslang, the harness, gt-compute,
// gt-cli or lavapipe is missing: `gt setup` provides them.
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture, Parallelizable(ParallelScope.Self), Order(8)]
    public class SnowRenderTests
    {
        static readonly string[] Stages = { "vert", "tesc", "tese", "frag", "fallback" };
        static readonly string[] Entries = { "vert", "hull_shader", "domain_shader", "frag", "vert_fallback" };
        static readonly string[] GlslangStages = { "vert", "tesc", "tese", "frag", "vert" };
        // What shaders.py (STAGE_DEFINES) defines per stage: the no-tessellator pass is GT_FALLBACK.
        static readonly string[][] StageDefines = { new string[0], new string[0], new string[0], new string[0], new[] { "-DGT_FALLBACK" } };
        // The terrain stages' register shifts (shaders.py REGISTER_SHIFTS, Tools~/rig/README.md bindings).
        static readonly string[] Shifts = { "--hlsl-iomap", "--shift-cbuffer-binding", "0", "--shift-texture-binding", "2", "--shift-UAV-binding", "5" };

        string _root, _work, _spirv, _cli, _runner;

        [OneTimeSetUp]
        public void Build()
        {
            _root = HarnessRun.PackageRoot();
            Assert.That(File.Exists(HarnessRun.HarnessPath()), Is.True, "gt-harness not built (run Tools~/gt setup)");
            Assert.That(File.Exists(HarnessRun.LavapipeIcd), Is.True, "lavapipe is not installed");
            _cli = Path.Combine(_root, ".build", "gt-cli", "gt-cli");
            Assert.That(File.Exists(_cli), Is.True, "gt-cli not built at " + _cli + " (run Tools~/gt setup)");
            _runner = Path.Combine(_root, ".build", "computerig", "gt-compute");
            Assert.That(File.Exists(_runner), Is.True, "gt-compute not built at " + _runner + " (run Tools~/gt setup)");
            _work = Path.Combine(Path.GetTempPath(), "gt-snowrender-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_work);
            var args = new List<string> { Path.Combine(_root, "Tools~", "gt"), "shaders", "--spirv-only" };
            foreach (string v in new[] { "base", "snow", "readback", "readback+snow", "noise+height_color+snow", "noise+snow", "noise+snow+vertex_cache" }) { args.Add("--only"); args.Add(v); }
            Exec("bash", args.ToArray(), new Dictionary<string, string> { ["GT_BUILD_DIR"] = _work });
            _spirv = Path.Combine(_work, "spirv");
        }

        [OneTimeTearDown]
        public void Clean()
        {
            if (_work != null && Directory.Exists(_work)) Directory.Delete(_work, true);
        }

        // ---- zero cost when off ----------------------------------------------------------------

        /// <summary>
        /// Removes every <c>#if defined(GT_SNOW)</c> block (keeping an <c>#else</c> branch) from HLSL
        /// text: what the shaders would be had snow never been written.
        /// </summary>
        static string StripSnow(string text, out int blocks)
        {
            var output = new StringBuilder();
            var stack = new Stack<(bool snow, bool keep)>();   // per open #if: is it GT_SNOW, is its current branch kept
            blocks = 0;
            foreach (string line in text.Split('\n'))
            {
                string t = line.Trim();
                bool outerKept = stack.All(s => s.keep);
                if (Regex.IsMatch(t, @"^#\s*if"))
                {
                    bool snow = Regex.IsMatch(t, @"^#\s*if\s+defined\s*\(\s*GT_SNOW\s*\)\s*$");
                    if (snow) blocks++;
                    stack.Push((snow, !snow));
                    if (!snow && outerKept) output.Append(line).Append('\n');
                    continue;
                }
                if (stack.Count > 0 && stack.Peek().snow && Regex.IsMatch(t, @"^#\s*(else|elif)"))
                {
                    stack.Pop();
                    stack.Push((true, true));   // the snow-off branch stays
                    continue;
                }
                if (Regex.IsMatch(t, @"^#\s*endif"))
                {
                    var top = stack.Pop();
                    if (!top.snow && stack.All(s => s.keep)) output.Append(line).Append('\n');
                    continue;
                }
                if (outerKept) output.Append(line).Append('\n');
            }
            Assert.That(stack, Is.Empty, "unbalanced #if");
            return output.ToString().TrimEnd('\n') + (text.EndsWith("\n") ? "\n" : "");
        }

        [Test]
        public void SnowOffStagesAreByteIdenticalToABuildWithoutAnySnowCode()
        {
            // A copy of Shaders/ with every GT_SNOW block cut out and the snow-only files deleted.
            string shaders = Path.Combine(_root, "Shaders"), copy = Path.Combine(_work, "nosnow", "Shaders");
            int blocks = 0;
            foreach (string file in Directory.GetFiles(shaders, "*.hlsl", SearchOption.AllDirectories))
            {
                string rel = Path.GetRelativePath(shaders, file), dst = Path.Combine(copy, rel);
                Directory.CreateDirectory(Path.GetDirectoryName(dst));
                if (Path.GetFileName(file) == "SnowMap.hlsl") continue;
                string text = File.ReadAllText(file);
                File.WriteAllText(dst, StripSnow(text, out int b));
                blocks += b;
            }
            // The rig's entry file, at the same place relative to the copy (it includes ../../Shaders).
            string rigEntry = Path.Combine(_work, "nosnow", "Tools~", "rig", "TerrainRig.hlsl");
            Directory.CreateDirectory(Path.GetDirectoryName(rigEntry));
            File.WriteAllText(rigEntry, StripSnow(File.ReadAllText(Path.Combine(_root, "Tools~", "rig", "TerrainRig.hlsl")), out int rigBlocks));
            Assert.That(rigBlocks, Is.EqualTo(0), "the rig's entry file has no snow code of its own");
            TestContext.Out.WriteLine($"{blocks} GT_SNOW blocks cut");
            Assert.That(blocks, Is.GreaterThanOrEqualTo(6), "the snow code lives in GT_SNOW blocks");
            foreach (string file in Directory.GetFiles(copy, "*.hlsl", SearchOption.AllDirectories))
            {
                // Code only: comments may mention snow.
                string code = string.Join("\n", File.ReadAllLines(file).Select(l => l.Split("//")[0]));
                Assert.That(code, Does.Not.Contain("_SnowDepth").And.Not.Contain("SnowMap"), file);
            }

            for (int k = 0; k < Stages.Length; k++)
            {
                string stripped = Path.Combine(_work, "nosnow", Stages[k] + ".spv");
                Exec("glslangValidator", new[] { "-D", "-V", "-S", GlslangStages[k], "-e", Entries[k] }.Concat(StageDefines[k]).Concat(Shifts)
                    .Concat(new[] { "-o", stripped, rigEntry }).ToArray(), null);
                byte[] shipped = File.ReadAllBytes(Path.Combine(_spirv, "base", Stages[k] + ".spv"));
                Assert.That(File.ReadAllBytes(stripped), Is.EqualTo(shipped), "base/" + Stages[k] + " differs from the build without snow code");
            }
        }

        [Test]
        public void SnowCostsInstructionsOnlyWhereItWorksAndItsBufferOnlyExistsWithTheKeyword()
        {
            foreach (string stage in Stages)
            {
                int off = Instructions("base", stage), on = Instructions("snow", stage);
                TestContext.Out.WriteLine($"{stage}: snow off {off}, snow on {on} SPIR-V instructions");
                // vert only declares the longer cbuffer (one member and its name); no snow code.
                if (stage == "vert") Assert.That(on - off, Is.LessThanOrEqualTo(2));
                else Assert.That(on, Is.GreaterThan(off), stage);
            }
            foreach (string variant in new[] { "base", "readback", "snow", "readback+snow", "noise+height_color+snow" })
                foreach (string stage in Stages)
                {
                    string dis = Disassemble(variant, stage);
                    bool samples = stage == "tese" || stage == "fallback";
                    Assert.That(dis.Contains("\"_SnowDepth\""), Is.EqualTo(variant.Contains("snow") && samples), $"{variant}/{stage} _SnowDepth");
                    Assert.That(dis.Contains("\"_SnowMapSize\""), Is.EqualTo(variant.Contains("snow")), $"{variant}/{stage} _SnowMapSize");
                }
        }

        int Instructions(string variant, string stage) =>
            Disassemble(variant, stage).Split('\n').Select(l => l.Trim()).Count(l => l.Length > 0 && !l.StartsWith(";"));

        string Disassemble(string variant, string stage) =>
            Exec("spirv-dis", new[] { "--no-header", Path.Combine(_spirv, variant, stage + ".spv") }, null);

        // ---- the snow stages against Core --------------------------------------------------------

        const int SceneTiles = 8, SceneFactor = 15, SceneMapSize = 128;
        const float SceneCap = 0.02f;

        /// <summary>
        /// The snow scene of the readback tests, its buffers written to <paramref name="dir"/>: the demo
        /// grid, 8 x 8 tiles at F = 15, noise, a top-down camera, and a depth map with structure at every
        /// scale the bilinear read sees, from 0 to the cap (depth.f32, size.f32).
        /// </summary>
        TerrainInputs WriteSnowScene(string dir)
        {
            const int tiles = SceneTiles, factor = SceneFactor, r = SceneMapSize;
            const float cap = SceneCap;
            string grid = Path.Combine(_work, "grid.json");
            if (!File.Exists(grid)) Exec(_cli, new[] { "demo-grid", "--samples", "129", "--out", grid }, null);
            PatchGrid g = PatchGridJson.Read(File.ReadAllText(grid));
            var p = TerrainParams.Create(g, TerrainRange.full, RangeOrigin.zero, TessellationSettings.Uniform(tiles, factor),
                new NoiseSettings(0.004f, 16f, 2f, 2f, 6), new HeightColorSettings(0.25f, 0.15f, 24f), new Float3(0, 0, 0), new Float3(1, 1, 1));
            // A depth map with structure at every scale the bilinear read sees, from 0 to the cap.
            var depth = new float[r * r];
            for (int j = 0; j < r; j++)
                for (int i = 0; i < r; i++)
                    depth[j * r + i] = cap * (float)(0.5 + 0.5 * Math.Sin(0.37 * i + 0.11 * j * j / r) * Math.Cos(0.23 * j));
            var snow = new SnowMap(depth, r, cap);
            TerrainInputs inputs = TerrainInputs.Create(g, p).WithSnow(snow);
            Directory.CreateDirectory(dir);
            WriteFloats(Path.Combine(dir, "control_points.f32"), inputs.ControlPoints);
            WriteFloats(Path.Combine(dir, "regions.f32"), inputs.Regions);
            WriteFloats(Path.Combine(dir, "grid_lines.f32"), inputs.GridLines);
            WriteFloats(Path.Combine(dir, "params.f32"), p.Pack());
            WriteFloats(Path.Combine(dir, "camera.f32"), TopDownCamera());
            WriteFloats(Path.Combine(dir, "depth.f32"), depth);
            Float4 size = snow.MapSize;
            WriteFloats(Path.Combine(dir, "size.f32"), new[] { size.x, size.y, size.z, size.w });
            return inputs;
        }

        string[] SnowMapArgs(string dir) => new[] { "--snow-depth", Path.Combine(dir, "depth.f32"), "--snow-params", Path.Combine(dir, "size.f32") };

        [Test]
        public void ReadbackWithSnowIsCoresTerrainVertexWithSnow()
        {
            const int tiles = SceneTiles, factor = SceneFactor, r = SceneMapSize;
            const float cap = SceneCap;
            string dir = Path.Combine(_work, "readback");
            TerrainInputs inputs = WriteSnowScene(dir);
            int vertices = tiles * tiles * (factor + 1) * (factor + 1);
            string v = Path.Combine(_spirv, "readback+snow"), readback = Path.Combine(dir, "readback.f32");
            HarnessRun h = HarnessRun.Harness(new[]
            {
                "--vert", Path.Combine(v, "vert.spv"), "--tesc", Path.Combine(v, "tesc.spv"),
                "--tese", Path.Combine(v, "tese.spv"), "--frag", Path.Combine(v, "frag.spv"), "--buffers", dir,
                "--patches", (tiles * tiles).ToString(), "--width", "64", "--height", "64", "--device", "llvmpipe",
                "--readback", readback, "--readback-floats", (12 * vertices).ToString(),
            }.Concat(SnowMapArgs(dir)).ToArray());
            Assert.That(h.ExitCode, Is.EqualTo(0), h.Stdout + h.Stderr);
            Assert.That(h.Long("inputs", "snow_resolution"), Is.EqualTo(r));
            float[] rb = ReadFloats(readback);
            double worst = 0, maxRaise = 0;
            int nan = 0;
            for (int k = 0; k < vertices; k++)
            {
                int o = 12 * k;
                if (float.IsNaN(rb[o]) || float.IsNaN(rb[o + 8])) { nan++; continue; }
                // Core at exactly the point the GPU used (origin 0: q is the read-back float).
                var q = new TerrainPoint(default, new Float2(rb[o + 8], rb[o + 9]));
                TerrainVertexOutput core = TerrainVertex.EvaluateAt(inputs, q, TerrainKeywords.Snow);
                Float3 gpu = new Float3(rb[o], rb[o + 1], rb[o + 2]);
                worst = Math.Max(worst, GMath.length(gpu - core.PositionOS));
                maxRaise = Math.Max(maxRaise, core.snowDepth);
            }
            TestContext.Out.WriteLine($"{vertices} vertices with snow: max |GPU - Core| {worst:E2}, max depth {maxRaise:E3}");
            Assert.That(nan, Is.EqualTo(0));
            Assert.That(maxRaise, Is.GreaterThan(0.9 * cap), "the map must raise the surface");
            // Float evaluation on two machines: a few ulp of heights of order 0.3 (the no-snow
            // readback test holds the same path to this size).
            Assert.That(worst, Is.LessThan(2e-6));
        }

        /// <summary>
        /// GT_SNOW through the vertex cache: the record's second uint4 holds the vertex's snow depth
        /// (its first, the snowed position and the packed shading), each slot Core's vertex with snow,
        /// and the cached draw shows the direct snow draw's picture (F = 15 is odd: fractional_odd and
        /// integer partitioning make the same vertices).
        /// </summary>
        [Test]
        public void CachedSnowRecordsHoldCoresSnowedVertexAndDrawTheDirectPicture()
        {
            const int tiles = SceneTiles;
            const TerrainKeywords keywords = TerrainKeywords.Noise | TerrainKeywords.Snow;
            string dir = Path.Combine(_work, "cached");
            TerrainInputs inputs = WriteSnowScene(dir);
            int limit = VertexCache.FactorLimit(inputs.Params.tess), slots = VertexCache.SlotsPerTile(limit);
            string cache = Path.Combine(_spirv, "noise+snow+vertex_cache"), direct = Path.Combine(_spirv, "noise+snow");
            string factorsFile = Path.Combine(dir, "tile_factors.f32"), recordsFile = Path.Combine(dir, "vertex_cache.u32");
            HarnessRun Draw(string variant, string png, params string[] extra) => HarnessRun.Harness(new[]
            {
                "--vert", Path.Combine(variant, "vert.spv"), "--tesc", Path.Combine(variant, "tesc.spv"), "--tese", Path.Combine(variant, "tese.spv"),
                "--frag", Path.Combine(variant, "frag.spv"), "--buffers", dir, "--patches", (tiles * tiles).ToString(), "--width", "64", "--height", "64",
                "--device", "llvmpipe", "--stats", "--png", png,
            }.Concat(SnowMapArgs(dir)).Concat(extra).ToArray());
            HarnessRun cached = Draw(cache, Path.Combine(dir, "cached.png"),
                ReadbackRun.VertexCacheArgs(cache, tiles, limit, true, factorsFile, recordsFile));
            cached.AssertSucceeded();
            HarnessRun plain = Draw(direct, Path.Combine(dir, "direct.png"));
            plain.AssertSucceeded();
            float[] factors = ReadFloats(factorsFile);
            uint[] records = ReadbackRun.ReadUints(recordsFile);
            Assert.That(records.Length, Is.EqualTo(8 * tiles * tiles * slots), "two uint4 a slot with snow");
            double worstPosition = 0, worstDepth = 0, worstNormal = 0, maxDepth = 0;
            int compared = 0, padding = 0;
            for (int tile = 0; tile < tiles * tiles; tile++)
            {
                TileFactorSet f = ReadbackRun.CacheTileFactors(factors, tile);
                Assert.That(f.IsCulled, Is.False, "the top-down view sees tile " + tile);
                foreach (var (tess, slot) in VertexCache.TilePoints(f, limit))
                {
                    TerrainVertexOutput v = TerrainVertex.Evaluate(inputs, tile, tess, keywords);
                    uint[] core = VertexCache.Record(v, TerrainVertex.HeightWeight(v, inputs, keywords), snow: true);
                    int o = 8 * (tile * slots + slot);
                    var gpuPosition = new Float3(ReadbackRun.FloatOfBits(records[o]), ReadbackRun.FloatOfBits(records[o + 1]), ReadbackRun.FloatOfBits(records[o + 2]));
                    worstPosition = Math.Max(worstPosition, GMath.length(gpuPosition - v.PositionOS));
                    Float3 gpuShading = VertexCache.UnpackCachedVaryings(records[o + 3]), coreShading = VertexCache.UnpackCachedVaryings(core[3]);
                    worstNormal = Math.Max(worstNormal, Math.Max(Math.Abs(gpuShading.x - coreShading.x), Math.Abs(gpuShading.y - coreShading.y)));
                    worstDepth = Math.Max(worstDepth, Math.Abs(ReadbackRun.FloatOfBits(records[o + 4]) - v.snowDepth));
                    maxDepth = Math.Max(maxDepth, ReadbackRun.FloatOfBits(records[o + 4]));
                    if (records[o + 5] != 0u || records[o + 6] != 0u || records[o + 7] != 0u) padding++;
                    compared++;
                }
            }
            RigPng a = RigPng.Read(Path.Combine(dir, "cached.png")), b = RigPng.Read(Path.Combine(dir, "direct.png"));
            int differing = a.PixelsDifferingFrom(b, 8);
            TestContext.Out.WriteLine("{0} cached snow vertices against Core: position {1:E2}, snow depth {2:E2} (max depth {3:E3}), encoded normal {4:G3}; cached vs direct: {5} of 4096 pixels differ by more than 8/255",
                compared, worstPosition, worstDepth, maxDepth, worstNormal, differing);
            Assert.That(compared, Is.EqualTo(tiles * tiles * (14 * 14 + 4 * 16)), "8 x 8 tiles, 14 x 14 interior points and 4 edges of 16 at F = 15");
            Assert.That(maxDepth, Is.GreaterThan(0.9 * SceneCap), "the map must raise the surface");
            Assert.That(worstPosition, Is.LessThan(2e-6), "the readback test's bound");
            Assert.That(worstDepth, Is.LessThan(1e-6));
            Assert.That(worstNormal, Is.LessThanOrEqualTo(2.0 / 1023 + 1e-6), "one step of the packing at most");
            Assert.That(padding, Is.EqualTo(0), "the snow part's last three words are zero");
            Assert.That(cached.Long("stat", "clipping_invocations"), Is.EqualTo(plain.Long("stat", "clipping_invocations")), "same triangles");
            Assert.That(differing, Is.LessThan(4096 / 200), "at most 0.5% of the pixels differ");
        }

        static float[] TopDownCamera()
        {
            float[,] m = { { 2, 0, 0, -1 }, { 0, 0, 2, -1 }, { 0, 0.01f, 0, 0.5f }, { 0, 0, 0, 1 } };
            var cam = new List<float>();
            for (int c = 0; c < 4; c++) for (int r = 0; r < 4; r++) cam.Add(m[r, c]);
            for (int c = 0; c < 4; c++) for (int r = 0; r < 4; r++) cam.Add(r == c ? 1 : 0);
            cam.AddRange(new float[] { 0.5f, 2, 0.5f, 1, 64, 64, 1f / 64, 1f / 64, 0, 1, 0, 0 });
            return cam.ToArray();
        }

        // ---- the field kernel and the whole chain ------------------------------------------------

        string CompileCompute(string file, string entry, params string[] extra)
        {
            string spv = Path.Combine(_work, entry + string.Join("", extra) + ".spv");
            var args = new List<string> { "-D", "-V", "-S", "comp", "-e", entry };
            if (file == "SnowField.compute") args.AddRange(Shifts);
            args.AddRange(extra);
            args.AddRange(new[] { "-o", spv, Path.Combine(_root, "Shaders", "Snow", file) });
            Exec("glslangValidator", args.ToArray(), null);
            Exec("spirv-val", new[] { spv }, null);
            return spv;
        }

        /// <summary>The snow scene of gt-cli snow-scene at one R (ridge across a +x wind).</summary>
        (string dir, TerrainInputs terrain, SnowSettings settings, int steps, float dt) Scene(int r)
        {
            string dir = Path.Combine(_work, "scene" + r);
            Exec(_cli, new[] { "snow-scene", "--out", dir, "--resolutions", r.ToString(), "--steps", "40", "--dt", "0.25" }, null);
            PatchGrid g = PatchGridJson.Read(File.ReadAllText(Path.Combine(dir, "grid.json")));
            float[] pf = ReadFloats(Path.Combine(dir, "scene", "params.f32"));
            var p = new TerrainParams();
            Float4 F(int i) => new Float4(pf[4 * i], pf[4 * i + 1], pf[4 * i + 2], pf[4 * i + 3]);
            p.range = F(0); p.rangeOrigin = F(1); p.gridSize = F(2); p.tess = F(3); p.noise = F(4);
            p.noiseOctaves = F(5); p.heightColor = F(6); p.colorLow = F(7); p.colorHigh = F(8);
            float[] sp = ReadFloats(Path.Combine(dir, $"snow_params_{r}.f32"));
            // Rebuild the settings from the packed params (the fields the step and exposure read).
            var s = SnowSettings.Default;
            s.resolution = r; s.rayLength = sp[2]; s.raySteps = (int)sp[3];
            float cosF = sp[6], sinF = sp[7];
            s.fallSpeed = 1f; s.wind = new Float2(-sp[4] * cosF / sinF, -sp[5] * cosF / sinF);
            s.scale = sp[11]; s.edgeStrength = sp[12]; s.edgeWidth = sp[13]; s.exposureSoftness = sp[14];
            s.depthCap = sp[17]; s.meltRate = sp[18];
            Assert.That(s.Params(sp[16]).Pack(), Is.EqualTo(sp).Within(1e-6f), "the scene's SnowParams round-trip");
            return (dir, TerrainInputs.Create(g, p), s, 40, sp[16]);
        }

        [Test]
        public void FieldKernelIsCoresTerrainAtTheCellCentresAndTheChainMatchesTheCpuReference()
        {
            const int r = 128;
            var (dir, terrain, settings, steps, dt) = Scene(r);
            string fieldSpv = CompileCompute("SnowField.compute", "SnowFieldKernel", "-DGT_NOISE");
            string exposureSpv = CompileCompute("SnowSimulation.compute", "SnowExposureKernel");
            string stepSpv = CompileCompute("SnowSimulation.compute", "SnowAccumulateKernel");
            string s = Path.Combine(dir, "scene"), groups = $"{r / 8},{r / 8}";
            string field = Path.Combine(dir, "gpu_field.f32"), exposure = Path.Combine(dir, "gpu_exposure.f32"), depth = Path.Combine(dir, "gpu_depth.f32");
            string o = Exec(_runner, new[] { "--spv", fieldSpv, "--entry", "SnowFieldKernel", "--device", "llvmpipe", "--groups", groups,
                "--uniform", "0=" + Path.Combine(dir, $"field_params_{r}.f32"), "--buffer", "2=" + Path.Combine(s, "control_points.f32"),
                "--buffer", "3=" + Path.Combine(s, "regions.f32"), "--buffer", "4=" + Path.Combine(s, "grid_lines.f32"),
                "--zeros", $"5={16 * r * r}", "--out", "5=" + field }, null);
            Assert.That(o, Does.Contain("device llvmpipe"));
            string sp = Path.Combine(dir, $"snow_params_{r}.f32");
            Exec(_runner, new[] { "--spv", exposureSpv, "--entry", "SnowExposureKernel", "--device", "llvmpipe", "--groups", groups,
                "--uniform", "0=" + sp, "--buffer", "1=" + field, "--zeros", $"2={4 * r * r}", "--out", "2=" + exposure }, null);
            Exec(_runner, new[] { "--spv", stepSpv, "--entry", "SnowAccumulateKernel", "--device", "llvmpipe", "--groups", groups,
                "--repeat", steps.ToString(), "--uniform", "0=" + sp, "--buffer", "1=" + field, "--buffer", "2=" + exposure,
                "--zeros", $"3={4 * r * r}", "--out", "3=" + depth }, null);

            // Core: the same field by the same path, and the CPU simulation on it.
            var cpuField = new SnowField(r);
            SnowFieldTerrain.Evaluate(terrain, cpuField, TerrainKeywords.Noise);
            var sim = new SnowSimulation(settings);
            for (int n = 0; n < steps; n++) sim.Step(cpuField, dt);

            float[] gf = ReadFloats(field), ge = ReadFloats(exposure), gd = ReadFloats(depth);
            double dh = 0, dn = 0, de = 0, dd = 0;
            for (int k = 0; k < r * r; k++)
            {
                dh = Math.Max(dh, Math.Abs(gf[4 * k + 3] - cpuField.Data[4 * k + 3]));
                for (int c = 0; c < 3; c++) dn = Math.Max(dn, Math.Abs(gf[4 * k + c] - cpuField.Data[4 * k + c]));
                de = Math.Max(de, Math.Abs(ge[k] - sim.Exposure[k]));
                dd = Math.Max(dd, Math.Abs(gd[k] - sim.Depth[k]));
            }
            TestContext.Out.WriteLine($"R {r}: field max |dh| {dh:E2}, max |dn| {dn:E2}; exposure max diff {de:E2}; depth after {steps} steps max diff {dd:E2} (cap {settings.depthCap})");
            Assert.That(dh, Is.LessThan(2e-6), "field height");
            Assert.That(dn, Is.LessThan(2e-5), "field normal");
            // Exposure: smoothstep of a max over a march; the field's last-ulp differences move a
            // sample's occlusion by about 1e-5, times 1.5 / softness (0.1).
            Assert.That(de, Is.LessThan(1e-3), "exposure");
            Assert.That(dd, Is.LessThan(1e-3 * settings.depthCap), "depth");

            // What the snow must look like on this ridge (crest near x = 0.5 at y = 0.5; wind +x).
            int j = r / 2;
            float D(double x) => gd[j * r + (int)(x * r)];
            float Nz(double x) => gf[4 * (j * r + (int)(x * r)) + 2];
            double windward = D(0.44), lee = D(0.56), flat = D(0.95);
            TestContext.Out.WriteLine($"depth / cap: windward face {windward / settings.depthCap:F3}, lee face {lee / settings.depthCap:F3}, open ground downwind {flat / settings.depthCap:F3}");
            Assert.That(Nz(0.95), Is.GreaterThan(0.98f), "open ground faces up");
            Assert.That(flat, Is.GreaterThan(0.8 * settings.depthCap), "level open ground accumulates");
            Assert.That(Nz(0.44), Is.LessThan(0.95f).And.GreaterThan(0.3f), "the windward twin is a slope");
            Assert.That(Nz(0.56), Is.LessThan(0.95f).And.GreaterThan(0.3f), "the lee twin is a slope");
            Assert.That(windward, Is.GreaterThan(0.3 * settings.depthCap));
            Assert.That(lee, Is.LessThan(0.25 * windward), "the lee face gets much less than its wind-facing twin");
        }

        // ---- helpers ---------------------------------------------------------------------------

        static void WriteFloats(string path, float[] values) => ReadbackRun.WriteFloats(path, values);

        static float[] ReadFloats(string path) => ReadbackRun.ReadFloats(path);

        // Every tool this fixture runs sees lavapipe only.
        static string Exec(string file, string[] args, Dictionary<string, string> env)
        {
            var withLavapipe = new Dictionary<string, string> { ["VK_ICD_FILENAMES"] = HarnessRun.LavapipeIcd };
            if (env != null) foreach (var kv in env) withLavapipe[kv.Key] = kv.Value;
            return ReadbackRun.Exec(file, args, withLavapipe);
        }
    }
}
