using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace GregoryTerrain.Rig
{
    /// <summary>One configuration of the accuracy sweep (a row of the table, before the camera path).</summary>
    sealed class BenchConfig
    {
        public string Method;       // paper | uniform | adaptive | fallback
        public bool Cached;         // adaptive / uniform through the vertex cache (GT_VERTEX_CACHE, integer partitioning)
        public int Tiles = 16;
        public double Factor;       // uniform factor (paper, uniform, fallback)
        public double Target;       // pixel error (adaptive)
        public double MaxFactor = 64;
        public int Octaves;         // 0: GT_NOISE off

        public string Name => (Cached ? "cached_" : "") + Method switch
        {
            "adaptive" => Inv($"adaptive_m{Tiles}_e{Target}_max{MaxFactor}_o{Octaves}"),
            "paper" => Inv($"paper_f{Factor}_o{Octaves}"),
            _ => Inv($"{Method}_m{Tiles}_f{Factor}_o{Octaves}"),
        };

        /// <summary>The method as the tables name it: "cached adaptive", "cached uniform" for the vertex cache.</summary>
        public string Label => Cached ? "cached " + Method : Method;

        public bool Noise => Octaves > 0;
        public string Variant => Method == "paper" ? (Noise ? "paper_mode+noise" : "paper_mode")
            : Cached ? (Noise ? "noise+vertex_cache" : "vertex_cache") : (Noise ? "noise" : "base");
        public string FactorVariant => Noise ? "factor_readback+noise" : "factor_readback";

        static string Inv(FormattableString s) => s.ToString(CultureInfo.InvariantCulture);
    }

    /// <summary>
    /// gt-cli bench-plan: writes everything one benchmark run needs, so the run itself is a shell
    /// script and the harness (the NVIDIA machine has no dotnet): the buffers of every
    /// (configuration, camera) pair, and plan.tsv, one harness job a line:
    /// <c>ID KIND REF ARGS...</c> (tab-separated) where KIND is run (time + statistics; vertex-cache
    /// jobs also dump their _TileFactors to @OUT@/readback/ID.tiles.f32), readback
    /// (GT_FACTOR_READBACK factors), static-match (a static grid mesh with as many triangles as job
    /// REF drew) or static-bake (a GT_READBACK capture of the terrain's vertices, packed into
    /// @OUT@/static/REF for vert_static); ARGS may hold @SPV@, @JOB@, @OUT@ and @MESH@, filled in by
    /// Tools~/rig/bench_run.sh.
    /// </summary>
    static partial class BenchPlan
    {
        /// <summary>The fixed camera path: the paper's zoom view at three ranges, whole terrain to close up.</summary>
        public static readonly (string name, double[] range)[] CameraPath =
        {
            ("far", new[] { 0.0, 0.0, 1.0, 1.0 }),
            ("mid", new[] { 0.25, 0.30, 0.65, 0.70 }),
            ("near", new[] { 0.42, 0.45, 0.52, 0.55 }),
        };

        public static List<BenchConfig> Sweep(bool quick)
        {
            var list = new List<BenchConfig>();
            double[] targets = quick ? new[] { 4.0, 1.0, 0.5 } : new[] { 8.0, 4.0, 2.0, 1.0, 0.5, 0.25 };
            double[] factors = quick ? new[] { 3.0, 7.0, 15.0 } : new[] { 3.0, 7.0, 15.0, 31.0, 63.0 };
            int[] octaves = quick ? new[] { 0 } : new[] { 0, 4 };
            int tiles = quick ? 8 : 16;
            foreach (int o in octaves)
            {
                foreach (double e in targets) list.Add(new BenchConfig { Method = "adaptive", Tiles = tiles, Target = e, Octaves = o });
                foreach (double f in factors) list.Add(new BenchConfig { Method = "uniform", Tiles = tiles, Factor = f, Octaves = o });
                double[] few = quick ? new[] { 3.0, 15.0 } : factors;
                foreach (double f in few) list.Add(new BenchConfig { Method = "paper", Tiles = 1, Factor = f, Octaves = o });
                foreach (double f in few) list.Add(new BenchConfig { Method = "fallback", Tiles = tiles, Factor = f, Octaves = o });
                // The vertex cache (compute pre-pass + integer partitioning) at the same targets and factors.
                foreach (double e in targets) list.Add(new BenchConfig { Method = "adaptive", Cached = true, Tiles = tiles, Target = e, Octaves = o });
                foreach (double f in quick ? new[] { 3.0, 15.0 } : factors) list.Add(new BenchConfig { Method = "uniform", Cached = true, Tiles = tiles, Factor = f, Octaves = o });
            }
            if (!quick)
            {
                // Tile count and max factor at a 1-pixel target, and the tile count for uniform factors.
                foreach (int m in new[] { 8, 32 })
                {
                    list.Add(new BenchConfig { Method = "adaptive", Tiles = m, Target = 1, Octaves = 0 });
                    list.Add(new BenchConfig { Method = "uniform", Tiles = m, Factor = 15, Octaves = 0 });
                }
                foreach (double e in new[] { 1.0, 0.5 })
                    list.Add(new BenchConfig { Method = "adaptive", Tiles = 16, Target = e, MaxFactor = 16, Octaves = 0 });
            }
            return list;
        }

        public static int Run(Args a)
        {
            var grid = RigScene.ReadGrid(a);
            string dir = a.String("out");
            bool quick = a.Flag("quick");
            int width = a.Int("width", quick ? 480 : 1920), height = a.Int("height", quick ? 270 : 1080);
            int frames = a.Int("frames", quick ? 3 : 60), warmup = a.Int("warmup", quick ? 1 : 10);
            Directory.CreateDirectory(dir);
            var plan = new StringBuilder();
            var meta = new StringBuilder("id\tmethod\ttiles\tfactor\ttarget\tmaxfactor\toctaves\tcamera\tpatches\n");
            string view = Inv($"--width {width} --height {height}");
            string timing = Inv($"--stats --timestamps --frames {frames} --warmup {warmup}");

            Table1(grid, dir, plan, meta, quick, width, height);   // first: the figures that matter most if a run is cut short
            var targets = new Dictionary<string, double>();
            FairStatic(grid, dir, plan, meta, quick, width, height, targets);
            Motion(grid, dir, plan, meta, quick, width, height, targets);
            Levels(grid, dir, plan, meta, quick, width, height);
            var path = quick ? new[] { CameraPath[0], CameraPath[2] } : CameraPath;
            foreach (var cfg in Sweep(quick))
                foreach (var (cam, range) in path)
                {
                    string id = cfg.Name + "@" + cam;
                    var scene = Scene(grid, cfg, range, width, height);
                    scene.WriteBuffers(Path.Combine(dir, "jobs", id));
                    int patches = cfg.Method == "paper" ? grid.PatchCount : cfg.Tiles * cfg.Tiles;
                    meta.Append(Inv($"{id}\t{cfg.Label}\t{cfg.Tiles}\t{cfg.Factor}\t{cfg.Target}\t{cfg.MaxFactor}\t{cfg.Octaves}\t{cam}\t{patches}\n"));
                    string buffers = "--buffers @JOB@/" + id;
                    // Cached rows: the range changing every frame, so both kernels evaluate every tile
                    // every frame, as while the view moves (the last frame draws the plan's range).
                    if (cfg.Cached)
                        plan.Append($"{id}\trun\t-\t{Stages(cfg.Variant, fallback: false)} --patches {patches} {CacheArgs(cfg.Variant, scene.Tessellation)} {FactorRecordsDump(scene.Tessellation.tiles, id)} {buffers} {view} {timing} --update-range-per-frame\n");
                    else if (cfg.Method == "fallback")
                        plan.Append($"{id}\trun\t-\t{Stages(cfg.Variant, fallback: true)} --grid-factor {Inv($"{cfg.Factor}")} --instances {patches} {buffers} {view} {timing}\n");
                    else
                        plan.Append($"{id}\trun\t-\t{Stages(cfg.Variant, fallback: false)} --patches {patches} {buffers} {view} {timing}\n");
                    if (cfg.Method == "adaptive" && !cfg.Cached)
                        plan.Append($"{id}\treadback\t-\t{Stages(cfg.FactorVariant, fallback: false)} --patches {patches} {buffers} {view} --readback @OUT@/readback/{id}.f32 --readback-floats {8 * patches}\n");
                }
            File.WriteAllText(Path.Combine(dir, "plan.tsv"), plan.ToString());
            File.WriteAllText(Path.Combine(dir, "jobs.tsv"), meta.ToString());
            File.WriteAllText(Path.Combine(dir, "settings.txt"), Inv($"width {width} height {height} quick {(quick ? 1 : 0)}\n"));
            Console.WriteLine($"bench plan: {plan.ToString().Split('\n').Length - 1} jobs -> {dir}");
            return 0;
        }

        /// <summary>
        /// The paper's Table 1 and the static-mesh comparison: a 64x64 surface (one tile at factor 64)
        /// and the same at >= 8M triangles (32 x 32 tiles at factor 64), each drawn with nothing changing,
        /// only _Range changing, the changed geometry re-sent (the triangle soup, 36 bytes a triangle),
        /// and as a static mesh of the same triangle count (the harness's minimal shader: a floor; the
        /// fair static mesh is FairStatic's).
        /// </summary>
        static void Table1(PatchGrid grid, string dir, StringBuilder plan, StringBuilder meta, bool quick, int width, int height)
        {
            int frames64 = quick ? 50 : 2000, framesBig = quick ? 3 : 100;
            string view = Inv($"--width {width} --height {height}");
            var sizes = quick ? new[] { (1, 64.0, frames64) } : new[] { (1, 64.0, frames64), (32, 64.0, framesBig) };
            foreach (var (tiles, f, frames) in sizes)
            {
                var cfg = new BenchConfig { Method = "uniform", Tiles = tiles, Factor = f };
                string id = Inv($"t1_m{tiles}_f{f}");
                Scene(grid, cfg, CameraPath[0].range, width, height).WriteBuffers(Path.Combine(dir, "jobs", id));
                // fractional_odd clamps the factor to 63, the largest odd count: (63 M)^2 quads.
                long n = tiles * 63L, tris = 2 * n * n;
                string t = Inv($"--stats --timestamps --frames {frames} --warmup {Math.Max(5, frames / 20)}");
                string common = $"{Stages("base", false)} --patches {tiles * tiles} --buffers @JOB@/{id} {view} {t}";
                plan.Append($"{id}:plain\trun\t-\t{common}\n");
                plan.Append($"{id}:range\trun\t-\t{common} --update-range-per-frame\n");
                plan.Append($"{id}:resend\trun\t-\t{common} --resend-bytes {tris * 36}\n");
                plan.Append($"{id}:static\tstatic-match\t{id}:plain\t--static-mesh --mesh @MESH@ --vert @SPV@/mesh.vert.spv --frag @SPV@/mesh.frag.spv --buffers @JOB@/{id} {view} {t}\n");
                meta.Append(Inv($"{id}\ttable1\t{tiles}\t{f}\t0\t64\t0\tfar\t{tiles * tiles}\n"));
            }
        }

        /// <summary>Tile count and uniform factor of the fair-static comparison (terrain = static = 2 M^2 F^2 triangles).</summary>
        public static (int tiles, int factor)[] FairSizes(bool quick) => quick
            ? new[] { (8, 7) }
            : new[] { (32, 17), (32, 31), (32, 63), (64, 31), (128, 15), (256, 7) };

        /// <summary>The adaptive terrain beside the fair static meshes: tiles, and the static size whose triangle count it aims at.</summary>
        public static (int tiles, int staticTiles, int staticFactor)[] AdaptiveVsStatic(bool quick) => quick
            ? new[] { (8, 8, 7) }
            // Per static size: 64 and 32 tiles, and fewer, larger tiles, down to about the count whose
            // cells still hold the triangles below the max factor (larger factors cost less per
            // triangle; the tile-count sweep of Tools~/bench/records.md: 10-16 tiles at 0.6M, 16-24 at 2M).
            : new[] { (64, 32, 17), (32, 32, 17), (16, 32, 17), (10, 32, 17),
                      (64, 32, 31), (32, 32, 31), (20, 32, 31),
                      (64, 32, 63), (32, 32, 63) };

        /// <summary>
        /// The fair static mesh (Documentation~/performance.md, "In short"): for M x M tiles at the uniform factor F,
        /// the package's terrain (tessellated, GT_NOISE, _Range changing every frame), the fallback grid
        /// (same vertices evaluated without a tessellator), the terrain's vertices baked once
        /// (GT_READBACK capture on the device, packed by bench_static_mesh.py) and drawn by vert_static
        /// with the same frag and the same index grid, and the old minimal-shader grid (a floor). Then the
        /// adaptive terrain (noise, 64 tiles) at the target whose Core-predicted triangle count matches
        /// each static size. Beside each, the vertex cache (GT_VERTEX_CACHE, compute pre-pass, integer
        /// partitioning): at the same uniform F ("cached", _Range changing every frame, so both kernels
        /// run every frame), the adaptive terrain at the target whose integer-factor prediction matches
        /// the static size (vc_*), and both with nothing changing ("still": the kernels dispatch in the
        /// first, warm-up frame only, harness --compute-once; the later frames draw from the cache).
        /// </summary>
        static void FairStatic(PatchGrid grid, string dir, StringBuilder plan, StringBuilder meta, bool quick, int width, int height,
                               Dictionary<string, double> targets)
        {
            foreach (var (_, f) in FairSizes(quick)) WriteStaticOrders(dir, f);
            string view = Inv($"--width {width} --height {height}");
            int frames = quick ? 3 : 100;
            // 50 warm-up frames: the jobs before (the bake's packing runs on the CPU) leave the GPU idle
            // long enough to drop its clocks; with 5, one H200 job's frames ramped from 5.3 to 1.3 ms.
            string t = Inv($"--stats --timestamps --frames {frames} --warmup {(quick ? 1 : 50)}");
            foreach (var (m, f) in FairSizes(quick))
            {
                var cfg = new BenchConfig { Method = "uniform", Tiles = m, Factor = f, Octaves = 4 };
                string id = Inv($"fs_m{m}_f{f}");
                var scene = Scene(grid, cfg, CameraPath[0].range, width, height);
                scene.WriteBuffers(Path.Combine(dir, "jobs", id));
                WriteOrbit(scene, dir, id);
                int patches = m * m;
                long vertices = (long)patches * (f + 1) * (f + 1);
                string buffers = $"--buffers @JOB@/{id}";
                plan.Append($"{id}:terrain\trun\t-\t{Stages(FairVariant, false)} --patches {patches} {buffers} {view} {t} --update-range-per-frame\n");
                plan.Append($"{id}:fallback\trun\t-\t{Stages(FairVariant, true)} --grid-factor {f} --instances {patches} {buffers} {view} {t} --update-range-per-frame\n");
                plan.Append($"{id}:bake\tstatic-bake\t{id}\t{Stages("readback+noise", true)} --grid-factor {f} --instances {patches} {buffers} {view} --readback @OUT@/capture/{id}.f32 --readback-floats {12 * vertices}\n");
                string staticRows = $"--vert @SPV@/static.spv --frag @SPV@/{FairVariant}/frag.spv --grid-factor {f} --instances {patches} --buffers @OUT@/static/{id} {view} {t}";
                string staticRun = $"{staticRows} {StaticOrder(f)}";
                // The fair static mesh: its triangles in Forsyth's order (GridIndexOrder); the same
                // mesh row by row and in 2-column strips beside it, labelled.
                plan.Append($"{id}:static\trun\t-\t{staticRun}\n");
                plan.Append($"{id}:static-rows\trun\t-\t{staticRows}\n");
                plan.Append($"{id}:static-strips\trun\t-\t{staticRows} --grid-indices @JOB@/{OrdersDir}/{GridIndexOrder.FileName("strips2", f)}\n");
                plan.Append($"{id}:static-if2\trun\t-\t{staticRun} {InFlight}\n");
                plan.Append($"{id}:static-orbit\trun\t-\t{staticRun} {Orbit(id)}\n");
                // The tessellator's floor: the terrain's tiles, factors and frag with a domain stage that evaluates nothing.
                plan.Append($"{id}:tess-floor\trun\t-\t{FloorStages} --patches {patches} {buffers} {view} {t} --update-range-per-frame\n");
                // Where the domain stage's time goes (Tools~/rig/bench_domain_parts.hlsl): the same draw with one piece taken out a job.
                if (Array.IndexOf(DomainPartSizes(quick), (m, f)) >= 0)
                {
                    // The package's own plain domain stage (variant base: no noise, no colour) with the fair variant's other stages.
                    string plainStages = $"--vert @SPV@/{FairVariant}/vert.spv --tesc @SPV@/{FairVariant}/tesc.spv --tese @SPV@/base/tese.spv --frag @SPV@/{FairVariant}/frag.spv";
                    plan.Append($"{id}:plain\trun\t-\t{plainStages} --patches {patches} {buffers} {view} {t} --update-range-per-frame\n");
                    foreach (var (part, _) in DomainParts)
                        plan.Append($"{id}:part-{part}\trun\t-\t{PartStages(part)} --patches {patches} {buffers} {view} {t} --update-range-per-frame\n");
                }
                plan.Append($"{id}:floor\tstatic-match\t{id}:terrain\t--static-mesh --mesh @MESH@ --vert @SPV@/mesh.vert.spv --frag @SPV@/mesh.frag.spv {buffers} {view} {t}\n");
                string cache = $"{Stages(CachedNoiseVariant, false)} --patches {patches} {CacheArgs(CachedNoiseVariant, scene.Tessellation)} {buffers} {view} {t}";
                plan.Append($"{id}:cached\trun\t-\t{cache} --update-range-per-frame\n");
                plan.Append($"{id}:cached-still\trun\t-\t{cache} --compute-once\n");
                meta.Append(Inv($"{id}\tfair\t{m}\t{f}\t0\t{f}\t4\tfar\t{patches}\n"));
            }
            Directory.CreateDirectory(Path.Combine(dir, "jobs"));
            BufferFiles.Write(Path.Combine(dir, "jobs", NoiseCellsFile), GradientNoiseTable.Floats);
            foreach (var (m, sm, sf) in AdaptiveVsStatic(quick))
            {
                double want = 2.0 * sm * sm * sf * sf;
                double target = TargetForTriangles(grid, m, want, width, height);
                var cfg = new BenchConfig { Method = "adaptive", Tiles = m, Target = target, Octaves = 4 };
                string id = Inv($"va_m{m}_s{sm}x{sf}");
                Scene(grid, cfg, CameraPath[0].range, width, height).WriteBuffers(Path.Combine(dir, "jobs", id));
                string direct = $"{Stages(FairVariant, false)} --patches {m * m} --buffers @JOB@/{id} {view} {t}";
                plan.Append($"{id}:terrain\trun\t-\t{direct} --update-range-per-frame\n");
                // The same with the tiled noise (GT_NOISE_TABLE): Core's cell table bound at 9.
                plan.Append($"{id}:terrain-tiled\trun\t-\t{Stages(TiledVariant, false)} --patches {m * m} --buffers @JOB@/{id} --storage-data 9:@JOB@/{NoiseCellsFile} {view} {t} --update-range-per-frame\n");
                // Goal "only _Range changes within 1.02x of nothing changing", with noise and colour on.
                plan.Append($"{id}:still\trun\t-\t{direct}\n");
                plan.Append($"{id}:tess-floor\trun\t-\t{FloorStages} --patches {m * m} --buffers @JOB@/{id} {view} {t} --update-range-per-frame\n");
                targets[id] = target;
                meta.Append(Inv($"{id}\tadaptive-vs\t{m}\t0\t{target:G6}\t64\t4\tfar\t{m * m}\n"));

                // The same through the vertex cache: its own target (integer factors draw more per factor).
                double ctarget = TargetForTriangles(grid, m, want, width, height, cached: true);
                var ccfg = new BenchConfig { Method = "adaptive", Cached = true, Tiles = m, Target = ctarget, Octaves = 4 };
                string cid = Inv($"vc_m{m}_s{sm}x{sf}");
                var cscene = Scene(grid, ccfg, CameraPath[0].range, width, height);
                cscene.WriteBuffers(Path.Combine(dir, "jobs", cid));
                WriteOrbit(cscene, dir, cid);
                string cache = $"{Stages(CachedNoiseVariant, false)} --patches {m * m} {CacheArgs(CachedNoiseVariant, cscene.Tessellation)} --buffers @JOB@/{cid} {view} {t}";
                plan.Append($"{cid}:terrain\trun\t-\t{cache} --update-range-per-frame\n");
                plan.Append($"{cid}:still\trun\t-\t{cache} --compute-once\n");
                // The camera moving, the range still: only tiles whose factors change are evaluated.
                plan.Append($"{cid}:orbit\trun\t-\t{cache} {Orbit(cid)} {FactorRecordsDump(m, cid + "-orbit")}\n");
                plan.Append($"{cid}:terrain-if2\trun\t-\t{cache} --update-range-per-frame {InFlight}\n");
                plan.Append($"{cid}:still-if2\trun\t-\t{cache} --compute-once {InFlight}\n");
                // lavapipe (the quick run) has one queue family: nothing to run the kernels alongside.
                if (!quick) plan.Append($"{cid}:terrain-async\trun\t-\t{cache} --update-range-per-frame {InFlight} --async-compute\n");
                targets[cid] = ctarget;
                meta.Append(Inv($"{cid}\tcached-adaptive-vs\t{m}\t0\t{ctarget:G6}\t64\t4\tfar\t{m * m}\n"));

                // Anchored tiles (TileLattice): the lattice is the plan's range, as the renderer anchors
                // it. The range pans inside the first cells every frame (the harness's shifts), which
                // changes nothing the kernels read (TileLattice.KernelRange): the renderer dispatches
                // nothing and the draw clips the cached cells (ClippedCell), so `pan` builds the cache
                // once. `pan-dispatched` runs the kernels every frame anyway (they find nothing to do):
                // the floor of a frame that brings cells in.
                string aid = cid + "-anchored";
                cscene.Params = cscene.Params.WithTileLattice(cscene.Params.range);
                cscene.WriteBuffers(Path.Combine(dir, "jobs", aid));
                int across = m + 1;
                string anchored = $"{Stages(CachedNoiseVariant, false)} --patches {across * across} {CacheArgs(CachedNoiseVariant, cscene.Tessellation, across)} --buffers @JOB@/{aid} {view} {t}";
                RequirePanInsideFirstCells(cscene.Params);
                plan.Append($"{cid}:pan\trun\t-\t{anchored} --compute-once --update-range-per-frame\n");
                plan.Append($"{cid}:pan-dispatched\trun\t-\t{anchored} --update-range-per-frame {FactorRecordsDump(across, cid + "-pan")}\n");
                plan.Append($"{cid}:pan-still\trun\t-\t{anchored} --compute-once\n");
            }
        }

        /// <summary>
        /// The harness's <c>--update-range-per-frame</c> moves the range by (f mod 8) 1e-4 of its
        /// size (frame f): the `pan` job builds the cache once only because no such frame changes the
        /// first cells, as a renderer would then dispatch nothing. Throws if one would.
        /// </summary>
        static void RequirePanInsideFirstCells(TerrainParams p)
        {
            Float4 first = TileLattice.KernelRange(p);
            for (int f = 0; f < 8; f++)
            {
                TerrainParams q = p;
                float k = 1e-4f * f, dx = (p.range.z - p.range.x) * k, dy = (p.range.w - p.range.y) * k;
                q.range = new Float4(p.range.x + dx, p.range.y + dy, p.range.z + dx, p.range.w + dy);
                if (!TileLattice.KernelRange(q).Equals(first))
                    throw new InvalidOperationException(Inv($"bench plan: the pan's frame {f} leaves the first cells {first}: the kernels would run"));
            }
        }

        /// <summary>
        /// The fair comparison's look (noise detail and height colour on): the terrain,
        /// the fallback and the static mesh's frag all use it. The static mesh's vertex stage
        /// (vert_static with GT_HEIGHT_COLOR) hands the frag its baked height and a colour noise of 0:
        /// the same fragment work, one interpolant less computed per vertex.
        /// </summary>
        public const string FairVariant = "noise+height_color";

        /// <summary>The fair variant with the tiled noise (GT_NOISE_TABLE), its table in the jobs folder.</summary>
        public const string TiledVariant = "noise+height_color+noise_table";
        const string NoiseCellsFile = "noise_cells.f32";

        /// <summary>
        /// Frames as an application runs them: two queued at once, each with its own vertex cache and
        /// TerrainParams, the time per frame the period between frame ends (harness --in-flight).
        /// </summary>
        public const string InFlight = "--in-flight 2";

        /// <summary>
        /// The moving camera of the *-orbit jobs (harness --camera-path): the zoom view turning about
        /// its target by OrbitDegrees sin(2 pi f / OrbitFrames), at most 0.13 degrees a frame.
        /// </summary>
        public const int OrbitFrames = 100;
        public const double OrbitDegrees = 2.0;

        static void WriteOrbit(RigScene scene, string dir, string id) =>
            BufferFiles.Write(Path.Combine(dir, "jobs", id, PackCommand.CameraPathFile), scene.OrbitCameraPath(OrbitFrames, OrbitDegrees));

        static string Orbit(string id) => $"--camera-path @JOB@/{id}/{PackCommand.CameraPathFile}";

        /// <summary>The cache variant of the fair comparison: <see cref="FairVariant"/> plus GT_VERTEX_CACHE.</summary>
        public const string CachedNoiseVariant = "noise+height_color+vertex_cache";

        /// <summary>
        /// The vertex cache's buffers and kernels for the harness (internals.md, "Vertex cache"): _TileFactors at
        /// binding 7 (64 bytes a tile), _VertexCache at binding 8, _TileCells at binding 10 (928 bytes a tile), CacheTileFactors over M x M
        /// groups (one a tile), then CacheTileVertices over M x M x G groups (G = VertexCache.GroupsPerTile), each frame before the draw.
        /// </summary>
        public static string CacheArgs(string variant, TessellationSettings t) => CacheArgs(variant, t, t.tiles);

        /// <summary><see cref="CacheArgs(string, TessellationSettings)"/> for T x T tiles (anchored: M + 1).</summary>
        public static string CacheArgs(string variant, TessellationSettings t, int across) =>
            Inv($"--storage 7:{TileFactorsBytes(across)} --storage 8:{VertexCacheBudget.VertexCacheBytes(across, VertexCache.FactorLimit(t), snow: false)} --storage 10:{VertexCacheBudget.TileCellsBytes(across)} ")
            + Inv($"--compute @SPV@/{variant}/cache_factors.spv:{across},{across},1 --compute @SPV@/{variant}/cache_vertices.spv:{across},{across},{VertexCache.GroupsPerTile(VertexCache.FactorLimit(t))}");

        /// <summary>The first M^2 records of _TileFactors, 64 bytes a tile: what the report reads.</summary>
        static string FactorRecordsDump(int tiles, string name) =>
            Inv($"--dump-storage-prefix 7:{VertexCacheBudget.TileFactorsBytes(tiles)}:@OUT@/readback/{name}.tiles.f32");

        /// <summary>_TileFactors: a TileFactorRecord a tile (Core's VertexCacheBudget).</summary>
        public static long TileFactorsBytes(int tiles) => VertexCacheBudget.TileFactorsBytes(tiles);

        /// <summary>_VertexCache: M^2 S(L) slots of one uint4 (no GT_SNOW in the bench), L = ceil(uniform F or max factor).</summary>
        public static long VertexCacheBytes(TessellationSettings t) => VertexCacheBudget.VertexCacheBytes(t.tiles, VertexCache.FactorLimit(t), snow: false);

        /// <summary>
        /// The pixel target at which the adaptive terrain (noise, <paramref name="tiles"/> tiles, far view)
        /// draws about <paramref name="triangles"/> triangles by Core's mirror of hull_const: 2 n0 n1 per
        /// tile, n the odd segment count fractional_odd makes of each inside factor (the transition rings
        /// are not counted). <paramref name="cached"/>: the vertex cache's integer factors (ceil, inside
        /// >= 2) and the exact integer-partitioning count, rings included (ModelTrianglesInteger).
        /// Bisection on log(target).
        /// </summary>
        public static double TargetForTriangles(PatchGrid grid, int tiles, double triangles, int width, int height, bool cached = false)
        {
            double lo = Math.Log(1e-4), hi = Math.Log(100);
            for (int it = 0; it < 24; it++)
            {
                double mid = 0.5 * (lo + hi);
                var cfg = new BenchConfig { Method = "adaptive", Tiles = tiles, Target = Math.Exp(mid), Octaves = 4 };
                var core = ErrorCommand.CoreFactors(Scene(grid, cfg, CameraPath[0].range, width, height), noise: true);
                double n = cached ? ModelTrianglesInteger(core) : ModelTriangles(core);
                if (n > triangles) lo = mid; else hi = mid;
            }
            return double.Parse(Math.Exp(0.5 * (lo + hi)).ToString("G4", CultureInfo.InvariantCulture), CultureInfo.InvariantCulture);
        }

        public static double ModelTriangles(PatchFactors[] factors)
        {
            static double Odd(double f) { double n = Math.Ceiling(Math.Min(Math.Max(f, 1), 63)); return n % 2 == 0 ? n + 1 : n; }
            double sum = 0;
            foreach (var p in factors) if (!p.culled) sum += 2 * Odd(p.i0) * Odd(p.i1);
            return sum;
        }

        /// <summary>Triangles of the vertex cache's draw for Core's float factors: made integer as CacheTileFactors does, counted exactly.</summary>
        public static double ModelTrianglesInteger(PatchFactors[] factors)
        {
            double sum = 0;
            foreach (var p in factors) sum += TessellationCells.IntegerTriangles(p.CacheIntegers());
            return sum;
        }

        /// <summary>The floor (Tools~/rig/bench_floor.hlsl, entry domain_floor): the fair variant's stages with a domain stage that evaluates nothing.</summary>
        static string FloorStages =>
            $"--vert @SPV@/{FairVariant}/vert.spv --tesc @SPV@/{FairVariant}/tesc.spv --tese @SPV@/floor.spv --frag @SPV@/{FairVariant}/frag.spv";

        /// <summary>
        /// The domain-stage breakdown (Tools~/rig/bench_domain_parts.hlsl, rig only): each part's name
        /// (SPIR-V spirv/parts/NAME.spv, compiled by Tools~/rig/bench.sh with -DPART_NAME in upper case)
        /// and what it takes out of the fair variant's domain stage. "full" takes nothing out.
        /// </summary>
        public static readonly (string name, string what)[] DomainParts =
        {
            ("full", "nothing: the rewrite of the stage (the deep-zoom code compiled in only with GT_RANGE_ORIGIN)"),
            ("no_lookup", "patch lookup: FindPatch's binary searches -> a multiply"),
            ("no_range", "range and origin arithmetic: tile -> q -> (u, v) in plain float"),
            ("no_deriv", "Gregory derivatives (position only)"),
            ("no_gregory", "Gregory evaluation (the bilinear patch of the corners)"),
            ("no_octaves", "the octave loop (noise height; colour kept)"),
            ("one_octave", "all octaves but the first"),
            ("cheap_hash", "PCG hash -> one multiply and shift"),
            ("plain_split", "lattice split (TwoProduct) -> plain floor"),
            ("no_normal", "normal and what only it needs (derivatives, noise gradient)"),
            ("no_colour", "the height colour's noise"),
            ("plain", "no noise, no colour: the plain domain stage"),
            ("minimal", "a minimal Gregory evaluator drawing the same triangles: patch by multiply, q and (u, v) in plain float, position and normal"),
            ("table_cells", "a candidate noise that repeats every 256 cells: each cell's corner gradients from a 256 x 256 table (2 float4 loads) instead of the hashes"),
            ("table_coef", "the same table holding each cell's noise polynomial (3 float4 loads)"),
        };

        /// <summary>The zero-filled table a candidate part reads (binding 9, t7): "--storage 9:BYTES", or "".</summary>
        static string PartStorage(string part) => part switch
        {
            "table_cells" => " --storage 9:" + (256 * 256 * 2 * 16),
            "table_coef" => " --storage 9:" + (256 * 256 * 3 * 16),
            _ => "",
        };

        /// <summary>The fair sizes (tiles, F) whose domain stage is broken down into DomainParts.</summary>
        public static (int tiles, int factor)[] DomainPartSizes(bool quick) => quick
            ? new[] { (8, 7) }
            : new[] { (32, 31), (32, 63) };

        /// <summary>The fair variant's stages with the domain stage of breakdown part `part`.</summary>
        static string PartStages(string part) =>
            $"--vert @SPV@/{FairVariant}/vert.spv --tesc @SPV@/{FairVariant}/tesc.spv --tese @SPV@/parts/{part}.spv --frag @SPV@/{FairVariant}/frag.spv{PartStorage(part)}";

        /// <summary>Folder of the plan's jobs/ holding the static meshes' index orders (GridIndexOrder files).</summary>
        public const string OrdersDir = "orders";

        /// <summary>The fair static mesh's index order for factor F (harness --grid-indices): Forsyth's.</summary>
        static string StaticOrder(int f) => $"--grid-indices @JOB@/{OrdersDir}/{GridIndexOrder.FileName("forsyth", f)}";

        /// <summary>Writes jobs/orders/{forsyth,strips2}_fF.u32 for an (F+1)^2 grid (once per F).</summary>
        static void WriteStaticOrders(string dir, int f)
        {
            string orders = Path.Combine(dir, "jobs", OrdersDir);
            Directory.CreateDirectory(orders);
            foreach (var method in new[] { "forsyth", "strips2" })
            {
                string file = Path.Combine(orders, GridIndexOrder.FileName(method, f));
                if (File.Exists(file)) continue;
                uint[] order = method == "forsyth" ? GridIndexOrder.Forsyth(GridIndexOrder.RowMajor(f), (f + 1) * (f + 1)) : GridIndexOrder.Strips(f, 2);
                var bytes = new byte[order.Length * 4];
                Buffer.BlockCopy(order, 0, bytes, 0, bytes.Length);
                File.WriteAllBytes(file, bytes);
            }
        }

        static string Stages(string variant, bool fallback) => fallback
            ? $"--vert @SPV@/{variant}/fallback.spv --frag @SPV@/{variant}/frag.spv"
            : $"--vert @SPV@/{variant}/vert.spv --tesc @SPV@/{variant}/tesc.spv --tese @SPV@/{variant}/tese.spv --frag @SPV@/{variant}/frag.spv";

        public static RigScene Scene(PatchGrid grid, BenchConfig cfg, double[] range, int width, int height)
        {
            var args = new List<string>
            {
                "--range", string.Join(",", Array.ConvertAll(range, x => x.ToString("R", CultureInfo.InvariantCulture))),
                "--tiles", cfg.Tiles.ToString(CultureInfo.InvariantCulture),
                "--max-factor", Inv($"{(cfg.Method == "adaptive" ? cfg.MaxFactor : Math.Max(cfg.Factor, 1))}"),
                "--target-pixels", Inv($"{(cfg.Method == "adaptive" ? cfg.Target : 1.0)}"),
                "--factor", Inv($"{(cfg.Method == "adaptive" ? 0 : cfg.Factor)}"),
                "--octaves", Math.Max(cfg.Octaves, 1).ToString(CultureInfo.InvariantCulture),
                "--width", width.ToString(CultureInfo.InvariantCulture), "--height", height.ToString(CultureInfo.InvariantCulture),
            };
            return RigScene.FromGrid(grid, Program.SceneArgs(args.ToArray()));
        }

        static string Inv(FormattableString s) => s.ToString(CultureInfo.InvariantCulture);
    }
}
