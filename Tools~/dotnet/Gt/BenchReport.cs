using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// gt-cli bench-report: turns a run of the plan (bench_run.sh's results.txt and readback.tar,
    /// from any machine) into the tables: per configuration, over the camera path, the triangles,
    /// domain-shader invocations and GPU time per frame (means over the cameras) and the error of
    /// ErrorMeasure (largest over the path; RMS over all samples of the path); then the paper's
    /// Table 1, the static-mesh comparison and the goals, as ratios. Vertex-cache rows ("cached
    /// adaptive", "cached uniform") also give the compute pre-pass's time (harness "time
    /// compute_ms_median", part of the frame) and take their factors from the dumped _TileFactors.
    /// Usage: bench-report --plan DIR --raw DIR --grid FILE [--tsv FILE]
    /// </summary>
    static partial class BenchReport
    {
        sealed class Job
        {
            public Dictionary<string, string> Stat = new Dictionary<string, string>();
            public double GpuMs = double.NaN, GpuMeanMs = double.NaN, CpuMs = double.NaN, CpuMeanMs = double.NaN, ComputeMs = double.NaN;
            public int Exit = -1;
            public string Skipped;   // bench_run.sh's reason when the job did not run
            public long Get(string k) => Stat.TryGetValue(k, out var v) ? long.Parse(v, CultureInfo.InvariantCulture) : -1;
        }

        public static int Run(Args a)
        {
            string planDir = a.String("plan"), raw = a.String("raw");
            var grid = RigScene.ReadGrid(a);
            var settings = File.ReadAllText(Path.Combine(planDir, "settings.txt")).Split(new[] { ' ', '\n' }, StringSplitOptions.RemoveEmptyEntries);
            int width = int.Parse(settings[1], CultureInfo.InvariantCulture), height = int.Parse(settings[3], CultureInfo.InvariantCulture);
            bool quick = settings[5] == "1";
            var jobs = ParseResults(Path.Combine(raw, "results.txt"));
            string rbDir = Path.Combine(raw, "readback-extracted");
            if (File.Exists(Path.Combine(raw, "readback.tar")) && !Directory.Exists(rbDir))
            {
                Directory.CreateDirectory(rbDir);
                System.Formats.Tar.TarFile.ExtractToDirectory(Path.Combine(raw, "readback.tar"), rbDir, true);
            }
            var o = new StringBuilder();
            string device = File.Exists(Path.Combine(raw, "device.txt")) ? File.ReadAllLines(Path.Combine(raw, "device.txt")).FirstOrDefault(l => l.StartsWith("device ")) ?? "?" : "?";
            string name = jobs.Values.Select(j => j.Stat.TryGetValue("name", out var n) ? n : null).FirstOrDefault(n => n != null) ?? device;
            o.AppendLine($"# gt bench ({(quick ? "quick" : "full")}), {width}x{height}, device: {name}");
            o.AppendLine();
            var tsv = new StringBuilder("method\ttiles\tfactor\ttarget\tmaxfactor\toctaves\ttriangles\tds_invocations\tgpu_ms\tmax_px\trms_px\tmax_world\tgpu_vs_core_factor\tcompute_ms\tmodel_triangles\n");
            o.AppendLine("| method | tiles | factor | target px | max F | octaves | triangles | DS invocations | GPU ms/frame | max err px | RMS err px | max err (terrain units) | compute ms/frame |");
            o.AppendLine("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
            double worstModel = 0; string worstModelId = null;
            double cacheFactorDiff = 0; long cacheTilesDiffer = 0, cacheTilesDrawn = 0;
            var estimate = new EstimateCheck();
            var cfgs = BenchPlan.Sweep(quick);
            var path = quick ? new[] { BenchPlan.CameraPath[0], BenchPlan.CameraPath[2] } : BenchPlan.CameraPath;
            foreach (var cfg in cfgs)
            {
                double tris = 0, ds = 0, gpu = 0, maxPx = 0, maxW = 0, sumSq = 0, factorDiff = 0, compute = 0, model = 0;
                long samples = 0;
                bool complete = true;
                foreach (var (cam, range) in path)
                {
                    string id = cfg.Name + "@" + cam;
                    if (!jobs.TryGetValue(id + " run", out var j) || j.Exit != 0) { complete = false; continue; }
                    tris += j.Get("clipping_invocations");
                    ds += cfg.Method == "fallback" ? j.Get("vertex_shader_invocations") : j.Get("tessellation_evaluation_shader_invocations");
                    gpu += j.GpuMs;
                    var scene = BenchPlan.Scene(grid, cfg, range, width, height);
                    if (cfg.Method == "adaptive") estimate.Add(cfg.Cached, id, j.Get("clipping_invocations"), InspectorEstimate(grid, scene, cfg));
                    if (cfg.Cached)
                    {
                        // The vertex cache: the integer factors the kernel wrote (_TileFactors dump),
                        // checked against Core's mirror made integer, and the exact triangle count
                        // they imply against the GPU's clipping invocations.
                        compute += j.ComputeMs;
                        string tf = Path.Combine(rbDir, "readback", id + ".tiles.f32");
                        if (!File.Exists(tf)) { complete = false; continue; }
                        var cacheF = PatchFactors.FromTileFactors(BufferFiles.Read(tf), cfg.Tiles * cfg.Tiles);
                        var coreI = ErrorCommand.CacheFactors(scene, cfg.Noise);
                        factorDiff = Math.Max(factorDiff, MaxFactorDifference(cacheF, coreI));
                        cacheFactorDiff = Math.Max(cacheFactorDiff, factorDiff);
                        for (int p = 0; p < cacheF.Length; p++)
                        {
                            if (cacheF[p].culled && coreI[p].culled) continue;
                            cacheTilesDrawn++;
                            if (MaxFactorDifference(new[] { cacheF[p] }, new[] { coreI[p] }) != 0 || cacheF[p].culled != coreI[p].culled) cacheTilesDiffer++;
                        }
                        long m = cacheF.Sum(TessellationCells.IntegerTriangles), g = j.Get("clipping_invocations");
                        model += m;
                        double rel = Math.Abs(g - m) / Math.Max(1.0, m);
                        if (rel >= worstModel) { worstModel = rel; worstModelId = $"{id}: GPU {g}, model {m}"; }
                        var cerr = ErrorCommand.Measure(scene, false, cfg.Noise, cacheF, 1024, integerPartitioning: true);
                        maxPx = Math.Max(maxPx, cerr.MaxPixels); maxW = Math.Max(maxW, cerr.MaxWorld);
                        sumSq += cerr.RmsPixels * cerr.RmsPixels * cerr.Samples; samples += cerr.Samples;
                        continue;
                    }
                    float[] rb = null;
                    if (cfg.Method == "adaptive")
                    {
                        string f = Path.Combine(rbDir, "readback", id + ".f32");
                        if (!File.Exists(f)) { complete = false; continue; }
                        rb = BufferFiles.Read(f);
                        var gpuF = PatchFactors.FromReadback(rb, cfg.Tiles * cfg.Tiles);
                        var coreF = ErrorCommand.CoreFactors(scene, cfg.Noise);
                        for (int p = 0; p < gpuF.Length; p++)
                            if (!gpuF[p].culled && !coreF[p].culled)
                                factorDiff = Math.Max(factorDiff, Math.Max(Math.Abs(gpuF[p].i0 - coreF[p].i0), Math.Abs(gpuF[p].e0 - coreF[p].e0)));
                    }
                    var err = ErrorCommand.Measure(scene, cfg.Method == "paper", cfg.Noise, rb, 1024, cfg.Method == "fallback");
                    maxPx = Math.Max(maxPx, err.MaxPixels); maxW = Math.Max(maxW, err.MaxWorld);
                    sumSq += err.RmsPixels * err.RmsPixels * err.Samples; samples += err.Samples;
                }
                int n = path.Length;
                double rms = samples > 0 ? Math.Sqrt(sumSq / samples) : double.NaN;
                string c = complete ? "" : " (incomplete)";
                string cm = cfg.Cached ? Inv($"{compute / n:G4}") : "-";
                o.AppendLine(Inv($"| {cfg.Label}{c} | {cfg.Tiles} | {(cfg.Method == "adaptive" ? "-" : cfg.Factor.ToString(CultureInfo.InvariantCulture))} | {(cfg.Method == "adaptive" ? cfg.Target.ToString(CultureInfo.InvariantCulture) : "-")} | {cfg.MaxFactor} | {cfg.Octaves} | {tris / n:F0} | {ds / n:F0} | {gpu / n:G4} | {maxPx:G3} | {rms:G3} | {maxW:G3} | {cm} |"));
                tsv.AppendLine(Inv($"{cfg.Label}\t{cfg.Tiles}\t{cfg.Factor}\t{cfg.Target}\t{cfg.MaxFactor}\t{cfg.Octaves}\t{tris / n:F0}\t{ds / n:F0}\t{gpu / n:G6}\t{maxPx:G6}\t{rms:G6}\t{maxW:G6}\t{factorDiff:G3}\t{(cfg.Cached ? compute / n : double.NaN):G6}\t{(cfg.Cached ? model / n : double.NaN):F0}"));
            }
            o.AppendLine();
            o.AppendLine("Triangles and DS invocations (vertex invocations for the fallback) are means per frame over the camera path; GPU time the mean of the per-camera medians; errors the largest (max) and RMS over every sample of the path.");
            o.AppendLine("Cached rows (GT_VERTEX_CACHE): each frame runs the compute pre-pass (kernels CacheTileFactors, CacheTileVertices) before the draw, with _Range changing every frame so that every tile is evaluated again (the last frame draws the plan's range); GPU ms is the whole frame, compute ms the pre-pass alone (mean of the per-camera medians); partitioning is integer, at the factors read back from _TileFactors.");
            if (worstModelId != null)
            {
                o.AppendLine(Inv($"Cached rows' triangles against the integer-partitioning count of their dumped factors (transition rings included): largest difference {100 * worstModel:G3}% ({worstModelId})."));
                o.AppendLine(Inv($"Cached rows' dumped factors against Core's mirror made integer (VertexCache.IntegerFactors): {cacheTilesDiffer} of {cacheTilesDrawn} drawn tiles differ (culling or a factor), largest factor difference {cacheFactorDiff:G3}."));
            }
            estimate.Report(o);
            o.AppendLine();
            Table1(o, jobs, quick);
            // Targets chosen at plan time (jobs.tsv: id, method, tiles, factor, target, ...).
            var planned = new Dictionary<string, string>();
            string jobsTsv = Path.Combine(planDir, "jobs.tsv");
            if (File.Exists(jobsTsv))
                foreach (var l in File.ReadLines(jobsTsv).Skip(1)) { var c = l.Split('\t'); if (c.Length > 4) planned[c[0]] = c[4]; }
            Headline(o, jobs, quick);
            Baseline(o, jobs, quick);
            DomainParts(o, jobs, quick);
            Fair(o, jobs, quick, planned);
            CameraMoving(o, jobs, quick, rbDir);
            AnchoredPan(o, jobs, quick, rbDir);
            TileCount(o, jobs, quick, planned, grid, width, height);
            MotionTable(o, jobs, quick, planDir);
            LevelsTable(o, jobs, quick);
            RangeOnlyWithEffects(o, jobs, quick);
            Goals(o, tsv.ToString());
            Console.Write(o.ToString());
            string tsvPath = a.String("tsv", Path.Combine(raw, "bench_table.tsv"));
            File.WriteAllText(tsvPath, tsv.ToString());
            File.WriteAllText(Path.ChangeExtension(tsvPath, ".md"), o.ToString());
            return 0;
        }

        /// <summary>Largest factor difference over the tiles both draw (as for the GT_FACTOR_READBACK rows).</summary>
        static double MaxFactorDifference(PatchFactors[] a, PatchFactors[] b)
        {
            double d = 0;
            for (int p = 0; p < a.Length; p++)
            {
                if (a[p].culled || b[p].culled) continue;
                foreach (var (x, y) in new[] { (a[p].e0, b[p].e0), (a[p].e1, b[p].e1), (a[p].e2, b[p].e2), (a[p].e3, b[p].e3), (a[p].i0, b[p].i0), (a[p].i1, b[p].i1) })
                    d = Math.Max(d, Math.Abs(x - y));
            }
            return d;
        }

        static void Table1(StringBuilder o, Dictionary<string, Job> jobs, bool quick)
        {
            o.AppendLine("## The paper's Table 1, and the static mesh");
            o.AppendLine();
            o.AppendLine("| case | triangles | GPU ms/frame (median) | CPU ms/frame (mean) | draws/s (1000 / CPU mean) |");
            o.AppendLine("| --- | ---: | ---: | ---: | ---: |");
            foreach (var kv in jobs.Where(k => k.Key.StartsWith("t1_") || k.Key.StartsWith("fs_") || k.Key.StartsWith("va_") || k.Key.StartsWith("vc_")))
            {
                var j = kv.Value;
                if (j.Skipped != null) { o.AppendLine($"| {kv.Key.Split(' ')[0]} | not run: {j.Skipped} | | | |"); continue; }
                long tris = j.Get("clipping_invocations");
                // Frames in flight (harness --in-flight) print no CPU time: GPU ms is their period.
                string cpu = double.IsNaN(j.CpuMeanMs) ? "- | -" : Inv($"{j.CpuMeanMs:G4} | {1000.0 / j.CpuMeanMs:F1}");
                o.AppendLine(Inv($"| {kv.Key.Split(' ')[0]} | {tris} | {j.GpuMs:G4} | {cpu} |"));
            }
            o.AppendLine();
            foreach (var prefix in jobs.Keys.Where(k => k.StartsWith("t1_") && k.Contains(":plain")).Select(k => k.Substring(0, k.IndexOf(':'))))
            {
                Job J(string s) => jobs.TryGetValue($"{prefix}:{s} run", out var j) ? j : jobs.TryGetValue($"{prefix}:{s} static-match", out j) ? j : null;
                Job plain = J("plain"), range = J("range"), resend = J("resend"), stat = J("static");
                if (plain == null || range == null || resend == null || stat == null) continue;
                long tris = plain.Get("clipping_invocations");
                o.AppendLine(Inv($"- {prefix} ({tris} triangles): range-only / nothing changes = {range.GpuMs / plain.GpuMs:F3}x GPU, {range.CpuMeanMs / plain.CpuMeanMs:F3}x CPU frame; ")
                    + Inv($"re-send / range-only = {resend.CpuMeanMs / range.CpuMeanMs:F2}x frame time ({1000 / range.CpuMeanMs:F0} vs {1000 / resend.CpuMeanMs:F0} draws/s; the paper: 594.954 / 192.901 = 3.08x), {resend.GpuMs / range.GpuMs:F2}x GPU; ")
                    + Inv($"tessellated (range-only) / static mesh = {range.GpuMs / stat.GpuMs:F3}x GPU"));
            }
            o.AppendLine();
        }

        /// <summary>The fair static mesh: terrain, fallback, baked mesh with the same frag, the minimal floor; adaptive beside them.</summary>
        static void Fair(StringBuilder o, Dictionary<string, Job> jobs, bool quick, Dictionary<string, string> planned)
        {
            o.AppendLine("## The terrain against the fair static mesh (same vertices, same frag)");
            o.AppendLine();
            o.AppendLine("| tiles | F | triangles | terrain GPU ms | fallback GPU ms | fair static GPU ms | floor (minimal shader) GPU ms | terrain / fair static | fallback / fair static | terrain / floor |");
            o.AppendLine("| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
            var statics = new List<(long tris, double ms, string id)>();
            foreach (var (m, f) in BenchPlan.FairSizes(quick))
            {
                string id = Inv($"fs_m{m}_f{f}");
                Job J(string s, string kind = "run") => jobs.TryGetValue($"{id}:{s} {kind}", out var j) && j.Exit == 0 ? j : null;
                Job ter = J("terrain"), fb = J("fallback"), st = J("static"), fl = J("floor", "static-match");
                if (ter == null || st == null) { o.AppendLine(Inv($"| {m} | {f} | (incomplete) | | | | | | | |")); continue; }
                double fbMs = fb?.GpuMs ?? double.NaN, flMs = fl?.GpuMs ?? double.NaN;
                long tris = ter.Get("clipping_invocations");
                statics.Add((st.Get("clipping_invocations"), st.GpuMs, id));
                o.AppendLine(Inv($"| {m} | {f} | {tris} | {ter.GpuMs:G4} | {fbMs:G4} | {st.GpuMs:G4} | {flMs:G4} | {ter.GpuMs / st.GpuMs:F3}x | {fbMs / st.GpuMs:F3}x | {ter.GpuMs / flMs:F3}x |"));
            }
            o.AppendLine();
            foreach (var (m, sm, sf) in BenchPlan.AdaptiveVsStatic(quick))
            {
                string id = Inv($"va_m{m}_s{sm}x{sf}");
                if (!jobs.TryGetValue(id + ":terrain run", out var t) || t.Exit != 0) continue;
                var s = statics.FirstOrDefault(x => x.id == Inv($"fs_m{sm}_f{sf}"));
                if (s.id == null) continue;
                long tris = t.Get("clipping_invocations");
                o.AppendLine(Inv($"- {id}: package terrain (adaptive + noise, {m} tiles, range changing every frame) {tris} triangles, {t.GpuMs:G4} ms / fair static mesh ({s.id}) {s.tris} triangles, {s.ms:G4} ms = {t.GpuMs / s.ms:F3}x GPU ({t.GpuMs / tris * 1e6 / (s.ms / s.tris * 1e6):F3}x per triangle)"));
            }
            o.AppendLine();

            // The vertex cache beside them: uniform F (same vertices as the terrain row) and the
            // adaptive terrain at the target whose integer-factor prediction matches the static size.
            o.AppendLine("### The vertex cache (GT_VERTEX_CACHE) against the same fair static meshes");
            o.AppendLine();
            o.AppendLine("Cached: compute pre-pass + draw, _Range changing every frame (both kernels run every frame); compute: the pre-pass alone (timestamp after the last dispatch); frame - compute: the rest of that frame (barrier + draw from the cache), derived, not a run of its own; nothing changes: the kernels run in the first (warm-up) frame only (harness --compute-once), the measured frames draw from the cache.");
            o.AppendLine();
            o.AppendLine("| cached terrain | tiles | F / target px | triangles | cached GPU ms | of which compute ms | frame - compute ms | nothing changes GPU ms | fair static GPU ms | cached / fair static | frame - compute / fair static | nothing changes / fair static |");
            o.AppendLine("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
            string Still(Job j) => j == null ? "not run" : j.Skipped != null ? "not run (" + j.Skipped + ")" : j.Exit != 0 ? "failed" : Inv($"{j.GpuMs:G4}");
            string Ratio(Job j, double ms) => j == null || j.Skipped != null || j.Exit != 0 || double.IsNaN(ms) ? "-" : Inv($"{j.GpuMs / ms:F3}x");
            Job Any(string key) => jobs.TryGetValue(key, out var j) ? j : null;
            var notes = new List<string>();
            foreach (var (m, f) in BenchPlan.FairSizes(quick))
            {
                string id = Inv($"fs_m{m}_f{f}");
                Job c = Any($"{id}:cached run"), still = Any($"{id}:cached-still run");
                var s = statics.FirstOrDefault(x => x.id == id);
                double sms = s.id == null ? double.NaN : s.ms;
                if (c == null || c.Exit != 0) { o.AppendLine(Inv($"| {id} (uniform) | {m} | {f} | (incomplete) | | | | {Still(still)} | {sms:G4} | | | |")); continue; }
                double draw = c.GpuMs - c.ComputeMs;
                o.AppendLine(Inv($"| {id} (uniform) | {m} | {f} | {c.Get("clipping_invocations")} | {c.GpuMs:G4} | {c.ComputeMs:G4} | {draw:G4} | {Still(still)} | {sms:G4} | {Ratio(c, sms)} | {draw / sms:F3}x | {Ratio(still, sms)} |"));
            }
            foreach (var (m, sm, sf) in BenchPlan.AdaptiveVsStatic(quick))
            {
                string id = Inv($"vc_m{m}_s{sm}x{sf}");
                Job c = Any($"{id}:terrain run"), still = Any($"{id}:still run");
                var s = statics.FirstOrDefault(x => x.id == Inv($"fs_m{sm}_f{sf}"));
                double sms = s.id == null ? double.NaN : s.ms;
                string target = planned.TryGetValue(id, out var pt) ? pt : "?";
                if (c == null || c.Exit != 0) { o.AppendLine(Inv($"| {id} (adaptive) | {m} | {target} | (incomplete) | | | | {Still(still)} | {sms:G4} | | | |")); continue; }
                long tris = c.Get("clipping_invocations");
                double draw = c.GpuMs - c.ComputeMs;
                o.AppendLine(Inv($"| {id} (adaptive) | {m} | {target} | {tris} | {c.GpuMs:G4} | {c.ComputeMs:G4} | {draw:G4} | {Still(still)} | {sms:G4} | {Ratio(c, sms)} | {draw / sms:F3}x | {Ratio(still, sms)} |"));
                if (s.id != null)
                {
                    double pct = 100.0 * (tris - s.tris) / s.tris;
                    notes.Add(Inv($"- {id}: cached adaptive terrain (noise, {m} tiles, target {target} px) {tris} triangles vs fair static {s.tris} ({(pct >= 0 ? "+" : "-")}{Math.Abs(pct):F2}%): {c.GpuMs:G4} ms / {s.ms:G4} ms = {c.GpuMs / s.ms:F3}x GPU with the pre-pass every frame")
                        + (still != null && still.Skipped == null && still.Exit == 0 ? Inv($", {still.GpuMs / s.ms:F3}x with nothing changing") : Inv($", {draw / s.ms:F3}x for the frame minus the pre-pass (nothing-changes run not made)")));
                }
            }
            o.AppendLine();
            foreach (var l in notes) o.AppendLine(l);
            if (notes.Count > 0) o.AppendLine();
            InFlight(o, jobs, quick);
        }

        /// <summary>
        /// The adaptive cached rows again, timed as an application runs frames (harness --in-flight 2,
        /// BenchPlan.InFlight): two frames queued, each its own cache; the time is the period between
        /// frame ends. Against the static mesh timed the same way.
        /// </summary>
        static void InFlight(StringBuilder o, Dictionary<string, Job> jobs, bool quick)
        {
            o.AppendLine("### Frames in flight (two queued, each with its own cache): the period between frame ends");
            o.AppendLine();
            o.AppendLine("Every column is a run of its own with harness `--in-flight 2`; async: the pre-pass on a queue of a compute-only family (`--async-compute`), beside the graphics queue. The static mesh runs the same way (`static-if2`).");
            o.AppendLine();
            o.AppendLine("| cached terrain | tiles | triangles | static in flight ms | range moving ms | / static | range moving, async compute ms | / static | nothing changes ms | / static |");
            o.AppendLine("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
            Job Any(string key) => jobs.TryGetValue(key, out var j) ? j : null;
            bool Ran(Job j) => j != null && j.Skipped == null && j.Exit == 0;
            // A failed run must not read as one that was not planned (lavapipe plans no async job).
            string Ms(Job j) => j == null ? "not run" : j.Skipped != null ? "not run (" + j.Skipped + ")" : j.Exit != 0 ? "failed" : Inv($"{j.GpuMs:G4}");
            string Over(Job j, Job st) => Ran(j) && Ran(st) ? Inv($"{j.GpuMs / st.GpuMs:F3}x") : "-";
            foreach (var (m, sm, sf) in BenchPlan.AdaptiveVsStatic(quick))
            {
                string id = Inv($"vc_m{m}_s{sm}x{sf}");
                Job st = Any(Inv($"fs_m{sm}_f{sf}:static-if2 run")), moving = Any($"{id}:terrain-if2 run"),
                    async = Any($"{id}:terrain-async run"), still = Any($"{id}:still-if2 run");
                string tris = Ran(moving) ? Inv($"{moving.Get("clipping_invocations")}") : "-";
                o.AppendLine(Inv($"| {id} (adaptive) | {m} | {tris} | {Ms(st)} | {Ms(moving)} | {Over(moving, st)} | {Ms(async)} | {Over(async, st)} | {Ms(still)} | {Over(still, st)} |"));
            }
            o.AppendLine();
        }

        /// <summary>
        /// The camera moving with the range still (harness --camera-path, BenchPlan.OrbitFrames): the
        /// cached terrain re-evaluates only the tiles whose integer factors changed; against the static
        /// mesh on the same camera path. Tiles evaluated: the last frame's, from its _TileFactors dump.
        /// </summary>
        static void CameraMoving(StringBuilder o, Dictionary<string, Job> jobs, bool quick, string rbDir)
        {
            o.AppendLine("### The camera moving, the range still");
            o.AppendLine();
            o.AppendLine(Inv($"The far view turning about its target by {BenchPlan.OrbitDegrees:G} sin(2 pi f / {BenchPlan.OrbitFrames}) degrees at frame f (harness `--camera-path`), for the cached terrain (`orbit`) and the static mesh (`static-orbit`) alike. Both kernels run every frame; CacheTileVertices evaluates only the tiles whose factors (or range) changed. Tiles evaluated: in the last frame, from its `_TileFactors` dump."));
            o.AppendLine();
            o.AppendLine("| cached terrain | tiles | triangles | static, camera moving ms | cached, camera moving ms (of which compute) | / static | static, camera still ms | cached, range moving ms (of which compute) | / static | tiles evaluated / drawn, last frame |");
            o.AppendLine("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
            foreach (var (m, sm, sf) in BenchPlan.AdaptiveVsStatic(quick))
            {
                string id = Inv($"vc_m{m}_s{sm}x{sf}");
                Job st = Ran(jobs, Inv($"fs_m{sm}_f{sf}:static-orbit run")), orbit = Ran(jobs, $"{id}:orbit run"), moving = Ran(jobs, $"{id}:terrain run"),
                    still = Ran(jobs, Inv($"fs_m{sm}_f{sf}:static run"));
                if (st == null || orbit == null) { o.AppendLine(Inv($"| {id} (adaptive) | {m} | (not run or failed) | | | | | | | |")); continue; }
                string evaluated = TilesEvaluated(rbDir, id + "-orbit", m);
                string range = moving == null || still == null ? "- | - | -" : Inv($"{still.GpuMs:G4} | {moving.GpuMs:G4} ({moving.ComputeMs:G3}) | {moving.GpuMs / still.GpuMs:F3}x");
                o.AppendLine(Inv($"| {id} (adaptive) | {m} | {orbit.Get("clipping_invocations")} | {st.GpuMs:G4} | {orbit.GpuMs:G4} ({orbit.ComputeMs:G3}) | {orbit.GpuMs / st.GpuMs:F3}x | {range} | {evaluated} |"));
            }
            o.AppendLine();
        }

        /// <summary>The job <paramref name="key"/> ("ID KIND") when it ran and exited 0, else null.</summary>
        static Job Ran(Dictionary<string, Job> jobs, string key) =>
            jobs.TryGetValue(key, out var j) && j.Skipped == null && j.Exit == 0 ? j : null;

        /// <summary>
        /// "evaluated / drawn" of a last frame's factor records (BenchPlan.FactorRecordsDump NAME):
        /// tiles not culled, and of those the ones CacheTileVertices evaluated; "-" without a dump.
        /// </summary>
        static string TilesEvaluated(string rbDir, string name, int tilesAcross)
        {
            string dump = Path.Combine(rbDir, "readback", name + ".tiles.f32");
            if (!File.Exists(dump)) return "-";
            float[] r = BufferFiles.Read(dump);
            int n = tilesAcross * tilesAcross, drawn = 0, again = 0;
            for (int t = 0; t < n && 8 * t + 7 < r.Length; t++)
                if (r[8 * t + 6] == 0f) { drawn++; if (r[8 * t + 7] != 0f) again++; }
            return Inv($"{again} / {drawn}");
        }

        /// <summary>
        /// Anchored tiles (TileLattice, the renderer's default with adaptive factors): the cached
        /// terrain with the range panning every frame inside the first cells of the lattice anchored
        /// at the plan's range (vc_*:pan: nothing dispatched, as the renderer does), with the kernels
        /// dispatched anyway (vc_*:pan-dispatched) and with nothing changing (vc_*:pan-still), against
        /// the fair static mesh. Tiles evaluated: the dispatched pan's last frame, from its _TileFactors dump.
        /// </summary>
        static void AnchoredPan(StringBuilder o, Dictionary<string, Job> jobs, bool quick, string rbDir)
        {
            o.AppendLine("### Anchored tiles, the range panning");
            o.AppendLine();
            o.AppendLine("The cached terrain with its (M + 1)^2 tiles anchored to the terrain at the plan's range (`_TileLattice`), the range panning inside the first cells every frame (`pan`, harness `--update-range-per-frame`: nothing dispatched, as the renderer does, `--compute-once`; `pan-dispatched`: the kernels run every frame anyway) or holding still (`pan-still`). The cache holds whole cells and the draw clips them, so a pan inside the cells evaluates nothing. Tiles evaluated: in the dispatched pan's last frame, from its `_TileFactors` dump.");
            o.AppendLine();
            o.AppendLine("| cached terrain | tiles drawn | triangles | panning ms | still ms | panning / still | fair static ms | panning / static | still / static | pan dispatched ms (of which compute) | tiles evaluated / drawn, last frame |");
            o.AppendLine("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
            foreach (var (m, sm, sf) in BenchPlan.AdaptiveVsStatic(quick))
            {
                string id = Inv($"vc_m{m}_s{sm}x{sf}");
                Job pan = Ran(jobs, $"{id}:pan run"), still = Ran(jobs, $"{id}:pan-still run"), st = Ran(jobs, Inv($"fs_m{sm}_f{sf}:static run"));
                Job dispatched = Ran(jobs, $"{id}:pan-dispatched run");
                int across = m + 1;
                if (pan == null || still == null || st == null) { o.AppendLine(Inv($"| {id} (adaptive) | {across * across} | (not run or failed) | | | | | | | | |")); continue; }
                string evaluated = TilesEvaluated(rbDir, id + "-pan", across);
                string withKernels = dispatched == null ? "(not run or failed)" : Inv($"{dispatched.GpuMs:G4} ({dispatched.ComputeMs:G3})");
                o.AppendLine(Inv($"| {id} (adaptive) | {across * across} | {pan.Get("clipping_invocations")} | {pan.GpuMs:G4} | {still.GpuMs:G4} | {pan.GpuMs / still.GpuMs:F3}x | {st.GpuMs:G4} | {pan.GpuMs / st.GpuMs:F3}x | {still.GpuMs / st.GpuMs:F3}x | {withKernels} | {evaluated} |"));
            }
            o.AppendLine();
        }

        /// <summary>
        /// Goal "changing only _Range: frame time within 1.02x of changing nothing", for the package's
        /// terrain (adaptive, noise, height colour): the domain-stage path (va_*: terrain / still) and
        /// the vertex cache (vc_*: terrain / still, where "still" dispatches nothing).
        /// </summary>
        static void RangeOnlyWithEffects(StringBuilder o, Dictionary<string, Job> jobs, bool quick)
        {
            foreach (var (m, sm, sf) in BenchPlan.AdaptiveVsStatic(quick))
                foreach (var (prefix, path) in new[] { ("va", "domain stage"), ("vc", "vertex cache") })
                {
                    string id = Inv($"{prefix}_m{m}_s{sm}x{sf}");
                    Job moving = Ran(jobs, $"{id}:terrain run"), still = Ran(jobs, $"{id}:still run");
                    if (moving == null || still == null) continue;
                    o.AppendLine(Inv($"- {id} ({path}, noise + height colour, {moving.Get("clipping_invocations")} triangles): range-only / nothing changes = {moving.GpuMs:G4} / {still.GpuMs:G4} ms = {moving.GpuMs / still.GpuMs:F3}x GPU"));
                }
            o.AppendLine();
        }

        /// <summary>Adaptive vs uniform at a 1-pixel largest error (no noise): triangles each needs, log-interpolated.</summary>
        static void Goals(StringBuilder o, string tsv)
        {
            var rows = tsv.Split('\n').Skip(1).Where(l => l.Length > 0).Select(l => l.Split('\t')).ToList();
            double Need(string method)
            {
                string mainTiles = rows.Where(r => r[0] == "adaptive").Select(r => r[1]).FirstOrDefault();
                var pts = rows.Where(r => r[0] == method && r[5] == "0" && r[1] == mainTiles && (!method.EndsWith("adaptive") || r[4] == "64"))
                              .Select(r => (tris: double.Parse(r[6], CultureInfo.InvariantCulture), err: double.Parse(r[9], CultureInfo.InvariantCulture)))
                              .Where(p => p.tris > 0).OrderBy(p => p.tris).ToList();
                for (int i = 0; i < pts.Count; i++)
                {
                    if (pts[i].err > 1.0) continue;
                    if (i == 0) return pts[0].tris;
                    var (t0, e0) = pts[i - 1]; var (t1, e1) = pts[i];
                    double w = (Math.Log(e0) - Math.Log(1.0)) / (Math.Log(e0) - Math.Log(e1));
                    return Math.Exp(Math.Log(t0) + w * (Math.Log(t1) - Math.Log(t0)));
                }
                return double.NaN;
            }
            double ad = Need("adaptive"), un = Need("uniform"), ca = Need("cached adaptive");
            o.AppendLine(Inv($"- 1-pixel largest error on the camera path (no noise, the sweep's main tile count): adaptive needs {ad:F0} triangles, uniform {un:F0}: {un / ad:F2}x fewer with adaptive factors (goal >= 4x)"));
            o.AppendLine(Inv($"- the same for the vertex cache (integer factors): cached adaptive needs {ca:F0} triangles, uniform {un:F0}: {un / ca:F2}x fewer (goal >= 4x)"));
        }

        /// <summary>The renderer inspector's "Triangles in view" for a job's camera: Core's TerrainTriangleEstimate over every tile.</summary>
        static double InspectorEstimate(PatchGrid grid, RigScene scene, BenchConfig cfg) =>
            TerrainTriangleEstimate.InView(TerrainInputs.Create(grid, scene.Params), scene.Camera.ObjectToClipFloat(),
                new Float2(scene.Camera.Width, scene.Camera.Height), cfg.Noise ? TerrainKeywords.Noise : TerrainKeywords.None,
                cfg.Cached ? TessellationPartitioning.Integer : TessellationPartitioning.FractionalOdd, int.MaxValue).triangles;

        /// <summary>The inspector's estimate against the GPU's clipping invocations, per path: the largest relative difference.</summary>
        sealed class EstimateCheck
        {
            readonly double[] _worst = new double[2];
            readonly string[] _worstId = new string[2];
            readonly int[] _jobs = new int[2], _exact = new int[2];

            public void Add(bool cached, string id, long gpu, double estimate)
            {
                int k = cached ? 1 : 0;
                double rel = Math.Abs(estimate - gpu) / Math.Max(1.0, gpu);
                _jobs[k]++;
                if (estimate == gpu) _exact[k]++;
                if (rel >= _worst[k]) { _worst[k] = rel; _worstId[k] = Inv($"{id}: GPU {gpu}, estimate {estimate:F0}"); }
            }

            public void Report(StringBuilder o)
            {
                string[] names = { "adaptive (fractional_odd)", "cached adaptive (integer)" };
                for (int k = 0; k < 2; k++)
                    if (_jobs[k] > 0)
                        o.AppendLine(Inv($"The inspector's triangle estimate (Core's TerrainTriangleEstimate, every tile) against the GPU's clipping invocations, {names[k]} jobs: {_exact[k]} of {_jobs[k]} exact, largest difference {100 * _worst[k]:G3}% ({_worstId[k]})."));
            }
        }

        static Dictionary<string, Job> ParseResults(string file)
        {
            var jobs = new Dictionary<string, Job>();
            Job cur = null;
            foreach (var line in File.ReadLines(file))
            {
                var w = line.Split(' ', StringSplitOptions.RemoveEmptyEntries);
                if (w.Length == 0) continue;
                if (w[0] == "==" && w.Length >= 3) { cur = new Job(); jobs[w[1] + " " + w[2]] = cur; continue; }
                if (cur == null) continue;
                if (w[0] == "skipped:") cur.Skipped = string.Join(" ", w.Skip(1));
                if (w[0] == "stat" && w.Length >= 3) cur.Stat[w[1]] = w[2];
                else if (w[0] == "floor" && w.Length >= 7 && w[1] == "tiles")   // bench_run.sh's floor-match line
                { cur.Stat["floor_tiles"] = w[2]; cur.Stat["floor_factor"] = w[4]; cur.Stat["floor_triangles"] = w[6]; }
                else if (w[0] == "device" && w.Length >= 3 && w[1] == "name") cur.Stat["name"] = string.Join(" ", w.Skip(2));
                else if (w[0] == "time" && w.Length >= 3 && w[1] == "frame_ms_median") cur.GpuMs = D(w[2]);
                else if (w[0] == "time" && w.Length >= 3 && w[1] == "frame_ms_mean") cur.GpuMeanMs = D(w[2]);
                else if (w[0] == "time" && w.Length >= 3 && w[1] == "cpu_frame_ms_median") cur.CpuMs = D(w[2]);
                else if (w[0] == "time" && w.Length >= 3 && w[1] == "cpu_frame_ms_mean") cur.CpuMeanMs = D(w[2]);
                else if (w[0] == "time" && w.Length >= 3 && w[1] == "compute_ms_median") cur.ComputeMs = D(w[2]);
                else if (w[0] == "exit" && w.Length >= 2) cur.Exit = int.Parse(w[1], CultureInfo.InvariantCulture);
            }
            return jobs;
        }

        static double D(string s) => double.Parse(s, CultureInfo.InvariantCulture);
        static string Inv(FormattableString s) => s.ToString(CultureInfo.InvariantCulture);
    }
}
