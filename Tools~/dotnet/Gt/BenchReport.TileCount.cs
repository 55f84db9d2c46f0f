using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using System.Text;

namespace GregoryTerrain.Rig
{
    static partial class BenchReport
    {
        /// <summary>
        /// The tile count as a knob at a fixed triangle count: for each fair static size, the cached
        /// adaptive terrain at every tile count the plan has for it (BenchPlan.AdaptiveVsStatic), its
        /// time against the static mesh still, with the camera moving and panning, and its error at
        /// the plan's view (ErrorMeasure at Core's integer factors, CacheFactors: the sweep rows check
        /// the GPU's dumped factors against the same mirror). Fewer, larger tiles make more triangles
        /// per patch, which costs less per triangle, until the nearest tiles reach the max factor.
        /// </summary>
        static void TileCount(StringBuilder o, Dictionary<string, Job> jobs, bool quick, Dictionary<string, string> planned,
                              PatchGrid grid, int width, int height)
        {
            o.AppendLine("### The tile count at a fixed triangle count");
            o.AppendLine();
            o.AppendLine("The cached adaptive terrain at each tile count the plan has for a static size, each at the target whose triangle count matches it. Error: at the plan's view, every cell, at Core's integer factors (the cached sweep rows check the GPU's factors against them). Ratios: the rows above, side by side.");
            o.AppendLine();
            o.AppendLine("| static mesh | tiles | target px | triangles | max err px | RMS err px | still / static | camera moving / static | panning / static |");
            o.AppendLine("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
            foreach (var size in BenchPlan.AdaptiveVsStatic(quick).GroupBy(x => (x.staticTiles, x.staticFactor)))
            {
                string sid = Inv($"fs_m{size.Key.staticTiles}_f{size.Key.staticFactor}");
                Job st = Ran(jobs, sid + ":static run"), stOrbit = Ran(jobs, sid + ":static-orbit run");
                foreach (var (m, _, _) in size.OrderByDescending(x => x.tiles))
                {
                    string id = Inv($"vc_m{m}_s{size.Key.staticTiles}x{size.Key.staticFactor}");
                    Job still = Ran(jobs, id + ":still run"), orbit = Ran(jobs, id + ":orbit run"), pan = Ran(jobs, id + ":pan run");
                    if (!planned.TryGetValue(id, out string target) || still == null || st == null)
                    {
                        o.AppendLine(Inv($"| {sid} | {m} | (not run or failed) | | | | | | |"));
                        continue;
                    }
                    var cfg = new BenchConfig { Method = "adaptive", Cached = true, Tiles = m, Target = double.Parse(target, CultureInfo.InvariantCulture), Octaves = 4 };
                    var scene = BenchPlan.Scene(grid, cfg, BenchPlan.CameraPath[0].range, width, height);
                    var err = ErrorCommand.Measure(scene, false, true, ErrorCommand.CacheFactors(scene, true), 1 << 20, integerPartitioning: true);
                    string Over(Job j, Job s) => j == null || s == null ? "-" : Inv($"{j.GpuMs / s.GpuMs:F3}x");
                    o.AppendLine(Inv($"| {sid} | {m} | {target} | {still.Get("clipping_invocations")} | {err.MaxPixels:G3} | {err.RmsPixels:G3} | {Over(still, st)} | {Over(orbit, stOrbit)} | {Over(pan, st)} |"));
                }
            }
            o.AppendLine();
        }
    }
}
