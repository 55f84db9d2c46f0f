using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;

namespace GregoryTerrain.Rig
{
    static partial class BenchReport
    {
        /// <summary>The row-major grid's unique vertices: instances (F+1)^2.</summary>
        static long GridVertices(int tiles, int f) => (long)tiles * tiles * (f + 1) * (f + 1);

        /// <summary>
        /// The fair baseline (issue 26): the baked static mesh in three index orders (Forsyth's, the
        /// fair one; 2-column strips; row by row), each with its measured vertex-stage runs per unique
        /// vertex (pipeline statistics: vertex shader invocations / (F+1)^2 M^2) and per triangle, and
        /// the tessellator's floor (the same tiles with a domain stage that evaluates nothing): every
        /// path at that size as a ratio to the fair static mesh and to the floor.
        /// </summary>
        static void Baseline(StringBuilder o, Dictionary<string, Job> jobs, bool quick)
        {
            o.AppendLine("## The fair baseline and the floor");
            o.AppendLine();
            o.AppendLine("The baked static mesh (the terrain's vertices, same frag) in three index orders of the same triangles: Forsyth's linear-speed vertex cache optimisation (the fair static mesh every ratio of this report uses), 2-column strips, and row by row (the harness's own order). Vertex-stage runs per vertex (ATVR) = vertex shader invocations / unique vertices, per triangle (ACMR) = invocations / triangles, from the pipeline statistics of the last frame. Floor: the same tiles, factors and frag with a domain stage that evaluates nothing (`Tools~/rig/bench_floor.hlsl`).");
            o.AppendLine();
            o.AppendLine("| tiles | F | triangles | Forsyth ms | ATVR | ACMR | strips ms | ATVR | row by row ms | ATVR | ACMR | floor ms | Forsyth / floor | row by row / Forsyth |");
            o.AppendLine("| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
            foreach (var (m, f) in BenchPlan.FairSizes(quick))
            {
                string id = Inv($"fs_m{m}_f{f}");
                Job fo = Ran(jobs, id + ":static run"), st = Ran(jobs, id + ":static-strips run"), rows = Ran(jobs, id + ":static-rows run"), fl = Ran(jobs, id + ":tess-floor run");
                long verts = GridVertices(m, f), tris = 2L * m * m * f * f;
                string Ms(Job j) => j == null ? "-" : Inv($"{j.GpuMs:G4}");
                string Atvr(Job j) => j == null ? "-" : Inv($"{j.Get("vertex_shader_invocations") / (double)verts:F3}");
                string Acmr(Job j) => j == null ? "-" : Inv($"{j.Get("vertex_shader_invocations") / (double)tris:F3}");
                string Over(Job a, Job b) => a == null || b == null ? "-" : Inv($"{a.GpuMs / b.GpuMs:F3}x");
                o.AppendLine(Inv($"| {m} | {f} | {tris} | {Ms(fo)} | {Atvr(fo)} | {Acmr(fo)} | {Ms(st)} | {Atvr(st)} | {Ms(rows)} | {Atvr(rows)} | {Acmr(rows)} | {Ms(fl)} | {Over(fo, fl)} | {Over(rows, fo)} |"));
            }
            o.AppendLine();
            o.AppendLine("Every path against the fair static mesh and the floor of the same size (GPU ms; the adaptive rows at the target whose triangle count matches the static mesh):");
            o.AppendLine();
            o.AppendLine("| path | tiles | triangles | GPU ms | / fair static | / floor |");
            o.AppendLine("| --- | ---: | ---: | ---: | ---: | ---: |");
            foreach (var (m, f) in BenchPlan.FairSizes(quick))
            {
                string id = Inv($"fs_m{m}_f{f}");
                Job fo = Ran(jobs, id + ":static run"), fl = Ran(jobs, id + ":tess-floor run");
                if (fo == null || fl == null) continue;
                void Row(string name, int tiles, Job j)
                {
                    if (j == null) return;
                    o.AppendLine(Inv($"| {name} | {tiles} | {j.Get("clipping_invocations")} | {j.GpuMs:G4} | {j.GpuMs / fo.GpuMs:F3}x | {j.GpuMs / fl.GpuMs:F3}x |"));
                }
                Row($"{id} fair static (Forsyth)", m, fo);
                Row($"{id} static row by row", m, Ran(jobs, id + ":static-rows run"));
                Row($"{id} domain stage, uniform F, range moving", m, Ran(jobs, id + ":terrain run"));
                Row($"{id} fallback grid, range moving", m, Ran(jobs, id + ":fallback run"));
                Row($"{id} compute cache, uniform F, range moving", m, Ran(jobs, id + ":cached run"));
                foreach (var (am, sm, sf) in BenchPlan.AdaptiveVsStatic(quick).Where(x => x.staticTiles == m && x.staticFactor == f))
                {
                    string va = Inv($"va_m{am}_s{sm}x{sf}"), vc = Inv($"vc_m{am}_s{sm}x{sf}");
                    Row($"{va} domain stage, adaptive, range moving", am, Ran(jobs, va + ":terrain run"));
                    Row($"{va} its own floor (same factors)", am, Ran(jobs, va + ":tess-floor run"));
                    Row($"{vc} compute cache, still", am, Ran(jobs, vc + ":still run"));
                    Row($"{vc} compute cache, panning over anchored tiles", am + 1, Ran(jobs, vc + ":pan run"));
                    Row($"{vc} compute cache, camera moving", am, Ran(jobs, vc + ":orbit run"));
                }
            }
            o.AppendLine();
            o.AppendLine("Domain stage per vertex against its own floor (same tiles and factors, nothing evaluated): (terrain - floor) / domain invocations:");
            o.AppendLine();
            foreach (var (am, sm, sf) in BenchPlan.AdaptiveVsStatic(quick))
            {
                string va = Inv($"va_m{am}_s{sm}x{sf}");
                Job t = Ran(jobs, va + ":terrain run"), fl = Ran(jobs, va + ":tess-floor run");
                if (t == null || fl == null) continue;
                long ds = t.Get("tessellation_evaluation_shader_invocations");
                o.AppendLine(Inv($"- {va}: {ds} domain invocations, {t.GpuMs:G4} ms vs floor {fl.GpuMs:G4} ms: {(t.GpuMs - fl.GpuMs) * 1e6 / ds:F3} ns a vertex above the floor, {t.GpuMs / fl.GpuMs:F3}x"));
            }
            o.AppendLine();
        }

        /// <summary>
        /// Where the domain stage's time goes (issue 26): per size of BenchPlan.DomainPartSizes, the
        /// terrain's domain stage (noise + colour), the same draw with one piece taken out a job
        /// (Tools~/rig/bench_domain_parts.hlsl, BenchPlan.DomainParts), the floor, and the plain stage
        /// against a minimal Gregory evaluator drawing the same triangles. A piece costs (full - part);
        /// ns a vertex = ms * 1e6 / domain invocations.
        /// </summary>
        static void DomainParts(StringBuilder o, Dictionary<string, Job> jobs, bool quick)
        {
            o.AppendLine("## Where the domain stage's time goes");
            o.AppendLine();
            o.AppendLine("The fair variant's domain stage (noise + height colour, uniform F, range moving) rewritten from the same library functions without its deep-zoom branch (`full`), then with one piece taken out a job (`Tools~/rig/bench_domain_parts.hlsl`, rig only; the pictures of those jobs are wrong on purpose). A piece costs full - that job; terrain - full is what the rewrite misses (up to 38e67eb the never-taken deep-zoom branch, now compiled in only with GT_RANGE_ORIGIN). ns a vertex: per domain invocation.");
            o.AppendLine();
            foreach (var (m, f) in BenchPlan.DomainPartSizes(quick))
            {
                string id = Inv($"fs_m{m}_f{f}");
                Job terrain = Ran(jobs, id + ":terrain run"), full = Ran(jobs, id + ":part-full run"), fl = Ran(jobs, id + ":tess-floor run");
                if (terrain == null || full == null || fl == null) continue;
                long ds = terrain.Get("tessellation_evaluation_shader_invocations");
                if (ds <= 0) continue;
                double Ns(double ms) => ms * 1e6 / ds;
                o.AppendLine(Inv($"{id}: {2L * m * m * f * f} triangles, {ds} domain invocations; terrain {terrain.GpuMs:G4} ms, floor {fl.GpuMs:G4} ms ({Ns(terrain.GpuMs - fl.GpuMs):F3} ns a vertex above it)."));
                o.AppendLine();
                o.AppendLine("| job | what it takes out | GPU ms | piece ms | piece ns a vertex | share of terrain - floor |");
                o.AppendLine("| --- | --- | ---: | ---: | ---: | ---: |");
                double above = terrain.GpuMs - fl.GpuMs;
                o.AppendLine(Inv($"| terrain | nothing (the package's domain stage) | {terrain.GpuMs:G4} | | | |"));
                foreach (var (part, what) in BenchPlan.DomainParts)
                {
                    Job j = Ran(jobs, id + ":part-" + part + " run");
                    if (j == null) { o.AppendLine($"| {part} | {what} | - | | | |"); continue; }
                    double piece = part == "full" ? terrain.GpuMs - j.GpuMs : full.GpuMs - j.GpuMs;
                    string cost = part == "plain" || part == "minimal" ? "| | | |" : Inv($"| {piece:F3} | {Ns(piece):F3} | {piece / above * 100:F0}% |");
                    o.AppendLine(Inv($"| {part} | {what} | {j.GpuMs:G4} {cost}"));
                }
                o.AppendLine(Inv($"| tess-floor | everything (the tessellator's floor) | {fl.GpuMs:G4} | | | |"));
                o.AppendLine();
                Job plain = Ran(jobs, id + ":plain run"), minimal = Ran(jobs, id + ":part-minimal run");
                if (plain != null && minimal != null)
                {
                    // Per vertex above the floor only where the minimal evaluator costs anything above it.
                    string perVertex = minimal.GpuMs > fl.GpuMs ? Inv($"**{(plain.GpuMs - fl.GpuMs) / (minimal.GpuMs - fl.GpuMs):F2}x** per vertex, ") : "";
                    o.AppendLine(Inv($"Plain domain stage (the package's, variant `base`) against the minimal Gregory evaluator: {plain.GpuMs:F4} vs {minimal.GpuMs:F4} ms, {Ns(plain.GpuMs - fl.GpuMs):F3} vs {Ns(minimal.GpuMs - fl.GpuMs):F3} ns a vertex above the floor: {perVertex}{plain.GpuMs / minimal.GpuMs:F3}x a frame."));
                }
                o.AppendLine();
            }
        }

        /// <summary>
        /// Motion users make (BenchPlan.Motion): per size and path, the domain stage and the compute
        /// cache (anchored tiles, kernels dispatched when the renderer would: jobs.tsv's count) against
        /// the fair static mesh on the same camera path, and the cache's still frame and floor.
        /// </summary>
        static void MotionTable(StringBuilder o, Dictionary<string, Job> jobs, bool quick, string planDir)
        {
            var dispatches = new Dictionary<string, string>();
            string jobsTsv = Path.Combine(planDir, "jobs.tsv");
            if (File.Exists(jobsTsv))
                foreach (var l in File.ReadLines(jobsTsv).Skip(1)) { var c = l.Split('\t'); if (c.Length > 8 && c[1] == "motion") dispatches[c[0]] = c[8]; }
            var (warmup, frames) = BenchPlan.MotionFrames(quick);
            o.AppendLine("## Motion users make");
            o.AppendLine();
            o.AppendLine(Inv($"Each path is {warmup} warm-up and {frames} measured frames at {BenchPlan.FramesPerSecond} fps, one TerrainParams and one camera a frame (harness `--params-path`, `--camera-path`), the tiles anchored as the renderer keeps them (`TileLattice.Follow`: a zoom anchors them again). The compute cache dispatches its kernels in the frames the renderer would (its inputs or the camera changed; dispatches: of all {warmup + frames} frames of the path; the kernels evaluate only the cells whose factors or place changed). GPU ms: the median frame (the mean in brackets). Static: the fair static mesh of the size on the same camera path."));
            o.AppendLine();
            foreach (var (name, what) in BenchPlan.MotionPathsOf(quick)) o.AppendLine($"- `{name}`: {what}.");
            o.AppendLine();
            o.AppendLine("| path | tiles | domain stage triangles | ms | / static | per triangle | compute cache triangles | dispatches | ms | / static | per triangle | static ms |");
            o.AppendLine("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
            foreach (var (m, sm, sf) in BenchPlan.MotionSizes(quick))
                foreach (var (path, _) in BenchPlan.MotionPathsOf(quick))
                {
                    string va = Inv($"va_m{m}_s{sm}x{sf}:{path}"), vc = Inv($"vc_m{m}_s{sm}x{sf}:{path}");
                    Job a = Ran(jobs, va + " run"), c = Ran(jobs, vc + " run"), st = Ran(jobs, Inv($"fs_m{sm}_f{sf}:static-{path}-{m} run"));
                    string Ms(Job j) => j == null ? "-" : Inv($"{j.GpuMs:G4} ({j.GpuMeanMs:G4})");
                    string Over(Job j) => j == null || st == null ? "-" : Inv($"{j.GpuMs / st.GpuMs:F3}x");
                    string Tris(Job j) => j == null ? "-" : Inv($"{j.Get("clipping_invocations")}");
                    string d = dispatches.TryGetValue(vc, out var n) ? n : "-";
                    string PerTri(Job j) => j == null || st == null ? "-" : Inv($"{j.GpuMs / j.Get("clipping_invocations") / (st.GpuMs / st.Get("clipping_invocations")):F3}x");
                    o.AppendLine(Inv($"| {path} | {m} | {Tris(a)} | {Ms(a)} | {Over(a)} | {PerTri(a)} | {Tris(c)} | {d} | {Ms(c)} | {Over(c)} | {PerTri(c)} | {(st == null ? "-" : Inv($"{st.GpuMs:G4}"))} |"));
                }
            o.AppendLine();
            o.AppendLine("Triangles: the last frame's (the paths change the range, so the count moves from frame to frame); per triangle: the ratio of ms per triangle, the static mesh drawing all of its own.");
            o.AppendLine();
        }

        /// <summary>
        /// The ratios the README and the manual quote (Tools~/RigTests/QuotedFiguresTests.cs compares
        /// them with this table): against the fair (Forsyth-ordered) static mesh and the floor, one
        /// row per path, one column per static size (the best tile count of each: BenchPlan.MotionSizes).
        /// </summary>
        static void Headline(StringBuilder o, Dictionary<string, Job> jobs, bool quick)
        {
            var sizes = BenchPlan.MotionSizes(quick);
            o.AppendLine("## Headline ratios");
            o.AppendLine();
            o.AppendLine("GPU time against the fair static mesh (Forsyth's order) of the same triangle count; `floor`: against the tessellator's floor of that size; `fastest static order`: against the faster of Forsyth's order and 2-column strips in this run. Best tile count per size. The motion rows (pans, zoom, fly-over) are frame against frame on the same camera path: the terrain draws the triangles its target gives for that view (fewer than the static mesh's: see \"Motion users make\"), the static mesh all of its own.");
            o.AppendLine();
            o.AppendLine("| path | " + string.Join(" | ", sizes.Select(s => SizeLabel(s.staticTiles, s.staticFactor))) + " |");
            o.AppendLine("| --- |" + string.Concat(sizes.Select(_ => " ---: |")));
            void Row(string name, Func<(int m, string va, string vc, string fs), double?> ratio)
            {
                var cells = sizes.Select(s =>
                {
                    double? r = ratio((s.tiles, Inv($"va_m{s.tiles}_s{s.staticTiles}x{s.staticFactor}"), Inv($"vc_m{s.tiles}_s{s.staticTiles}x{s.staticFactor}"), Inv($"fs_m{s.staticTiles}_f{s.staticFactor}")));
                    return r.HasValue ? Inv($"{r.Value:F3}x") : "-";
                });
                o.AppendLine($"| {name} | " + string.Join(" | ", cells) + " |");
            }
            double? Over(string a, string b) { var x = Ran(jobs, a + " run"); var y = Ran(jobs, b + " run"); return x == null || y == null ? null : x.GpuMs / y.GpuMs; }
            double? OverBest(string a, string fs)
            {
                var x = Ran(jobs, a + " run"); var f = Ran(jobs, fs + ":static run"); var st = Ran(jobs, fs + ":static-strips run");
                if (x == null || f == null) return null;
                return x.GpuMs / Math.Min(f.GpuMs, st?.GpuMs ?? double.PositiveInfinity);
            }
            Row("compute cache, panning (anchored tiles)", s => Over(s.vc + ":pan", s.fs + ":static"));
            Row("compute cache, still", s => Over(s.vc + ":still", s.fs + ":static"));
            Row("compute cache, camera moving", s => Over(s.vc + ":orbit", s.fs + ":static-orbit"));
            Row("compute cache, still / floor", s => Over(s.vc + ":still", s.fs + ":tess-floor"));
            Row("compute cache, pan at the sample's speed", s => Over(s.vc + ":pan-sample", s.fs + $":static-pan-sample-{s.m}"));
            Row("compute cache, pan of a tile a frame", s => Over(s.vc + ":pan-cell", s.fs + $":static-pan-cell-{s.m}"));
            Row("compute cache, zoom", s => Over(s.vc + ":zoom", s.fs + $":static-zoom-{s.m}"));
            Row("compute cache, fly-over", s => Over(s.vc + ":flyover", s.fs + $":static-flyover-{s.m}"));
            Row("domain stage, noise + colour", s => Over(s.va + ":terrain", s.fs + ":static"));
            Row("domain stage, tiled noise + colour", s => Over(s.va + ":terrain-tiled", s.fs + ":static"));
            Row("domain stage, fly-over", s => Over(s.va + ":flyover", s.fs + $":static-flyover-{s.m}"));
            Row("compute cache, still / fastest static order", s => OverBest(s.vc + ":still", s.fs));
            Row("compute cache, panning / fastest static order", s => OverBest(s.vc + ":pan", s.fs));
            Row("domain stage / fastest static order", s => OverBest(s.va + ":terrain", s.fs));
            Row("2-column strips / fair static (Forsyth)", s => Over(s.fs + ":static-strips", s.fs + ":static"));
            Row("fair static / floor", s => Over(s.fs + ":static", s.fs + ":tess-floor"));
            Row("static row by row / fair static", s => Over(s.fs + ":static-rows", s.fs + ":static"));
            Row("compute cache, panning / floor", s => Over(s.vc + ":pan", s.fs + ":tess-floor"));
            Row("domain stage / floor", s => Over(s.va + ":terrain", s.fs + ":tess-floor"));
            Row("domain stage, tiled noise / floor", s => Over(s.va + ":terrain-tiled", s.fs + ":tess-floor"));
            o.AppendLine();
        }

        /// <summary>"0.6M" for a static size of 2 M^2 F^2 triangles.</summary>
        public static string SizeLabel(int tiles, int f)
        {
            double t = 2.0 * tiles * tiles * f * f / 1e6;
            return t >= 0.1 ? Inv($"{t:0.#}M") : Inv($"{t * 1000:0.#}K");
        }
    }
}
