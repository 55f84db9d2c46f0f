using System.Collections.Generic;
using System.Text;

namespace GregoryTerrain.Rig
{
    static partial class BenchReport
    {
        /// <summary>The goal of a ground view's path against the tessellator's floor (issue 38): still 2.0x, walking 1.25x, flying 1.5x.</summary>
        public static double LevelsGoal(string path) => path switch { "walk" => 1.25, "fly" => 1.5, _ => 2.0 };

        /// <summary>
        /// The Horizon levels at ground level (BenchPlan.Levels): each view's frame beside the levels'
        /// own floor (same vert and hull, flat domain stage) and the tessellator's floor (a uniform tile
        /// grid at about the same triangles, the headline table's floor), and the split between them.
        /// </summary>
        static void LevelsTable(StringBuilder o, Dictionary<string, Job> jobs, bool quick)
        {
            o.AppendLine("## Horizon levels");
            o.AppendLine();
            o.AppendLine(Inv($"Ground views drawn with the levels (`{BenchPlan.LevelsVariant}`, M = 16 tiles a level, 1 px target, the continuous octave rule at 2 px), the domain-stage path with the tile factors from the factor kernels every frame (LodFactorPieces, LodFactorSeams: what the renderer dispatches where compute runs; frame time includes them). Levels' floor: the same vert, hull and frag with `bench_floor.hlsl`'s flat domain stage. Floor: the headline table's (the fair variant's uniform tile grid, flat domain stage), M x M tiles at odd F with 2 (M F)^2 nearest the levels' triangles. Domain stage: levels - levels' floor. Cached: the same view drawn from the levels' vertex cache (LodVertexSlots, LodCacheVertices after the factor kernels every frame, the domain stage reading one record a vertex: what the renderer draws where compute runs; frame time includes the kernels)."));
            o.AppendLine();
            o.AppendLine("| ground view | triangles | levels ms | levels' floor ms | floor ms (tiles x F, triangles) | levels / floor | cached ms | cached / floor | goal | levels' floor / floor | domain stage ms |");
            o.AppendLine("| --- | ---: | ---: | ---: | --- | ---: | ---: | ---: | ---: | ---: | ---: |");
            foreach (double m in BenchPlan.LevelTerrains(quick))
                foreach (var (name, _, _, _) in BenchPlan.LevelPathsOf(quick))
                {
                    string id = BenchPlan.LevelsId(m, name);
                    Job lv = Ran(jobs, id + ":levels run"), own = Ran(jobs, id + ":levels-floor run"), fl = Ran(jobs, id + ":floor floor-match"), ca = Ran(jobs, id + ":levels-cached run");
                    if (lv == null || own == null || fl == null || ca == null) { o.AppendLine(Inv($"| {m / 1000:N0} km, {name} (incomplete) | | | | | | | | | | |")); continue; }
                    // The goal is the path the renderer picks where compute runs: the cached one.
                    double goal = LevelsGoal(name), ratio = lv.GpuMs / fl.GpuMs, cachedRatio = ca.GpuMs / fl.GpuMs;
                    o.AppendLine(Inv($"| {m / 1000:N0} km, {name} | {lv.Get("clipping_invocations"):N0} | {lv.GpuMs:F2} | {own.GpuMs:F2} | {fl.GpuMs:F2} ({fl.Stat["floor_tiles"]} x {fl.Stat["floor_factor"]}, {fl.Get("floor_triangles"):N0}) | {ratio:F2}x | {ca.GpuMs:F2} | {cachedRatio:F2}x | {goal:F2}x{(cachedRatio <= goal ? "" : " (not met)")} | {own.GpuMs / fl.GpuMs:F2}x | {lv.GpuMs - own.GpuMs:F2} |"));
                }
            o.AppendLine();
            o.AppendLine("Cameras: " + string.Join("; ", System.Linq.Enumerable.Select(BenchPlan.LevelPathsOf(quick), p => $"{p.name}: {p.what}")) + ". Moving paths: camera and levels laid out again every frame (harness `--camera-path`, `--params-tail-path`), the levels' range origin kept (as the renderer keeps it over a small move). Triangles: the last frame's clipping invocations.");
            if (!quick)
            {
                o.AppendLine();
                o.AppendLine("Where the still views' domain-stage time goes (the same job with one thing changed; the change moves the factors too, so compare per triangle):");
                o.AppendLine();
                o.AppendLine("| ground view | change | levels triangles | levels ms | changed triangles | changed ms | ns a triangle, levels / changed |");
                o.AppendLine("| --- | --- | ---: | ---: | ---: | ---: | ---: |");
                foreach (double m in BenchPlan.LevelTerrains(quick))
                    foreach (var (split, what) in BenchPlan.LevelSplits)
                    {
                        string id = BenchPlan.LevelsId(m, "still");
                        Job lv = Ran(jobs, id + ":levels run"), ch = Ran(jobs, id + "-" + split + ":levels run");
                        if (lv == null || ch == null) { o.AppendLine(Inv($"| {m / 1000:N0} km, still | {split} (incomplete) | | | | | |")); continue; }
                        long lt = lv.Get("clipping_invocations"), ct = ch.Get("clipping_invocations");
                        o.AppendLine(Inv($"| {m / 1000:N0} km, still | {what} | {lt:N0} | {lv.GpuMs:F2} | {ct:N0} | {ch.GpuMs:F2} | {lv.GpuMs * 1e6 / lt:F1} / {ch.GpuMs * 1e6 / ct:F1} |"));
                    }
            }
            o.AppendLine();
            o.AppendLine("The cached path is GT_LOD's own (LevelVertexCacheKernels.hlsl, `_LodLevels.z`), not GT_VERTEX_CACHE: the two are never on together. Its triangles are the domain-stage path's (same factors).");
            o.AppendLine();
        }
    }
}
