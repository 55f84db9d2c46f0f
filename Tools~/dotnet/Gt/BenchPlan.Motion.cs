using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// Motion users make (issue 26): the range and the camera moving together, as the sample and the
    /// renderer drive them, frame by frame. Each path is written as harness --params-path records
    /// (the frame's whole TerrainParams, the anchored tiles following the range as the renderer keeps
    /// them, <see cref="TileLattice.Follow"/>, and whether the renderer would dispatch the vertex
    /// cache's kernels that frame) and a --camera-path of the same length, one record a frame.
    /// </summary>
    static partial class BenchPlan
    {
        /// <summary>Frames a second at which the sample's speeds are read.</summary>
        public const double FramesPerSecond = 60;

        /// <summary>The sample's flight (Samples~/TerrainFlyover/FlyoverCamera.cs defaults): a loop of this many seconds,</summary>
        public const double FlyoverLoopSeconds = 60;
        /// <summary>of radius 0.3 about the terrain's centre, at this height above the terrain's base,</summary>
        public const double FlyoverRadius = 0.3, FlyoverHeight = 0.08;
        /// <summary>the range's side between these, zooming in and out twice a loop.</summary>
        public const double FlyoverWidthNear = 0.02, FlyoverWidthFar = 0.6;
        /// <summary>Where the fly-over path starts in the loop: its zoom is fastest there.</summary>
        public const double FlyoverStartSeconds = 7.5;

        /// <summary>The sample's speed over the terrain: 2 pi 0.3 / 60 units a second, in units a frame.</summary>
        public static double FlyoverUnitsPerFrame => 2 * Math.PI * FlyoverRadius / FlyoverLoopSeconds / FramesPerSecond;

        /// <summary>The sample's zoom rate at its middle width, relative, a frame: |dw/dt| / w.</summary>
        public static double FlyoverZoomPerFrame =>
            (FlyoverWidthFar - FlyoverWidthNear) * 2 * Math.PI / FlyoverLoopSeconds / FramesPerSecond / (0.5 * (FlyoverWidthFar + FlyoverWidthNear));

        /// <summary>Side of the panned ranges (inside the unit square, so a pan has room).</summary>
        public const double PanSide = 0.5;

        /// <summary>Warm-up and measured frames of a motion job: the path has one record a frame.</summary>
        public static (int warmup, int frames) MotionFrames(bool quick) => quick ? (1, 3) : (20, 100);

        /// <summary>Where the motion paths run: the best tile count of each static size (the tile-count table).</summary>
        public static (int tiles, int staticTiles, int staticFactor)[] MotionSizes(bool quick) => quick
            ? new[] { (8, 8, 7) }
            : new[] { (10, 32, 17), (20, 32, 31), (32, 32, 63) };

        /// <summary>The paths, and what the report says of each.</summary>
        public static readonly (string name, string what)[] MotionPaths =
        {
            ("pan-sample", "the range (side 0.5) panning diagonally to and fro at the sample's flying speed over its narrowest range (0.026 range sides a frame), the camera following"),
            ("pan-cell", "the range (side 0.5) panning diagonally to and fro by one tile a frame, the camera following: new cells every frame"),
            ("zoom", "the range (centred) zooming in and out at up to the sample's zoom rate at its middle width (0.33% a frame), the camera following"),
            ("flyover", "the sample's fly-over from 7.5 s into its loop (where its zoom is fastest): camera on the loop, range around it"),
        };

        /// <summary>Paths in the quick plan: one, so the harness's --params-path runs in CI.</summary>
        public static IEnumerable<(string name, string what)> MotionPathsOf(bool quick) =>
            quick ? new[] { MotionPaths[1] } : MotionPaths;

        /// <summary>One frame of a path: the range, and the fly-over's eye and look-at point (object space), else null.</summary>
        sealed class MotionFrame
        {
            public TerrainRange Range;
            public double[] Eye, Look;
        }

        static MotionFrame[] MotionFramesOf(string path, int tiles, int count)
        {
            var frames = new MotionFrame[count];
            for (int f = 0; f < count; f++)
            {
                var m = new MotionFrame();
                switch (path)
                {
                    case "pan-sample":
                    case "pan-cell":
                    {
                        double step = path == "pan-sample" ? FlyoverUnitsPerFrame / FlyoverWidthNear * PanSide : PanSide / tiles;
                        double c = Triangle(0.25 + f * step, 1 - PanSide);
                        m.Range = new TerrainRange(c, c, c + PanSide, c + PanSide);
                        break;
                    }
                    case "zoom":
                    {
                        // w = 0.5 exp(a sin(2 pi f / count)): largest relative step a 2 pi / count.
                        double a = FlyoverZoomPerFrame * count / (2 * Math.PI);
                        double w = 0.5 * Math.Exp(a * Math.Sin(2 * Math.PI * f / count));
                        m.Range = new TerrainRange(0.5 - 0.5 * w, 0.5 - 0.5 * w, 0.5 + 0.5 * w, 0.5 + 0.5 * w);
                        break;
                    }
                    case "flyover":
                    {
                        // FlyoverCamera.LateUpdate at t = start + f / fps.
                        double phase = 2 * Math.PI * (FlyoverStartSeconds + f / FramesPerSecond) / FlyoverLoopSeconds;
                        double x = 0.5 + FlyoverRadius * Math.Cos(phase), y = 0.5 + FlyoverRadius * Math.Sin(phase);
                        double zoom = 0.5 + 0.5 * Math.Cos(2 * phase);
                        double w = FlyoverWidthNear + (FlyoverWidthFar - FlyoverWidthNear) * zoom;
                        m.Eye = new[] { x, FlyoverHeight * (0.3 + 0.7 * zoom), y };
                        m.Look = new[] { 0.5 + FlyoverRadius * Math.Cos(phase + 0.3), 0.0, 0.5 + FlyoverRadius * Math.Sin(phase + 0.3) };
                        m.Range = RangeAround(x, y, w);
                        break;
                    }
                    default: throw new ArgumentException("bench plan: no motion path '" + path + "'", nameof(path));
                }
                frames[f] = m;
            }
            return frames;
        }

        /// <summary>Runtime's RangeFit.Around for a square range: centred on (x, y), kept inside the unit square.</summary>
        static TerrainRange RangeAround(double x, double y, double w)
        {
            double c = Math.Clamp(x - 0.5 * w, 0.0, 1.0 - w), d = Math.Clamp(y - 0.5 * w, 0.0, 1.0 - w);
            return new TerrainRange(c, d, Math.Min(c + w, 1.0), Math.Min(d + w, 1.0));
        }

        /// <summary>x folded into [0, span] back and forth (a pan to and fro at constant speed).</summary>
        static double Triangle(double x, double span)
        {
            double m = x % (2 * span);
            return m <= span ? m : 2 * span - m;
        }

        /// <summary>
        /// Writes a path's records for a configuration (its pixel target, tiles, octaves): DIR/params_path.f32
        /// (per frame the TerrainParams, anchored tiles kept by TileLattice.Follow when
        /// <paramref name="anchored"/>, then (dispatch, 0, 0, 0)), DIR/camera_path.f32, and the buffers of
        /// frame 0 (--buffers DIR). Dispatch is the renderer's test (VertexCachePass): the kernels'
        /// inputs (the range, anchored only its first cells) or the camera changed. Returns the
        /// frames that dispatch, of the path's whole length.
        /// </summary>
        static int WriteMotion(PatchGrid grid, BenchConfig cfg, string path, bool anchored, string dir, int width, int height, int count)
        {
            var frames = MotionFramesOf(path, cfg.Tiles, count);
            var records = new List<float>();
            var cameras = new List<float>();
            RigScene first = null;
            TerrainParams prev = default;
            float[] prevCamera = null;
            int dispatches = 0;
            for (int f = 0; f < count; f++)
            {
                var r = frames[f].Range;
                var scene = Scene(grid, cfg, new[] { r.c, r.d, r.g, r.h }, width, height);
                if (!scene.Origin.Equals(RangeOrigin.zero))
                    throw new InvalidOperationException(Inv($"bench plan: motion path {path} frame {f} needs a range origin ({r}): the paths keep one origin"));
                TerrainParams p = scene.Params;
                if (anchored) p = p.WithTileLattice(TileLattice.Follow(f == 0 ? default : prev.tileLattice, p.range, p.tess.x));
                scene.Params = p;
                if (frames[f].Eye != null)
                    scene.Camera = RigCamera.LookAt(frames[f].Eye, frames[f].Look, 60, width, height, 0.001, 4, Identity());
                float[] camera = scene.Camera.Pack();
                bool dispatch = f == 0 || !SameFloats(KernelParams(p), KernelParams(prev)) || !SameFloats(camera, prevCamera);
                if (dispatch) dispatches++;
                records.AddRange(p.Pack());
                records.AddRange(new[] { dispatch ? 1f : 0f, 0f, 0f, 0f });
                cameras.AddRange(camera);
                if (f == 0) first = scene;
                prev = p;
                prevCamera = camera;
            }
            first.WriteBuffers(dir);
            BufferFiles.Write(Path.Combine(dir, ParamsPathFile), records.ToArray());
            BufferFiles.Write(Path.Combine(dir, PackCommand.CameraPathFile), cameras.ToArray());
            return dispatches;
        }

        /// <summary>The record file of a motion job (harness --params-path).</summary>
        public const string ParamsPathFile = "params_path.f32";

        /// <summary>What the kernels read of TerrainParams: the range replaced by TileLattice.KernelRange (VertexCachePass.WithKernelRange).</summary>
        static float[] KernelParams(TerrainParams p)
        {
            p.range = TileLattice.KernelRange(p);
            return p.Pack();
        }

        static bool SameFloats(float[] a, float[] b)
        {
            if (a == null || b == null || a.Length != b.Length) return false;
            for (int i = 0; i < a.Length; i++) if (!a[i].Equals(b[i])) return false;
            return true;
        }

        static double[,] Identity() => new double[,] { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 }, { 0, 0, 0, 1 } };

        /// <summary>
        /// The motion jobs: per size (<see cref="MotionSizes"/>) and path, the domain-stage terrain
        /// (va, anchored, as the renderer draws adaptive factors), the cached terrain (vc, anchored, its
        /// kernels dispatched when the renderer would) and the fair static mesh on the same camera
        /// path (`static-PATH`). jobs.tsv gets a `motion` line per job: id, path, tiles, dispatches.
        /// </summary>
        static void Motion(PatchGrid grid, string dir, StringBuilder plan, StringBuilder meta, bool quick, int width, int height,
                           Dictionary<string, double> targets)
        {
            var (warmup, frames) = MotionFrames(quick);
            int count = warmup + frames;
            string view = Inv($"--width {width} --height {height}");
            string t = Inv($"--stats --timestamps --frames {frames} --warmup {warmup}");
            foreach (var (m, sm, sf) in MotionSizes(quick))
            {
                string size = Inv($"m{m}_s{sm}x{sf}");
                string staticId = Inv($"fs_m{sm}_f{sf}");
                int across = m + 1;
                foreach (var (path, _) in MotionPathsOf(quick))
                {
                    foreach (var (prefix, cached) in new[] { ("va", false), ("vc", true) })
                    {
                        string id = $"{prefix}_{size}";
                        if (!targets.TryGetValue(id, out double target)) continue;
                        var cfg = new BenchConfig { Method = "adaptive", Cached = cached, Tiles = m, Target = target, Octaves = 4 };
                        string mid = $"{id}-{path}";
                        int dispatches = WriteMotion(grid, cfg, path, anchored: true, Path.Combine(dir, "jobs", mid), width, height, count);
                        string motion = $"--params-path @JOB@/{mid}/{ParamsPathFile} --camera-path @JOB@/{mid}/{PackCommand.CameraPathFile}";
                        string variant = cached ? CachedNoiseVariant : FairVariant;
                        var tess = new TessellationSettings(m, 64, (float)target, 0);
                        string cache = cached ? " " + CacheArgs(variant, tess, across) : "";
                        plan.Append($"{id}:{path}\trun\t-\t{Stages(variant, false)} --patches {across * across}{cache} --buffers @JOB@/{mid} {view} {t} {motion}\n");
                        meta.Append(Inv($"{id}:{path}\tmotion\t{m}\t0\t{target:G6}\t64\t4\t{path}\t{dispatches}\n"));
                        // The static mesh on the same camera path (once per size and path: va's and vc's cameras are the same).
                        if (!cached)
                        {
                            string staticRun = $"--vert @SPV@/static.spv --frag @SPV@/{FairVariant}/frag.spv --grid-factor {sf} --instances {sm * sm} {StaticOrder(sf)} --buffers @OUT@/static/{staticId} {view} {t}";
                            plan.Append($"{staticId}:static-{path}-{m}\trun\t-\t{staticRun} --camera-path @JOB@/{mid}/{PackCommand.CameraPathFile}\n");
                        }
                    }
                }
            }
        }
    }
}
