using System;
using System.Collections.Generic;
using System.IO;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// Everything one harness run draws: the grid, the range, the settings and the camera, read from
    /// command-line options with the demo's defaults, packed with Core's GpuLayout and TerrainParams.
    /// </summary>
    sealed class RigScene
    {
        public PatchGrid Grid;
        public TerrainRange Range;
        public RangeOrigin Origin;
        public TessellationSettings Tessellation;
        public NoiseSettings Noise;
        public HeightColorSettings HeightColor;
        public Float3 ColorLow = new Float3(0.16f, 0.30f, 0.10f), ColorHigh = new Float3(0.85f, 0.82f, 0.78f);
        public RigCamera Camera;
        public TerrainParams Params;

        public static RigScene FromArgs(Args a) => FromGrid(ReadGrid(a), a);

        /// <summary>The patch grid JSON named by --grid (every command that takes one reads it so).</summary>
        public static PatchGrid ReadGrid(Args a) => PatchGridJson.ReadFile(a.String("grid"));

        /// <summary>The scene of the options in <paramref name="a"/> over an already loaded grid.</summary>
        public static RigScene FromGrid(PatchGrid grid, Args a)
        {
            var s = new RigScene { Grid = grid };
            var r = a.Doubles("range", 4, "0,0,1,1");
            s.Range = new TerrainRange(r[0], r[1], r[2], r[3]);
            s.Range.Validate();
            s.Origin = a.Flag("plain-origin") ? RangeOrigin.zero : RangeOrigin.For(s.Range);
            s.Tessellation = new TessellationSettings(a.Int("tiles", 8), (float)a.Double("max-factor", 64),
                (float)a.Double("target-pixels", 8), (float)a.Double("factor", 0));
            var n = a.Doubles("noise", 4, "0.004,16,2,2");
            s.Noise = new NoiseSettings((float)n[0], (float)n[1], (float)n[2], (float)n[3], a.Int("octaves", 4));
            s.HeightColor = new HeightColorSettings((float)a.Double("gamma", 0.25), 0.15f, 24f);
            s.Params = TerrainParams.Create(s.Grid, s.Range, s.Origin, s.Tessellation, s.Noise, s.HeightColor,
                s.ColorLow, s.ColorHigh, (float)a.Double("noise-vertices", 0));
            // --anchor-at c,d,g,h: tiles anchored to the terrain at that range (TileLattice), as the
            // renderer anchors them at the range it had when a pan began.
            if (a.Flag("anchor-at"))
            {
                var l = a.Doubles("anchor-at", 4);
                RangeMapping.EncodeRange(new TerrainRange(l[0], l[1], l[2], l[3]), s.Origin, out Float4 lattice, out _);
                s.Params = s.Params.WithTileLattice(lattice);
            }
            s.Camera = ZoomViewCamera(s, a.Int("width", 800), a.Int("height", 600));
            return s;
        }

        /// <summary>
        /// The paper's zoom view: the range fills a fixed display box of size 1 centred on the origin,
        /// scaled uniformly (heights too, so zooming in is a camera coming closer), looked at from
        /// above at an angle. The height at the range's centre is the box's centre height.
        /// </summary>
        internal static RigCamera ZoomViewCamera(RigScene s, int width, int height, double yawDegrees = 0)
        {
            double w = Math.Max(s.Range.Width, s.Range.Height), scale = 1.0 / w;
            double cx = 0.5 * (s.Range.c + s.Range.g), cy = 0.5 * (s.Range.d + s.Range.h);
            double z0 = CoreSurface.HeightAt(s.Grid, cx, cy);
            // object (x, z, y) -> world ((x - cx) s, (z - z0) s, (y - cy) s). While a range origin is
            // set the shaders output S(q) - S(O) (precision.md): add S(O) back here, in double, where it
            // cancels against the centre (only the small difference reaches the float matrix).
            Double3 r = RelativeSurface.IsActive(s.Origin.ToFloat4())
                ? RelativeSurface.ReferencePoint(s.Grid, s.Origin) : new Double3(0, 0, 0);
            var objectToWorld = new double[,]
            {
                { scale, 0, 0, (r.x - cx) * scale },
                { 0, scale, 0, (r.z - z0) * scale },
                { 0, 0, scale, (r.y - cy) * scale },
                { 0, 0, 0, 1 },
            };
            // yaw: the eye turned about the vertical through the target (x, z of the eye rotated).
            double a = yawDegrees * Math.PI / 180.0, ex = -1.05 * Math.Sin(a), ez = -1.05 * Math.Cos(a);
            return RigCamera.LookAt(new[] { ex, 0.75, ez }, new[] { 0.0, -0.05, 0.0 }, 50, width, height, 0.01, 20, objectToWorld);
        }

        /// <summary>
        /// A camera moving around the terrain (harness --camera-path): <paramref name="frames"/>
        /// RigCamera blocks, the zoom view turned by <c>amplitudeDegrees sin(2 pi f / frames)</c> about
        /// the vertical through its target, so every frame moves a little (at most
        /// <c>2 pi amplitude / frames</c> degrees) and the path returns to its start.
        /// </summary>
        public float[] OrbitCameraPath(int frames, double amplitudeDegrees)
        {
            var path = new List<float>();
            for (int f = 0; f < frames; f++)
                path.AddRange(ZoomViewCamera(this, Camera.Width, Camera.Height, amplitudeDegrees * Math.Sin(2 * Math.PI * f / frames)).Pack());
            return path.ToArray();
        }

        /// <summary>Writes the five buffer files the harness reads (--buffers DIR).</summary>
        public void WriteBuffers(string dir)
        {
            Directory.CreateDirectory(dir);
            BufferFiles.Write(Path.Combine(dir, "control_points.f32"), GpuLayout.PackControlPoints(Grid));
            BufferFiles.Write(Path.Combine(dir, "regions.f32"), GpuLayout.PackRegions(Grid));
            BufferFiles.Write(Path.Combine(dir, "grid_lines.f32"), GpuLayout.PackGridLines(Grid));
            BufferFiles.Write(Path.Combine(dir, "params.f32"), Params.Pack());
            BufferFiles.Write(Path.Combine(dir, "camera.f32"), Camera.Pack());
        }
    }
}
