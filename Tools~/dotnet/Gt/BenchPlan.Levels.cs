using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// The Horizon levels at ground level (issue 38): <see cref="LodScene"/>'s view of a terrain
    /// drawn with the levels of detail at a 1 px target, for a still camera and along a walking and a
    /// flying path (camera and levels moving every frame: harness --camera-path and
    /// --params-tail-path, one record a frame), each beside two floors: the levels' own stages with
    /// the floor's domain stage (same hull, <c>floor_lod.spv</c>), and the tessellator's floor of the
    /// headline table (the fair variant's uniform tile grid with <c>floor.spv</c>) at the triangle
    /// count the levels drew, matched on the device (bench_run.sh's floor-match kind: M x M tiles at
    /// odd F with 2 (M F)^2 nearest the count). Each view twice: the domain-stage path
    /// (<c>levels</c>) and the cached one (<c>levels-cached</c>: the vertex cache's kernels after the
    /// factor kernels every frame, the domain stage reading the records; what the renderer draws where
    /// compute runs), the same camera, tails and triangles.
    /// </summary>
    static partial class BenchPlan
    {
        /// <summary>The levels' variant: the fair comparison's look (noise, two-colour height colour) with GT_LOD.</summary>
        public const string LevelsVariant = "lod+noise+height_color";

        /// <summary>Terrain widths (metres) of the ground views.</summary>
        public static double[] LevelTerrains(bool quick) => quick ? new[] { 100000.0 } : new[] { 100000.0, 1000000.0 };

        /// <summary>The camera paths: name, eye height (m), speed (m/s), and what the report says of it.</summary>
        public static readonly (string name, double eyeM, double speed, string what)[] LevelPaths =
        {
            ("still", 2, 0, "2 m up"),
            ("walk", 2, 1.5, "1.5 m/s forward, 2 m up"),
            ("fly", 200, 50, "50 m/s forward, 200 m up"),
        };

        /// <summary>Paths of the quick plan: the walk alone (so --params-tail-path runs in CI).</summary>
        public static IEnumerable<(string name, double eyeM, double speed, string what)> LevelPathsOf(bool quick) =>
            quick ? new[] { LevelPaths[1] } : LevelPaths;

        /// <summary>The ground views' screen: the plan's, or 160 x 90 in the quick plan (lavapipe draws 1 px levels at 480 x 270 in seconds a frame).</summary>
        static (int width, int height) LevelsView(bool quick, int width, int height) => quick ? (160, 90) : (width, height);

        /// <summary>Job id of a ground view: lod_t{metres}_{path}.</summary>
        public static string LevelsId(double terrainM, string path) => Inv($"lod_t{terrainM:F0}_{path}");

        /// <summary>
        /// The cached jobs' records (<c>_LodLevels.z</c>): 64 MB, above the ground views' 5.9-16 MB, so
        /// no tile falls back to the domain stage (a short buffer draws right but times the fallback).
        /// </summary>
        public const int LevelsCacheRecords = LevelVertexCache.MaxRecords / 4;

        /// <summary>The cached jobs' tail (<c>_LodLevels.z</c> set) and tail path, beside the domain-stage job's.</summary>
        public const string LevelsCachedTailFile = "lod_tail_cached.f32", LevelsCachedTailPathFile = "lod_tail_path_cached.f32";

        /// <summary>Folder of jobs/ holding the uniform grid the floor-match jobs draw (params patched on the device).</summary>
        public const string LevelsFloorTemplate = "levels_floor";

        static void Levels(PatchGrid grid, string dir, StringBuilder plan, StringBuilder meta, bool quick, int width, int height)
        {
            var (warmup, frames) = MotionFrames(quick);
            (width, height) = LevelsView(quick, width, height);
            string view = Inv($"--width {width} --height {height}");
            string t = Inv($"--stats --timestamps --frames {frames} --warmup {warmup}");
            // The floor's uniform grid: the fair variant's far view; bench_run.sh sets tiles and F.
            var floorCfg = new BenchConfig { Method = "uniform", Tiles = 32, Factor = 31, Octaves = 4 };
            Scene(grid, floorCfg, CameraPath[0].range, width, height).WriteBuffers(Path.Combine(dir, "jobs", LevelsFloorTemplate));
            PatchGrid lodGrid = DemoGridCommand.GroundViewGrid();
            foreach (double m in LevelTerrains(quick))
                foreach (var (name, eye, speed, _) in LevelPathsOf(quick))
                {
                    string id = LevelsId(m, name), jobDir = Path.Combine(dir, "jobs", id);
                    var scene = new LodScene { TerrainMeters = m, EyeMeters = eye, Width = width, Height = height, KernelFactors = true }.Build(lodGrid);
                    scene.Write(jobDir);
                    LodScene cached = scene.WithCacheRecords(LevelsCacheRecords);
                    BufferFiles.Write(Path.Combine(jobDir, LevelsCachedTailFile), cached.Tail);
                    string moving = "", movingCached = "";
                    if (speed > 0)
                    {
                        int n = warmup + frames;
                        var cameras = new List<float>(n * 44);
                        var tails = new List<float>(n * scene.Tail.Length);
                        var cachedTails = new List<float>(n * scene.Tail.Length);
                        for (int f = 0; f < n; f++)
                        {
                            LodScene s = scene.Stepped(speed * f / FramesPerSecond);
                            cameras.AddRange(s.Camera.Pack());
                            tails.AddRange(s.Tail);
                            cachedTails.AddRange(s.WithCacheRecords(LevelsCacheRecords).Tail);
                        }
                        BufferFiles.Write(Path.Combine(jobDir, PackCommand.CameraPathFile), cameras.ToArray());
                        BufferFiles.Write(Path.Combine(jobDir, LevelsTailPathFile), tails.ToArray());
                        BufferFiles.Write(Path.Combine(jobDir, LevelsCachedTailPathFile), cachedTails.ToArray());
                        moving = $" --camera-path @JOB@/{id}/{PackCommand.CameraPathFile} --params-tail-path @JOB@/{id}/{LevelsTailPathFile}";
                        movingCached = $" --camera-path @JOB@/{id}/{PackCommand.CameraPathFile} --params-tail-path @JOB@/{id}/{LevelsCachedTailPathFile}";
                    }
                    string input = $"--patches {scene.Patches} --buffers @JOB@/{id} --params-tail @JOB@/{id}/lod_tail.f32{moving} {LevelsKernels(scene)} {view} {t}";
                    plan.Append($"{id}:levels\trun\t-\t{Stages(LevelsVariant, false)} {input}\n");
                    plan.Append($"{id}:levels-cached\trun\t-\t{Stages(LevelsVariant, false)} --patches {scene.Patches} --buffers @JOB@/{id} --params-tail @JOB@/{id}/{LevelsCachedTailFile}{movingCached} {LevelsKernels(cached)} {view} {t}\n");
                    plan.Append($"{id}:levels-floor\trun\t-\t{LevelsFloorStages} {input}\n");
                    plan.Append($"{id}:floor\tfloor-match\t{id}:levels\t{FloorStages} --buffers @FLOOR@ {view} {t}\n");
                    meta.Append(Inv($"{id}\tlevels\t{scene.Tiles}\t0\t{scene.TargetPixels}\t{scene.MaxFactor}\t{scene.Noise.octaves}\t{name}\t{scene.Patches}\n"));
                }
            if (quick) return;
            // Where the still views' domain-stage time goes: the same view without the range origin
            // (every vertex in plain absolute float: the precise path's cost) and with the continuous
            // octave rule at 64 px segments (fewer octaves near the feet: the octave loop's cost).
            foreach (double m in LevelTerrains(quick))
                foreach (var (split, _) in LevelSplits)
                {
                    string id = LevelsId(m, "still") + "-" + split, jobDir = Path.Combine(dir, "jobs", id);
                    var scene = new LodScene { TerrainMeters = m, Width = width, Height = height, KernelFactors = true };
                    if (split == "no_origin") scene.UseOrigin = false; else scene.SegmentPixels = 64f;
                    scene.Build(lodGrid).Write(jobDir);
                    plan.Append($"{id}:levels\trun\t-\t{Stages(LevelsVariant, false)} --patches {scene.Patches} --buffers @JOB@/{id} --params-tail @JOB@/{id}/lod_tail.f32 {LevelsKernels(scene)} {view} {t}\n");
                }
        }

        /// <summary>The still views' split jobs (full plan only): name and what each leaves out.</summary>
        public static readonly (string name, string what)[] LevelSplits =
        {
            ("no_origin", "no range origin: every vertex in plain absolute float (not stable at 1,000 km; the precise path's cost)"),
            ("octaves_64px", "the continuous octave rule at 64 px segments instead of 2 (fewer octaves near the feet; the octave loop's cost)"),
        };

        /// <summary>The factor kernels every frame before the draw, the hull reading their records (binding 7); with the scene's cache records, the vertex cache's kernels after them (binding 8).</summary>
        static string LevelsKernels(LodScene scene)
        {
            string s = $"--storage {scene.FactorStorage} --storage {scene.CacheStorage} " + string.Join(" ", scene.KernelArgs($"@SPV@/{LevelsVariant}/lod_pieces.spv", $"@SPV@/{LevelsVariant}/lod_seams.spv"));
            return scene.CacheRecords == 0 ? s : s + " " + string.Join(" ", scene.CacheKernelArgs($"@SPV@/{LevelsVariant}/lod_slots.spv", $"@SPV@/{LevelsVariant}/lod_vertices.spv"));
        }

        /// <summary>The levels' tails a frame (--params-tail-path), beside the job's camera path.</summary>
        public const string LevelsTailPathFile = "lod_tail_path.f32";

        /// <summary>The levels' vert, hull and frag with the floor's domain stage (floor_lod.spv: bench_floor.hlsl with GT_LOD).</summary>
        static string LevelsFloorStages =>
            $"--vert @SPV@/{LevelsVariant}/vert.spv --tesc @SPV@/{LevelsVariant}/tesc.spv --tese @SPV@/floor_lod.spv --frag @SPV@/{LevelsVariant}/frag.spv";
    }
}
